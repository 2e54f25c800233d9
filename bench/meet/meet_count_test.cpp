// The exact counts of `ricochet bench meet` (meet_count.hpp) on pairs worked by hand: touching is not overlapping, a
// radius sum that doubles would round, two balls that cross within a frame, a tangent pass, a path that turns.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "meet_count.hpp"

namespace ricochet::meet_bench {
namespace {

TEST(MeetCount, TouchingIsNotCloser) {
    // |(3, 4)| = 5 = 2.5 + 2.5 exactly: touching; a radius one ulp larger makes it an overlap.
    EXPECT_FALSE(closer_than({0, 0}, {3, 4}, 2.5, 2.5));
    EXPECT_TRUE(closer_than({0, 0}, {3, 4}, 2.5, std::nextafter(2.5, 3.0)));
}

TEST(MeetCount, TheRadiusSumIsExact) {
    // S = 1 + 2^-60 rounds to 1 in doubles, which would call distance 1 touching; exactly, 1 < S.
    std::int64_t exact = 0;
    EXPECT_TRUE(closer_than({0, 0}, {1, 0}, 1.0, 0x1p-60, &exact));
    EXPECT_EQ(exact, 1);
}

TEST(MeetCount, BallsCrossingWithinAFramePassThrough) {
    // a from (−10, 0) to (10, 0), b from (10, 0.9) to (−10, 0.9), radii 0.5: closest at t = 1/2, 0.9 apart < S = 1;
    // 20.02 apart at both ends.
    const std::vector<PathPoint> a{{0, {-10, 0}}, {1, {10, 0}}};
    const std::vector<PathPoint> b{{0, {10, 0.9}}, {1, {-10, 0.9}}};
    EXPECT_TRUE(came_within(a, b, 0.5, 0.5));
    EXPECT_TRUE(pass_through(a, b, 0.5, 0.5));
    EXPECT_NEAR(least_distance(a, b), 0.9, 1e-12);  // in doubles: |D0|² − (D0·W)²/|W|² cancels
}

TEST(MeetCount, ATangentPassIsNoPassThrough) {
    // The same, 1 apart at closest (y = 1 is exact): a tangent, not within S; one ulp closer, within.
    const std::vector<PathPoint> a{{0, {-10, 0}}, {1, {10, 0}}};
    EXPECT_FALSE(came_within(a, std::vector<PathPoint>{{0, {10, 1}}, {1, {-10, 1}}}, 0.5, 0.5));
    const double y = std::nextafter(1.0, 0.0);
    EXPECT_TRUE(came_within(a, std::vector<PathPoint>{{0, {10, y}}, {1, {-10, y}}}, 0.5, 0.5));
}

TEST(MeetCount, ClearAtBothEndsIsRequired) {
    // b rests where a ends: they are within S at the frame's end, an overlap, not a pass-through.
    const std::vector<PathPoint> a{{0, {-10, 0}}, {1, {10, 0}}};
    const std::vector<PathPoint> b{{0, {10.5, 0}}, {1, {10.5, 0}}};
    EXPECT_TRUE(came_within(a, b, 0.5, 0.5));
    EXPECT_FALSE(pass_through(a, b, 0.5, 0.5));
}

TEST(MeetCount, APathThatTurnsIsFollowedNotItsChord) {
    // a goes to (5, 0) at t = 1/2 and back: it passes 0.8 from b at rest at (5, 0.8); its chord never moves.
    const std::vector<PathPoint> a{{0, {0, 0}}, {0.5, {5, 0}}, {1, {0, 0}}};
    const std::vector<PathPoint> b{{0, {5, 0.8}}, {1, {5, 0.8}}};
    EXPECT_TRUE(pass_through(a, b, 0.5, 0.5));
    const std::vector<PathPoint> chord{{0, {0, 0}}, {1, {0, 0}}};
    EXPECT_FALSE(came_within(chord, b, 0.5, 0.5));
}

TEST(MeetCount, TheCounterSumsOverFramesAndLeavesOutWhatMet) {
    // Two balls crossing head on in a box of side 40 each frame (chords), a third at rest far away.
    std::vector<Ball> balls{{{10, 20}, {10, 0}, 0.5}, {{20, 20.5}, {-10, 0}, 0.5}, {{35, 35}, {0, 0}, 0.5}};
    MeetCounter counter(40.0, balls);
    std::vector<Ball> end{{{20, 20}, {10, 0}, 0.5}, {{10, 20.5}, {-10, 0}, 0.5}, {{35, 35}, {0, 0}, 0.5}};
    counter.add({end, {}, {}, {}});
    EXPECT_EQ(counter.counts().pass_throughs, 1);
    EXPECT_DOUBLE_EQ(counter.counts().deepest, 0.5);  // 0.5 apart at closest, S = 1
    // Back again, the engine reporting them in contact: they met.
    const std::pair<std::uint32_t, std::uint32_t> met[] = {{0, 1}};
    counter.add({balls, {}, met, {}});
    EXPECT_EQ(counter.counts().pass_throughs, 1);
    // Across again, ball 0 having touched something: its chord may not be its path.
    const std::uint8_t touched[] = {1, 0, 0};
    counter.add({end, {}, {}, touched});
    EXPECT_EQ(counter.counts().pass_throughs, 1);
    EXPECT_EQ(counter.counts().unsure, 1);
    EXPECT_EQ(counter.counts().overlaps, 0);
    EXPECT_EQ(counter.counts().energy_drift, 0.0);
    // Ball 2 outside the box for two frames and overlapping ball 0: one ball escaped, one overlap a frame.
    std::vector<Ball> out = end;
    out[2] = {{40.25, 20}, {0, 0}, 0.5};
    out[0].pos = {40.25, 20.5};
    counter.add({out, {}, {}, {}});
    counter.add({out, {}, {}, {}});
    EXPECT_EQ(counter.counts().escaped, 2);  // balls 0 and 2, each counted once
    EXPECT_EQ(counter.counts().overlaps, 2);
}

TEST(MeetCount, BoxPairsFindsOverlappingBoxesOnly) {
    // Boxes 0 and 1 overlap; 2 is apart along x, 3 along y from 1 and along x from 0 (closed boxes: touching counts).
    const std::vector<Vec2> lo{{0, 0}, {1, 1}, {5, 0}, {0.5, 3}};
    const std::vector<Vec2> hi{{2, 2}, {3, 3}, {6, 1}, {0.9, 4}};
    const auto pairs = box_pairs(lo, hi);
    ASSERT_EQ(pairs.size(), 1u);
    EXPECT_EQ(pairs[0], (std::pair<std::uint32_t, std::uint32_t>{0, 1}));
}

}  // namespace
}  // namespace ricochet::meet_bench
