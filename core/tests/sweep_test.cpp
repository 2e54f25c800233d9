// The animated point against one wall: the five non-collision tests, t_i, B_i and the bounce.
#include <gtest/gtest.h>

#include <cmath>

#include "ricochet/kernel.hpp"

namespace ricochet {
namespace {

class Sweeps : public ::testing::TestWithParam<KernelId> {};
INSTANTIATE_TEST_SUITE_P(Kernels, Sweeps, ::testing::ValuesIn(k_all_kernels));

// A floor from (0, 0) to (10, 0): n = (0, −10), so "outside" is below it.
const Wall k_floor{{0, 0}, {10, 0}};

TEST_P(Sweeps, HitTimeAndPointWorkedByHand) {
    const KernelId k = GetParam();
    // Bs = (2, 3), v = (4, −4): n̂ = (0, −1), t_i = (n̂·P0 − n̂·Bs)/(n̂·v) = (0 + 3)/4 = 0.75,
    // B_i = (2, 3) + 0.75·(4, −4) = (5, 0).
    const Sweep s = sweep(k, {2, 3}, {4, -4}, k_floor);
    ASSERT_TRUE(s.hit()) << miss_name(s.miss);
    EXPECT_EQ(s.t, 0.75);
    EXPECT_EQ(s.point, (Vec2{5, 0}));
}

TEST_P(Sweeps, TheFiveTestsInOrder) {
    const KernelId k = GetParam();
    // 1: both ends inside (above the floor)
    EXPECT_EQ(sweep(k, {2, 3}, {1, -1}, k_floor).miss, Miss::both_inside);
    // 2: both ends outside (below)
    EXPECT_EQ(sweep(k, {2, -3}, {1, 1}, k_floor).miss, Miss::both_outside);
    // 3: n̂·v = 0, moving along the wall's line
    EXPECT_EQ(sweep(k, {2, 0}, {3, 0}, k_floor).miss, Miss::parallel);
    // 4: the hit point lies before P0: B_i = (−1, 0)
    EXPECT_EQ(sweep(k, {-1, 1}, {0, -2}, k_floor).miss, Miss::before_p0);
    // 5: the hit point lies past P1: B_i = (11, 0)
    EXPECT_EQ(sweep(k, {11, 1}, {0, -2}, k_floor).miss, Miss::past_p1);
}

TEST_P(Sweeps, TouchingIsACollision) {
    const KernelId k = GetParam();
    // The leg ends exactly on the wall: t_i = 1, B_i = Be.
    const Sweep end = sweep(k, {3, 2}, {1, -2}, k_floor);
    ASSERT_TRUE(end.hit());
    EXPECT_EQ(end.t, 1.0);
    EXPECT_EQ(end.point, (Vec2{4, 0}));
    // Crossing exactly at an end point: P0 and P1 belong to the closed segment.
    EXPECT_TRUE(sweep(k, {0, 1}, {0, -2}, k_floor).hit());
    EXPECT_TRUE(sweep(k, {10, -1}, {0, 2}, k_floor).hit());
}

TEST_P(Sweeps, DegenerateInputsAreNeverDividedBy) {
    const KernelId k = GetParam();
    EXPECT_EQ(sweep(k, {5, 1}, {0, -2}, Wall{{5, 0}, {5, 0}}).miss, Miss::degenerate);
    EXPECT_EQ(sweep(k, {5, 0}, {0, 0}, k_floor).miss, Miss::degenerate);
}

TEST(Sweeps, LeavingTheWallIsNoHitForRobustAndExact) {
    // A ball lying on the wall and moving off it does not hit it.
    for (KernelId k : {KernelId::robust, KernelId::exact}) {
        EXPECT_EQ(sweep(k, {5, 0}, {0, 1}, k_floor).miss, Miss::leaving);
        EXPECT_EQ(sweep(k, {5, 0}, {1, -1}, k_floor).miss, Miss::leaving);
    }
    // The lecture's formulas say t_i = 0: a hit. That is their behaviour, kept as the baseline.
    EXPECT_TRUE(sweep(KernelId::lecture_double, {5, 0}, {0, 1}, k_floor).hit());
}

TEST_P(Sweeps, ReversedWallSameDecision) {
    const KernelId k = GetParam();
    const Wall back{k_floor.p1, k_floor.p0};
    for (Vec2 bs : {Vec2{2, 3}, Vec2{-1, 1}, Vec2{11, 1}, Vec2{2, -3}}) {
        for (Vec2 v : {Vec2{4, -4}, Vec2{0, -2}, Vec2{1, 1}}) {
            EXPECT_EQ(sweep(k, bs, v, k_floor).hit(), sweep(k, bs, v, back).hit());
        }
    }
}

TEST_P(Sweeps, ReflectPreservesSpeedAndFlipsTheNormalPart) {
    const KernelId k = GetParam();
    // About the floor: (3, −4) → (3, 4).
    EXPECT_EQ(reflect(k, {3, -4}, k_floor), (Vec2{3, 4}));
    // About the diagonal wall (0, 0) → (1, 1): (1, 0) → (0, 1).
    const Vec2 r = reflect(k, {1, 0}, Wall{{0, 0}, {1, 1}});
    const double tol = k == KernelId::lecture_float ? 1e-7 : 1e-15;
    EXPECT_NEAR(r.x, 0.0, tol);
    EXPECT_NEAR(r.y, 1.0, tol);
}

TEST(Sweeps, RobustDecidesTheEndPointOnAWallExactly) {
    // Be = Bs + v lies exactly on a wall with an inexact slope: robust and exact call it a hit at t = 1.
    const Wall w{{0.5, 0.25}, {1.25, 0.5}};
    const Vec2 bs{1.0, 1.0};
    const Vec2 be{2.0, 0.75};  // P0 + 2·e, on the line beyond P1
    const Wall longer{{0.5, 0.25}, {2.75, 1.0}};  // P0 + 3·e: now Be is on the segment
    const Vec2 v = be - bs;
    ASSERT_EQ(bs + v, be);
    EXPECT_EQ(sweep(KernelId::robust, bs, v, w).miss, Miss::past_p1);
    EXPECT_EQ(sweep(KernelId::exact, bs, v, w).miss, Miss::past_p1);
    const Sweep r = sweep(KernelId::robust, bs, v, longer);
    ASSERT_TRUE(r.hit());
    EXPECT_EQ(r.t, 1.0);
    EXPECT_EQ(r.point, be);
}

}  // namespace
}  // namespace ricochet
