// The peer kernels (peers/): registered once by name, each answer the peer's own on hand-worked cases,
// the frame loop (the index, the bounce limit, no query for a ball at rest), and the trace the checks read.
// A peer this build lacks is skipped, after checking that its name is refused with why.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ricochet/kernel.hpp"
#include "ricochet/step_trace.hpp"
#include "ricochet_peers/peers.hpp"

namespace ricochet {
namespace {

/// The closed box [0, 10]²: 0 left, 1 bottom, 2 right, 3 top, each normal pointing out.
std::vector<Wall> box() { return {{{0, 10}, {0, 0}}, {{0, 0}, {10, 0}}, {{10, 0}, {10, 10}}, {{10, 10}, {0, 10}}}; }

struct Stepped {
    Ball ball;
    std::vector<HitEvent> hits;
    FrameStatus status;
};

Stepped step(KernelId k, Ball b, const std::vector<Wall>& walls, StepTrace* trace = nullptr,
             const WallIndex* index = nullptr) {
    BallMemory memory;
    StepScratch scratch;
    scratch.trace = trace;
    std::vector<HitEvent> hits;
    const FrameStatus st = step_ball(k, b, memory, walls, hits, scratch, index);
    return {b, hits, st};
}

/// An index that offers no wall at all.
class NoWalls final : public WallIndex {
public:
    void query(Vec2, Vec2, std::vector<std::uint32_t>&) const override {}
    void query_near(Vec2, Vec2, double, std::vector<std::uint32_t>&) const override {}
};

class Peer : public ::testing::TestWithParam<std::string> {
protected:
    void SetUp() override {
        peers::register_peer_kernels();
        const auto k = parse_kernel(GetParam());
        if (!k) {
            // Not built in: the name is refused with why, never as an unknown kernel.
            const auto why = absent_kernel_message(GetParam());
            ASSERT_TRUE(why.has_value()) << GetParam() << " is neither registered nor noted absent";
            GTEST_SKIP() << *why;
        }
        k_ = *k;
    }
    bool box2d() const { return GetParam() == "box2d"; }
    KernelId k_{};
};
INSTANTIATE_TEST_SUITE_P(Peers, Peer, ::testing::Values("box2d", "chipmunk"),
                         [](const auto& info) { return info.param; });

TEST(PeerRegistry, RegisteringTwiceRegistersOnce) {
    peers::register_peer_kernels();
    const std::size_t n = registered_kernels().size();
    peers::register_peer_kernels();
    EXPECT_EQ(registered_kernels().size(), n);
    for (const char* name : {"box2d", "chipmunk"})
        EXPECT_TRUE(parse_kernel(name).has_value() != absent_kernel_message(name).has_value()) << name;
}

TEST_P(Peer, StatesItsBoundsAndDocumentsItsFailures) {
    const KernelOps& ops = kernel_ops(k_);
    EXPECT_TRUE(ops.failures_documented);
    // Box2D in float: 2^-18 and 2^-144; Chipmunk in double: 2^-47 and robust's 2^-1068 (the derivations are
    // above each kernel's constants).
    EXPECT_EQ(ops.speed_rel_bound, box2d() ? 0x1p-18 : 0x1p-47);
    EXPECT_EQ(ops.speed_abs_bound, box2d() ? 0x1p-144 : 0x1p-1068);
    EXPECT_NE(kernel_names().find(GetParam()), std::string::npos);
}

TEST_P(Peer, ThePinballBouncesAndSpendsTheRestOfTheFrame) {
    // Bs = (8, 5), v = (4, 1): the right wall is met at t = 0.5, (10, 5.5), exactly in float and double; the
    // normal the peer returns, (−1, 0), reflects v to (−4, 1); the rest, (−2, 0.5), ends at (8, 6).
    const Stepped s = step(k_, {{8, 5}, {4, 1}}, box());
    ASSERT_EQ(s.hits.size(), 1u);
    EXPECT_EQ(s.hits[0].wall, 2u);
    EXPECT_EQ(s.hits[0].t, 0.5);
    EXPECT_EQ(s.hits[0].point, (Vec2{10, 5.5}));
    EXPECT_EQ(s.ball, (Ball{{8, 6}, {-4, 1}}));
    EXPECT_EQ(s.status, FrameStatus::ok);
}

TEST_P(Peer, TheTraceHoldsTheLegsAsSweptAndEachDecision) {
    StepTrace trace;
    const Stepped traced = step(k_, {{8, 5}, {4, 1}}, box(), &trace);
    // The trace changes nothing.
    EXPECT_EQ(traced.ball, step(k_, {{8, 5}, {4, 1}}, box()).ball);
    ASSERT_EQ(trace.legs.size(), 2u);
    const TracedLeg& first = trace.legs[0];
    EXPECT_EQ(first.from, (Vec2{8, 5}));
    EXPECT_EQ(first.to, (Vec2{12, 6}));
    EXPECT_EQ(first.vel, (Vec2{4, 1}));
    EXPECT_EQ(first.hit, 2u);
    EXPECT_EQ(first.hit_t, 0.5);
    EXPECT_FALSE(first.skipped.has_value());
    ASSERT_EQ(first.decision_count, 4u);
    // Left wall: the peer said "no hit", and gives no reason. Right: hit.
    EXPECT_EQ(trace.decisions[first.first_decision + 0].miss, Miss::no_reason);
    EXPECT_EQ(trace.decisions[first.first_decision + 2].miss, Miss::none);
    // The rest of the frame: from the hit point, every wall but the one bounced off.
    const TracedLeg& rest = trace.legs[1];
    EXPECT_EQ(rest.from, (Vec2{10, 5.5}));
    EXPECT_EQ(rest.to, (Vec2{8, 6}));
    EXPECT_EQ(rest.vel, (Vec2{-4, 1}));
    EXPECT_EQ(rest.skipped, 2u);
    EXPECT_EQ(rest.decision_count, 3u);
    EXPECT_FALSE(rest.hit.has_value());
    EXPECT_EQ(trace.reflections, 1);
}

TEST_P(Peer, ALegEndingOnTheWall) {
    // (8, 5) moving (2, 0) ends exactly on the right wall: a hit at t = 1 by the conventions. Box2D takes it
    // (t ≤ maxFraction); Chipmunk does not (its test ad·bd < 0 is strict): "no hit", without a reason.
    const Sweep s = sweep(k_, {8, 5}, {2, 0}, box()[2]);
    if (box2d()) {
        EXPECT_EQ(s.miss, Miss::none);
        EXPECT_EQ(s.t, 1.0);
        EXPECT_EQ(s.point, (Vec2{10, 5}));
    } else {
        EXPECT_EQ(s.miss, Miss::no_reason);
    }
}

TEST_P(Peer, AMissHasNoReason) {
    // A peer answers hit or no hit: every miss is Miss::no_reason, which the oracle judges as a miss.
    const Wall w = box()[2];
    EXPECT_EQ(sweep(k_, {8, 5}, {1, 0}, w).miss, Miss::no_reason);
    EXPECT_EQ(sweep(k_, {12, 5}, {1, 0}, w).miss, Miss::no_reason);
    EXPECT_EQ(sweep(k_, {8, 12}, {4, 0}, w).miss, Miss::no_reason);
    // A ball that does not move makes no query: no hit.
    EXPECT_EQ(sweep(k_, {10, 5}, {0, 0}, w).miss, Miss::no_reason);
    // And a leg that crosses the wall is a hit.
    EXPECT_EQ(sweep(k_, {8, 5}, {4, 0}, w).miss, Miss::none);
}

TEST_P(Peer, ClassifiesInItsOwnPrecision) {
    // 1e-50 below the wall's line: float holds it as 0 (Box2D says on); Chipmunk's double keeps it (inside).
    const Wall w{{0, 0}, {1, 0}};
    EXPECT_EQ(classify(k_, {0.5, -1e-50}, w), box2d() ? Side::on : Side::outside);
    EXPECT_EQ(classify(k_, {0.5, 1}, w), Side::inside);
    EXPECT_EQ(classify(k_, {0.5, 0}, w), Side::on);
}

TEST_P(Peer, TheStaticTests) {
    // Touching circles: Box2D's b2CollideCircles collides at distance² = (rA + rB)²; Chipmunk's circle pair
    // test is strict (distance² < (rA + rB)²), so touching is no collision there.
    EXPECT_EQ(circles_overlap(k_, {{0, 0}, 1}, {{2, 0}, 1}), box2d());
    EXPECT_TRUE(circles_overlap(k_, {{0, 0}, 1}, {{1.5, 0}, 1}));
    EXPECT_FALSE(circles_overlap(k_, {{0, 0}, 1}, {{3, 0}, 1}));
    EXPECT_TRUE(point_in_circle(k_, {1, 0}, {{0, 0}, 1}));
    EXPECT_FALSE(point_in_circle(k_, {1.5, 0}, {{0, 0}, 1}));
    EXPECT_TRUE(point_in_rect(k_, {0, 0}, {0, 0, 1, 1}));
    EXPECT_FALSE(point_in_rect(k_, {1.5, 0}, {0, 0, 1, 1}));
    EXPECT_TRUE(rects_overlap(k_, {0, 0, 1, 1}, {1, 0, 2, 1}));
    EXPECT_FALSE(rects_overlap(k_, {0, 0, 1, 1}, {1.5, 0, 2, 1}));
}

TEST_P(Peer, ReflectsAboutTheWallsNormal) {
    EXPECT_EQ(reflect(k_, {1, -1}, {{0, 0}, {4, 0}}), (Vec2{1, 1}));
    EXPECT_EQ(reflect(k_, {3, 2}, {{0, 0}, {0, 2}}), (Vec2{-3, 2}));
}

TEST_P(Peer, StartingOnAWall) {
    // On the right wall, moving out. Box2D's ray starts on the edge: a hit at fraction 0, the normal facing the
    // ray, so the ball bounces back into the box. Chipmunk's query finds the start on the segment first and
    // returns early: a hit at alpha 0 with a zero normal (cpvnormalize of a zero vector) and, as the point, the
    // query's end, which it never overwrote. So v is unchanged, the ball jumps to (11, 5) and spends the whole
    // frame from there.
    const Stepped s = step(k_, {{10, 5}, {1, 0}}, box());
    ASSERT_EQ(s.hits.size(), 1u);
    EXPECT_EQ(s.hits[0].wall, 2u);
    EXPECT_EQ(s.hits[0].t, 0.0);
    EXPECT_EQ(s.hits[0].point, box2d() ? (Vec2{10, 5}) : (Vec2{11, 5}));
    EXPECT_EQ(s.ball, box2d() ? (Ball{{9, 5}, {-1, 0}}) : (Ball{{12, 5}, {1, 0}}));
}

TEST_P(Peer, ABallAtRestMakesNoQuery) {
    // Resting on the right wall: nothing is cast, so nothing is hit (Chipmunk's query would report the wall).
    StepTrace trace;
    const Stepped s = step(k_, {{10, 5}, {0, 0}}, box(), &trace);
    EXPECT_TRUE(s.hits.empty());
    EXPECT_EQ(s.ball, (Ball{{10, 5}, {0, 0}}));
    ASSERT_EQ(trace.legs.size(), 1u);
    EXPECT_EQ(trace.legs[0].decision_count, 0u);
}

TEST_P(Peer, UsesTheIndexItIsGiven) {
    // An index that offers no wall: the ball goes straight through the right wall.
    const NoWalls none;
    const Stepped s = step(k_, {{8, 5}, {4, 1}}, box(), nullptr, &none);
    EXPECT_TRUE(s.hits.empty());
    EXPECT_EQ(s.ball.pos, (Vec2{12, 6}));
}

TEST_P(Peer, StopsAtTheBounceLimit) {
    // Between x = 0 and x = 1, moving 100 a frame: 16 bounces taken, the 17th found, the ball left at the 16th.
    const std::vector<Wall> walls = {{{0, 10}, {0, -10}}, {{1, -10}, {1, 10}}};
    const Stepped s = step(k_, {{0.5, 0}, {100, 0}}, walls);
    EXPECT_EQ(s.status, FrameStatus::bounce_limit);
    ASSERT_EQ(s.hits.size(), 16u);
    EXPECT_EQ(s.ball.pos, s.hits.back().point);
}

}  // namespace
}  // namespace ricochet
