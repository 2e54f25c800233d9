// Internal: the lecture's point/rectangle and rectangle/rectangle tests, written once for every kernel. They only
// compare coordinates, so in double they are exact: lecture-double, robust and exact share them; lecture-float
// compares the coordinates rounded to float.
#pragma once

#include "ricochet/shapes.hpp"
#include "ricochet/vec2.hpp"

namespace ricochet {

/// left ≤ x ≤ right and bottom ≤ y ≤ top, every coordinate rounded to Real first: touching an edge is inside.
template <class Real>
bool point_in_rect_in(Vec2 p, const Rect& r) {
    const Real x = static_cast<Real>(p.x), y = static_cast<Real>(p.y);
    return static_cast<Real>(r.left) <= x && x <= static_cast<Real>(r.right) && static_cast<Real>(r.bottom) <= y &&
           y <= static_cast<Real>(r.top);
}

/// Overlap of a and b (sharing an edge or a corner counts), every coordinate rounded to Real first.
template <class Real>
bool rects_overlap_in(const Rect& a, const Rect& b) {
    // Apart only if one lies wholly left, right, below or above the other.
    const auto f = [](double v) { return static_cast<Real>(v); };
    return !(f(a.right) < f(b.left) || f(b.right) < f(a.left) || f(a.top) < f(b.bottom) || f(b.top) < f(a.bottom));
}

}  // namespace ricochet
