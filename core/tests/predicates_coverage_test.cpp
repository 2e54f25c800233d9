// The exact predicates beyond the expansions' safe range (a non-zero input outside [2^-450, 2^450]):
// the filter declines (its products overflow or may have underflowed) and GMP decides. Each answer is
// worked by hand, and the GMP counter shows the path taken.
#include <gtest/gtest.h>

#include "ricochet/predicates.hpp"

namespace ricochet {
namespace {

constexpr double k_big = 0x1p600;    // squares overflow double
constexpr double k_small = 0x1p-500;  // squares fall below k_tiny

/// How many GMP fallbacks f took.
template <class F>
unsigned long long gmp_calls(F&& f) {
    const auto before = exact::fallback_counts().gmp;
    f();
    return exact::fallback_counts().gmp - before;
}

TEST(PredicatesGmp, OrientFarOutside) {
    // (0, 0), (2^600, 0), (0, 2^600): (b − a) × (c − a) = 2^1200 > 0, counter-clockwise.
    int o = 0;
    EXPECT_EQ(gmp_calls([&] { o = exact::orient({0, 0}, {k_big, 0}, {0, k_big}); }), 1u);
    EXPECT_EQ(o, 1);
    EXPECT_EQ(exact::orient({0, 0}, {0, k_big}, {k_big, 0}), -1);
    // Collinear on y = x, no coordinate shared: no shortcut, GMP says 0.
    EXPECT_EQ(gmp_calls([&] { o = exact::orient({0, 0}, {k_big, k_big}, {2 * k_big, 2 * k_big}); }), 1u);
    EXPECT_EQ(o, 0);
    // Tiny: the products 2^-1000 are below k_tiny.
    EXPECT_EQ(gmp_calls([&] { o = exact::orient({0, 0}, {k_small, 0}, {0, k_small}); }), 1u);
    EXPECT_EQ(o, 1);
}

TEST(PredicatesGmp, DirectionSideFarOutside) {
    // Wall (0, 0) → (2^600, 0): n = (e_y, −e_x) = (0, −2^600). n·(0, 2^600) = −2^1200: inside.
    const Wall w{{0, 0}, {k_big, 0}};
    int s = 0;
    EXPECT_EQ(gmp_calls([&] { s = exact::direction_side({0, k_big}, w); }), 1u);
    EXPECT_EQ(s, -1);
    EXPECT_EQ(exact::direction_side({0, -k_big}, w), 1);
    EXPECT_EQ(exact::direction_side({k_big, 0}, w), 0);
    // Tiny wall and direction: e_x·d_y = 2^-1000 is below k_tiny.
    const Wall t{{0, 0}, {k_small, 0}};
    EXPECT_EQ(gmp_calls([&] { s = exact::direction_side({0, k_small}, t); }), 1u);
    EXPECT_EQ(s, -1);
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
}

TEST(PredicatesGmp, CircleCircleFarOutside) {
    // Radii 2^600 each: centres 2^601 apart touch; 2^601 + 2^560 apart do not; 2^600 apart overlap.
    const Circle a{{0, 0}, k_big};
    int s = 2;
    EXPECT_EQ(gmp_calls([&] { s = exact::circle_circle(a, {{2 * k_big, 0}, k_big}); }), 1u);
    EXPECT_EQ(s, 0);
    EXPECT_EQ(exact::circle_circle(a, {{2 * k_big + 0x1p560, 0}, k_big}), 1);
    EXPECT_EQ(exact::circle_circle(a, {{k_big, 0}, k_big}), -1);
}

TEST(PredicatesGmp, CompareCrossingsFarOutside) {
    // The leg (0, 0) → (2^602, 0) crosses x = 2^600 at s = 1/4 and x = 2^601 at s = 1/2. Every orient
    // value overflows: the two orients for the signs go to GMP, and so does the comparison.
    const Vec2 a{0, 0}, b{0x1p602, 0};
    const Wall w1{{k_big, -k_big}, {k_big, k_big}}, w2{{2 * k_big, -k_big}, {2 * k_big, k_big}};
    int c = 2;
    EXPECT_EQ(gmp_calls([&] { c = exact::compare_crossings(a, b, w1, w2); }), 3u);
    EXPECT_EQ(c, -1);
    EXPECT_EQ(exact::compare_crossings(a, b, w2, w1), 1);
    EXPECT_EQ(exact::compare_crossings(a, b, w1, w1), 0);
    // The same wall walked the other way (a_k and b_k change sign together): the same crossing time.
    EXPECT_EQ(exact::compare_crossings(a, b, w1, Wall{w1.p1, w1.p0}), 0);
}

}  // namespace
}  // namespace ricochet
