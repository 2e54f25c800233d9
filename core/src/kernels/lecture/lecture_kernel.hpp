// Internal: the lecture kernels, LectureKernel<float> and LectureKernel<double>: the lecture's formulas
// (line.hpp, vec2.hpp) computed in Real exactly as the lecture writes them, every input rounded to Real.
// These kernels are the baseline that the harness must expose: do not fix them.
#pragma once

#include <cmath>
#include <span>
#include <vector>

#include "kernels/lecture/lecture_disc.hpp"
#include "kernels/naive_frame.hpp"
#include "kernels/rect_tests.hpp"
#include "ricochet/kernel.hpp"
#include "ricochet/line.hpp"
#include "ricochet/vec2.hpp"

namespace ricochet {

/// The lecture's tests in precision Real (float or double): a Kernel (kernel.hpp).
template <class Real>
struct LectureKernel {
    /// A vector in the kernel's precision.
    using V = Vec2T<Real>;

    /// The stated bound on the relative change of |v| per reflection: the unit normal and the reflection
    /// round at ε = 2^-24 (float) or 2^-53 (double) per operation, a few times over; 1e-3 and 1e-6 sit far
    /// above that, so only real blunders fail.
    static constexpr double k_speed_rel_bound = sizeof(Real) == sizeof(float) ? 1e-3 : 1e-6;
    /// No absolute part: the baseline's subnormal losses are what `speed` is there to show.
    static constexpr double k_speed_abs_bound = 0.0;
    /// The baseline fails on purpose: its failure logs document the weakness (`expect failure`).
    static constexpr bool k_failures_documented = true;

    static Side classify(Vec2 p, const Wall& w) {
        // BC = n̂·(P − P0), its sign
        return side_of_line(vec_cast<Real>(p), vec_cast<Real>(w.p0), vec_cast<Real>(w.p1));
    }

    static bool point_in_circle(Vec2 p, const Circle& c) {
        // |CP| ≤ R
        return length(vec_cast<Real>(p) - vec_cast<Real>(c.c)) <= static_cast<Real>(c.r);
    }

    static bool circles_overlap(const Circle& a, const Circle& b) {
        // |cA − cB|² ≤ (rA + rB)²
        const V d = vec_cast<Real>(a.c) - vec_cast<Real>(b.c);
        const Real rs = static_cast<Real>(a.r) + static_cast<Real>(b.r);
        return length_squared(d) <= rs * rs;
    }

    static bool point_in_rect(Vec2 p, const Rect& r) { return point_in_rect_in<Real>(p, r); }

    static bool rects_overlap(const Rect& a, const Rect& b) { return rects_overlap_in<Real>(a, b); }

    static Sweep sweep(Vec2 bs, Vec2 v, const Wall& w) {
        const Leg r = sweep_leg(vec_cast<Real>(bs), vec_cast<Real>(v), vec_cast<Real>(w.p0), vec_cast<Real>(w.p1));
        return {r.miss, static_cast<double>(r.t), vec_cast<double>(r.point)};
    }

    static Vec2 reflect(Vec2 v, const Wall& w) { return vec_cast<double>(reflect_real(vec_cast<Real>(v), w)); }

    /// One frame among many walls, the naive way (naive_frame.hpp): the earliest t_i over every wall but the
    /// one just bounced off, bounce, repeat for the rest of the frame, all in Real. memory is not read or
    /// written: the lecture remembers nothing between frames (that is what lets it tunnel), and this baseline
    /// is not fixed.
    static FrameStatus step_ball(Ball& ball, BallMemory& /*memory*/, std::span<const Wall> walls,
                                 std::vector<HitEvent>& hits, StepScratch& scratch, const WallIndex* index) {
        return detail::step_naive_frame<Real>(
            ball, walls, hits, scratch, index,
            [](V pos, V d, const Wall& w) { return sweep_leg(pos, d, vec_cast<Real>(w.p0), vec_cast<Real>(w.p1)); },
            [](V v, const Wall& w) { return reflect_real(v, w); });
    }

    /// A disc among walls and bumpers, or a point ball in a scene with bumpers, the lecture's way
    /// (lecture_disc.hpp): shifted lines, the quadratic formula, every obstacle tried, nothing remembered.
    static FrameStatus step_disc(Ball& ball, BallMemory& /*memory*/, const Obstacles& obstacles,
                                 std::vector<HitEvent>& hits, StepScratch& scratch) {
        return disc::step_lecture_disc<Real>(ball, obstacles, hits, scratch);
    }
    /// step_disc bounces balls off bumpers too.
    static constexpr bool k_steps_bumpers = true;

    /// Balls that meet, the lecture's way: the static test at the frame's end (meet_at_end).
    static constexpr MeetRule k_meet_rule = MeetRule::end_of_frame;

    /// Two balls at the frame's end through the lecture's static circle/circle test, in Real; overlapping and
    /// approaching, they are pushed apart along the line of centres and bounce elastically (docs/scene-log.md,
    /// "Balls that meet"). A pair that crossed within the frame never overlaps here: it passed through.
    static bool meet_at_end(Ball& a, Ball& b, double ma, double mb) {
        V pa = vec_cast<Real>(a.pos), pb = vec_cast<Real>(b.pos);
        const V va = vec_cast<Real>(a.vel), vb = vec_cast<Real>(b.vel);
        const Real S = static_cast<Real>(a.r) + static_cast<Real>(b.r);
        const V n = pa - pb;
        const Real d2 = dot(n, n);
        // |B_a − B_b|² ≤ (R_a + R_b)², no square root; and approaching: (v_a − v_b)·(B_a − B_b) < 0.
        if (!(d2 <= S * S) || !(dot(va - vb, n) < Real(0))) return false;
        // Degenerate: coincident centres have no line between them.
        const Real d = std::sqrt(d2);
        if (!(d > Real(0))) return false;
        const V nh{n.x / d, n.y / d};
        const Real m_a = static_cast<Real>(ma), m_b = static_cast<Real>(mb), M = m_a + m_b;
        // Push apart to distance S, each by its share of the overlap S − d.
        const Real overlap = S - d;
        pa = pa + nh * (overlap * (m_b / M));
        pb = pb - nh * (overlap * (m_a / M));
        // u = (v_a − v_b)·n̂;  v_a′ = v_a − 2·m_b/M·u·n̂,  v_b′ = v_b + 2·m_a/M·u·n̂
        const Real u = dot(va - vb, nh);
        const V wa = va - nh * (Real(2) * (m_b / M) * u), wb = vb + nh * (Real(2) * (m_a / M) * u);
        a = {vec_cast<double>(pa), vec_cast<double>(wa), a.r};
        b = {vec_cast<double>(pb), vec_cast<double>(wb), b.r};
        return true;
    }

private:
    /// The animated point's answer against one wall, in Real.
    using Leg = detail::NaiveLeg<Real>;

    /// B(t) = Bs + v·t against P0 → P1, the five tests in the lecture's order.
    static Leg sweep_leg(V bs, V v, V p0, V p1) {
        const V e = edge(p0, p1);
        // Degenerate: a zero-length wall has no normal, a zero velocity no motion.
        if ((e.x == Real(0) && e.y == Real(0)) || (v.x == Real(0) && v.y == Real(0))) return {Miss::degenerate, 0, {}};
        const V n = unit_normal(p0, p1);
        const V be = bs + v;
        // BC = n̂·(B − P0) at both ends
        const Real bc_s = boundary_condition(bs, p0, n);
        const Real bc_e = boundary_condition(be, p0, n);
        // Tests 1 and 2: both ends strictly on one side.
        if (bc_s < Real(0) && bc_e < Real(0)) return {Miss::both_inside, 0, {}};
        if (bc_s > Real(0) && bc_e > Real(0)) return {Miss::both_outside, 0, {}};
        // Test 3: moving parallel to the line.
        const Real nv = dot(n, v);
        if (nv == Real(0)) return {Miss::parallel, 0, {}};
        // n̂·B(t_i) = n̂·P0  ⇒  t_i = (n̂·P0 − n̂·Bs)/(n̂·v)
        const Real ti = (dot(n, p0) - dot(n, bs)) / nv;
        const V bi = bs + v * ti;
        // Test 4, hit point before P0: (B_i − P0)·e < 0; test 5, past P1: (B_i − P1)·e > 0.
        if (dot(bi - p0, e) < Real(0)) return {Miss::before_p0, 0, {}};
        if (dot(bi - p1, e) > Real(0)) return {Miss::past_p1, 0, {}};
        return {Miss::none, ti, bi};
    }

    /// v' = v − 2(v·n̂)n̂, in Real.
    static V reflect_real(V v, const Wall& w) {
        const V n = unit_normal(vec_cast<Real>(w.p0), vec_cast<Real>(w.p1));
        return v - n * (Real(2) * dot(v, n));
    }
};

}  // namespace ricochet
