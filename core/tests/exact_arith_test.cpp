// The exact kernel's arithmetic at its limits: splitting doubles (largest, smallest, subnormal), exact
// signs where the filter must decline (cancellation, exponents 2^±1074 and up to 2^1023), and rounding
// of integer quotients against big rationals (ties, subnormals, zero, overflow conventions), on the build's
// big-number backend (base/bignum.hpp; the Boost variant of this test runs it on Boost.Multiprecision too).
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "base/bignum.hpp"
#include "base/round.hpp"
#include "bignum_cases.hpp"
#include "kernels/exact/filter.hpp"
#include "kernels/exact/scaled.hpp"

namespace ricochet::exact_kernel::num {
namespace {

using bignum::Integer;
using bignum::Rational;
using bignum::round_quotient;

TEST(ExactArith, SixtyFourBitIntegersCrossIntoBigIntegersWhole) {
    // Past 32 bits, where a 32-bit long (i386, wasm32) would cut them; both signs and INT64_MIN.
    for (const std::int64_t v : {std::int64_t{0}, std::int64_t{1} << 53 | 1, -(std::int64_t{1} << 62) - 7,
                                 INT64_MIN, INT64_MAX}) {
        Integer z;
        bignum::set_int64(z, v);
        EXPECT_EQ(bignum::compare(z, Integer(std::to_string(v))), 0) << v;
    }
    // The low 64 bits of |z|, for a 57-bit quotient and one past 64 bits.
    const Integer q("144115188075855875");  // 2^57 + 3
    EXPECT_EQ(bignum::low_uint64(q), (std::uint64_t{1} << 57) + 3);
    const Integer big = (Integer(1) << 70) + 5;
    EXPECT_EQ(bignum::low_uint64(big), 5u);
    EXPECT_EQ(bignum::low_uint64(Integer(-9)), 9u);
    EXPECT_EQ(bignum::low_uint64(Integer(0)), 0u);
}

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

Rational exact(double x) { return bignum::rational(x); }

/// The reference rounding: the truncation (bignum::to_double), then the nearer of it and its neighbour, ties to even.
double reference_round(const Rational& x) {
    const double d = bignum::to_double(x);
    const double away = std::nextafter(d, bignum::sign(x) >= 0 ? INFINITY : -INFINITY);
    if (!std::isfinite(away)) return d;
    const Rational ed = abs(Rational(x - exact(d))), ea = abs(Rational(exact(away) - x));
    if (ea < ed || (ea == ed && (bits(away) & 1u) == 0)) return away;
    return d;
}

double round_of(const Integer& n, const Integer& d, long k) { return round_quotient(n, d, k); }
Rational value_of(const Integer& n, const Integer& d, long k) { return bignum::rational(n, d) * bignum::pow2(k); }

TEST(ExactArith, SplitIsExactAtTheLimits) {
    for (double x : {DBL_MAX, -DBL_MAX, DBL_MIN, 0x1p-1074, -0x1p-1074, 0x1.8p-1073, 1.0, -3.0, 0x1p256, 0.1}) {
        const Dyad d = split(x);
        EXPECT_NE(d.m % 2, 0) << x;
        EXPECT_EQ(std::ldexp(static_cast<double>(d.m), d.e), x) << x;
    }
    EXPECT_EQ(split(0.0).m, 0);
    EXPECT_EQ(split(-0.0).m, 0);
    EXPECT_EQ(split(0x1p-1074).e, -1074);
    EXPECT_EQ(split(DBL_MAX).e, 1023 - 52);
}

TEST(ExactArith, SignsAtTheLimitsMatchRationals) {
    std::mt19937_64 rng(3);
    const auto any = [&] {
        const int e = static_cast<int>(rng() % 2098) - 1074;
        const double x = std::ldexp(std::ldexp(static_cast<double>(rng() >> 11), -53), e);
        return (rng() & 1 ? 1 : -1) * (std::isfinite(x) ? x : DBL_MAX);
    };
    for (int i = 0; i < test::bignum_cases(200000); ++i) {
        double v[8];
        for (double& x : v) x = any();
        // Force cancellation: the second product equals the first one or a neighbour.
        if (i % 3 == 0) { v[4] = v[0]; v[5] = v[1]; v[6] = v[2]; v[7] = std::nextafter(v[3], i % 2 ? INFINITY : 0.0); }
        if (i % 3 == 1) { v[4] = v[2]; v[5] = v[3]; v[6] = v[0]; v[7] = v[1]; }
        const Rational want = (exact(v[0]) - exact(v[1])) * (exact(v[2]) - exact(v[3])) -
                              (exact(v[4]) - exact(v[5])) * (exact(v[6]) - exact(v[7]));
        ASSERT_EQ(det_sign(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7]), bignum::sign(want)) << i;
        const Rational dx = exact(v[0]) - exact(v[1]), dy = exact(v[2]) - exact(v[3]), r = exact(v[4]) + exact(v[5]);
        ASSERT_EQ(circle_sign(v[0], v[1], v[2], v[3], v[4], v[5]), bignum::sign(Rational(dx * dx + dy * dy - r * r))) << i;
    }
    // Exact cancellations: 3-4-5 on the circle at both ends of the exponent range.
    for (int e : {-1074, -1000, 0, 500, 1020}) {
        const double s = std::ldexp(1.0, e);
        EXPECT_EQ(circle_sign(3 * s, 0, 4 * s, 0, 5 * s, 0), 0) << e;
        EXPECT_EQ(circle_sign(3 * s, 0, 4 * s, 0, 2 * s, 3 * s), 0) << e;
        EXPECT_EQ(det_sign(s, 0, s, 0, s, 0, s, 0), 0) << e;
    }
    // Differences that overflow a double are still exact.
    EXPECT_EQ(det_sign(DBL_MAX, -DBL_MAX, 1, 0, DBL_MAX, -DBL_MAX, 1, 0), 0);
    EXPECT_EQ(det_sign(DBL_MAX, -DBL_MAX, 0x1p-1074, 0, 1, 0, DBL_MAX, 0), -1);  // 2·DBL_MAX·2^-1074 − DBL_MAX < 0
}

TEST(ExactArith, RoundingMatchesRationals) {
    std::mt19937_64 rng(5);
    const auto big = [&](int bits_) {
        Integer z = 0;
        for (int b = 0; b < bits_; b += 64) z = (z << 64) + Integer(std::to_string(rng()));
        return Integer(z >> static_cast<unsigned>((bits_ + 63) / 64 * 64 - bits_));
    };
    for (int i = 0; i < 200000; ++i) {
        Integer n = big(1 + static_cast<int>(rng() % 300)), d = big(1 + static_cast<int>(rng() % 200));
        if (d == 0) d = 1;
        if (rng() & 1) n = -n;
        // Exact ties and exact doubles: a 54-bit or 53-bit odd numerator over a power of two.
        if (i % 4 == 0) {
            n = (Integer(1) << 53) + Integer(static_cast<unsigned long>(rng() % 4));
            d = 1;
        }
        const long k = static_cast<long>(rng() % 2400) - 1300;
        const double got = round_of(n, d, k), want = reference_round(value_of(n, d, k));
        ASSERT_EQ(bits(got), bits(want)) << i << " k=" << k;
    }
    // The conventions: −tiny rounds to +0; past DBL_MAX gives DBL_MAX below 2^1024, infinity from it on.
    EXPECT_EQ(bits(round_of(-1, 1, -1076)), bits(0.0));
    EXPECT_EQ(bits(round_of(-3, 1, -1076)), bits(-0x1p-1074));
    EXPECT_EQ(round_of(Integer(1) << 53, 1, 1023 - 53 + 1) , INFINITY);
    EXPECT_EQ(round_of((Integer(1) << 54) - 1, 1, 1023 - 53), DBL_MAX);
    EXPECT_EQ(round_of(-1, 3, 0), -1.0 / 3.0);
}

}  // namespace
}  // namespace ricochet::exact_kernel::num
