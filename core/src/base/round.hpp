// Rounding an exact quotient num/den·2^k to a double, as the exact kernel prints every value: the nearest
// double, ties to even, with two conventions kept from its first (mpq) version: a value that rounds to
// zero gives +0 whatever its sign, and a value beyond the largest double gives ±DBL_MAX below 2^1024 and
// ±infinity from 2^1024 on (mpq's get_d truncates, then the nearer of it and its neighbour was taken).
#pragma once

#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>

#include "base/bignum.hpp"

namespace ricochet::bignum {

/// Scratch integers for round_quotient, reused so that rounding allocates nothing in the steady state.
struct RoundScratch {
    Integer a, d, q, rem;
};

/// The double nearest to num/den·2^k (den > 0), with the conventions above.
inline double round_quotient(const Integer& num, const Integer& den, long k) {
    const int sg = sign(num);
    if (sg == 0) return 0.0;
    // Degenerate: a zero denominator has no value; callers never pass one.
    if (sign(den) <= 0) return NAN;
    thread_local RoundScratch s;
    const long la = bit_length(num);
    const long ld = bit_length(den);
    // 2^(la−1) ≤ |num| < 2^la and 2^(ld−1) ≤ den < 2^ld, so |num|·2^sh/den lies in (2^(la−ld+sh−1), 2^(la−ld+sh+1)):
    // sh = 56 − la + ld gives an integer quotient q with 2^55 ≤ q < 2^57, i.e. at least 3 bits beyond 53.
    const long sh = 56 - la + ld;
    abs(s.a, num);
    if (sh >= 0) {
        mul_2exp(s.a, s.a, static_cast<unsigned long>(sh));
        tdiv_qr(s.q, s.rem, s.a, den);
    } else {
        mul_2exp(s.d, den, static_cast<unsigned long>(-sh));
        tdiv_qr(s.q, s.rem, s.a, s.d);
    }
    // value = (q + rem/d)·2^low with low = k − sh
    const long low = k - sh;
    const std::uint64_t qi = low_uint64(s.q);
    const long qbits = std::bit_width(qi);
    const long top = qbits - 1 + low;  // 2^top ≤ value < 2^(top+1)
    if (top >= 1024) return sg > 0 ? INFINITY : -INFINITY;
    // The double's ulp at that magnitude: 2^(top−52) for normals, 2^-1074 for subnormals.
    const long ulp = std::max(top - 52, -1074L);
    const long drop = ulp - low;  // ≥ 3: the bits of q below the ulp
    // Degenerate: the value is below a quarter of the smallest subnormal, so it rounds to zero.
    if (drop > 58) return 0.0;
    std::uint64_t m = qi >> drop;
    const std::uint64_t below = qi & ((std::uint64_t{1} << drop) - 1), half = std::uint64_t{1} << (drop - 1);
    // Round to nearest; on an exact tie (no remainder beyond q) to the even mantissa.
    if (below > half || (below == half && (sign(s.rem) != 0 || (m & 1u) != 0))) ++m;
    if (m == 0) return 0.0;
    const double mag = std::ldexp(static_cast<double>(m), static_cast<int>(ulp));
    if (std::isinf(mag)) return sg > 0 ? DBL_MAX : -DBL_MAX;
    return sg > 0 ? mag : -mag;
}

/// The double nearest to q, with the same conventions.
inline double nearest(const Rational& q) { return round_quotient(numerator(q), denominator(q), 0); }

}  // namespace ricochet::bignum
