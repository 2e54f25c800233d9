// Internal: the lecture's formulas, in float or double, exactly as the lecture writes them.
// These kernels are the baseline that the harness must expose: do not fix them.
#pragma once

#include <cmath>
#include <limits>

#include "path.hpp"
#include "ricochet/kernel.hpp"
#include "ricochet/step_trace.hpp"

namespace ricochet::lecture {

/// lecture-float's stated bound on the relative change of |v| per reflection: its unit normal and
/// reflection round at 2^-24 per operation, a few times over; 1e-3 (about 2^-10) fails only real blunders.
inline constexpr double k_float_speed_rel_bound = 1e-3;
/// lecture-double's: the same formulas at 2^-53 per operation; 1e-6 fails only real blunders.
inline constexpr double k_double_speed_rel_bound = 1e-6;

/// A vector in the kernel's precision.
template <class Real>
struct V {
    Real x, y;
};
template <class Real>
V<Real> to(Vec2 p) {
    return {static_cast<Real>(p.x), static_cast<Real>(p.y)};
}
template <class Real>
V<Real> operator+(V<Real> a, V<Real> b) { return {a.x + b.x, a.y + b.y}; }
template <class Real>
V<Real> operator-(V<Real> a, V<Real> b) { return {a.x - b.x, a.y - b.y}; }
template <class Real>
V<Real> operator*(V<Real> a, Real k) { return {a.x * k, a.y * k}; }
template <class Real>
Real dot(V<Real> a, V<Real> b) { return a.x * b.x + a.y * b.y; }

/// n̂ = (e_y, −e_x)/|e|, zero for a zero-length wall.
template <class Real>
V<Real> unit_normal(V<Real> p0, V<Real> p1) {
    const V<Real> e = p1 - p0;
    const Real len = std::sqrt(dot(e, e));
    if (len == Real(0)) return {Real(0), Real(0)};
    return {e.y / len, -e.x / len};
}

template <class Real>
Side classify(Vec2 p, const Wall& w) {
    const V<Real> p0 = to<Real>(w.p0), p1 = to<Real>(w.p1);
    // BC = n̂·(P − P0)
    const Real bc = dot(unit_normal(p0, p1), to<Real>(p) - p0);
    return bc > Real(0) ? Side::Outside : bc < Real(0) ? Side::Inside : Side::On;
}

template <class Real>
bool point_in_circle(Vec2 p, const Circle& c) {
    // |CP| ≤ R
    const V<Real> cp = to<Real>(p) - to<Real>(c.c);
    return std::sqrt(dot(cp, cp)) <= static_cast<Real>(c.r);
}

template <class Real>
bool circles_overlap(const Circle& a, const Circle& b) {
    // |cA − cB|² ≤ (rA + rB)²
    const V<Real> d = to<Real>(a.c) - to<Real>(b.c);
    const Real rs = static_cast<Real>(a.r) + static_cast<Real>(b.r);
    return dot(d, d) <= rs * rs;
}

template <class Real>
bool point_in_rect(Vec2 p, const Rect& r) {
    const Real x = static_cast<Real>(p.x), y = static_cast<Real>(p.y);
    return static_cast<Real>(r.left) <= x && x <= static_cast<Real>(r.right) && static_cast<Real>(r.bottom) <= y &&
           y <= static_cast<Real>(r.top);
}

template <class Real>
bool rects_overlap(const Rect& a, const Rect& b) {
    // Apart only if one lies wholly left, right, below or above the other.
    const auto f = [](double v) { return static_cast<Real>(v); };
    return !(f(a.right) < f(b.left) || f(b.right) < f(a.left) || f(a.top) < f(b.bottom) || f(b.top) < f(a.bottom));
}

/// The animated point: B(t) = Bs + v·t against P0 → P1, the five tests in the lecture's order.
template <class Real>
struct LegResult {
    Miss miss;
    Real t;
    V<Real> point;
};

template <class Real>
LegResult<Real> sweep_leg(V<Real> bs, V<Real> v, V<Real> p0, V<Real> p1) {
    const V<Real> e = p1 - p0;
    // Degenerate: a zero-length wall has no normal, a zero velocity no motion.
    if ((e.x == Real(0) && e.y == Real(0)) || (v.x == Real(0) && v.y == Real(0))) return {Miss::degenerate, 0, {}};
    const V<Real> n = unit_normal(p0, p1);
    const V<Real> be = bs + v;
    // BC = n̂·(B − P0) at both ends
    const Real bc_s = dot(n, bs - p0);
    const Real bc_e = dot(n, be - p0);
    if (bc_s < Real(0) && bc_e < Real(0)) return {Miss::both_inside, 0, {}};
    if (bc_s > Real(0) && bc_e > Real(0)) return {Miss::both_outside, 0, {}};
    const Real nv = dot(n, v);
    if (nv == Real(0)) return {Miss::parallel, 0, {}};
    // n̂·B(t_i) = n̂·P0  ⇒  t_i = (n̂·P0 − n̂·Bs)/(n̂·v)
    const Real ti = (dot(n, p0) - dot(n, bs)) / nv;
    const V<Real> bi = bs + v * ti;
    // Hit point before P0: (B_i − P0)·e < 0; past P1: (B_i − P1)·e > 0.
    if (dot(bi - p0, e) < Real(0)) return {Miss::before_p0, 0, {}};
    if (dot(bi - p1, e) > Real(0)) return {Miss::past_p1, 0, {}};
    return {Miss::none, ti, bi};
}

template <class Real>
Sweep sweep(Vec2 bs, Vec2 v, const Wall& w) {
    const LegResult<Real> r = sweep_leg(to<Real>(bs), to<Real>(v), to<Real>(w.p0), to<Real>(w.p1));
    return {r.miss, static_cast<double>(r.t), {static_cast<double>(r.point.x), static_cast<double>(r.point.y)}};
}

template <class Real>
V<Real> reflect(V<Real> v, const Wall& w) {
    // v' = v − 2(v·n̂)n̂
    const V<Real> n = unit_normal(to<Real>(w.p0), to<Real>(w.p1));
    return v - n * (Real(2) * dot(v, n));
}

/// One frame among many walls, the naive way: the earliest t_i over every wall but the one just
/// bounced off, bounce, repeat for the rest of the frame.
template <class Real>
FrameStatus step_ball(Ball& ball, std::span<const Wall> walls, std::vector<HitEvent>& hits, StepScratch& scratch,
                      const WallIndex* index) {
    V<Real> pos = to<Real>(ball.pos), vel = to<Real>(ball.vel);
    Real rest = 1, now = 0;
    std::uint32_t last = std::numeric_limits<std::uint32_t>::max();
    FrameStatus status = FrameStatus::ok;
    for (int bounce = 0;; ++bounce) {
        const V<Real> d = vel * rest;
        const Vec2 a{static_cast<double>(pos.x), static_cast<double>(pos.y)};
        const Vec2 b{static_cast<double>(pos.x + d.x), static_cast<double>(pos.y + d.y)};
        bool found = false;
        std::uint32_t best = 0;
        LegResult<Real> hit{};
        TracedLeg* traced = nullptr;
        if (StepTrace* t = scratch.trace) {
            // The leg as the kernel's own numbers: pos and pos + d in Real, widened to double exactly.
            const auto first = static_cast<std::uint32_t>(t->decisions.size());
            const std::optional<std::uint32_t> skipped =
                last == std::numeric_limits<std::uint32_t>::max() ? std::nullopt : std::optional<std::uint32_t>(last);
            traced = &t->legs.emplace_back(TracedLeg{a, b, false, 0, 0, std::nullopt, first, 0, skipped});
        }
        for (std::uint32_t i : detail::candidates(walls, index, a, b, scratch.candidates, scratch.all_walls)) {
            if (i == last) continue;
            const LegResult<Real> r = sweep_leg(pos, d, to<Real>(walls[i].p0), to<Real>(walls[i].p1));
            if (traced != nullptr) {
                scratch.trace->decisions.push_back({i, r.miss});
                ++traced->decision_count;
            }
            if (r.miss != Miss::none) continue;
            if (!found || r.t < hit.t || (r.t == hit.t && i < best)) {
                found = true;
                best = i;
                hit = r;
            }
        }
        if (!found) {
            pos = pos + d;
            break;
        }
        if (traced != nullptr) traced->hit = best;
        if (bounce == k_max_bounces) {
            status = FrameStatus::bounce_limit;
            break;
        }
        if (scratch.trace != nullptr) ++scratch.trace->reflections;
        now = now + rest * hit.t;
        hits.push_back({best, static_cast<double>(now), {static_cast<double>(hit.point.x), static_cast<double>(hit.point.y)}});
        // Spend the rest of the frame, (1 − t_i)·v', moving on from B_i.
        vel = reflect(vel, walls[best]);
        pos = hit.point;
        rest = rest * (Real(1) - hit.t);
        last = best;
    }
    ball = {{static_cast<double>(pos.x), static_cast<double>(pos.y)},
            {static_cast<double>(vel.x), static_cast<double>(vel.y)}};
    return status;
}

}  // namespace ricochet::lecture
