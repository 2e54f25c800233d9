// The exact predicates against big rationals (base/bignum.hpp: GMP, or Boost.Multiprecision in the Boost variant),
// on random and on near-degenerate inputs, so that the filter and both fallbacks (expansions, the big rationals
// counted as FallbackCounts::gmp) are all exercised and all agree.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "base/bignum.hpp"
#include "ricochet/predicates.hpp"

namespace ricochet {
namespace {

using bignum::Rational;

int sign(const Rational& v) { return bignum::sign(v); }
Rational q(double x) { return bignum::rational(x); }

int orient_gmp(Vec2 a, Vec2 b, Vec2 c) {
    return sign((q(b.x) - q(a.x)) * (q(c.y) - q(a.y)) - (q(b.y) - q(a.y)) * (q(c.x) - q(a.x)));
}

// Inputs in every regime: random, collinear up to rounding, far from the origin, tiny, huge.
struct Gen {
    std::mt19937_64 rng{12345};
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
    double ulps(double x, int n) {
        for (int i = 0; i < std::abs(n); ++i) x = std::nextafter(x, n > 0 ? INFINITY : -INFINITY);
        return x;
    }
    double scale() {
        static const double scales[] = {1, 1e-3, 1e3, 1e15, 1e-150, 1e150, 0x1p-460, 0x1p255};
        return scales[rng() % 8];
    }
    // Three points, the third near the line through the first two.
    void near_collinear(Vec2& a, Vec2& b, Vec2& c) {
        if (rng() % 4 == 0) {
            // Exactly collinear: small integers times a power of two, c = a + k·(b − a), k integer.
            const double s = std::ldexp(1.0, static_cast<int>(rng() % 200) - 100);
            auto i = [&] { return static_cast<double>(static_cast<int>(rng() % 2001) - 1000); };
            a = {s * i(), s * i()};
            b = {s * i(), s * i()};
            const double k = static_cast<double>(static_cast<int>(rng() % 6) - 2);
            c = {a.x + k * (b.x - a.x), a.y + k * (b.y - a.y)};
            return;
        }
        const double s = scale();
        const double off = (rng() % 2) ? s * 1e6 : 0.0;
        a = {off + s * uniform(-1, 1), off + s * uniform(-1, 1)};
        b = {off + s * uniform(-1, 1), off + s * uniform(-1, 1)};
        const double t = uniform(-2, 3);
        c = {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
        c = {ulps(c.x, static_cast<int>(rng() % 5) - 2), ulps(c.y, static_cast<int>(rng() % 5) - 2)};
    }
};

TEST(Predicates, OrientMatchesGmp) {
    Gen g;
    int zeros = 0;
    for (int i = 0; i < 200000; ++i) {
        Vec2 a, b, c;
        g.near_collinear(a, b, c);
        const int expect = orient_gmp(a, b, c);
        zeros += expect == 0;
        ASSERT_EQ(exact::orient(a, b, c), expect) << i;
        ASSERT_EQ(exact::side(c, Wall{a, b}), -expect) << i;
    }
    EXPECT_GT(zeros, 100);  // the generator reaches exact collinearity, not only near misses
    const auto fb = exact::fallback_counts();
    EXPECT_GT(fb.expansion, 1000u);
    EXPECT_GT(fb.gmp, 100u);
}

TEST(Predicates, DirectionSideMatchesGmp) {
    Gen g;
    for (int i = 0; i < 100000; ++i) {
        Vec2 a, b, c;
        g.near_collinear(a, b, c);
        const Vec2 d{c.x - a.x, c.y - a.y};
        const Wall w{a, b};
        // n·d = e_y·d_x − e_x·d_y
        const int expect = sign((q(b.y) - q(a.y)) * q(d.x) - (q(b.x) - q(a.x)) * q(d.y));
        ASSERT_EQ(exact::direction_side(d, w), expect) << i;
    }
}

TEST(Predicates, CirclesMatchGmp) {
    Gen g;
    for (int i = 0; i < 100000; ++i) {
        const double s = g.scale();
        const Vec2 c{s * g.uniform(-1, 1), s * g.uniform(-1, 1)};
        const double r = s * g.uniform(0, 1);
        const double ang = g.uniform(0, 6.283185307179586);
        Vec2 p{c.x + r * std::cos(ang), c.y + r * std::sin(ang)};
        p = {g.ulps(p.x, static_cast<int>(g.rng() % 3) - 1), p.y};
        const Rational dx = q(p.x) - q(c.x), dy = q(p.y) - q(c.y);
        ASSERT_EQ(exact::point_circle(p, {c, r}), sign(dx * dx + dy * dy - q(r) * q(r))) << i;
        const double r2 = s * g.uniform(0, 1);
        const Circle b{{p.x + (i % 2 ? r2 : 0.0), p.y}, r2};
        const Rational ex = q(c.x) - q(b.c.x), ey = q(c.y) - q(b.c.y), rs = q(r) + q(r2);
        ASSERT_EQ(exact::circle_circle({c, r}, b), sign(ex * ex + ey * ey - rs * rs)) << i;
    }
    // Inexact differences on the expansion path: 0.1 − (−0.2) and 0.1 + 0.2 both round, to the same double,
    // and are the same exact number, so the circles touch; a centre one ulp further apart or closer is apart
    // or overlapping (the sum of the radii is inexact too). GMP agrees on all three.
    for (int k = -1; k <= 1; ++k) {
        const Circle a{{0.1, 0}, 0.1}, b{{g.ulps(-0.2, -k), 0}, 0.2};
        const Rational ex = q(a.c.x) - q(b.c.x), rs = q(a.r) + q(b.r);
        ASSERT_EQ(exact::circle_circle(a, b), sign(ex * ex - rs * rs)) << k;
        ASSERT_EQ(exact::circle_circle(a, b), k) << k;
        // Along y: the x difference is exact, the y one is not.
        ASSERT_EQ(exact::circle_circle({{0, 0.1}, 0.1}, {{0, g.ulps(-0.2, -k)}, 0.2}), k) << k;
        // The same for a point on the circle of radius 0.3 around (−0.2, 0): 0.1 − (−0.2) rounds.
        const Vec2 pnt{0.1, 0};
        const Circle c{{g.ulps(-0.2, -k), 0}, 0.1 + 0.2};
        const Rational px = q(pnt.x) - q(c.c.x);
        ASSERT_EQ(exact::point_circle(pnt, c), sign(px * px - q(c.r) * q(c.r))) << k;
    }
    // Exact touching: a 3-4-5 triangle scaled by a power of two.
    EXPECT_EQ(exact::point_circle({3 * 0x1p-500, 4 * 0x1p-500}, {{0, 0}, 5 * 0x1p-500}), 0);
    EXPECT_EQ(exact::circle_circle({{0, 0}, 2}, {{3e150, 4e150}, 5e150 - 2}), sign(q(3e150) * q(3e150) + q(4e150) * q(4e150) - (q(2) + q(5e150 - 2)) * (q(2) + q(5e150 - 2))));
}

TEST(Predicates, CompareCrossingsMatchesGmp) {
    Gen g;
    int decided = 0;
    for (int i = 0; i < 50000; ++i) {
        // A leg a → b and two walls through points near a common point of the leg.
        const Vec2 a{g.uniform(-5, -1), g.uniform(-5, 5)}, b{g.uniform(1, 5), g.uniform(-5, 5)};
        const double t = g.uniform(0.1, 0.9);
        const Vec2 x{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
        const Wall w1{{x.x, x.y - 1}, {g.ulps(x.x, static_cast<int>(g.rng() % 3) - 1), x.y + 1}};
        const Wall w2{{x.x - 1, x.y + 2}, {x.x + (i % 3 == 0 ? 1.0 : 1.5), x.y - 2}};
        auto det = [](const Wall& w, Vec2 p) -> Rational {
            return (q(w.p0.x) - q(p.x)) * (q(w.p1.y) - q(p.y)) - (q(w.p0.y) - q(p.y)) * (q(w.p1.x) - q(p.x));
        };
        const Rational a1 = det(w1, a), b1 = det(w1, b), a2 = det(w2, a), b2 = det(w2, b);
        // Only legs that meet both lines from one side: a_k ≠ 0 and b_k of the other sign or 0.
        if (sign(a1) == 0 || sign(a2) == 0 || sign(a1) * sign(b1) > 0 || sign(a2) * sign(b2) > 0) continue;
        const Rational s1 = a1 / (a1 - b1), s2 = a2 / (a2 - b2);
        ++decided;
        ASSERT_EQ(exact::compare_crossings(a, b, w1, w2), sign(s1 - s2)) << i;
    }
    EXPECT_GT(decided, 10000);
    // Two walls through the same point of the leg: an exact tie, which the filter cannot decide.
    const Vec2 a{-1, 0.1}, b{1, -0.1};
    EXPECT_EQ(exact::compare_crossings(a, b, Wall{{0, -1}, {0, 1}}, Wall{{-0.5, 1}, {0.5, -1}}), 0);
    EXPECT_EQ(exact::compare_crossings(a, b, Wall{{0, -1}, {0, 1}}, Wall{{0.25, -1}, {0.25, 1}}), -1);
}

}  // namespace
}  // namespace ricochet
