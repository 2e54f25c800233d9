// Static tests, every kernel: the lecture's boundary rule "be consistent": touching is a collision.
#include <gtest/gtest.h>

#include <cmath>

#include "ricochet/kernel.hpp"

namespace ricochet {
namespace {

class EveryKernel : public ::testing::TestWithParam<KernelId> {};
std::string test_name(const ::testing::TestParamInfo<KernelId>& p) {
    std::string n(kernel_name(p.param));
    for (char& c : n)
        if (c == '-') c = '_';
    return n;
}
INSTANTIATE_TEST_SUITE_P(Kernels, EveryKernel, ::testing::ValuesIn(k_all_kernels), test_name);

TEST_P(EveryKernel, PointCircle) {
    const KernelId k = GetParam();
    const Circle c{{1, 1}, 5};
    // (4, 5) − (1, 1) = (3, 4): |CP| = 5 = R exactly, a 3-4-5 triangle. Touching is inside.
    EXPECT_TRUE(point_in_circle(k, {4, 5}, c));
    EXPECT_TRUE(point_in_circle(k, {1, 1}, c));
    EXPECT_TRUE(point_in_circle(k, {1, 6}, c));
    EXPECT_FALSE(point_in_circle(k, {1, 6.25}, c));
    EXPECT_FALSE(point_in_circle(k, {4.25, 5}, c));
}

TEST_P(EveryKernel, CircleCircleSquaredDistance) {
    const KernelId k = GetParam();
    // Centres 10 apart, radii 4 + 6 = 10: touching, so overlapping; (rA + rB)² = 100 = |d|².
    EXPECT_TRUE(circles_overlap(k, {{0, 0}, 4}, {{6, 8}, 6}));
    EXPECT_TRUE(circles_overlap(k, {{6, 8}, 6}, {{0, 0}, 4}));
    EXPECT_FALSE(circles_overlap(k, {{0, 0}, 4}, {{6, 8}, 5.75}));
    EXPECT_TRUE(circles_overlap(k, {{0, 0}, 4}, {{1, 1}, 0.5}));  // one inside the other
}

TEST_P(EveryKernel, PointRect) {
    const KernelId k = GetParam();
    const Rect r{-1, -2, 3, 4};
    EXPECT_TRUE(point_in_rect(k, {0, 0}, r));
    EXPECT_TRUE(point_in_rect(k, {-1, 1}, r));  // on the left edge
    EXPECT_TRUE(point_in_rect(k, {3, 4}, r));   // on the top-right corner
    EXPECT_FALSE(point_in_rect(k, {3.5, 4}, r));
    EXPECT_FALSE(point_in_rect(k, {0, -2.5}, r));
}

TEST_P(EveryKernel, RectRectLeftRightBottomTop) {
    const KernelId k = GetParam();
    const Rect a{0, 0, 2, 2};
    EXPECT_TRUE(rects_overlap(k, a, {1, 1, 3, 3}));
    EXPECT_TRUE(rects_overlap(k, a, {2, 0, 4, 2}));      // sharing the right edge
    EXPECT_TRUE(rects_overlap(k, a, {2, 2, 4, 4}));      // sharing a corner
    EXPECT_TRUE(rects_overlap(k, {2, 2, 4, 4}, a));
    EXPECT_FALSE(rects_overlap(k, a, {2.5, 0, 4, 2}));   // wholly right
    EXPECT_FALSE(rects_overlap(k, a, {0, -3, 2, -0.5}));  // wholly below
    EXPECT_FALSE(rects_overlap(k, a, {-3, 0, -1, 2}));   // wholly left
    EXPECT_FALSE(rects_overlap(k, a, {0, 3, 2, 4}));     // wholly above
}

TEST_P(EveryKernel, DegenerateShapesAgreeWithAPoint) {
    const KernelId k = GetParam();
    // A point, a radius-0 circle and a zero-size rectangle at (2, 3) are the same thing.
    const Vec2 p{2, 3};
    const Circle dot{p, 0};
    const Rect box{2, 3, 2, 3};
    for (Vec2 q : {Vec2{2, 3}, Vec2{2.5, 3}, Vec2{2, 2.75}}) {
        const bool same = q == p;
        EXPECT_EQ(point_in_circle(k, q, dot), same);
        EXPECT_EQ(point_in_rect(k, q, box), same);
        EXPECT_EQ(circles_overlap(k, {q, 0}, dot), same);
        EXPECT_EQ(rects_overlap(k, {q.x, q.y, q.x, q.y}, box), same);
    }
    // A zero-width rectangle still overlaps what touches it.
    EXPECT_TRUE(rects_overlap(k, {1, 0, 1, 5}, {0, 5, 1, 6}));
}

TEST(Static, RobustIsExactWhereLectureRoundsWrong) {
    // |P − C|² = R² exactly in real numbers, but the double differences round: a point 1e-17
    // outside a radius-1 circle centred at 0.1 and the lecture's squared distance disagree.
    const Circle c{{0.1, 0.0}, 0.30000000000000004};
    const Vec2 p{0.4, 0.0};
    // 0.4 − 0.1 is 0.30000000000000004 in double but exactly 0.3000000000000000166… in reals.
    EXPECT_EQ(point_in_circle(KernelId::robust, p, c), point_in_circle(KernelId::exact, p, c));
}

}  // namespace
}  // namespace ricochet
