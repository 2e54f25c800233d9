// Exact geometric predicates on doubles: each returns the sign of a polynomial in its (double)
// arguments exactly as if computed with real numbers. A floating-point filter answers almost every
// call; when the rounded value is too close to zero to trust, an exact path decides in stages, each
// only when the one before cannot: for a determinant of exact differences, the order of its two rounded
// products; the leading terms of the exact expansion and a rounded tail, when farther from zero than a
// derived bound; the complete sum in expansion arithmetic (error-free sums and products, Shewchuk 1997).
// Those need inputs in the range where products cannot underflow or overflow; beyond it GMP rationals
// decide. Valid for every finite input.
#pragma once

#include "ricochet/shapes.hpp"
#include "ricochet/vec2.hpp"

namespace ricochet::exact {

/// Unit roundoff of double: every basic operation is exact up to a factor (1 ± k_eps).
inline constexpr double k_eps = 0x1p-53;
/// Shewchuk's bound for a 2×2 determinant of differences: |det − fl(det)| ≤ k_ccw·(|l| + |r|), where
/// l and r are the two rounded products. A filter may vouch for sign(fl(det)) only beyond it.
inline constexpr double k_ccw = (3.0 + 16.0 * k_eps) * k_eps;
/// Below this magnitude a product may have underflowed: filters decline and the exact path decides.
inline constexpr double k_tiny = 0x1p-900;

/// sign((b − a) × (c − a)): +1 if a, b, c turn counter-clockwise, −1 clockwise, 0 collinear.
int orient(Vec2 a, Vec2 b, Vec2 c);
/// sign of BC = n·(p − P0) with n = (e_y, −e_x): +1 Outside, −1 Inside, 0 On. Equals −orient(P0, P1, p).
int side(Vec2 p, const Wall& w);
/// sign of n·d: +1 if the direction d points to the wall's outside, −1 inside, 0 parallel.
int direction_side(Vec2 d, const Wall& w);
/// sign(|p − c|² − r²): −1 strictly inside the circle, 0 on it, +1 outside.
int point_circle(Vec2 p, const Circle& c);
/// sign(|cA − cB|² − (rA + rB)²): −1 overlapping, 0 touching, +1 apart.
int circle_circle(const Circle& a, const Circle& b);
/// Orders two crossing times along one leg. For wall k with a_k = orient(P0k, P1k, A) ≠ 0 and
/// b_k = orient(P0k, P1k, B) of sign 0 or −sign(a_k), the leg A → B meets wall k's line at
/// s_k = a_k/(a_k − b_k). Returns sign(s_1 − s_2).
int compare_crossings(Vec2 a, Vec2 b, const Wall& w1, const Wall& w2);

/// How many calls the filter could not decide on the calling thread since it started, by what decided
/// them (for benchmarks and the tests that reach each stage). Each thread counts its own calls.
struct FallbackCounts {
    /// Decided without GMP: the sum of the three stages below.
    unsigned long long expansion = 0;
    /// Decided by GMP rationals (an input beyond the expansions' range, or compare_crossings).
    unsigned long long gmp = 0;
    /// Exact differences whose two rounded products differ: their order is the sign.
    unsigned long long ordered = 0;
    /// The leading terms and a rounded tail, farther from zero than the bound on what was rounded or dropped.
    unsigned long long bounded = 0;
    /// The complete exact sum.
    unsigned long long complete = 0;
};
FallbackCounts fallback_counts();

}  // namespace ricochet::exact
