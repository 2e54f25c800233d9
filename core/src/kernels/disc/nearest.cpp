// A disc's constructions correctly rounded from their exact values (frame.hpp): the exact kernel prints them, and
// robust takes them where its own constructions in doubles are ill-conditioned (robust_disc.cpp).
//
// How each printed number is rounded:
// - The contact's time t* = (a + b·√c)/d (contact_root) is irrational in general (a cap's or a bumper's root, a
//   face's |n|). It is bracketed between two rationals, √c taken from below and from above to 2^−bits
//   relative (bignum::sqrt_below), bits = 64, 256, 1024, 4096, until both ends of the bracket round to the same
//   doubles: then t and each coordinate of B_i = q + t*·(b − q) are the doubles nearest to their exact values
//   (rounding is monotone, and the exact value lies inside the bracket). When √c is an integer the values are
//   rational and rounded directly. An irrational value is never a midpoint, so the bracket closes; past 4096
//   bits (never seen) the lower end's rounding is taken, which is then within one ulp.
// - The bounce reflects v about the exact outward normal at the printed B_i (n = (e_y, −e_x) of the wall's exact
//   ends on a face, B_i − P_k at a cap, B_i − C at a bumper; the part chosen exactly, normal_at's rule):
//   v′ = v − 2(v·N)N/(N·N) exactly, each coordinate then rounded to the nearest double. Its length differs from
//   |v| by at most ½ ulp per coordinate, well inside robust's bound (limits.hpp).
// - The legs are robust's: b = q + rest·v and rest·(1 − t) in doubles.
// What that means for `penetration` (δ = 0): the nearest double to a contact point lies within half an ulp of
// the capsule's boundary, on either side, so half of them would be inside by that much. Every rounded contact
// point is walked back exactly as robust's is (frame.hpp) until the piece to it keeps the disc at least R from
// every wall and R + r from every bumper: the printed point is the correctly rounded one whenever that one is
// clear, and the nearest clear point on the way back towards the leg's start otherwise. So exact holds every
// check a disc log may list, δ = 0 included.
#include <algorithm>
#include <cmath>

#include "base/bignum.hpp"
#include "base/round.hpp"
#include "kernels/disc/contact_root.hpp"
#include "kernels/disc/frame.hpp"

namespace ricochet {
namespace {

using bignum::Integer;
using bignum::Rational;
using bignum::nearest;

Rational rat(double x) { return bignum::rational(x); }
Rational rat(const Integer& z) { return bignum::rational(z, Integer(1)); }

/// t, and B = q + t·(b − q), each rounded to the nearest double.
disc::Constructions::Point round_at(const disc::Leg& leg, const Rational& t) {
    const Rational x = rat(leg.q.x) + t * (rat(leg.b.x) - rat(leg.q.x));
    const Rational y = rat(leg.q.y) + t * (rat(leg.b.y) - rat(leg.q.y));
    return {std::clamp(nearest(t), 0.0, 1.0), {nearest(x), nearest(y)}};
}

bool same(const disc::Constructions::Point& u, const disc::Constructions::Point& v) {
    return u.t == v.t && u.x == v.x;
}

}  // namespace

/// The contact's time and point, each the double nearest to its exact value (the bracket above).
disc::Constructions::Point disc::nearest_contact_point(const Leg& leg, const Obstacle& o, const Contact& c) {
    // The same nearest doubles from double-double where its bound decides them (contact.cpp), without GMP.
    if (const auto fine = nearest_contact_fine(leg, o, c)) return {fine->t, fine->x};
    const disc::TimeRoot r = disc::contact_root(leg, o, c);
    const Rational a = rat(r.a), b = rat(r.b), d = rat(r.d);
    if (bignum::sign(r.b) == 0 || bignum::sign(r.c) == 0) return round_at(leg, a / d);
    const Integer s = bignum::isqrt(r.c);
    // √c is an integer: t is rational.
    const Integer s2 = s * s;
    if (bignum::compare(s2, r.c) == 0) return round_at(leg, (a + b * rat(s)) / d);
    const Rational cq = rat(r.c);
    disc::Constructions::Point lo;
    for (long bits = 64; bits <= 4096; bits *= 4) {
        // root_lo ≤ √c < root_lo·(1 + 2^(1 − bits)) = root_hi
        const Rational root_lo = bignum::sqrt_below(cq, bits);
        const Rational root_hi = root_lo + root_lo * bignum::pow2(1 - bits);
        lo = round_at(leg, (a + b * root_lo) / d);
        if (same(lo, round_at(leg, (a + b * root_hi) / d))) return lo;
    }
    return lo;
}

/// v reflected about the exact outward normal at x, each coordinate rounded to the nearest double.
Vec2 disc::nearest_reflection(Vec2 v, Vec2 x, const Obstacle& o) {
    Rational nx, ny;
    if (o.wall == nullptr) {
        nx = rat(x.x) - rat(o.c.x);
        ny = rat(x.y) - rat(o.c.y);
    } else {
        const Wall& w = *o.wall;
        const disc::Part part = disc::nearest_part(x, w);
        if (part == disc::Part::face) {
            // n = (e_y, −e_x); its side does not change the reflection.
            nx = rat(w.p1.y) - rat(w.p0.y);
            ny = rat(w.p0.x) - rat(w.p1.x);
        } else {
            const Vec2 p = part == disc::Part::cap0 ? w.p0 : w.p1;
            nx = rat(x.x) - rat(p.x);
            ny = rat(x.y) - rat(p.y);
        }
    }
    const Rational nn = nx * nx + ny * ny;
    // Degenerate: a centre on the segment (or a bumper's centre) has no normal.
    if (bignum::sign(bignum::numerator(nn)) == 0) return v;
    // v′ = v − 2(v·N)/(N·N)·N
    const Rational k = Rational(2) * (rat(v.x) * nx + rat(v.y) * ny) / nn;
    return {nearest(rat(v.x) - k * nx), nearest(rat(v.y) - k * ny)};
}

}  // namespace ricochet
