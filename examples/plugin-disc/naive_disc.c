/* A plug-in kernel (ricochet/plugin.h, ABI version 2) sweeping discs as a game's collision code usually does: in
 * float, the wall's line shifted by the radius along its normal for the face, a quadratic for the end caps and for
 * the bumpers, the bounce about the contact normal. ricochet's harness runs against it unchanged:
 *
 *     ricochet run LOG --kernel plugin:./naive_disc.so
 *     RICOCHET_KERNEL=plugin:$PWD/naive_disc.so ricochet_properties --gtest_filter='*Disc*'
 *     ricochet fuzz --kernel plugin:./naive_disc.so --target disc
 *
 * and finds discs ending up closer to a wall than their radius, or through it (float rounding puts the contact
 * point a little past the shifted line, and the next leg starts there). Point balls among walls get the same float
 * code with a radius of 0; everything else (classify, the static tests) is left to ricochet's robust kernel, so the
 * failures found are this code's. */
#include <math.h>

#include "ricochet/plugin.h"

/* The disc's entry into the circle (cx, cy, rho) along p + d*t, t in [0, 1]: |p + d*t - c|^2 = rho^2, the smaller
 * root of a*t^2 + b*t + c = 0. Writes a contact earlier than out's, if any; the normal is B_i - c. */
static void circle_entry(float px, float py, float dx, float dy, float cx, float cy, float rho,
                         ricochet_disc_result* out) {
    const float fx = px - cx, fy = py - cy;
    const float a = dx * dx + dy * dy;
    const float b = 2.0f * (fx * dx + fy * dy);
    const float c = fx * fx + fy * fy - rho * rho;
    const float disc = b * b - 4.0f * a * c;
    float t;
    if (rho <= 0.0f) return; /* a point meeting a bumper of radius 0: never a hit */
    if (a == 0.0f || disc < 0.0f || b >= 0.0f) return; /* no motion, no meeting, or moving away */
    t = (-b - sqrtf(disc)) / (2.0f * a);
    if (t < 0.0f || t > 1.0f) return;
    if (out->miss == RICOCHET_HIT && !(t < out->t)) return;
    out->miss = RICOCHET_HIT;
    out->t = t;
    out->point.x = px + dx * t;
    out->point.y = py + dy * t;
    out->normal.x = (float)out->point.x - cx;
    out->normal.y = (float)out->point.y - cy;
}

/* The leg bs -> bs + v of a disc of radius r against the wall: its face, then its caps. */
static void sweep_disc(void* context, ricochet_vec2 bs, ricochet_vec2 v, double r, const ricochet_wall* wall,
                       ricochet_disc_result* out) {
    const float px = (float)bs.x, py = (float)bs.y, dx = (float)v.x, dy = (float)v.y, R = (float)r;
    const float ax = (float)wall->p0.x, ay = (float)wall->p0.y, bx = (float)wall->p1.x, by = (float)wall->p1.y;
    const float ex = bx - ax, ey = by - ay;
    const float len = sqrtf(ex * ex + ey * ey);
    (void)context;
    out->miss = RICOCHET_MISS;
    if (len == 0.0f) return;
    {
        /* The unit normal toward the disc's side, and the line shifted by R along it: n.X = n.A + R. */
        float nx = ey / len, ny = -ex / len;
        float dist = (px - ax) * nx + (py - ay) * ny;
        float vn, t, cx, cy, u;
        if (dist < 0.0f) {
            nx = -nx;
            ny = -ny;
            dist = -dist;
        }
        vn = dx * nx + dy * ny;
        if (vn < 0.0f) {
            /* n.(p + d*t) = n.A + R  =>  t = (R - dist)/(n.d) */
            t = (R - dist) / vn;
            /* the contact point on the wall, B_i - R*n, between the ends */
            cx = px + dx * t - R * nx;
            cy = py + dy * t - R * ny;
            u = ((cx - ax) * ex + (cy - ay) * ey) / (len * len);
            if (t >= 0.0f && t <= 1.0f && u >= 0.0f && u <= 1.0f) {
                out->miss = RICOCHET_HIT;
                out->t = t;
                out->point.x = px + dx * t;
                out->point.y = py + dy * t;
                out->normal.x = nx;
                out->normal.y = ny;
            }
        }
    }
    if (R > 0.0f) {
        circle_entry(px, py, dx, dy, ax, ay, R, out);
        circle_entry(px, py, dx, dy, bx, by, R, out);
    }
}

/* The same leg against a bumper: the circle of radius r + its own around its centre. */
static void sweep_disc_bumper(void* context, ricochet_vec2 bs, ricochet_vec2 v, double r, const ricochet_circle* bumper,
                              ricochet_disc_result* out) {
    (void)context;
    out->miss = RICOCHET_MISS;
    circle_entry((float)bs.x, (float)bs.y, (float)v.x, (float)v.y, (float)bumper->c.x, (float)bumper->c.y,
                 (float)(r + bumper->r), out);
}

/* A point ball's leg against a wall: the disc's face test with r = 0. */
static void sweep(void* context, ricochet_vec2 bs, ricochet_vec2 v, const ricochet_wall* wall, ricochet_sweep_result* out) {
    ricochet_disc_result d;
    d.miss = RICOCHET_MISS;
    sweep_disc(context, bs, v, 0.0, wall, &d);
    out->miss = d.miss;
    out->t = d.t;
    out->point = d.point;
}

/* v' = v - 2 (v.n) n about the contact normal, normalized here. */
static ricochet_vec2 reflect_disc(void* context, ricochet_vec2 v, ricochet_vec2 normal) {
    const float nx0 = (float)normal.x, ny0 = (float)normal.y;
    const float len = sqrtf(nx0 * nx0 + ny0 * ny0);
    const float nx = nx0 / len, ny = ny0 / len;
    const float k = 2.0f * ((float)v.x * nx + (float)v.y * ny);
    ricochet_vec2 out;
    (void)context;
    out.x = (float)v.x - k * nx;
    out.y = (float)v.y - k * ny;
    return out;
}

/* A point ball's bounce off a wall: about its normal. */
static ricochet_vec2 reflect(void* context, ricochet_vec2 v, const ricochet_wall* wall) {
    ricochet_vec2 n;
    n.x = wall->p1.y - wall->p0.y;
    n.y = -(wall->p1.x - wall->p0.x);
    return reflect_disc(context, v, n);
}

RICOCHET_PLUGIN_EXPORT const ricochet_plugin* ricochet_plugin_entry(uint32_t abi_version) {
    static ricochet_plugin table;
    (void)abi_version;
    table.abi_version = RICOCHET_PLUGIN_ABI_VERSION;
    table.struct_size = sizeof table;
    table.name = "naive-disc";
    table.sweep = sweep;
    table.reflect = reflect;
    table.sweep_disc = sweep_disc;
    table.sweep_disc_bumper = sweep_disc_bumper;
    table.reflect_disc = reflect_disc;
    /* What this bounce promises for |v'|: float rounding, a few parts in 10^7; 10^-5 leaves room. */
    table.speed_rel_bound = 1e-5;
    return &table;
}
