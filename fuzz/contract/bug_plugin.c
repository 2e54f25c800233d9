/* Modified cores for the contract test (modified_cores_test.sh): plug-in kernels (ricochet/plugin.h) holding a
 * plausible collision code in double — the ray/segment test of examples/plugin in double, the bounce about the
 * unit normal — each built with one bug of the kind a competent engineer makes:
 *
 *   BUG_SINKING  "bug-sinking": its own frame loop (the lecture's: earliest hit, bounce, the rest of the frame)
 *                lets the ball sink by 2^-20 in y at the end of every frame: a bug in a whole-frame step, which
 *                the checks see only through the frame's result. (A ball sliding over a wall sinks into it
 *                frames later; on what the targets and properties draw, symmetry and no-tunnel see the drift in
 *                the frame it starts, so the logs saved are one frame long. A bug seen only frames after it
 *                acts is FailureLog.ABugThatActsBeforeItIsSeenFailsItsLogAndTheFixedKernelPassesIt's.)
 *   BUG_TOUCH    "bug-touch": a point on a circle's rim is not in it (< for <=), and a leg that ends exactly on a
 *                wall does not hit it (t < 1 for t <= 1): touching, which ricochet's conventions count, is missed.
 *
 * Left NULL, ricochet supplies robust's functions, so what the harness finds is in this code. */
#include <math.h>

#include "ricochet/plugin.h"

/* The leg bs -> bs + v against the wall p0 -> p1: bs + t*v = p0 + u*e, t and u in [0, 1]. */
static void sweep(void* context, ricochet_vec2 bs, ricochet_vec2 v, const ricochet_wall* wall, ricochet_sweep_result* out) {
    const double ex = wall->p1.x - wall->p0.x, ey = wall->p1.y - wall->p0.y;
    const double ax = wall->p0.x - bs.x, ay = wall->p0.y - bs.y;
    /* cross(v, e): zero when the leg runs parallel to the wall (or either has no length). */
    const double denom = v.x * ey - v.y * ex;
    double t, u;
    (void)context;
    out->miss = RICOCHET_MISS;
    if (denom == 0.0) return;
    t = (ax * ey - ay * ex) / denom;
    u = (ax * v.y - ay * v.x) / denom;
#ifdef BUG_TOUCH
    if (!(t >= 0.0 && t < 1.0 && u >= 0.0 && u <= 1.0)) return;
#else
    if (!(t >= 0.0 && t <= 1.0 && u >= 0.0 && u <= 1.0)) return;
#endif
    out->miss = RICOCHET_HIT;
    out->t = t;
    out->point.x = bs.x + t * v.x;
    out->point.y = bs.y + t * v.y;
}

/* v' = v - 2 (v.n) n with the wall's unit normal n = (e_y, -e_x) / |e|. */
static ricochet_vec2 reflect(void* context, ricochet_vec2 v, const ricochet_wall* wall) {
    const double ex = wall->p1.x - wall->p0.x, ey = wall->p1.y - wall->p0.y;
    const double len = sqrt(ex * ex + ey * ey);
    const double nx = ey / len, ny = -ex / len;
    const double k = 2.0 * (v.x * nx + v.y * ny);
    ricochet_vec2 r;
    (void)context;
    r.x = v.x - k * nx;
    r.y = v.y - k * ny;
    return r;
}

#ifdef BUG_SINKING
/* The lecture's frame: the earliest hit over every wall but the one just bounced off (the lowest index on a tie),
 * bounce at B_i, the rest of the frame from there; then the bug. */
static void step(void* context, ricochet_frame* frame) {
    ricochet_vec2 pos = frame->ball.pos, vel = frame->ball.vel;
    double rest = 1.0, now = 0.0;
    uint32_t last = UINT32_MAX;
    for (;;) {
        ricochet_vec2 d;
        ricochet_sweep_result best, r;
        uint32_t best_wall = UINT32_MAX, i;
        d.x = vel.x * rest;
        d.y = vel.y * rest;
        best.miss = RICOCHET_MISS;
        for (i = 0; i < frame->wall_count; ++i) {
            if (i == last) continue;
            sweep(context, pos, d, &frame->walls[i], &r);
            if (r.miss == RICOCHET_HIT && (best_wall == UINT32_MAX || r.t < best.t)) {
                best = r;
                best_wall = i;
            }
        }
        if (best_wall == UINT32_MAX) {
            pos.x += d.x;
            pos.y += d.y;
            break;
        }
        if (frame->hit_count == frame->hit_capacity) {
            frame->status = RICOCHET_FRAME_BOUNCE_LIMIT;
            break;
        }
        now += rest * best.t;
        frame->hits[frame->hit_count].wall = best_wall;
        frame->hits[frame->hit_count].t = now;
        frame->hits[frame->hit_count].point = best.point;
        ++frame->hit_count;
        ++frame->reflections;
        vel = reflect(context, vel, &frame->walls[best_wall]);
        pos = best.point;
        rest *= 1.0 - best.t;
        last = best_wall;
    }
    /* The bug: a drift applied once per frame, as a misplaced gravity or a position correction might be. */
    pos.y -= 0x1p-20;
    frame->ball.pos = pos;
    frame->ball.vel = vel;
}
#endif

#ifdef BUG_TOUCH
/* |cp| <= r, written with <: a point on the rim is left out. */
static int32_t point_in_circle(void* context, ricochet_vec2 p, const ricochet_circle* c) {
    const double dx = p.x - c->c.x, dy = p.y - c->c.y;
    (void)context;
    return dx * dx + dy * dy < c->r * c->r;
}
#endif

RICOCHET_PLUGIN_EXPORT const ricochet_plugin* ricochet_plugin_entry(uint32_t abi_version) {
    static ricochet_plugin table;
    (void)abi_version;
    table.abi_version = RICOCHET_PLUGIN_ABI_VERSION;
    table.struct_size = sizeof table;
    table.sweep = sweep;
    table.reflect = reflect;
#ifdef BUG_SINKING
    table.name = "bug-sinking";
    table.step = step;
#endif
#ifdef BUG_TOUCH
    table.name = "bug-touch";
    table.point_in_circle = point_in_circle;
#endif
    /* The bounce in double: a few ulps of |v|. */
    table.speed_rel_bound = 1e-14;
    return &table;
}
