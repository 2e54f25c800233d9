// Internal: what truth.cpp and truth_discs.cpp share: rationals from doubles, their signs, and a filter on
// bounding boxes. Part of the independent oracle: it shares nothing with predicates.hpp or any kernel.
#pragma once

#include <algorithm>
#include <utility>

#include "base/bignum.hpp"
#include "ricochet/truth.hpp"
#include "ricochet/vec2.hpp"

namespace ricochet::truth {

using bignum::Rational;

inline int sgn(const Rational& q) { return bignum::sign(q); }
/// Exact: every finite double is a rational.
inline Rational Q(double x) { return bignum::rational(x); }

/// sign(x + y·√u), u ≥ 0.
inline int sign2(const Rational& x, const Rational& y, const Rational& u) {
    const int sx = sgn(x), sy = sgn(u) == 0 ? 0 : sgn(y);
    if (sy == 0) return sx;
    if (sx == 0 || sx == sy) return sy;
    // Opposite signs: |x| against |y|·√u, by their squares.
    return sx * sgn(x * x - y * y * u);
}

/// sign(x + y·√u + z·√v), u, v ≥ 0.
inline int sign3(const Rational& x, const Rational& y, const Rational& u, const Rational& z, const Rational& v) {
    const int sl = sign2(x, y, u), sz = sgn(v) == 0 ? 0 : sgn(z);
    if (sz == 0) return sl;
    if (sl == 0 || sl == sz) return sz;
    // L = x + y·√u against |z|·√v, by their squares: L² − z²v = x² + y²u − z²v + 2xy·√u.
    return sl * sign2(x * x + y * y * u - z * z * v, Rational(2) * x * y, u);
}

/// An entry time t = (A − √C)/D, D > 0, C ≥ 0 (a disc's contact, a meet of two balls).
struct Root {
    Rational A, C, D;
};

/// sign(t1 − t2) = sign((D2·A1 − D1·A2) − D2·√C1 + D1·√C2), both denominators positive.
inline int compare(const Root& r1, const Root& r2) { return sign3(r2.D * r1.A - r1.D * r2.A, -r2.D, r1.C, r1.D, r2.C); }

/// Every coordinate of the boxes of a → b and of c → d apart by more than reach, decided on doubles with a
/// margin (a computed gap g > 0 is at least g/(1 + 2^−53) exactly): no point of one is within reach of the
/// other. False says nothing.
inline bool boxes_apart(Vec2 a, Vec2 b, Vec2 c, Vec2 d, double reach) {
    const double limit = reach * (1.0 + 0x1p-48);
    return std::min(c.x, d.x) - std::max(a.x, b.x) > limit || std::min(a.x, b.x) - std::max(c.x, d.x) > limit ||
           std::min(c.y, d.y) - std::max(a.y, b.y) > limit || std::min(a.y, b.y) - std::max(c.y, d.y) > limit;
}

/// p − X for the point X of the closed segment a → b nearest to p: X = a + u·(b − a) with u the projection
/// (p − a)·e/(e·e) clamped to [0, 1] (u = 0 for a segment of no length), all in rationals.
std::pair<Rational, Rational> from_segment(Vec2 p, Vec2 a, Vec2 b);

/// v_out against the exact reflection of v about the normal n = (nx, ny) (not unit), as bounce_accuracy
/// states it for a wall's n.
HitAccuracy reflection_accuracy(Vec2 v, const Rational& nx, const Rational& ny, Vec2 v_out, double rel,
                                double abs_bound);

}  // namespace ricochet::truth
