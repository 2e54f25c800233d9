#include "disc_score.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <boost/multiprecision/cpp_int.hpp>

#include "ricochet/truth.hpp"

namespace ricochet::bench {
namespace {

using Ld = long double;

/// The distance from p to w's closed segment in long double (64-bit significand on x86-64): the projection's
/// parameter clamped to [0, 1]. Only its size is used; whether p is inside at all is decided exactly.
Ld distance_to_wall(Vec2 p, const Wall& w) {
    const Ld ex = Ld(w.p1.x) - Ld(w.p0.x), ey = Ld(w.p1.y) - Ld(w.p0.y);
    const Ld px = Ld(p.x) - Ld(w.p0.x), py = Ld(p.y) - Ld(w.p0.y);
    const Ld ee = ex * ex + ey * ey;
    const Ld u = ee > 0 ? std::clamp((px * ex + py * ey) / ee, Ld(0), Ld(1)) : Ld(0);
    const Ld dx = px - u * ex, dy = py - u * ey;
    return std::sqrt(dx * dx + dy * dy);
}

/// The part of w nearest to p: 0 face, 1 cap at P0, 2 cap at P1, 3 within 1e-9 of the wall's length of a face/cap
/// boundary (either part: a contact there is on both), from the projection's parameter in long double.
int part_of(Vec2 p, const Wall& w) {
    const Ld ex = Ld(w.p1.x) - Ld(w.p0.x), ey = Ld(w.p1.y) - Ld(w.p0.y);
    const Ld ee = ex * ex + ey * ey;
    if (!(ee > 0)) return 3;
    const Ld u = ((Ld(p.x) - Ld(w.p0.x)) * ex + (Ld(p.y) - Ld(w.p0.y)) * ey) / ee;
    constexpr Ld k_band = 1e-9L;
    if (std::fabs(u) <= k_band || std::fabs(u - 1) <= k_band) return 3;
    return u < 0 ? 1 : u > 1 ? 2 : 0;
}

bool same_part(const DiscQuery& q, const DiscAnswer& a, const DiscAnswer& b) {
    if (a.bumper != b.bumper) return false;
    if (a.bumper) return true;
    if (a.index != b.index || a.index >= q.nwalls) return false;
    const int pa = part_of(a.point, q.walls[a.index]), pb = part_of(b.point, q.walls[b.index]);
    return pa == pb || pa == 3 || pb == 3;
}

bool finite(Vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

using Q = boost::multiprecision::cpp_rational;  // exact: a double converts to it without rounding

Q dot(Q ax, Q ay, Q bx, Q by) { return ax * bx + ay * by; }

/// The leg q → b ends with the disc's centre exactly at R from wall w's closed segment, moving closer along b − q
/// (exactly: not the rounded v): the disc enters the capsule at t = 1, a hit (contact.hpp's rule) that
/// clear_of_wall, a closed distance, calls clear. Exact rationals (Boost.Multiprecision: no GMP, so that every
/// backend builds it).
bool ends_entering(Vec2 q, Vec2 b, const Wall& w, double R) {
    // Far from touching in long double (whose error is far below 10^−12 of these sizes): not touching.
    if (std::fabs(distance_to_wall(b, w) - Ld(R)) > 1e-12L * (Ld(R) + 1)) return false;
    const Q ex = Q(w.p1.x) - Q(w.p0.x), ey = Q(w.p1.y) - Q(w.p0.y);
    const Q ax = Q(b.x) - Q(w.p0.x), ay = Q(b.y) - Q(w.p0.y);
    const Q ee = dot(ex, ey, ex, ey), u = dot(ax, ay, ex, ey), R2 = Q(R) * Q(R);
    const Q vx = Q(b.x) - Q(q.x), vy = Q(b.y) - Q(q.y);
    if (ee == 0 || u < 0 || u > ee) {
        // A cap: |b − P_k| = R, moving in when (b − P_k)·v < 0.
        const Vec2 p = u > ee ? w.p1 : w.p0;
        const Q dx = Q(b.x) - Q(p.x), dy = Q(b.y) - Q(p.y);
        return dot(dx, dy, dx, dy) == R2 && dot(dx, dy, vx, vy) < 0;
    }
    // The face: (n·(b − P0))² = R²·(n·n) with n = (e_y, −e_x), moving in when n·(b − P0) and n·v differ in sign.
    const Q c = dot(ey, -ex, ax, ay);
    return c * c == R2 * ee && c * dot(ey, -ex, vx, vy) < 0;
}

/// The same for the circle of radius R + r around c.
bool ends_entering(Vec2 q, Vec2 b, Vec2 c, double R, double r) {
    const Ld ldx = Ld(b.x) - Ld(c.x), ldy = Ld(b.y) - Ld(c.y);
    if (std::fabs(std::sqrt(ldx * ldx + ldy * ldy) - (Ld(R) + Ld(r))) > 1e-12L * (Ld(R) + Ld(r) + 1)) return false;
    const Q dx = Q(b.x) - Q(c.x), dy = Q(b.y) - Q(c.y), rho = Q(R) + Q(r);
    return dot(dx, dy, dx, dy) == rho * rho && dot(dx, dy, Q(b.x) - Q(q.x), Q(b.y) - Q(q.y)) < 0;
}

}  // namespace

bool truth_hit(const DiscQuery& q) {
    const Vec2 be = q.bs + q.v;
    for (const Wall& w : q.wall_span())
        if (!truth::clear_of_wall(q.bs, be, w, q.R) || ends_entering(q.bs, be, w, q.R)) return true;
    return q.has_bumper && (!truth::clear_of_circle(q.bs, be, q.bumper.c, q.R, q.bumper.r) ||
                            ends_entering(q.bs, be, q.bumper.c, q.R, q.bumper.r));
}

DiscScore score_discs(std::span<const DiscQuery> qs, std::span<const DiscAnswer> got, std::span<const DiscAnswer> exact,
                      const std::vector<bool>& hits, bool joint) {
    DiscScore s;
    if (joint) s.ghosts = 0;
    for (std::size_t i = 0; i < qs.size(); ++i) {
        const DiscQuery& q = qs[i];
        const DiscAnswer& a = got[i];
        if (a.hit != hits[i]) (hits[i] ? s.fn : s.fp) += 1;
        if (joint && a.hit && !hits[i]) ++s.ghosts;
        if (!a.hit) continue;
        if (hits[i] && exact[i].hit && !same_part(q, a, exact[i])) ++s.part;
        // How far inside the printed point is: exactly whether, in long double by how much.
        Ld deepest = -1;
        if (!finite(a.point)) {
            deepest = std::numeric_limits<Ld>::infinity();
        } else {
            for (const Wall& w : q.wall_span())
                if (!truth::clear_of_wall(a.point, a.point, w, q.R))
                    deepest = std::max(deepest, std::max(Ld(0), Ld(q.R) - distance_to_wall(a.point, w)));
            if (q.has_bumper && !truth::clear_of_circle(a.point, a.point, q.bumper.c, q.R, q.bumper.r)) {
                const Ld dx = Ld(a.point.x) - Ld(q.bumper.c.x), dy = Ld(a.point.y) - Ld(q.bumper.c.y);
                deepest = std::max(deepest, std::max(Ld(0), Ld(q.R) + Ld(q.bumper.r) - std::sqrt(dx * dx + dy * dy)));
            }
        }
        if (deepest < 0) continue;
        ++s.inside;
        s.depth = std::max(s.depth, static_cast<double>(deepest));
        s.depth_rel = std::max(s.depth_rel, static_cast<double>(deepest / Ld(q.R)));
    }
    return s;
}

bool disc_score_clean(const DiscScore& s) {
    return s.fn == 0 && s.fp == 0 && s.ghosts <= 0 && s.inside == 0;
}

}  // namespace ricochet::bench
