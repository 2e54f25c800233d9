// Doubles as integers at one common scale: every finite double is x = m·2^e with m an odd integer
// (|m| < 2^53) or x = 0. For a set of doubles, k = the smallest such e makes every x/2^k an integer,
// and a polynomial that is homogeneous of degree d changes by the positive factor 2^(−d·k) only, so
// its sign (and any ratio of two such polynomials of equal degree) is computed exactly in integers.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>
#include <initializer_list>

#include "base/bignum.hpp"

namespace ricochet::exact_kernel::num {

/// x = m·2^e with m odd, or m = 0 (e = 0) for x = 0.
struct Dyad {
    std::int64_t m = 0;
    int e = 0;
};

/// The odd mantissa and exponent of a finite double (subnormals included).
inline Dyad split(double x) {
    if (x == 0.0) return {};
    int big_e = 0;
    // x = f·2^E with 1/2 ≤ |f| < 1, so f·2^53 is an integer of at most 53 bits: exact.
    const double f = std::frexp(x, &big_e);
    const auto m = static_cast<std::int64_t>(std::ldexp(f, 53));
    const int tz = std::countr_zero(static_cast<std::uint64_t>(m < 0 ? -m : m));
    return {m / (std::int64_t{1} << tz), big_e - 53 + tz};
}

/// Bits of |m|, so that |m·2^e| < 2^(e + bits).
inline int top_bit(const Dyad& d) { return d.e + static_cast<int>(std::bit_width(static_cast<std::uint64_t>(d.m < 0 ? -d.m : d.m))); }

/// The common scale 2^k of a set of doubles, and how many bits their scaled integers need.
struct Scale {
    int k = INT_MAX;  ///< smallest exponent among the non-zero values (INT_MAX: all zero)
    int top = INT_MIN;

    void add(const Dyad& d) {
        if (d.m == 0) return;
        k = std::min(k, d.e);
        top = std::max(top, top_bit(d));
    }
    void add(double x) { add(split(x)); }
    /// The scale to use: 0 when every value is zero.
    int exponent() const { return k == INT_MAX ? 0 : k; }
    /// Every scaled value has magnitude below 2^bits.
    bool fits(int bits) const { return k == INT_MAX || top - k <= bits; }
};

/// Bound for the integer path: scaled inputs below 2^60, so a difference is below 2^61, a product of
/// two differences below 2^122 and a sum of two such products below 2^124: all fit in __int128.
inline constexpr int k_small_bits = 60;

/// x/2^k as a 64-bit integer (needs Scale::fits(k_small_bits)).
inline std::int64_t scaled_small(double x, int k) {
    const Dyad d = split(x);
    return d.m == 0 ? 0 : d.m * (std::int64_t{1} << (d.e - k));
}

/// x/2^k as a big integer (x/2^k must be an integer: k ≤ the exponent of x).
inline void scaled_big(bignum::Integer& out, double x, int k) {
    const Dyad d = split(x);
    bignum::set_int64(out, d.m);
    if (d.m != 0) bignum::mul_2exp(out, out, static_cast<unsigned long>(d.e - k));
}

}  // namespace ricochet::exact_kernel::num
