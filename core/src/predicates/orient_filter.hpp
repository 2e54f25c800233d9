// Internal: orient's floating-point filter inline, for the robust kernel's leg test (robust_leg.hpp), which asks
// it four times a leg; the exact path behind it stays out of line in predicates.cpp. exact::orient and
// exact::side are these same functions, called.
#pragma once

#include <cmath>

#include "ricochet/predicates.hpp"

namespace ricochet::exact::detail {

/// orient's exact path (predicates.cpp), for a call its filter declined; l and r are the filter's two products.
int orient_exact(Vec2 a, Vec2 b, Vec2 c, double l, double r);

/// exact::orient with its filter inline.
inline int orient(Vec2 a, Vec2 b, Vec2 c) {
    // (a − c) × (b − c) equals (b − a) × (c − a): the same signed double area.
    const double l = (a.x - c.x) * (b.y - c.y);
    const double r = (a.y - c.y) * (b.x - c.x);
    const double sum = std::fabs(l) + std::fabs(r);
    // Shewchuk's bound k_ccw; below k_tiny a product may have underflowed. An overflowed sum declines without a
    // test of its own: k_ccw·∞ = ∞, and |l − r| (∞ or NaN) is not greater. fl(l − r) has the sign of l − r,
    // which is (l > r) − (l < r).
    if (sum >= k_tiny && std::fabs(l - r) > k_ccw * sum) return (l > r) - (l < r);
    // Both products have an exactly-zero factor (x − y = 0 exactly iff x = y): the area is exactly 0.
    if ((a.x == c.x || b.y == c.y) && (a.y == c.y || b.x == c.x)) return 0;
    return orient_exact(a, b, c, l, r);
}

/// exact::side with orient's filter inline: BC = n·(p − P0) with n = (e_y, −e_x) is −e × (p − P0) =
/// −orient(P0, P1, p).
inline int side(Vec2 p, const Wall& w) { return -orient(w.p0, w.p1, p); }

/// sign(x − y): a rounded difference has the sign of the exact one, and comparisons need no difference at all.
inline int sign_of_difference(double x, double y) { return (x > y) - (x < y); }

/// An axis-aligned wall's side test: BC(p) = e·(p_k − c), k the coordinate across the wall. With P0.y = P1.y = Y,
/// n = (e_y, −e_x) = (0, x0 − x1) and BC = n·(p − P0) = (x0 − x1)(p.y − Y): k = y, c = Y, e = sign(x0 − x1); with
/// P0.x = P1.x = X, n = (y1 − y0, 0) and BC = (y1 − y0)(p.x − X): k = x, c = X, e = sign(y1 − y0). Both signs are
/// exact for every double, so BC's sign is the sign orient gives; e = 0 only on a zero-length wall (0 either way).
struct AxisWall {
    int kind = 0;  ///< 0: neither, 1: along y = c, 2: along x = c
    int e = 0;
    double c = 0.0;
};

[[gnu::always_inline]] inline AxisWall axis_wall(const Wall& w) {
    if (w.p0.y == w.p1.y) return {1, sign_of_difference(w.p0.x, w.p1.x), w.p0.y};
    if (w.p0.x == w.p1.x) return {2, sign_of_difference(w.p1.y, w.p0.y), w.p0.x};
    return {};
}

/// sign(BC(p)) for an axis-aligned wall (a.kind ≠ 0): one comparison.
[[gnu::always_inline]] inline int axis_side(Vec2 p, const AxisWall& a) {
    return a.e * sign_of_difference(a.kind == 1 ? p.y : p.x, a.c);
}

/// side for a scene with axis-aligned walls (wall_plan.hpp): such a wall by comparison, any other by side.
[[gnu::always_inline]] inline int side_planned(Vec2 p, const Wall& w) {
    const AxisWall a = axis_wall(w);
    return a.kind != 0 ? axis_side(p, a) : side(p, w);
}

/// side, or side_planned when the scene's plan found axis-aligned walls: the same sign either way.
template <bool Axis>
[[gnu::always_inline]] inline int side_as(Vec2 p, const Wall& w) {
    if constexpr (Axis) return side_planned(p, w);
    return side(p, w);
}

}  // namespace ricochet::exact::detail
