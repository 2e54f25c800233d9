// The example user's collision code (my_kernel.hpp): the lecture's sweep and bounce in double. The bounce
// carries a deliberate bug, the kind that slips through code review: the wall's normal is divided by |e|² where
// |e| was meant (the square root forgotten), so a bounce off any wall whose length is not 1 changes the speed.
// Build with -DMY_KERNEL_FIXED=ON for the bounce as intended.
#include "my_kernel.hpp"

#include <cmath>

namespace my {
namespace {

double dot(ricochet_vec2 a, ricochet_vec2 b) { return a.x * b.x + a.y * b.y; }
ricochet_vec2 sub(ricochet_vec2 a, ricochet_vec2 b) { return {a.x - b.x, a.y - b.y}; }

/// The leg bs -> bs + v against the wall p0 -> p1, the lecture's way: the sides of both ends on the wall's line
/// (the outward normal n = (e_y, -e_x)), t_i where the line is crossed, and B_i between p0 and p1.
void sweep(void*, ricochet_vec2 bs, ricochet_vec2 v, const ricochet_wall* wall, ricochet_sweep_result* out) {
    const ricochet_vec2 e = sub(wall->p1, wall->p0);
    const ricochet_vec2 n = {e.y, -e.x};
    const ricochet_vec2 be = {bs.x + v.x, bs.y + v.y};
    const double side_s = dot(n, sub(bs, wall->p0));
    const double side_e = dot(n, sub(be, wall->p0));
    out->miss = RICOCHET_MISS;
    if ((side_s < 0 && side_e < 0) || (side_s > 0 && side_e > 0)) return;  // both ends on one side
    const double nv = dot(n, v);
    if (nv == 0) return;  // along the wall's line (or a zero-length wall, or no motion)
    // n·B(t_i) = n·P0  =>  t_i = (n·P0 - n·Bs) / (n·v)
    const double t = -side_s / nv;
    const ricochet_vec2 bi = {bs.x + v.x * t, bs.y + v.y * t};
    if (dot(sub(bi, wall->p0), e) < 0 || dot(sub(bi, wall->p1), e) > 0) return;  // before p0, past p1
    out->miss = RICOCHET_HIT;
    out->t = t;
    out->point = bi;
}

/// The bounce: v' = v - 2(v·n̂)n̂ with n̂ the wall's unit normal.
ricochet_vec2 reflect(void*, ricochet_vec2 v, const ricochet_wall* wall) {
    const ricochet_vec2 e = sub(wall->p1, wall->p0);
#ifdef MY_KERNEL_FIXED
    const double len = std::sqrt(dot(e, e));
#else
    const double len = dot(e, e);  // the bug: |e|² where |e| was meant
#endif
    const ricochet_vec2 n = {e.y / len, -e.x / len};
    const double k = 2 * dot(v, n);
    return {v.x - k * n.x, v.y - k * n.y};
}

}  // namespace

const ricochet_plugin& kernel_table() {
    static const ricochet_plugin table = [] {
        ricochet_plugin t{};
        t.abi_version = RICOCHET_PLUGIN_ABI_VERSION;
        t.struct_size = sizeof(ricochet_plugin);
        t.name = "my-kernel";
        t.sweep = sweep;
        t.reflect = reflect;
        // What this bounce promises for |v'|: a few ulps of double rounding; 10^-12 leaves room.
        t.speed_rel_bound = 1e-12;
        return t;
    }();
    return table;
}

}  // namespace my
