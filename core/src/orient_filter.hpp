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

}  // namespace ricochet::exact::detail
