/* A plug-in kernel (ricochet/plugin.h) holding collision code as a game might ship it: a ray/segment test
 * and a bounce, in float, the way they are usually written. ricochet's harness runs against it unchanged:
 *
 *     ricochet run LOG --kernel plugin:./naive_float.so
 *     RICOCHET_KERNEL=plugin:$PWD/naive_float.so ricochet_properties
 *     ricochet fuzz --kernel plugin:./naive_float.so --target sweep
 *
 * and finds balls passing through walls (float rounding puts the hit point a little past the wall, and the
 * next leg starts on the wrong side). Everything else (classify, the static tests) is left to ricochet, which
 * supplies its robust kernel's exact answers, so the failures found are this code's. */
#include <math.h>

#include "ricochet/plugin.h"

/* The leg bs -> bs + v against the wall p0 -> p1: solve bs + t*v = p0 + u*e for t (along the leg) and u
 * (along the wall) with 2D cross products; a hit needs both in [0, 1]. */
static void sweep(void* context, ricochet_vec2 bs, ricochet_vec2 v, const ricochet_wall* wall, ricochet_sweep_result* out) {
    const float px = (float)bs.x, py = (float)bs.y;
    const float dx = (float)v.x, dy = (float)v.y;
    const float ax = (float)wall->p0.x, ay = (float)wall->p0.y;
    const float ex = (float)wall->p1.x - ax, ey = (float)wall->p1.y - ay;
    /* cross(d, e): zero when the leg runs parallel to the wall (or either has no length). */
    const float denom = dx * ey - dy * ex;
    float t, u;
    (void)context;
    if (denom == 0.0f) {
        out->miss = RICOCHET_MISS;
        return;
    }
    /* t = cross(a - p, e) / cross(d, e), u = cross(a - p, d) / cross(d, e) */
    t = ((ax - px) * ey - (ay - py) * ex) / denom;
    u = ((ax - px) * dy - (ay - py) * dx) / denom;
    if (t < 0.0f || t > 1.0f || u < 0.0f || u > 1.0f) {
        out->miss = RICOCHET_MISS;
        return;
    }
    out->miss = RICOCHET_HIT;
    out->t = t;
    out->point.x = px + t * dx;
    out->point.y = py + t * dy;
}

/* v' = v - 2 (v.n) n with the wall's unit normal n. */
static ricochet_vec2 reflect(void* context, ricochet_vec2 v, const ricochet_wall* wall) {
    const float ex = (float)(wall->p1.x - wall->p0.x), ey = (float)(wall->p1.y - wall->p0.y);
    const float len = sqrtf(ex * ex + ey * ey);
    const float nx = ey / len, ny = -ex / len;
    const float k = 2.0f * ((float)v.x * nx + (float)v.y * ny);
    ricochet_vec2 r;
    (void)context;
    r.x = (float)v.x - k * nx;
    r.y = (float)v.y - k * ny;
    return r;
}

RICOCHET_PLUGIN_EXPORT const ricochet_plugin* ricochet_plugin_entry(uint32_t abi_version) {
    static ricochet_plugin table;
    (void)abi_version;
    table.abi_version = RICOCHET_PLUGIN_ABI_VERSION;
    table.struct_size = sizeof table;
    table.name = "naive-float";
    table.sweep = sweep;
    table.reflect = reflect;
    /* What this bounce promises for |v'|: float rounding, a few parts in 10^7; 10^-5 leaves room. */
    table.speed_rel_bound = 1e-5;
    return &table;
}
