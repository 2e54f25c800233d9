// The exact kernel at a corner whose second reflection leaves v' exactly parallel to the wall hit: the
// ball slides along that wall's line (the contact stays while it is on the closed segment, and is still
// there when a later leg hits another wall), and the rounded v' is moved by an ulp so that it points
// strictly back to the side the hit came from (kernel.hpp, exact). Every expectation is worked by hand:
// the corner is the origin, the reflections are of small integers, the frame times are tenths.
#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "ricochet/kernel.hpp"
#include "ricochet/step_trace.hpp"

namespace ricochet {
namespace {

constexpr double tiny = std::numeric_limits<double>::denorm_min();

struct Stepped {
    Ball ball;
    BallMemory memory;
    std::vector<HitEvent> hits;
    int reflections = 0;
};

Stepped step_exact(const std::vector<Wall>& walls, Ball ball) {
    Stepped out{ball, {}, {}, 0};
    StepTrace trace;
    StepScratch scratch;
    scratch.trace = &trace;
    EXPECT_EQ(step_ball(KernelId::exact, out.ball, out.memory, walls, out.hits, scratch), FrameStatus::ok);
    EXPECT_FALSE(trace.legs_traced);  // the exact kernel's legs are rational: reflections only
    out.reflections = trace.reflections;
    return out;
}

// Floor A = wall 0 along y = 0 and B = wall 1 from the origin along (−1, 2). The ball from (−1.5, 2)
// moving (3, −4) meets both at the origin at t = 1/2, from side −1 of each (A: n = (0, −e_x), above
// it; B: n = (2, 1), BC = −3 + 2 = −1). Off A: (3, 4), which points through B (n·w = 10), so off B:
// (3, 4) − 2·10/5·(2, 1) = (−5, 0), parallel to A: no wall is crossed, v' = (−5, 0). The ball slides
// along A's line for the rest of the frame to (−2.5, 0). v' rounded does not point strictly back
// above A (n·v' = 0), so v'.y moves one ulp towards that side: the smallest subnormal. v'.x stays, as
// A's normal has no x component.
TEST(ExactCorner, AParallelSecondReflectionSlidesAlongTheWallHitAndKeepsItsContact) {
    const std::vector<Wall> walls = {{{-5, 0}, {5, 0}}, {{0, 0}, {-1, 2}}};
    const Stepped s = step_exact(walls, {{-1.5, 2}, {3, -4}});
    ASSERT_EQ(s.hits.size(), 1u);
    EXPECT_EQ(s.hits[0].wall, 0u);
    EXPECT_EQ(s.hits[0].t, 0.5);
    EXPECT_EQ(s.hits[0].point, (Vec2{0, 0}));
    EXPECT_EQ(s.reflections, 2);
    EXPECT_EQ(s.ball.pos, (Vec2{-2.5, 0}));
    EXPECT_EQ(s.ball.vel, (Vec2{-5, tiny}));
    // Still on A's closed segment: the contact stays, with the side the ball first met it from.
    ASSERT_EQ(s.memory.count, 1);
    EXPECT_EQ(s.memory.contacts[0].wall, 0u);
    EXPECT_EQ(s.memory.contacts[0].side, -1);
    EXPECT_EQ(s.memory.bounced_wall, 0u);
    EXPECT_EQ(s.memory.bounced_from, -1);
}

TEST(ExactCorner, WalkedTheOtherWayTheFloorIsMetFromItsOtherSide) {
    // A from (5, 0) to (−5, 0): n = (0, 10), the ball above it is on side +1. The same bounces and end;
    // the nudge is still upwards, towards side +1.
    const std::vector<Wall> walls = {{{5, 0}, {-5, 0}}, {{0, 0}, {-1, 2}}};
    const Stepped s = step_exact(walls, {{-1.5, 2}, {3, -4}});
    EXPECT_EQ(s.ball.pos, (Vec2{-2.5, 0}));
    EXPECT_EQ(s.ball.vel, (Vec2{-5, tiny}));
    ASSERT_EQ(s.memory.count, 1);
    EXPECT_EQ(s.memory.contacts[0].side, 1);
    EXPECT_EQ(s.memory.bounced_from, 1);
}

TEST(ExactCorner, SlidingPastEitherEndOfTheWallDropsTheContact) {
    // A from (−2, 0) to (5, 0): the slide ends at (−2.5, 0), on A's line before P0.
    {
        const std::vector<Wall> walls = {{{-2, 0}, {5, 0}}, {{0, 0}, {-1, 2}}};
        const Stepped s = step_exact(walls, {{-1.5, 2}, {3, -4}});
        EXPECT_EQ(s.ball.pos, (Vec2{-2.5, 0}));
        EXPECT_EQ(s.ball.vel, (Vec2{-5, tiny}));
        EXPECT_EQ(s.memory.count, 0);
        EXPECT_EQ(s.memory.bounced_from, -1);
    }
    // Mirrored, with A from (−5, 0) to (2, 0) and B along (1, 2): the ball from (1.5, 2) moving (−3, −4);
    // off A (−3, 4), off B (n = (2, −1), the ball on side +1, n·w = −10): (−3, 4) + 4·(2, −1) = (5, 0). The
    // slide ends at (2.5, 0), past P1.
    {
        const std::vector<Wall> walls = {{{-5, 0}, {2, 0}}, {{0, 0}, {1, 2}}};
        const Stepped s = step_exact(walls, {{1.5, 2}, {-3, -4}});
        ASSERT_EQ(s.hits.size(), 1u);
        EXPECT_EQ(s.hits[0].point, (Vec2{0, 0}));
        EXPECT_EQ(s.ball.pos, (Vec2{2.5, 0}));
        EXPECT_EQ(s.ball.vel, (Vec2{5, tiny}));
        EXPECT_EQ(s.memory.count, 0);
    }
}

TEST(ExactCorner, OnAVerticalWallTheNudgeMovesVx) {
    // The first test mirrored across y = x: A along x = 0, B from the origin along (2, −1), the ball from
    // (2, −1.5) moving (−4, 3), on side +1 of both (A: n = (10, 0); B: n = (−1, −2), BC = −2 + 3 = 1).
    // Off A: (4, 3); n_B·w = −10 = −side, so off B: (4, 3) + 4·(−1, −2) = (0, −5). The nudge is along A's
    // normal (1, 0): v'.x becomes the smallest subnormal, v'.y stays.
    for (const double p0y : {-5.0, -2.0}) {
        // A from (0, −5) keeps the contact at (0, −2.5); from (0, −2) the slide ends past it.
        const std::vector<Wall> walls = {{{0, p0y}, {0, 5}}, {{0, 0}, {2, -1}}};
        const Stepped s = step_exact(walls, {{2, -1.5}, {-4, 3}});
        ASSERT_EQ(s.hits.size(), 1u);
        EXPECT_EQ(s.hits[0].wall, 0u);
        EXPECT_EQ(s.hits[0].point, (Vec2{0, 0}));
        EXPECT_EQ(s.ball.pos, (Vec2{0, -2.5}));
        EXPECT_EQ(s.ball.vel, (Vec2{tiny, -5}));
        EXPECT_EQ(s.memory.count, p0y == -5.0 ? 1 : 0) << p0y;
    }
}

TEST(ExactCorner, ALaterHitOnTheSlideKeepsTheWallSlidAlong) {
    // The first test with wall C = 2 along x = −2 from (−2, −1) to (−2, 1): sliding at (−5, 0) from the
    // origin (t = 1/2) the ball hits C at (−2, 0) at t = 1/2 + 2/5 = 9/10, still on A's segment, so A stays a
    // contact there. Off C: (5, 0), parallel to A again; for the last tenth it moves to (−1.5, 0). C was met
    // from side +1 (n = (2, 0), x > −2) and (5, 0) points to it: no nudge.
    const std::vector<Wall> walls = {{{-5, 0}, {5, 0}}, {{0, 0}, {-1, 2}}, {{-2, -1}, {-2, 1}}};
    const Stepped s = step_exact(walls, {{-1.5, 2}, {3, -4}});
    ASSERT_EQ(s.hits.size(), 2u);
    EXPECT_EQ(s.hits[0].wall, 0u);
    EXPECT_EQ(s.hits[1].wall, 2u);
    EXPECT_EQ(s.hits[1].t, 0.9);  // the double nearest 9/10
    EXPECT_EQ(s.hits[1].point, (Vec2{-2, 0}));
    EXPECT_EQ(s.reflections, 3);
    EXPECT_EQ(s.ball.pos, (Vec2{-1.5, 0}));
    EXPECT_EQ(s.ball.vel, (Vec2{5, 0}));
    ASSERT_EQ(s.memory.count, 1);
    EXPECT_EQ(s.memory.contacts[0].wall, 0u);
    EXPECT_EQ(s.memory.contacts[0].side, -1);
    EXPECT_EQ(s.memory.bounced_wall, 2u);
    EXPECT_EQ(s.memory.bounced_from, 1);
}

TEST(ExactReflect, AZeroLengthWallLeavesTheVelocityAsItIs) {
    // kernel.hpp: a zero-length wall has no normal; exact's reflect returns v (rounded: v itself).
    const Wall dot{{2, 3}, {2, 3}};
    EXPECT_EQ(reflect(KernelId::exact, {1.5, -2}, dot), (Vec2{1.5, -2}));
    EXPECT_EQ(reflect(KernelId::exact, {0x1p-1074, -0x1p200}, dot), (Vec2{0x1p-1074, -0x1p200}));
    // A real wall for contrast: x = 0 flips vx.
    EXPECT_EQ(reflect(KernelId::exact, {1.5, -2}, Wall{{0, 0}, {0, 1}}), (Vec2{-1.5, -2}));
}

}  // namespace
}  // namespace ricochet
