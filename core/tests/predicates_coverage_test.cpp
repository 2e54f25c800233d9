// The exact predicates beyond the expansions' safe range (a non-zero input outside [2^-450, 2^450]): the filter
// declines (its products overflow or may have underflowed); the first two stages of the exact path still decide
// where they can (the order of two rounded products of exact differences, overflowed or not; a leading estimate
// whose terms stay in range), and GMP decides the rest. Each answer is worked by hand, and the fallback counters
// show the path taken.
#include <gtest/gtest.h>

#include <cmath>

#include "ricochet/predicates.hpp"

namespace ricochet {
namespace {

constexpr double k_big = 0x1p600;    // squares overflow double
constexpr double k_small = 0x1p-500;  // squares fall below k_tiny

/// How many calls f's predicates left to the given fallback counter.
template <class F>
unsigned long long calls(unsigned long long exact::FallbackCounts::*counter, F&& f) {
    const auto before = exact::fallback_counts().*counter;
    f();
    return exact::fallback_counts().*counter - before;
}

/// How many GMP fallbacks f took.
template <class F>
unsigned long long gmp_calls(F&& f) {
    return calls(&exact::FallbackCounts::gmp, f);
}

TEST(PredicatesGmp, OrientFarOutside) {
    // (0, 0), (2^600, 0), (0, 2^600): (b − a) × (c − a) = 2^1200 > 0, counter-clockwise. The filter's products
    // (a − c)x·(b − c)y = 0·(−2^600) = −0 and (a − c)y·(b − c)x = −2^600·2^600 = −∞ overflow, but the differences
    // are exact and −0 > −∞: the first stage orders them, no GMP.
    int o = 0;
    EXPECT_EQ(calls(&exact::FallbackCounts::ordered, [&] { o = exact::orient({0, 0}, {k_big, 0}, {0, k_big}); }), 1u);
    EXPECT_EQ(o, 1);
    EXPECT_EQ(gmp_calls([&] { o = exact::orient({0, 0}, {0, k_big}, {k_big, 0}); }), 0u);
    EXPECT_EQ(o, -1);
    // Collinear on y = x, no coordinate shared: both products are +∞ (a tie out of range), no shortcut, GMP says 0.
    EXPECT_EQ(gmp_calls([&] { o = exact::orient({0, 0}, {k_big, k_big}, {2 * k_big, 2 * k_big}); }), 1u);
    EXPECT_EQ(o, 0);
    // Inexact differences and overflowing products: a = (2^600, 2^600), b = (−2^600, 2^600), c = (1, 0);
    // (b − a) × (c − a) = (−2^601)·(−2^600) − 0·(1 − 2^600) = 2^1201 > 0, and only GMP can say so.
    EXPECT_EQ(gmp_calls([&] { o = exact::orient({k_big, k_big}, {-k_big, k_big}, {1, 0}); }), 1u);
    EXPECT_EQ(o, 1);
    // Tiny: the products 0 and −2^-1000 are below k_tiny, the filter declines; they differ, exact differences:
    // the first stage says counter-clockwise.
    EXPECT_EQ(calls(&exact::FallbackCounts::ordered, [&] { o = exact::orient({0, 0}, {k_small, 0}, {0, k_small}); }), 1u);
    EXPECT_EQ(o, 1);
    // Tiny and collinear: both products 2^-999, a tie below k_tiny, so GMP: 0.
    EXPECT_EQ(gmp_calls([&] { o = exact::orient({0, 0}, {k_small, k_small}, {2 * k_small, 2 * k_small}); }), 1u);
    EXPECT_EQ(o, 0);
    // Beyond the range but with products far from overflow: a = (2^460, 2^460), b = (1, 1 + 2^-52), c = (2^-60, 0).
    // (a − c) × (b − c) = (2^460 − 2^-60)(1 + 2^-52) − 2^460(1 − 2^-60) = 2^408 + 2^400 − 2^-60 − 2^-112 > 0; the
    // filter's 2^408 is within its bound 3ε·2^461, two differences are inexact, and the second stage decides.
    const Vec2 fa{0x1p460, 0x1p460}, fb{1, 1 + 0x1p-52}, fc{0x1p-60, 0};
    EXPECT_EQ(calls(&exact::FallbackCounts::bounded, [&] { o = exact::orient(fa, fb, fc); }), 1u);
    EXPECT_EQ(o, 1);
}

TEST(PredicatesGmp, DirectionSideFarOutside) {
    // Wall (0, 0) → (2^600, 0): n = (e_y, −e_x) = (0, −2^600). n·(0, 2^600) = −2^1200: inside. e × d's products
    // e_x·d_y = +∞ and e_y·d_x = 0 differ: the first stage orders them.
    const Wall w{{0, 0}, {k_big, 0}};
    int s = 0;
    EXPECT_EQ(calls(&exact::FallbackCounts::ordered, [&] { s = exact::direction_side({0, k_big}, w); }), 1u);
    EXPECT_EQ(s, -1);
    EXPECT_EQ(exact::direction_side({0, -k_big}, w), 1);
    // Along the wall: both products 0, a tie below k_tiny; GMP says parallel.
    EXPECT_EQ(gmp_calls([&] { s = exact::direction_side({k_big, 0}, w); }), 1u);
    EXPECT_EQ(s, 0);
    // Tiny wall and direction: e_x·d_y = 2^-1000 is below k_tiny, e_y·d_x = 0; ordered: inside.
    const Wall t{{0, 0}, {k_small, 0}};
    EXPECT_EQ(calls(&exact::FallbackCounts::ordered, [&] { s = exact::direction_side({0, k_small}, t); }), 1u);
    EXPECT_EQ(s, -1);
    EXPECT_EQ(gmp_calls([&] { s = exact::direction_side({k_small, 0}, t); }), 1u);
    EXPECT_EQ(s, 0);
}

TEST(PredicatesGmp, PointCircleFarOutside) {
    // Centre 0, r = 2^600: |p|² − r² for p = (2^600, 0) is 0 (on it), (2^600, 2^590) outside,
    // (2^599, 0) inside.
    const Circle c{{0, 0}, k_big};
    int s = 2;
    EXPECT_EQ(gmp_calls([&] { s = exact::point_circle({k_big, 0}, c); }), 1u);
    EXPECT_EQ(s, 0);
    EXPECT_EQ(exact::point_circle({k_big, 0x1p590}, c), 1);
    EXPECT_EQ(exact::point_circle({0x1p599, 0}, c), -1);
    // Beyond the range with squares far from overflow: centre (2^460, 0), p = c + (3, 4)·2^420, r one ulp (2^370)
    // above 5·2^420. |p − c|² − r² = −10·2^790 − 2^740 < 0: inside. The filter's d2 − r2 ≈ −2.5·2^792 is within its
    // bound 125ε·2^840; the differences are exact and the second stage decides.
    const Circle far{{0x1p460, 0}, std::nextafter(5 * 0x1p420, 1e300)};
    const Vec2 near{0x1p460 + 3 * 0x1p420, 4 * 0x1p420};
    EXPECT_EQ(calls(&exact::FallbackCounts::bounded, [&] { s = exact::point_circle(near, far); }), 1u);
    EXPECT_EQ(s, -1);
    // Subnormal: p = (3, 4)·2^-1074 on the circle of radius 5·2^-1074 around 0; every square underflows to 0.
    EXPECT_EQ(gmp_calls([&] { s = exact::point_circle({3 * 0x1p-1074, 4 * 0x1p-1074}, {{0, 0}, 5 * 0x1p-1074}); }), 1u);
    EXPECT_EQ(s, 0);
}

TEST(PredicatesGmp, CircleCircleFarOutside) {
    // Radii 2^600 each: centres 2^601 apart touch; 2^601 + 2^560 apart do not; 2^600 apart overlap.
    const Circle a{{0, 0}, k_big};
    int s = 2;
    EXPECT_EQ(gmp_calls([&] { s = exact::circle_circle(a, {{2 * k_big, 0}, k_big}); }), 1u);
    EXPECT_EQ(s, 0);
    EXPECT_EQ(exact::circle_circle(a, {{2 * k_big + 0x1p560, 0}, k_big}), 1);
    EXPECT_EQ(exact::circle_circle(a, {{k_big, 0}, k_big}), -1);
    // Beyond the range with squares far from overflow: centres (3, 4)·2^420 apart around (2^460, 0), radii 2·2^420
    // and 3·2^420 + 2^369 (one ulp up). rA + rB = 5·2^420 + 2^369 is half an ulp of 5·2^420: an inexact sum.
    // 25·2^840 − (5·2^420 + 2^369)² = −10·2^789 − 2^738 < 0: overlapping, decided by the second stage.
    const Circle c1{{0x1p460, 0}, 2 * 0x1p420}, c2{{0x1p460 + 3 * 0x1p420, 4 * 0x1p420}, std::nextafter(3 * 0x1p420, 1e300)};
    EXPECT_EQ(calls(&exact::FallbackCounts::bounded, [&] { s = exact::circle_circle(c1, c2); }), 1u);
    EXPECT_EQ(s, -1);
    // Subnormal: radii 2 and 3 (times 2^-1074) with centres (3, 4)·2^-1074 apart touch.
    const Circle t1{{0, 0}, 2 * 0x1p-1074}, t2{{3 * 0x1p-1074, 4 * 0x1p-1074}, 3 * 0x1p-1074};
    EXPECT_EQ(gmp_calls([&] { s = exact::circle_circle(t1, t2); }), 1u);
    EXPECT_EQ(s, 0);
}

TEST(PredicatesGmp, CompareCrossingsFarOutside) {
    // The leg (0, 0) → (2^602, 0) crosses x = 2^600 at s = 1/4 and x = 2^601 at s = 1/2. Every orient
    // value overflows: the two orients for the signs have exact differences and products +∞ and −∞, which
    // the first stage orders; the comparison goes to GMP.
    const Vec2 a{0, 0}, b{0x1p602, 0};
    const Wall w1{{k_big, -k_big}, {k_big, k_big}}, w2{{2 * k_big, -k_big}, {2 * k_big, k_big}};
    int c = 2;
    EXPECT_EQ(calls(&exact::FallbackCounts::ordered, [&] {
                  EXPECT_EQ(gmp_calls([&] { c = exact::compare_crossings(a, b, w1, w2); }), 1u);
              }),
              2u);
    EXPECT_EQ(c, -1);
    EXPECT_EQ(exact::compare_crossings(a, b, w2, w1), 1);
    EXPECT_EQ(exact::compare_crossings(a, b, w1, w1), 0);
    // The same wall walked the other way (a_k and b_k change sign together): the same crossing time.
    EXPECT_EQ(exact::compare_crossings(a, b, w1, Wall{w1.p1, w1.p0}), 0);
}

}  // namespace
}  // namespace ricochet
