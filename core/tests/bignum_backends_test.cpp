// The two big-number backends of base/bignum.hpp side by side, operation by operation, on the same values (fixed
// seeds): every integer and rational operation gives the same number, and to_double the same bits (GMP's
// mpq_get_d truncates; the Boost backend derives the truncation itself, since Boost's convert_to rounds), over
// magnitudes from below the smallest subnormal to past the largest double. Their agreement is what lets a
// Boost build (wasm32) print what a GMP build prints.
#include <gtest/gtest.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "base/bignum_boost.hpp"
#include "base/bignum_gmp.hpp"

namespace ricochet::bignum {
namespace {

namespace g = gmp_backend;
namespace b = boost_backend;

std::string str(const g::Integer& z) { return z.get_str(); }
std::string str(const b::Integer& z) { return z.str(); }
std::string str(const g::Rational& q) { return q.get_str(); }
std::string str(const b::Rational& q) { return q.str(); }
std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

/// One integer in both backends.
struct Z {
    g::Integer gz;
    b::Integer bz;
    explicit Z(const std::string& decimal) : gz(decimal), bz(decimal) {}
};

/// Integers of 0 to max_bits bits, either sign, with small and boundary values mixed in.
struct Gen {
    std::mt19937_64 rng;
    explicit Gen(std::uint64_t seed) : rng(seed) {}
    std::string digits(int nbits) {
        g::Integer z = 0;
        for (int k = 0; k < nbits; k += 64) z = (z << 64) + g::Integer(std::to_string(rng()));
        z >>= static_cast<unsigned>((nbits + 63) / 64 * 64 - nbits);
        return z.get_str();
    }
    Z integer(int max_bits) {
        static const std::vector<std::string> special = {"0", "1", "-1", "18446744073709551615", "18446744073709551616",
                                                         "-9223372036854775808", "9007199254740993"};
        if (rng() % 8 == 0) return Z(special[rng() % special.size()]);
        std::string d = digits(static_cast<int>(rng() % (max_bits + 1)));
        if (rng() & 1 && d != "0") d = "-" + d;
        return Z(d);
    }
    double any_double() {
        // Every exponent, subnormals and the largest finite values included.
        const int e = static_cast<int>(rng() % 2100) - 1076;
        const double x = std::ldexp(static_cast<double>(rng() >> 11), e - 53);
        return (rng() & 1 ? -1 : 1) * (std::isfinite(x) ? x : DBL_MAX);
    }
};

TEST(BignumBackends, IntegerOperationsAgree) {
    Gen gen(11);
    for (int i = 0; i < 20000; ++i) {
        const Z x = gen.integer(600), y = gen.integer(600);
        ASSERT_EQ(g::sign(x.gz), b::sign(x.bz)) << str(x.gz);
        ASSERT_EQ(g::compare(x.gz, y.gz) < 0, b::compare(x.bz, y.bz) < 0) << str(x.gz) << " " << str(y.gz);
        ASSERT_EQ(g::compare(x.gz, y.gz) == 0, b::compare(x.bz, y.bz) == 0);
        ASSERT_EQ(g::low_uint64(x.gz), b::low_uint64(x.bz)) << str(x.gz);
        if (g::sign(x.gz) != 0) ASSERT_EQ(g::bit_length(x.gz), b::bit_length(x.bz)) << str(x.gz);
        g::Integer gr;
        b::Integer br;
        g::add(gr, x.gz, y.gz);
        b::add(br, x.bz, y.bz);
        ASSERT_EQ(str(gr), str(br));
        g::sub(gr, x.gz, y.gz);
        b::sub(br, x.bz, y.bz);
        ASSERT_EQ(str(gr), str(br));
        g::mul(gr, x.gz, y.gz);
        b::mul(br, x.bz, y.bz);
        ASSERT_EQ(str(gr), str(br));
        // In place, as the exact kernel uses them: r = x; r += x·y; r −= y·y.
        gr = x.gz;
        br = x.bz;
        g::addmul(gr, x.gz, y.gz);
        b::addmul(br, x.bz, y.bz);
        g::submul(gr, y.gz, y.gz);
        b::submul(br, y.bz, y.bz);
        ASSERT_EQ(str(gr), str(br));
        g::neg(gr, x.gz);
        b::neg(br, x.bz);
        ASSERT_EQ(str(gr), str(br));
        g::abs(gr, x.gz);
        b::abs(br, x.bz);
        ASSERT_EQ(str(gr), str(br));
        const auto n = static_cast<unsigned long>(gen.rng() % 200);
        g::mul_2exp(gr, x.gz, n);
        b::mul_2exp(br, x.bz, n);
        ASSERT_EQ(str(gr), str(br)) << str(x.gz) << " << " << n;
        if (g::sign(y.gz) != 0) {
            g::Integer gq, grem;
            b::Integer bq, brem;
            g::tdiv_qr(gq, grem, x.gz, y.gz);
            b::tdiv_qr(bq, brem, x.bz, y.bz);
            ASSERT_EQ(str(gq), str(bq)) << str(x.gz) << " / " << str(y.gz);
            ASSERT_EQ(str(grem), str(brem)) << str(x.gz) << " % " << str(y.gz);
            // x·y / y, exactly.
            g::mul(gr, x.gz, y.gz);
            b::mul(br, x.bz, y.bz);
            g::divexact(gr, gr, y.gz);
            b::divexact(br, br, y.bz);
            ASSERT_EQ(str(gr), str(br));
            ASSERT_EQ(str(gr), str(x.gz));
        }
        g::gcd(gr, x.gz, y.gz);
        b::gcd(br, x.bz, y.bz);
        ASSERT_EQ(str(gr), str(br)) << "gcd(" << str(x.gz) << ", " << str(y.gz) << ")";
        g::abs(gr, x.gz);
        b::abs(br, x.bz);
        ASSERT_EQ(str(g::isqrt(gr)), str(b::isqrt(br))) << "isqrt " << str(gr);
        const auto v = static_cast<std::int64_t>(gen.rng());
        g::set_int64(gr, v);
        b::set_int64(br, v);
        ASSERT_EQ(str(gr), std::to_string(v));
        ASSERT_EQ(str(br), std::to_string(v));
    }
    for (const std::int64_t v : {INT64_MIN, INT64_MAX, std::int64_t{0}, std::int64_t{-1}}) {
        g::Integer gr;
        b::Integer br;
        g::set_int64(gr, v);
        b::set_int64(br, v);
        EXPECT_EQ(str(gr), str(br)) << v;
    }
}

TEST(BignumBackends, RationalsOfDoublesAndPowersOfTwoAgree) {
    Gen gen(12);
    for (double x : {0.0, -0.0, DBL_MAX, -DBL_MAX, DBL_MIN, 0x1p-1074, -0x1p-1074, 0x1.fffffffffffffp-1023, 0.1, 1.0})
        EXPECT_EQ(str(g::rational(x)), str(b::rational(x))) << x;
    for (int i = 0; i < 20000; ++i) {
        const double x = gen.any_double();
        ASSERT_EQ(str(g::rational(x)), str(b::rational(x))) << x;
        // And back: a double's rational converts to the same double (−0 has the rational 0, which gives +0).
        ASSERT_EQ(bits(g::to_double(g::rational(x))), bits(x + 0.0)) << x;
        ASSERT_EQ(bits(b::to_double(b::rational(x))), bits(x + 0.0)) << x;
    }
    for (long e = -1200; e <= 1200; ++e) ASSERT_EQ(str(g::pow2(e)), str(b::pow2(e))) << e;
}

TEST(BignumBackends, RationalArithmeticAgrees) {
    Gen gen(13);
    for (int i = 0; i < 5000; ++i) {
        const Z n1 = gen.integer(300), n2 = gen.integer(300);
        Z d1 = gen.integer(300), d2 = gen.integer(300);
        if (g::sign(d1.gz) == 0) d1 = Z("3");
        if (g::sign(d2.gz) == 0) d2 = Z("-7");
        const g::Rational gp = g::rational(n1.gz, d1.gz), gq = g::rational(n2.gz, d2.gz);
        const b::Rational bp = b::rational(n1.bz, d1.bz), bq = b::rational(n2.bz, d2.bz);
        ASSERT_EQ(str(gp), str(bp));
        ASSERT_EQ(str(g::numerator(gp)), str(b::numerator(bp)));
        ASSERT_EQ(str(g::denominator(gp)), str(b::denominator(bp)));
        ASSERT_EQ(g::sign(gp), b::sign(bp));
        ASSERT_EQ(str(g::Rational(gp + gq)), str(b::Rational(bp + bq)));
        ASSERT_EQ(str(g::Rational(gp - gq)), str(b::Rational(bp - bq)));
        ASSERT_EQ(str(g::Rational(gp * gq)), str(b::Rational(bp * bq)));
        if (g::sign(gq) != 0) ASSERT_EQ(str(g::Rational(gp / gq)), str(b::Rational(bp / bq)));
        ASSERT_EQ(gp < gq, bp < bq);
        ASSERT_EQ(gp <= gq, bp <= bq);
        ASSERT_EQ(str(g::Rational(abs(gp))), str(b::Rational(abs(bp))));
        // Mixed with machine integers, as truth.cpp writes them.
        const long k = static_cast<long>(gen.rng() % 100) - 50;
        ASSERT_EQ(str(g::Rational((2 * k + 3) * gp + 1)), str(b::Rational((2 * k + 3) * bp + 1)));
    }
}

TEST(BignumBackends, TruncationToDoubleAgreesBitForBit) {
    Gen gen(14);
    // Quotients of every size, scaled by 2^e from far below the smallest subnormal to past 2^1024.
    for (int i = 0; i < 40000; ++i) {
        Z n = gen.integer(200), d = gen.integer(200);
        if (g::sign(d.gz) == 0) d = Z("1");
        const long e = static_cast<long>(gen.rng() % 2500) - 1300;
        const g::Rational gq = g::rational(n.gz, d.gz) * g::pow2(e);
        const b::Rational bq = b::rational(n.bz, d.bz) * b::pow2(e);
        ASSERT_EQ(bits(g::to_double(gq)), bits(b::to_double(bq))) << str(gq);
    }
    // Doubles and their neighbours' midpoints: the truncation keeps the lower magnitude.
    for (int i = 0; i < 20000; ++i) {
        const double x = gen.any_double();
        const double y = std::nextafter(x, x < 0 ? -INFINITY : INFINITY);
        if (!std::isfinite(y) || x == 0) continue;
        const g::Rational gm = (g::rational(x) + g::rational(y)) / 2;
        const b::Rational bm = (b::rational(x) + b::rational(y)) / 2;
        ASSERT_EQ(bits(g::to_double(gm)), bits(x)) << x;
        ASSERT_EQ(bits(b::to_double(bm)), bits(x)) << x;
    }
    // The edges: what truncates to zero is +0 either sign; the largest double, and infinity from 2^1024 on.
    for (long e : {-1075L, -1076L, -1100L, -2000L}) {
        EXPECT_EQ(bits(g::to_double(-g::pow2(e))), bits(b::to_double(-b::pow2(e)))) << e;
        EXPECT_EQ(bits(b::to_double(-b::pow2(e))), bits(0.0)) << e;
    }
    EXPECT_EQ(b::to_double(b::pow2(-1074) * 3 / 2), 0x1p-1074);
    EXPECT_EQ(b::to_double(-b::pow2(-1074) * 7 / 4), -0x1p-1074);
    EXPECT_EQ(b::to_double(b::pow2(1024) - 1), DBL_MAX);
    EXPECT_EQ(b::to_double(b::pow2(1024)), INFINITY);
    EXPECT_EQ(b::to_double(-b::pow2(1100)), -INFINITY);
    EXPECT_EQ(g::to_double(g::pow2(1024) - 1), DBL_MAX);
    EXPECT_EQ(g::to_double(g::pow2(1024)), INFINITY);
    EXPECT_EQ(g::to_double(-g::pow2(1100)), -INFINITY);
    EXPECT_EQ(b::to_double(b::Rational(1) / 3), g::to_double(g::Rational(1) / 3));
    EXPECT_EQ(b::to_double(b::Rational(-2) / 3), -0x1.5555555555555p-1);
}

}  // namespace
}  // namespace ricochet::bignum
