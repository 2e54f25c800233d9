// Internal: the robust kernel's leg decision, the lecture's five tests on exact predicates. The one
// definition shared by the robust kernel (robust_kernel.cpp) and the batched decisions (batch.cpp).
#pragma once

#include "predicates/orient_filter.hpp"
#include "ricochet/predicates.hpp"
#include "ricochet/shapes.hpp"
#include "ricochet/sweep.hpp"

namespace ricochet::robust {

/// A decision for the leg q → b against w, with the exact sides of q and b (exact::side: +1 outside).
struct Leg {
    Miss miss;
    int sq = 0;
    int sb = 0;
};

/// Tests 4 and 5, once q and b are known on opposite sides of w's line or one of them on it (not both).
inline Leg cross_tests(Vec2 q, Vec2 b, const Wall& w, int sq, int sb) {
    if (sq == 0) return {Miss::leaving, sq, sb};
    // Tests 4 and 5 without constructing B_i. The leg meets the line at X = P0 + u·e with
    // u = −o0/(d × e), 1 − u = o1/(d × e), where o_k = orient(q, b, P_k) and sign(d × e) = −sign(sq).
    // The lecture's (B_i − P0)·e < 0 is u < 0: test 4, before P0; its (B_i − P1)·e > 0 is u > 1: test 5,
    // past P1.
    if (exact::detail::orient(q, b, w.p0) == -sq) return {Miss::before_p0, sq, sb};
    if (exact::detail::orient(q, b, w.p1) == sq) return {Miss::past_p1, sq, sb};
    return {Miss::none, sq, sb};
}

/// Tests 1 to 3 on the exact sides sq, sb of q and b, then tests 4 and 5.
inline Leg side_tests(Vec2 q, Vec2 b, const Wall& w, int sq, int sb) {
    if (sq < 0 && sb < 0) return {Miss::both_inside, sq, sb};
    if (sq > 0 && sb > 0) return {Miss::both_outside, sq, sb};
    // Test 3: both on the line, so the motion is along it, n·v = 0.
    if (sq == 0 && sb == 0) return {Miss::parallel, sq, sb};
    return cross_tests(q, b, w, sq, sb);
}

/// The leg q → b against w: the lecture's five tests, each decided exactly. Axis: the scene has axis-aligned
/// walls (wall_plan.hpp), whose sides are comparisons (orient_filter.hpp, side_planned); the same decisions
/// either way.
template <bool Axis = false>
[[gnu::always_inline]] inline Leg test_leg(Vec2 q, Vec2 b, const Wall& w) {
    if constexpr (Axis) {
        // Classified once for both ends; e = 0 only on a zero-length wall, which has no normal: degenerate.
        const exact::detail::AxisWall a = exact::detail::axis_wall(w);
        if (a.kind != 0) {
            if (a.e == 0 || q == b) return {Miss::degenerate};
            using exact::detail::sign_of_difference;
            // axis_side at both ends, with the coordinate picked once.
            if (a.kind == 1) return side_tests(q, b, w, a.e * sign_of_difference(q.y, a.c), a.e * sign_of_difference(b.y, a.c));
            return side_tests(q, b, w, a.e * sign_of_difference(q.x, a.c), a.e * sign_of_difference(b.x, a.c));
        }
    }
    // Degenerate: a zero-length wall has no normal, a zero-length leg no motion.
    if (w.p0 == w.p1 || q == b) return {Miss::degenerate};
    // Tests 1 and 2 on the exact signs of BC at both ends.
    return side_tests(q, b, w, exact::detail::side(q, w), exact::detail::side(b, w));
}

}  // namespace ricochet::robust
