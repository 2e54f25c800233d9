// Line segments: the lecture's edge vector, outward normal, point-normal equation and the
// classification of a point against a wall, written in double as the lecture writes them.
#pragma once

#include "ricochet/shapes.hpp"
#include "ricochet/vec2.hpp"

namespace ricochet {

/// Where a point lies against a wall's line: Outside (BC > 0, the side the normal points to),
/// Inside (BC < 0) or On (BC = 0).
enum class Side : int { Inside = -1, On = 0, Outside = 1 };

/// The side whose sign is s (s in {−1, 0, 1}).
constexpr Side side_from_sign(int s) { return s > 0 ? Side::Outside : s < 0 ? Side::Inside : Side::On; }
/// The sign of a side: Outside +1, Inside −1, On 0.
constexpr int sign_of(Side s) { return static_cast<int>(s); }
/// The opposite side (On stays On).
constexpr Side opposite(Side s) { return side_from_sign(-sign_of(s)); }

/// Edge vector e = P1 − P0.
constexpr Vec2 edge(const Wall& w) { return w.p1 - w.p0; }
/// Outward normal n = (e_y, −e_x): e rotated by −90°, not normalized.
constexpr Vec2 normal(const Wall& w) { return perp(edge(w)); }
/// Unit normal n̂ = n/|n|; zero for a zero-length wall.
inline Vec2 unit_normal(const Wall& w) { return normalize(normal(w)); }
/// The boundary condition BC = n̂·(P − P0), the signed distance of P from the wall's line, rounded.
inline double boundary_condition(Vec2 p, const Wall& w) { return dot(unit_normal(w), p - w.p0); }

}  // namespace ricochet
