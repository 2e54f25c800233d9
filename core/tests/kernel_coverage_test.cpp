// The kernel registry's names, step_ball's range guard on every field, and the robust kernel's
// degenerate constructions (a zero-length wall's reflection, a crossing whose BC values underflow).
#include <gtest/gtest.h>

#include <vector>

#include "ricochet/kernel.hpp"

namespace ricochet {
namespace {

TEST(KernelNames, EveryMissHasItsName) {
    EXPECT_EQ(miss_name(Miss::none), "hit");
    EXPECT_EQ(miss_name(Miss::both_inside), "both-inside");
    EXPECT_EQ(miss_name(Miss::both_outside), "both-outside");
    EXPECT_EQ(miss_name(Miss::parallel), "parallel");
    EXPECT_EQ(miss_name(Miss::before_p0), "before-p0");
    EXPECT_EQ(miss_name(Miss::past_p1), "past-p1");
    EXPECT_EQ(miss_name(Miss::degenerate), "degenerate");
    EXPECT_EQ(miss_name(Miss::leaving), "leaving");
    EXPECT_EQ(miss_name(static_cast<Miss>(200)), "?");
}

TEST(KernelNames, AnIdNothingIsRegisteredAtHasNoName) {
    EXPECT_EQ(kernel_name(static_cast<KernelId>(k_max_kernels - 1)), "?");
    EXPECT_EQ(kernel_name(KernelId::exact), "exact");
    EXPECT_FALSE(parse_kernel("?"));
}

TEST(StepBallRange, AnyFieldOutOfRangeStopsTheBallBeforeItMoves) {
    // Each of x, y, vx, vy past 2^256 (or not finite) in turn: the ball and its memory stay as they were.
    const std::vector<Ball> outside = {{{0x1p257, 0}, {1, 1}},
                                       {{0, -0x1p257}, {1, 1}},
                                       {{0, 0}, {0x1p257, 1}},
                                       {{0, 0}, {1, NAN}}};
    const std::vector<Wall> walls = {{{1, -1}, {1, 1}}};
    for (const Ball& start : outside) {
        Ball b = start;
        BallMemory memory;
        std::vector<HitEvent> hits;
        StepScratch scratch;
        EXPECT_EQ(step_ball(KernelId::robust, b, memory, walls, hits, scratch, nullptr), FrameStatus::out_of_range);
        EXPECT_EQ(b.pos, start.pos);
        EXPECT_TRUE(hits.empty());
    }
}

TEST(StepBallRange, AFrameThatWouldLeaveTheRangeTakesBackItsHits) {
    // From (0, 2^250) moving (4, 2^256): the leg meets the wall x = 1 at s = 1/4 (a hit at
    // (1, 2^250 + 2^254)); the wall is vertical, so y still moves by 2^256 over the frame and ends at
    // 2^256 + 2^250, past the range: the hit is dropped and the ball keeps its state.
    const std::vector<Wall> walls = {{{1, -0x1p256}, {1, 0x1p256}}};
    Ball b{{0, 0x1p250}, {4, 0x1p256}};
    const Ball start = b;
    BallMemory memory;
    std::vector<HitEvent> hits = {{7, 0.25, {3, 4}}};  // an earlier ball's hit stays
    StepScratch scratch;
    EXPECT_EQ(step_ball(KernelId::robust, b, memory, walls, hits, scratch, nullptr), FrameStatus::out_of_range);
    EXPECT_EQ(b, start);
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_EQ(hits[0].wall, 7u);
}

TEST(RobustConstruction, AZeroLengthWallReflectsNothing) {
    const Wall dot{{2, 3}, {2, 3}};
    EXPECT_EQ(reflect(KernelId::robust, {1.5, -2}, dot), (Vec2{1.5, -2}));
    // A real wall for contrast: x = 0 flips vx.
    EXPECT_EQ(reflect(KernelId::robust, {1.5, -2}, Wall{{0, 0}, {0, 1}}), (Vec2{-1.5, -2}));
}

TEST(RobustConstruction, ACrossingWhoseBcValuesUnderflowIsTakenAtTheLegsStart) {
    // The wall (0, 0) → (2^-600, 0) and the leg (2^-601, 2^-600) → (2^-601, −2^-600) cross at the
    // wall's midpoint: the exact decision says hit. BC(q) = −2^-1200 and BC(b) = 2^-1200 round to ∓0, so
    // s = 0/0 is not finite and the crossing is taken at s = 0, the leg's start.
    const Wall w{{0, 0}, {0x1p-600, 0}};
    const Vec2 bs{0x1p-601, 0x1p-600}, v{0, -0x1p-599};
    const Sweep s = sweep(KernelId::robust, bs, v, w);
    ASSERT_TRUE(s.hit()) << miss_name(s.miss);
    EXPECT_EQ(s.t, 0.0);
    EXPECT_EQ(s.point, bs);
    // The exact kernel constructs the true crossing, halfway.
    const Sweep e = sweep(KernelId::exact, bs, v, w);
    ASSERT_TRUE(e.hit());
    EXPECT_EQ(e.t, 0.5);
    EXPECT_EQ(e.point, (Vec2{0x1p-601, 0}));
}

}  // namespace
}  // namespace ricochet
