// Line segments: edge, outward normal, point-normal equation, BC and classification.
#include <gtest/gtest.h>

#include <cmath>

#include "ricochet/kernel.hpp"
#include "ricochet/line.hpp"

namespace ricochet {
namespace {

TEST(Line, EdgeAndNormal) {
    const Wall w{{1, 1}, {4, 5}};
    EXPECT_EQ(edge(w), (Vec2{3, 4}));
    // n = (e_y, −e_x) = (4, −3), to the right of P0 → P1
    EXPECT_EQ(normal(w), (Vec2{4, -3}));
    EXPECT_EQ(unit_normal(w), (Vec2{0.8, -0.6}));
    EXPECT_EQ(dot(normal(w), edge(w)), 0.0);
}

TEST(Line, PointNormalEquationAndBC) {
    const Wall w{{1, 1}, {4, 5}};
    // n̂·P − n̂·P0 = 0 on the line: P0, P1 and their midpoint.
    EXPECT_EQ(boundary_condition({1, 1}, w), 0.0);
    // At P1, n̂ = (0.8, −0.6) is rounded and BC = 0.8·3 − 0.6·4 comes out 4.4e-16, not 0: the
    // lecture's BC is a rounded value, which is why robust decides sides with exact predicates.
    EXPECT_NEAR(boundary_condition({4, 5}, w), 0.0, 1e-15);
    EXPECT_EQ(classify(KernelId::robust, {4, 5}, w), Side::on);
    // BC = n̂·(P − P0): (5, 1) − (1, 1) = (4, 0), n̂·(4, 0) = 3.2, outside.
    EXPECT_DOUBLE_EQ(boundary_condition({5, 1}, w), 3.2);
    EXPECT_DOUBLE_EQ(boundary_condition({1, 6}, w), -3.0);
    // Zero-length wall: no normal, BC is 0 everywhere.
    EXPECT_EQ(boundary_condition({9, 9}, Wall{{2, 2}, {2, 2}}), 0.0);
}

TEST(Line, FormulasInFloat) {
    // The same formulas in float, as lecture-float reads them: e = (3, 4), n = (4, −3), |n| = 5 exactly.
    const Vec2T<float> p0{1, 1}, p1{4, 5};
    EXPECT_EQ(edge(p0, p1), (Vec2T<float>{3, 4}));
    EXPECT_EQ(normal(p0, p1), (Vec2T<float>{4, -3}));
    EXPECT_EQ(unit_normal(p0, p1), (Vec2T<float>{0.8f, -0.6f}));
    // BC = n̂·(P − P0) = 0.8f·4 − 0.6f·0 at (5, 1), rounded in float.
    EXPECT_EQ(boundary_condition(Vec2T<float>{5, 1}, p0, unit_normal(p0, p1)), 0.8f * 4.0f);
    EXPECT_EQ(side_of_line(Vec2T<float>{5, 1}, p0, p1), Side::outside);
    EXPECT_EQ(side_of_line(Vec2T<float>{1, 6}, p0, p1), Side::inside);
    EXPECT_EQ(side_of_line(p0, p0, p1), Side::on);
    // Degenerate: a zero-length segment has no normal; every point is on its "line".
    EXPECT_EQ(unit_normal(p0, p0), (Vec2T<float>{0, 0}));
    EXPECT_EQ(side_of_line(Vec2T<float>{9, 9}, p0, p0), Side::on);
}

TEST(Line, FloatRoundsWhereDoubleDoesNot) {
    // 1 + 2^-30 is a double but rounds to 1 in float: lecture-double sees the point off the line y = 1,
    // lecture-float (every input rounded to float first) sees it on the line.
    const Wall w{{0, 1}, {10, 1}};
    const Vec2 p{5, 1 + 0x1p-30};
    EXPECT_EQ(side_of_line(vec_cast<float>(p), vec_cast<float>(w.p0), vec_cast<float>(w.p1)), Side::on);
    EXPECT_EQ(classify(KernelId::lecture_float, p, w), Side::on);
    EXPECT_EQ(classify(KernelId::lecture_double, p, w), Side::inside);
}

class Classify : public ::testing::TestWithParam<KernelId> {};
INSTANTIATE_TEST_SUITE_P(Kernels, Classify, ::testing::ValuesIn(k_all_kernels));

TEST_P(Classify, OutsideInsideOn) {
    const KernelId k = GetParam();
    const Wall w{{0, 0}, {10, 0}};  // normal (0, −10): outside is below
    EXPECT_EQ(classify(k, {5, -1}, w), Side::outside);
    EXPECT_EQ(classify(k, {5, 1}, w), Side::inside);
    EXPECT_EQ(classify(k, {5, 0}, w), Side::on);
    EXPECT_EQ(classify(k, {-50, 0}, w), Side::on);  // on the line, beyond the segment
    // Reversing the wall flips the normal and the side.
    EXPECT_EQ(classify(k, {5, -1}, Wall{{10, 0}, {0, 0}}), Side::inside);
}

TEST(Classify, RobustIsExactOnTheLine) {
    // P = P0 + 2·e exactly (dyadic coordinates): on the line in real numbers. The lecture's n̂ is
    // irrational, so its rounded BC need not be 0; robust and exact must say On.
    const Wall w{{0.5, 0.25}, {1.25, 0.5}};
    const Vec2 p{2.0, 0.75};
    EXPECT_EQ(classify(KernelId::robust, p, w), Side::on);
    EXPECT_EQ(classify(KernelId::exact, p, w), Side::on);
    // One ulp off the line, both see the same strict side.
    const Vec2 up{2.0, std::nextafter(0.75, 1.0)};
    EXPECT_EQ(classify(KernelId::robust, up, w), Side::inside);
    EXPECT_EQ(classify(KernelId::exact, up, w), Side::inside);
    // Far from the origin, where the lecture's products lose every low bit.
    const Wall far{{1e15, 1e15}, {1e15 + 4, 1e15 + 2}};
    EXPECT_EQ(classify(KernelId::robust, {1e15 + 8, 1e15 + 4}, far), Side::on);
    EXPECT_EQ(classify(KernelId::robust, {1e15 + 8, 1e15 + 4.125}, far), Side::inside);
}

}  // namespace
}  // namespace ricochet
