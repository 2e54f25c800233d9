/* Test plug-ins (ricochet/plugin.h), one source built into several libraries, each with one define:
 *   PLUGIN_GOOD          "test-good": a plain double-precision sweep, the lecture's five tests with reasons
 *   PLUGIN_FRAME         "test-frame": the same, plus a whole-frame step of its own (the lecture's loop)
 *   PLUGIN_FRAME_WRONG   "test-frame-wrong": a frame step that never hits anything (balls pass through walls)
 *   PLUGIN_NO_ENTRY      no ricochet_plugin_entry at all
 *   PLUGIN_WRONG_ABI     a table of ABI version 99
 *   PLUGIN_SHORT_TABLE   struct_size 8: too short to hold sweep
 *   PLUGIN_NO_TABLE      the entry returns NULL
 *   PLUGIN_BAD_NAME      the name "bad name"
 *   PLUGIN_TAKEN_NAME    the name "robust"
 *   PLUGIN_NO_SWEEP      no sweep function
 *   PLUGIN_INIT_FAILS    init returns 7
 *   PLUGIN_BAD_MISS      sweep answers miss code 42 for legs moving left
 *   PLUGIN_CRASH         "test-crash": crashes in sweep on some inputs (below), else as PLUGIN_GOOD
 *   PLUGIN_HANG          "test-hang": never returns from sweep for a leg moving left, else as PLUGIN_GOOD
 *   PLUGIN_NO_REASON     "test-no-reason": misses without reasons (RICOCHET_MISS), and blind to walls from x = 7
 *   PLUGIN_V1            "test-v1": PLUGIN_GOOD as a version-1 table (abi_version 1, struct_size ending before the
 *                        disc functions), with a sweep_disc past its struct_size that must never be read, served
 *                        only to a loader asking for version 1 (NULL for any other)
 *   PLUGIN_DISC          "test-disc": version 2, PLUGIN_GOOD plus discs against walls and bumpers in double (the
 *                        shifted line for the face, quadratics for the caps and bumpers, entries only)
 *   PLUGIN_DISC_WALLS    "test-disc-walls": PLUGIN_DISC without sweep_disc_bumper (discs among walls only)
 *   PLUGIN_DISC_BROKEN   "test-disc-broken": PLUGIN_DISC whose disc hits say t = 2 on legs moving left, and give a
 *                        zero normal on legs moving down
 * PLUGIN_CRASH's inputs: a wall starting at x = -1001 (SIGSEGV, a write through a null pointer), -1002
 * (SIGABRT, abort()), -1003 (SIGFPE), -1004 (SIGILL), -1005 (SIGBUS), -1006 (a stack overflow, SIGSEGV on
 * the guard page); and any leg moving left and down from x < 0 (SIGSEGV), which generated cases reach. */
#define _POSIX_C_SOURCE 200809L /* SIGBUS */
#include <math.h>
#include <stddef.h>
#include <signal.h>
#include <stdlib.h>

#include "ricochet/plugin.h"

static ricochet_vec2 sub(ricochet_vec2 a, ricochet_vec2 b) {
    ricochet_vec2 r = {a.x - b.x, a.y - b.y};
    return r;
}
static double dot(ricochet_vec2 a, ricochet_vec2 b) { return a.x * b.x + a.y * b.y; }

#if defined(PLUGIN_CRASH)
/* Recursion the compiler may not turn into a loop: a stack overflow, on purpose. */
#pragma GCC diagnostic ignored "-Winfinite-recursion"
static volatile int g_depth_sink;
static int deep(int n) {
    volatile char pad[4096];
    pad[0] = (char)n;
    g_depth_sink = pad[0];
    return deep(n + 1) + pad[0];
}

static void crash_on(ricochet_vec2 bs, ricochet_vec2 v, const ricochet_wall* w) {
    if (w->p0.x == -1001) *(volatile int*)0 = 1;
    if (w->p0.x == -1002) abort();
    if (w->p0.x == -1003) raise(SIGFPE);
    if (w->p0.x == -1004) __builtin_trap();
    if (w->p0.x == -1005) raise(SIGBUS);
    if (w->p0.x == -1006) g_depth_sink = deep(0);
    if (bs.x < 0 && v.x < 0) *(volatile int*)0 = 2;
}
#endif

#if defined(PLUGIN_HANG)
static volatile int g_forever = 1;
#endif

/* The lecture's five tests in double, with n = (e_y, -e_x) not normalized. */
static void sweep(void* context, ricochet_vec2 bs, ricochet_vec2 v, const ricochet_wall* w, ricochet_sweep_result* out) {
    (void)context;
#if defined(PLUGIN_CRASH)
    crash_on(bs, v, w);
#endif
#if defined(PLUGIN_HANG)
    if (v.x < 0)
        while (g_forever) {
        }
#endif
#if defined(PLUGIN_NO_REASON)
    if (w->p0.x == 7) {
        out->miss = RICOCHET_MISS;
        return;
    }
#endif
#if defined(PLUGIN_BAD_MISS)
    if (v.x < 0) {
        out->miss = 42;
        return;
    }
#endif
    ricochet_vec2 e = sub(w->p1, w->p0);
    ricochet_vec2 n = {e.y, -e.x};
    ricochet_vec2 be = {bs.x + v.x, bs.y + v.y};
    double s0, s1, nv, t;
    ricochet_vec2 bi;
    /* Degenerate: a zero-length wall, or a leg whose end rounds to its start (kernel.hpp's leg is Bs -> Be). */
    if ((e.x == 0 && e.y == 0) || (be.x == bs.x && be.y == bs.y)) {
        out->miss = RICOCHET_MISS_DEGENERATE;
        return;
    }
    s0 = dot(n, sub(bs, w->p0));
    s1 = dot(n, sub(be, w->p0));
    if (s0 < 0 && s1 < 0) {
        out->miss = RICOCHET_MISS_BOTH_INSIDE;
        return;
    }
    if (s0 > 0 && s1 > 0) {
        out->miss = RICOCHET_MISS_BOTH_OUTSIDE;
        return;
    }
    nv = dot(n, v);
    if (nv == 0) {
        out->miss = RICOCHET_MISS_PARALLEL;
        return;
    }
    if (s0 == 0) {
        out->miss = RICOCHET_MISS_LEAVING;
        return;
    }
    t = -s0 / nv;
    bi.x = bs.x + v.x * t;
    bi.y = bs.y + v.y * t;
    if (dot(sub(bi, w->p0), e) < 0) {
        out->miss = RICOCHET_MISS_BEFORE_P0;
        return;
    }
    if (dot(sub(bi, w->p1), e) > 0) {
        out->miss = RICOCHET_MISS_PAST_P1;
        return;
    }
    out->miss = RICOCHET_HIT;
    out->t = t;
    out->point = bi;
}

#if defined(PLUGIN_FRAME) || defined(PLUGIN_FRAME_WRONG)
static ricochet_vec2 reflect(ricochet_vec2 v, const ricochet_wall* w) {
    ricochet_vec2 e = sub(w->p1, w->p0);
    double len = sqrt(e.x * e.x + e.y * e.y);
    ricochet_vec2 n = {e.y / len, -e.x / len};
    double k = 2 * dot(v, n);
    ricochet_vec2 r = {v.x - n.x * k, v.y - n.y * k};
    return r;
}

/* The lecture's frame loop: earliest hit but the wall just bounced off, bounce, the rest of the frame. */
static void step(void* context, ricochet_frame* f) {
    ricochet_vec2 pos = f->ball.pos, vel = f->ball.vel;
    double rest = 1, now = 0;
    uint32_t last = 0xffffffffu;
    int bounce;
    (void)context;
    (void)last;
    for (bounce = 0;; ++bounce) {
        ricochet_vec2 d = {vel.x * rest, vel.y * rest};
        ricochet_sweep_result best = {RICOCHET_MISS, 0, {0, 0}};
        uint32_t best_wall = 0, i;
        int found = 0;
#if defined(PLUGIN_FRAME_WRONG)
        (void)i;
#else
        for (i = 0; i < f->wall_count; ++i) {
            ricochet_sweep_result r = {RICOCHET_MISS, 0, {0, 0}};
            if (i == last) continue;
            sweep(context, pos, d, &f->walls[i], &r);
            if (r.miss != RICOCHET_HIT) continue;
            if (!found || r.t < best.t) {
                found = 1;
                best = r;
                best_wall = i;
            }
        }
#endif
        if (!found) {
            pos.x += d.x;
            pos.y += d.y;
            break;
        }
        if (bounce == RICOCHET_PLUGIN_MAX_BOUNCES) {
            f->status = RICOCHET_FRAME_BOUNCE_LIMIT;
            break;
        }
        now += rest * best.t;
        f->hits[f->hit_count].wall = best_wall;
        f->hits[f->hit_count].t = now;
        f->hits[f->hit_count].point = best.point;
        ++f->hit_count;
        ++f->reflections;
        vel = reflect(vel, &f->walls[best_wall]);
        pos = best.point;
        rest *= 1 - best.t;
        last = best_wall;
    }
    f->ball.pos = pos;
    f->ball.vel = vel;
}
#endif

#if defined(PLUGIN_DISC) || defined(PLUGIN_DISC_WALLS) || defined(PLUGIN_DISC_BROKEN) || defined(PLUGIN_V1)
/* The entry into the circle (c, rho) of the leg bs -> bs + v: the smaller root of |f + v*t|^2 = rho^2, f = bs - c,
 * while the distance decreases (f.v < 0); a start in reach hits at t = 0 if it moves closer. The normal B - c. */
static int circle_entry(ricochet_vec2 bs, ricochet_vec2 v, ricochet_vec2 c, double rho, ricochet_disc_result* out) {
    ricochet_vec2 f = sub(bs, c);
    double a = dot(v, v), b = 2 * dot(f, v), cc = dot(f, f) - rho * rho, disc, t;
    /* Degenerate: no radius, no motion, or moving away (or along) from c. */
    if (!(rho > 0) || a == 0 || !(b < 0)) return 0;
    if (cc <= 0) {
        t = 0;
    } else {
        disc = b * b - 4 * a * cc;
        if (!(disc > 0)) return 0; /* a tangent is no hit */
        t = (-b - sqrt(disc)) / (2 * a);
        if (!(t >= 0 && t <= 1)) return 0;
    }
    if (out->miss == RICOCHET_HIT && !(t < out->t)) return 0;
    out->miss = RICOCHET_HIT;
    out->t = t;
    out->point.x = bs.x + v.x * t;
    out->point.y = bs.y + v.y * t;
    out->normal = sub(out->point, c);
    return 1;
}

/* A disc of radius r against the wall's face (the line shifted by r toward the disc, between the ends) and caps. */
static void sweep_disc(void* context, ricochet_vec2 bs, ricochet_vec2 v, double r, const ricochet_wall* w,
                       ricochet_disc_result* out) {
    ricochet_vec2 e = sub(w->p1, w->p0);
    double len2 = dot(e, e), len, s0, side, dist, approach, t, u;
    ricochet_vec2 n, b;
    (void)context;
    out->miss = RICOCHET_MISS;
    /* Degenerate: a zero-length wall, or no motion. */
    if (len2 == 0 || (v.x == 0 && v.y == 0)) return;
    len = sqrt(len2);
    n.x = e.y / len;
    n.y = -e.x / len;
    s0 = dot(n, sub(bs, w->p0));
    /* Degenerate: the centre on the wall's line has no side, and no face normal. */
    if (s0 != 0) {
        side = s0 > 0 ? 1 : -1;
        dist = side * s0;             /* the centre's distance from the line */
        approach = -side * dot(n, v); /* how fast it closes in */
        if (approach > 0) {
            t = dist <= r ? 0 : (dist - r) / approach;
            if (t <= 1) {
                b.x = bs.x + v.x * t;
                b.y = bs.y + v.y * t;
                u = dot(sub(b, w->p0), e) / len2;
                if (u >= 0 && u <= 1) {
                    out->miss = RICOCHET_HIT;
                    out->t = t;
                    out->point = b;
                    out->normal.x = side * n.x;
                    out->normal.y = side * n.y;
                }
            }
        }
    }
    circle_entry(bs, v, w->p0, r, out);
    circle_entry(bs, v, w->p1, r, out);
#if defined(PLUGIN_DISC_BROKEN)
    if (out->miss == RICOCHET_HIT && v.x < 0) out->t = 2;
    if (out->miss == RICOCHET_HIT && v.y < 0) out->normal.x = out->normal.y = 0;
#endif
}

static void sweep_disc_bumper(void* context, ricochet_vec2 bs, ricochet_vec2 v, double r, const ricochet_circle* c,
                              ricochet_disc_result* out) {
    (void)context;
    out->miss = RICOCHET_MISS;
    circle_entry(bs, v, c->c, r + c->r, out);
}
#endif

#if defined(PLUGIN_INIT_FAILS)
static int32_t init(void** context) {
    (void)context;
    return 7;
}
#endif

#if defined(PLUGIN_NO_ENTRY)
/* Exported under another name: the library loads, the loader finds no entry. */
RICOCHET_PLUGIN_EXPORT void (*ricochet_plugin_sweep)(void*, ricochet_vec2, ricochet_vec2, const ricochet_wall*,
                                                     ricochet_sweep_result*) = sweep;
#else
RICOCHET_PLUGIN_EXPORT const ricochet_plugin* ricochet_plugin_entry(uint32_t abi_version) {
    static ricochet_plugin table;
    (void)abi_version;
    table.abi_version = RICOCHET_PLUGIN_ABI_VERSION;
    table.struct_size = sizeof(ricochet_plugin);
    table.sweep = sweep;
#if defined(PLUGIN_GOOD)
    table.name = "test-good";
#elif defined(PLUGIN_FRAME)
    table.name = "test-frame";
    table.step = step;
#elif defined(PLUGIN_FRAME_WRONG)
    table.name = "test-frame-wrong";
    table.step = step;
#elif defined(PLUGIN_WRONG_ABI)
    table.name = "test-wrong-abi";
    table.abi_version = 99;
#elif defined(PLUGIN_SHORT_TABLE)
    table.name = "test-short";
    table.struct_size = 8;
#elif defined(PLUGIN_NO_TABLE)
    return 0;
#elif defined(PLUGIN_BAD_NAME)
    table.name = "bad name";
#elif defined(PLUGIN_TAKEN_NAME)
    table.name = "robust";
#elif defined(PLUGIN_NO_SWEEP)
    table.name = "test-no-sweep";
    table.sweep = 0;
#elif defined(PLUGIN_INIT_FAILS)
    table.name = "test-init-fails";
    table.init = init;
#elif defined(PLUGIN_BAD_MISS)
    table.name = "test-bad-miss";
#elif defined(PLUGIN_CRASH)
    table.name = "test-crash";
#elif defined(PLUGIN_HANG)
    table.name = "test-hang";
#elif defined(PLUGIN_NO_REASON)
    table.name = "test-no-reason";
#elif defined(PLUGIN_V1)
    /* As a plug-in built against version 1 of the header sees its table; what lies past it is never read. */
    if (abi_version != 1) return 0;
    table.name = "test-v1";
    table.abi_version = 1;
    table.struct_size = offsetof(ricochet_plugin, sweep_disc);
    table.sweep_disc = sweep_disc;
    table.sweep_disc_bumper = sweep_disc_bumper;
#elif defined(PLUGIN_DISC)
    table.name = "test-disc";
    table.sweep_disc = sweep_disc;
    table.sweep_disc_bumper = sweep_disc_bumper;
#elif defined(PLUGIN_DISC_WALLS)
    table.name = "test-disc-walls";
    table.sweep_disc = sweep_disc;
    (void)sweep_disc_bumper;
#elif defined(PLUGIN_DISC_BROKEN)
    table.name = "test-disc-broken";
    table.sweep_disc = sweep_disc;
    table.sweep_disc_bumper = sweep_disc_bumper;
#endif
    return &table;
}
#endif
