// One frame of one ball among many walls: the lecture's pinball, corners, the bounce, limits.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "base/bignum.hpp"
#include "bignum_cases.hpp"
#include "ricochet/kernel.hpp"
#include "ricochet/tunnel.hpp"

namespace ricochet {
namespace {

using bignum::Rational;

// SpeedBoundHolds' cases (a tenth of them on Boost.Multiprecision).
constexpr int k_speed_cases = test::bignum_cases(300000);

// A closed box [lo, hi]²: 0 left, 1 bottom, 2 right, 3 top. For P0 → P1 the normal (e_y, −e_x) points
// to the right of the direction of travel, so going counter-clockwise keeps the outside on the right.
std::vector<Wall> box(double lo = 0, double hi = 10) {
    return {{{lo, hi}, {lo, lo}}, {{lo, lo}, {hi, lo}}, {{hi, lo}, {hi, hi}}, {{hi, hi}, {lo, hi}}};
}

struct Stepped {
    Ball ball;
    std::vector<HitEvent> hits;
    FrameStatus status;
};

Stepped step(KernelId k, Ball b, const std::vector<Wall>& walls, BallMemory* memory = nullptr) {
    BallMemory local;
    StepScratch scratch;
    std::vector<HitEvent> hits;
    const FrameStatus st = step_ball(k, b, memory ? *memory : local, walls, hits, scratch);
    return {b, hits, st};
}

class Frames : public ::testing::TestWithParam<KernelId> {};
INSTANTIATE_TEST_SUITE_P(Kernels, Frames, ::testing::ValuesIn(k_all_kernels));

TEST_P(Frames, BoxWallsPointOutward) {
    for (const Wall& w : box()) EXPECT_EQ(classify(GetParam(), {5, 5}, w), Side::inside);
}

TEST_P(Frames, ThePinballBouncesAndSpendsTheRestOfTheFrame) {
    // Bs = (8, 5), v = (4, 1): the right wall x = 10 is met at t_i = 0.5, B_i = (10, 5.5);
    // v' = (−4, 1); the rest (1 − 0.5)·v' = (−2, 0.5) ends at (8, 6).
    const Stepped s = step(GetParam(), {{8, 5}, {4, 1}}, box());
    ASSERT_EQ(s.hits.size(), 1u);
    EXPECT_EQ(s.hits[0].wall, 2u);
    EXPECT_EQ(s.hits[0].t, 0.5);
    EXPECT_EQ(s.hits[0].point, (Vec2{10, 5.5}));
    EXPECT_EQ(s.ball.pos, (Vec2{8, 6}));
    EXPECT_EQ(s.ball.vel, (Vec2{-4, 1}));
    EXPECT_EQ(s.status, FrameStatus::ok);
}

TEST_P(Frames, ABallAtRestStaysWithItsMemory) {
    // First a frame ending exactly on the right wall after a bounce off the top one, so robust and exact
    // remember a contact and a bounce; then the ball at rest: nothing moves, nothing is hit or forgotten.
    BallMemory memory;
    Stepped s = step(GetParam(), {{9, 9}, {1, 2}}, box(), &memory);
    const BallMemory before = memory;
    if (GetParam() == KernelId::robust || GetParam() == KernelId::exact) {
        ASSERT_EQ(before.count, 1);  // lying on the right wall
        ASSERT_NE(before.bounced_from, 0);
    }
    const Vec2 at = s.ball.pos;
    s = step(GetParam(), {at, {0, 0}}, box(), &memory);
    EXPECT_EQ(s.status, FrameStatus::ok);
    EXPECT_EQ(s.ball.pos, at);
    EXPECT_TRUE(s.hits.empty());
    EXPECT_EQ(s.ball.vel, (Vec2{0, 0}));
    EXPECT_EQ(memory.count, before.count);
    for (std::uint8_t i = 0; i < memory.count; ++i) {
        EXPECT_EQ(memory.contacts[i].wall, before.contacts[i].wall);
        EXPECT_EQ(memory.contacts[i].side, before.contacts[i].side);
    }
    EXPECT_EQ(memory.bounced_from, before.bounced_from);
    EXPECT_EQ(memory.bounced_wall, before.bounced_wall);
}

TEST_P(Frames, SeveralBouncesInOneFrame) {
    // Fast enough to cross the box twice: (5, 5) + (25, 0) bounces off x = 10 then x = 0.
    const Stepped s = step(GetParam(), {{5, 5}, {25, 0}}, box());
    // 5 → 10 (5), → 0 (10), → 10 with the rest, 25 − 15 = 10: the frame ends touching the right
    // wall, and touching is a collision, so that is a third bounce at t = 1.
    ASSERT_EQ(s.hits.size(), 3u);
    EXPECT_EQ(s.hits[0].wall, 2u);
    EXPECT_EQ(s.hits[1].wall, 0u);
    EXPECT_EQ(s.hits[2].wall, 2u);
    // Hit times are constructions: rounded, except in exact (correctly rounded from the rational).
    const double tol = GetParam() == KernelId::exact ? 0.0 : GetParam() == KernelId::lecture_float ? 1e-7 : 1e-15;
    EXPECT_NEAR(s.hits[0].t, 0.2, tol);
    EXPECT_NEAR(s.hits[1].t, 0.6, tol);
    EXPECT_NEAR(s.hits[2].t, 1.0, tol);
    EXPECT_EQ(s.ball.pos, (Vec2{10, 5}));
    EXPECT_EQ(s.ball.vel, (Vec2{-25, 0}));
}

TEST(Frames, CornerGoesStraightBackForRobustAndExact) {
    // Aimed exactly at the corner (10, 10): both walls are met at the same time. The lowest index (the
    // right wall, 2) is reported; reflecting about both sends the ball straight back.
    for (KernelId k : {KernelId::robust, KernelId::exact}) {
        const Stepped s = step(k, {{6, 6}, {8, 8}}, box());
        ASSERT_EQ(s.hits.size(), 1u) << kernel_name(k);
        EXPECT_EQ(s.hits[0].wall, 2u);
        EXPECT_EQ(s.hits[0].point, (Vec2{10, 10}));
        EXPECT_EQ(s.ball.vel, (Vec2{-8, -8}));
        EXPECT_EQ(s.ball.pos, (Vec2{6, 6}));
    }
}

TEST(Frames, EndOnACornerThenLeaveIntoTheBox) {
    // The frame ends exactly in the corner; the next frame must leave it into the box, never out.
    for (KernelId k : {KernelId::robust, KernelId::exact}) {
        BallMemory memory;
        Stepped s = step(k, {{6, 6}, {4, 4}}, box(), &memory);
        ASSERT_EQ(s.hits.size(), 1u);
        EXPECT_EQ(s.ball.pos, (Vec2{10, 10}));
        const auto walls = box();
        const std::vector<Ball> start{{{6, 6}, {4, 4}}};
        TunnelChecker checker(walls, start);
        EXPECT_FALSE(checker.advance(0, s.ball.pos));
        s = step(k, s.ball, walls, &memory);
        EXPECT_FALSE(checker.advance(0, s.ball.pos));
        EXPECT_LE(s.ball.pos.x, 10.0);
        EXPECT_LE(s.ball.pos.y, 10.0);
    }
}

TEST_P(Frames, BounceLimitStopsAtASafePoint) {
    // A corridor 2^-40 wide crossed at speed 1: thousands of bounces are needed, 16 are allowed.
    const double h = 0x1p-40;
    const std::vector<Wall> corridor{{{-10, 0}, {10, 0}}, {{10, h}, {-10, h}}};
    const Stepped s = step(GetParam(), {{0, h / 2}, {1, 1}}, corridor);
    EXPECT_EQ(s.status, FrameStatus::bounce_limit);
    EXPECT_EQ(s.hits.size(), static_cast<std::size_t>(k_max_bounces));
    if (GetParam() == KernelId::robust || GetParam() == KernelId::exact) {
        EXPECT_GE(s.ball.pos.y, 0.0);
        EXPECT_LE(s.ball.pos.y, h);
    }
}

TEST_P(Frames, ZeroVelocityDoesNoSweep) {
    const Stepped s = step(GetParam(), {{5, 5}, {0, 0}}, box());
    EXPECT_TRUE(s.hits.empty());
    EXPECT_EQ(s.ball.pos, (Vec2{5, 5}));
}

TEST_P(Frames, OutOfRangeIsAnErrorAndChangesNothing) {
    const Ball nan{{std::nan(""), 0}, {1, 0}};
    Stepped s = step(GetParam(), nan, box());
    EXPECT_EQ(s.status, FrameStatus::out_of_range);
    const Ball huge{{1e300, 0}, {1, 0}};
    s = step(GetParam(), huge, box());
    EXPECT_EQ(s.status, FrameStatus::out_of_range);
    EXPECT_EQ(s.ball, huge);
}

TEST(Frames, BounceKeepsSpeedAndSide) {
    // Many bounces off a wall with an inexact direction: |v| stays within the stated bound and the
    // ball always ends on the side it came from.
    const Wall w{{0.1, 0.3}, {7.3, 2.9}};
    for (KernelId k : {KernelId::robust, KernelId::exact}) {
        for (int i = 1; i < 200; ++i) {
            const Vec2 start{3.0 + i * 0.01, 5.0};
            const Vec2 v{0.37 * i - 30.0, -7.0 - 0.011 * i};
            BallMemory memory;
            Stepped s = step(k, {start, v}, {w}, &memory);
            if (s.hits.empty()) continue;
            const double before = std::hypot(v.x, v.y), after = std::hypot(s.ball.vel.x, s.ball.vel.y);
            EXPECT_LE(std::fabs(after - before), k_speed_rel_bound * before + 4e-16 * before);
            const Side from = classify(KernelId::exact, start, w);
            const Side to = classify(KernelId::exact, s.ball.pos, w);
            EXPECT_TRUE(to == from || to == Side::on) << kernel_name(k) << " case " << i;
        }
    }
}

TEST(Tunnel, SlidingAlongTheWallKeepsTheSideItCameFrom) {
    // Arrive on the floor from above, slide along it on the segment, leave below: a tunnel.
    const std::vector<Wall> floor{{{0, 0}, {10, 0}}};
    const std::vector<Ball> start{{{1, 1}, {0, 0}}};
    TunnelChecker through(floor, start);
    EXPECT_FALSE(through.advance(0, {2, 0}));
    EXPECT_FALSE(through.advance(0, {3, 0}));
    EXPECT_EQ(through.advance(0, {4, -1}), std::optional<std::uint32_t>{0});
    // Slide off the segment's end first: going round it is no tunnel.
    TunnelChecker round(floor, start);
    EXPECT_FALSE(round.advance(0, {9, 0}));
    EXPECT_FALSE(round.advance(0, {11, 0}));
    EXPECT_FALSE(round.advance(0, {12, -1}));
    // Starting on the wall, either side is fine.
    const std::vector<Ball> on{{{5, 0}, {0, 0}}};
    TunnelChecker free(floor, on);
    EXPECT_FALSE(free.advance(0, {5, -1}));
}

TEST(Frames, SpeedBoundHolds) {
    // | |v'| − |v| | ≤ k_speed_rel_bound·|v| + k_speed_abs_bound for one reflection, measured with square roots
    // within 2^-256 (relative) of the exact ones, on walls of every length and velocities down to the subnormal range.
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    auto norm = [](Vec2 a) {
        const Rational x = bignum::rational(a.x), y = bignum::rational(a.y);
        return bignum::sqrt_below(x * x + y * y, 256);
    };
    double worst_rel = 0;
    for (int i = 0; i < k_speed_cases; ++i) {
        const double ws = std::ldexp(1.0, static_cast<int>(rng() % 400) - 200);
        const int ve = i % 10 == 0 ? -1074 + static_cast<int>(rng() % 60) : static_cast<int>(rng() % 400) - 200;
        const double vs = std::ldexp(1.0, ve);
        const Wall w{{ws * u(rng), ws * u(rng)}, {ws * u(rng), ws * u(rng)}};
        const Vec2 v{vs * u(rng), vs * u(rng)};
        for (KernelId k : {KernelId::robust, KernelId::exact}) {
            const Vec2 r = reflect(k, v, w);
            const Rational n0 = norm(v), n1 = norm(r);
            const Rational diff = abs(Rational(n1 - n0));
            const Rational allowed = n0 * bignum::rational(k_speed_rel_bound) + bignum::rational(k_speed_abs_bound);
            ASSERT_LE(diff, allowed) << kernel_name(k) << " v=(" << v.x << "," << v.y << ") case " << i;
            if (ve > -1000 && k == KernelId::robust) worst_rel = std::max(worst_rel, bignum::to_double(Rational(diff / n0)));
        }
    }
    // Say how close the stated bound is to what was seen.
    std::printf("robust: worst relative |v| change per bounce %.3g = 2^%.2f (bound 2^-48)\n", worst_rel,
                std::log2(worst_rel));
}

TEST(Frames, RobustNeverTunnelsThroughAThinWedge) {
    // Two walls meeting at a sharp angle, balls aimed near the apex from many directions over many
    // frames: the exact checker must never see a tunnel.
    const std::vector<Wall> walls{{{0, 0}, {10, 1e-9}}, {{10, -1e-9}, {0, 0}}, {{10, 1e-9}, {10, -1e-9}}};
    for (KernelId k : {KernelId::robust, KernelId::exact}) {
        for (int i = 0; i < 64; ++i) {
            const std::vector<Ball> balls{{{-1.0 - i * 0.37, 0.5 - i * 0.013}, {1.0 + i * 0.11, -0.5 + i * 0.0131}}};
            TunnelChecker checker(walls, balls);
            Ball b = balls[0];
            BallMemory memory;
            StepScratch scratch;
            for (int f = 0; f < 40; ++f) {
                std::vector<HitEvent> hits;
                step_ball(k, b, memory, walls, hits, scratch);
                for (const HitEvent& h : hits) ASSERT_FALSE(checker.advance(0, h.point)) << kernel_name(k) << " ball " << i;
                ASSERT_FALSE(checker.advance(0, b.pos)) << kernel_name(k) << " ball " << i << " frame " << f;
            }
        }
    }
}

}  // namespace
}  // namespace ricochet
