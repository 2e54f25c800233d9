// Line segments: the lecture's edge vector, outward normal, point-normal equation and the
// classification of a point against a wall, written once over Vec2T<T> (the lecture kernels read
// them in float and double), with the core's double overloads for a Wall.
#pragma once

#include <algorithm>

#include "ricochet/shapes.hpp"
#include "ricochet/vec2.hpp"

namespace ricochet {

/// Where a point lies against a wall's line: outside (BC > 0, the side the normal points to),
/// inside (BC < 0) or on (BC = 0).
enum class Side : int { inside = -1, on = 0, outside = 1 };

/// The side whose sign is s (s in {−1, 0, 1}).
constexpr Side side_from_sign(int s) { return s > 0 ? Side::outside : s < 0 ? Side::inside : Side::on; }
/// The sign of a side: outside +1, inside −1, on 0.
constexpr int sign_of(Side s) { return static_cast<int>(s); }
/// The opposite side (on stays on).
constexpr Side opposite(Side s) { return side_from_sign(-sign_of(s)); }

/// Edge vector e = P1 − P0 of the segment P0 → P1.
template <class T>
constexpr Vec2T<T> edge(const Vec2T<T>& p0, const Vec2T<T>& p1) {
    return p1 - p0;
}
/// Outward normal n = (e_y, −e_x) of P0 → P1: e rotated by −90°, not normalized.
template <class T>
constexpr Vec2T<T> normal(const Vec2T<T>& p0, const Vec2T<T>& p1) {
    return perp(edge(p0, p1));
}
/// Unit normal n̂ = n/|n| of P0 → P1, in T's precision; zero for a zero-length segment (floating-point T).
template <class T>
Vec2T<T> unit_normal(const Vec2T<T>& p0, const Vec2T<T>& p1) {
    return normalize(normal(p0, p1));
}
/// The boundary condition BC = n̂·(P − P0) of P against the line through P0 with unit normal n̂: the
/// signed distance of P from the line (rounded in T).
template <class T>
constexpr T boundary_condition(const Vec2T<T>& p, const Vec2T<T>& p0, const Vec2T<T>& n_hat) {
    return dot(n_hat, p - p0);
}
/// The side a BC value says: outside if BC > 0, inside if BC < 0, on otherwise.
template <class T>
constexpr Side side_of(const T& bc) {
    return bc > T(0) ? Side::outside : bc < T(0) ? Side::inside : Side::on;
}
/// Classifies P against the line P0 → P1 by the sign of its BC, every step rounded in T.
template <class T>
Side side_of_line(const Vec2T<T>& p, const Vec2T<T>& p0, const Vec2T<T>& p1) {
    return side_of(boundary_condition(p, p0, unit_normal(p0, p1)));
}

/// Edge vector e = P1 − P0.
constexpr Vec2 edge(const Wall& w) { return edge(w.p0, w.p1); }
/// Outward normal n = (e_y, −e_x): e rotated by −90°, not normalized.
constexpr Vec2 normal(const Wall& w) { return normal(w.p0, w.p1); }
/// Unit normal n̂ = n/|n|; zero for a zero-length wall.
inline Vec2 unit_normal(const Wall& w) { return unit_normal(w.p0, w.p1); }
/// The boundary condition BC = n̂·(P − P0), the signed distance of P from the wall's line, rounded.
inline double boundary_condition(Vec2 p, const Wall& w) { return boundary_condition(p, w.p0, unit_normal(w)); }
/// True if p lies in the closed bounding box of w's segment: for a point on w's line, on the closed segment.
/// Exact: comparisons of doubles.
constexpr bool in_segment_box(Vec2 p, const Wall& w) {
    return std::min(w.p0.x, w.p1.x) <= p.x && p.x <= std::max(w.p0.x, w.p1.x) && std::min(w.p0.y, w.p1.y) <= p.y &&
           p.y <= std::max(w.p0.y, w.p1.y);
}

}  // namespace ricochet
