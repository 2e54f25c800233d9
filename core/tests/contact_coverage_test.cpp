// Contacts (BallMemory) in robust's and exact's step_ball: a leg through a contact wall bounces off it
// without a hit, a hit point rounded onto a contact's far side is walked back, a slide along a contact's
// line keeps it only on the closed segment, an end point on the far side of the wall last bounced off
// is walked back while a contact is held, and a point where more walls meet than BallMemory holds is
// never printed. The states are ones a kernel leaves (the ball on the contact's segment, on the near
// side of the wall it bounced off); expectations worked by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ricochet/kernel.hpp"
#include "ricochet/step_trace.hpp"
#include "ricochet/truth.hpp"

namespace ricochet {
namespace {

struct Stepped {
    Ball ball;
    BallMemory memory;
    std::vector<HitEvent> hits;
    StepTrace trace;
};

Stepped step(KernelId k, const std::vector<Wall>& walls, Ball ball, BallMemory memory) {
    Stepped out{ball, memory, {}, {}};
    StepScratch scratch;
    scratch.trace = &out.trace;
    EXPECT_EQ(step_ball(k, out.ball, out.memory, walls, out.hits, scratch), FrameStatus::ok) << kernel_name(k);
    return out;
}

BallMemory touching(std::uint32_t wall, std::int8_t side) {
    BallMemory m;
    m.contacts[0] = {wall, side};
    m.count = 1;
    return m;
}

// Wall C = 0 along x = 1.5 from (1.5, −1) to (1.5, 1): n = (2, 0), so x > 1.5 is side +1. The ball lies
// on it at (1.5, 0.5), having arrived from side +1.
const std::vector<Wall> k_post = {{{1.5, -1}, {1.5, 1}}};

TEST(Contacts, ALegThroughAContactWallBouncesOffItWithoutAHit) {
    // Moving (−1, 0) would end at (0.5, 0.5) on side −1: both kernels reflect v off C instead, (1, 0), count
    // one reflection and print no hit; the rest of the frame takes the ball to (2.5, 0.5), off C's line.
    for (const KernelId k : {KernelId::robust, KernelId::exact}) {
        const Stepped s = step(k, k_post, {{1.5, 0.5}, {-1, 0}}, touching(0, 1));
        EXPECT_TRUE(s.hits.empty()) << kernel_name(k);
        EXPECT_EQ(s.trace.reflections, 1) << kernel_name(k);
        EXPECT_EQ(s.ball.pos, (Vec2{2.5, 0.5})) << kernel_name(k);
        EXPECT_EQ(s.ball.vel, (Vec2{1, 0})) << kernel_name(k);
        EXPECT_EQ(s.memory.count, 0) << kernel_name(k);
    }
    // robust traces the blocked leg: from the ball to the end it would have had.
    const Stepped r = step(KernelId::robust, k_post, {{1.5, 0.5}, {-1, 0}}, touching(0, 1));
    ASSERT_FALSE(r.trace.legs.empty());
    EXPECT_TRUE(r.trace.legs[0].blocked);
    EXPECT_EQ(r.trace.legs[0].blocked_wall, 0u);
    EXPECT_EQ(r.trace.legs[0].to, (Vec2{0.5, 0.5}));
}

TEST(Contacts, ASlideAlongTheContactsLineKeepsItOnlyOnTheClosedSegment) {
    for (const KernelId k : {KernelId::robust, KernelId::exact}) {
        // Up by 0.25 to (1.5, 0.75): still on C's segment, the contact stays with its side.
        const Stepped on = step(k, k_post, {{1.5, 0.5}, {0, 0.25}}, touching(0, 1));
        EXPECT_EQ(on.ball.pos, (Vec2{1.5, 0.75})) << kernel_name(k);
        ASSERT_EQ(on.memory.count, 1) << kernel_name(k);
        EXPECT_EQ(on.memory.contacts[0].side, 1) << kernel_name(k);
        // Up by 1 to (1.5, 1.5): on C's line past P1, so the ball lies on no wall.
        const Stepped off = step(k, k_post, {{1.5, 0.5}, {0, 1}}, touching(0, 1));
        EXPECT_EQ(off.ball.pos, (Vec2{1.5, 1.5})) << kernel_name(k);
        EXPECT_TRUE(off.hits.empty()) << kernel_name(k);
        EXPECT_EQ(off.memory.count, 0) << kernel_name(k);
    }
}

TEST(Contacts, AnEndOnTheFarSideOfTheWallLastBouncedOffIsWalkedBackWhileAContactIsHeld) {
    // Walls K = 0 from (0, 0) to (1, 0) (n = (0, −1): y > 0 is side −1), bounced off last from side −1,
    // and C = 1 as above, the ball on it from side +1. Moving (0.5, −1) the leg (1.5, 0.5) → (2, −0.5) meets
    // no wall (it crosses K's line at x = 1.75, past P1) but ends below K's line, on K's far side: the end
    // is walked back. Every step of the walk short of half the piece is still below the line (y =
    // −0.5 + g, g < 1/2); half the piece is (1.75, 0), on K's line (side 0), which is allowed. It lies on
    // neither wall's closed segment, so the memory is empty; v is unchanged.
    const std::vector<Wall> walls = {{{0, 0}, {1, 0}}, {{1.5, -1}, {1.5, 1}}};
    BallMemory before = touching(1, 1);
    before.bounced_wall = 0;
    before.bounced_from = -1;
    for (const KernelId k : {KernelId::robust, KernelId::exact}) {
        const Stepped s = step(k, walls, {{1.5, 0.5}, {0.5, -1}}, before);
        EXPECT_TRUE(s.hits.empty()) << kernel_name(k);
        EXPECT_EQ(s.ball.pos, (Vec2{1.75, 0})) << kernel_name(k);
        EXPECT_EQ(s.ball.vel, (Vec2{0.5, -1})) << kernel_name(k);
        EXPECT_EQ(s.memory.count, 0) << kernel_name(k);
        EXPECT_EQ(s.memory.bounced_wall, 0u) << kernel_name(k);
        EXPECT_EQ(s.memory.bounced_from, -1) << kernel_name(k);
    }
}

TEST(Contacts, AHitPointRoundedAcrossTheContactsLineIsWalkedBack) {
    // The ball on C from (0, 0) to (3, 1), leaving it at a grazing angle to side −1 (v a few ulps off C's
    // direction), hits the vertical wall K at x = X. The crossing is exactly on side −1 of C, but q + t·d
    // rounded lands on side +1, the far side of the contact (found by a seeded search): robust must walk
    // it back, to a point on C's line or its near side, within a few ulps of the rounded one.
    const Wall c{{0, 0}, {3, 1}};
    const double x = 0x1.032c93803a199p-1;
    const std::vector<Wall> walls = {{{x, -10}, {x, 10}}, c};
    const Vec2 v{0x1.c851ee5f27cbp+0, 0x1.30369eea1a876p-1};
    ASSERT_EQ(truth::side(v, c), -1);  // b = q + v is on side −1
    const Sweep sw = sweep(KernelId::robust, {0, 0}, v, walls[0]);
    ASSERT_TRUE(sw.hit());
    const Vec2 rounded = sw.t * v;
    ASSERT_EQ(truth::side(rounded, c), 1);  // the naive point is on the far side
    const Stepped s = step(KernelId::robust, walls, {{0, 0}, v}, touching(1, -1));
    ASSERT_EQ(s.hits.size(), 1u);
    EXPECT_EQ(s.hits[0].wall, 0u);
    EXPECT_NE(truth::side(s.hits[0].point, c), 1);
    EXPECT_NE(s.hits[0].point, rounded);
    EXPECT_LE(std::fabs(s.hits[0].point.x - rounded.x), 0x1p-48);
    EXPECT_LE(std::fabs(s.hits[0].point.y - rounded.y), 0x1p-48);
}

TEST(Contacts, APointWhereFiveWallsMeetIsNeverPrinted) {
    // Walls 0..3 from the origin to (0, 1), (1, 1), (0, −1), (1, −1), and wall 4 along y = 0 from (−2, 0)
    // to (2, 0), which the ball lies on (from side −1, above). Moving (1, 0) from (−1, 0) the leg ends at
    // the origin on walls 0..3, a hit of all four at t = 1 (wall 0 reported, the lowest). Arriving there
    // the ball would lie on five walls, one more than BallMemory holds, so the point is walked back
    // along the piece: robust's first step is one ulp of M = 1 (g = 2^-52), exact's a fixed 2^-50 of
    // the piece. Off wall 0 (n = (1, 0)) v' = (−1, 0), which crosses no other wall; the frame is over.
    const std::vector<Wall> walls = {{{0, 0}, {0, 1}}, {{0, 0}, {1, 1}}, {{0, 0}, {0, -1}}, {{0, 0}, {1, -1}},
                                     {{-2, 0}, {2, 0}}};
    for (const KernelId k : {KernelId::robust, KernelId::exact}) {
        const Stepped s = step(k, walls, {{-1, 0}, {1, 0}}, touching(4, -1));
        const double back = k == KernelId::robust ? 0x1p-52 : 0x1p-50;
        ASSERT_EQ(s.hits.size(), 1u) << kernel_name(k);
        EXPECT_EQ(s.hits[0].wall, 0u) << kernel_name(k);
        EXPECT_EQ(s.hits[0].t, 1.0) << kernel_name(k);
        EXPECT_EQ(s.hits[0].point, (Vec2{-back, 0})) << kernel_name(k);
        EXPECT_EQ(s.ball.vel, (Vec2{-1, 0})) << kernel_name(k);
        // The slide along wall 4 keeps it as a contact, with its old side; walls 0..3 are not reached.
        ASSERT_EQ(s.memory.count, 1) << kernel_name(k);
        EXPECT_EQ(s.memory.contacts[0].wall, 4u) << kernel_name(k);
        EXPECT_EQ(s.memory.contacts[0].side, -1) << kernel_name(k);
        EXPECT_EQ(s.memory.bounced_wall, 0u) << kernel_name(k);
        EXPECT_EQ(s.memory.bounced_from, -1) << kernel_name(k);
    }
    // robust ends the frame at its hit point (t = 1). exact rounds the frame's exact end (the origin
    // again) and walks that piece back too: from −2^-50 by 2^-50 of its length, to −2^-100.
    EXPECT_EQ(step(KernelId::robust, walls, {{-1, 0}, {1, 0}}, touching(4, -1)).ball.pos, (Vec2{-0x1p-52, 0}));
    EXPECT_EQ(step(KernelId::exact, walls, {{-1, 0}, {1, 0}}, touching(4, -1)).ball.pos, (Vec2{-0x1p-100, 0}));
}

}  // namespace
}  // namespace ricochet
