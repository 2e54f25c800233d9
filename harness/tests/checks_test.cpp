// The checks of checks.hpp: for each, a scene where it must pass and a kernel or scene where it must fail.
#include <gtest/gtest.h>

#include <vector>

#include "mutant_kernel.hpp"
#include "ricochet/checks.hpp"
#include "ricochet/kernel.hpp"
#include "ricochet/step_trace.hpp"

namespace ricochet {
namespace {

std::vector<Wall> box(double lo, double hi) {
    return {{{lo, hi}, {lo, lo}}, {{lo, lo}, {hi, lo}}, {{hi, lo}, {hi, hi}}, {{hi, hi}, {lo, hi}}};
}

/// A closed box with a few balls, a circle and a rect: every check holds on it under robust and exact.
Scene pinball() {
    Scene s;
    s.frames = 40;
    s.walls = box(0, 10);
    s.walls.push_back({{0, 2}, {3, 0.5}});
    s.balls = {{{8, 5}, {4, 1}}, {{1, 1}, {0.75, 0.5}}, {{5, 5}, {-3, 2.5}}};
    s.circles = {{{8, 6}, 0.0}, {{3, 7}, 1}};
    s.rects = {{0, 0, 1, 1}, {1, 1, 2, 2}};
    return s;
}

std::optional<CheckFailure> first_failure(const Scene& s, KernelId k, Check c) {
    return run_checked(s, k, s.frames, std::vector<Check>{c}).failure;
}

TEST(Checks, EveryNameRoundTrips) {
    for (Check c : k_all_checks) EXPECT_EQ(parse_check(check_name(c)), c);
    EXPECT_FALSE(parse_check("no_tunnel"));
}

TEST(Checks, EveryCheckHoldsOnThePinballUnderRobustAndExact) {
    for (KernelId k : {KernelId::robust, KernelId::exact})
        for (Check c : k_all_checks) {
            const auto f = first_failure(pinball(), k, c);
            EXPECT_FALSE(f) << kernel_name(k) << ": " << f->str();
        }
}

TEST(Checks, AccuracyFailsForFloatsRoundingAndHoldsForRobust) {
    // The leg (0.1, 0.1) → (2.1, 0.3) crosses the wall x = 1 at a steep angle (well-conditioned): robust's
    // B_i is within a few ulps, lecture-float's is off by about 2^-24 relative, ~10^6 times the bound.
    Scene s;
    s.frames = 1;
    s.walls = {{{1, -1}, {1, 1}}};
    s.balls = {{{0.1, 0.1}, {2, 0.2}}};
    EXPECT_FALSE(first_failure(s, KernelId::robust, Check::accuracy));
    EXPECT_FALSE(first_failure(s, KernelId::lecture_double, Check::accuracy));
    const auto f = first_failure(s, KernelId::lecture_float, Check::accuracy);
    ASSERT_TRUE(f);
    EXPECT_EQ(f->frame, 1);
    // Its t_i (the trace's leg fraction) is off first; the printed point's own bound is what it is off by next.
    EXPECT_NE(f->message.find("at t_i = "), std::string::npos) << f->message;
    EXPECT_NE(f->message.find("eps*M along the leg from the exact crossing"), std::string::npos) << f->message;
    // The same leg grazing the wall (|e × d| < |e|∞·|d|∞ / 4) is not held to the bound: what fails is that
    // its leg runs between floats, not from Bs (0.1 is not a float).
    Scene graze = s;
    graze.walls = {{{-1, 0.2}, {3, 0.2 + 0.5 / 1024}}};
    graze.balls = {{{0.1, 0.1}, {2, 0.2}}};
    const auto g = first_failure(graze, KernelId::lecture_float, Check::accuracy);
    ASSERT_TRUE(g);
    EXPECT_NE(g->message.find("leg 0 starts at"), std::string::npos) << g->message;
    EXPECT_EQ(g->message.find("exact crossing"), std::string::npos) << g->message;
}

/// A leg after a bounce at B_i = hit (t_i = t) leaving with v′ = v: where a wrong kernel puts it.
struct LegAfter {
    Vec2 from, to, vel;
};
/// A whole frame's v′ instead of the rest, (1 − t_i)·v′.
LegAfter whole_frame(Vec2 hit, Vec2 v, double) { return {hit, hit + v, v}; }
/// The rest of the frame, but from a point a quarter above B_i.
LegAfter from_elsewhere(Vec2 hit, Vec2 v, double t) {
    const Vec2 from = hit + Vec2{0, 0.25};
    return {from, from + (1 - t) * v, v};
}
/// The rest of the frame, traced with a velocity that is not a number.
LegAfter nan_velocity(Vec2 hit, Vec2 v, double t) { return {hit, hit + (1 - t) * v, {std::nan(""), v.y}}; }

/// robust's sweep and reflection against wall 0 alone, the leg after a bounce placed by after(B_i, v′, t_i),
/// the hit printed if print_hit. Traced as a kernel traces its legs.
template <LegAfter (*after)(Vec2 hit, Vec2 v, double t), bool print_hit = true>
FrameStatus bounce_then(Ball& ball, BallMemory&, std::span<const Wall> walls, std::vector<HitEvent>& hits,
                        StepScratch& scratch, const WallIndex*) {
    const KernelOps& robust = kernel_ops(KernelId::robust);
    const auto leg = [&](Vec2 from, Vec2 to, Vec2 vel) -> TracedLeg* {
        if (scratch.trace == nullptr) return nullptr;
        TracedLeg& l = scratch.trace->legs.emplace_back();
        l.from = from;
        l.to = to;
        l.vel = vel;
        return &l;
    };
    const Sweep s = robust.sweep(ball.pos, ball.vel, walls[0]);
    TracedLeg* first = leg(ball.pos, ball.pos + ball.vel, ball.vel);
    if (s.miss != Miss::none) {
        ball.pos = ball.pos + ball.vel;
        return FrameStatus::ok;
    }
    if (first != nullptr) {
        first->hit = 0;
        first->hit_t = s.t;
        ++scratch.trace->reflections;
    }
    if (print_hit) hits.push_back({0, s.t, s.point});
    const LegAfter next = after(s.point, robust.reflect(ball.vel, walls[0]), s.t);
    leg(next.from, next.to, next.vel);
    ball = {next.to, next.vel};
    return FrameStatus::ok;
}

TEST(Checks, AccuracyHoldsEachLegToTheRestOfTheFrame) {
    // Hit at t_i = 1/2 at (0.75, 0); the rest of the frame ends at (0.75, 0) + (1/2)·(0.5, 2) = (1, 1).
    Scene s;
    s.frames = 1;
    s.walls = {{{10, 0}, {-10, 0}}};
    s.balls = {{{0.5, 1}, {0.5, -2}}};
    EXPECT_FALSE(first_failure(s, KernelId::robust, Check::accuracy));
    EXPECT_FALSE(first_failure(s, KernelId::lecture_double, Check::accuracy));
    mutant::Mutation m;
    m.ops.step_ball = &bounce_then<whole_frame>;
    const std::optional<KernelId> bad = mutant::id();
    // Its t_i, B_i and v′ are robust's: only the second leg's length is wrong.
    const auto f = first_failure(s, *bad, Check::accuracy);
    ASSERT_TRUE(f);
    EXPECT_EQ(f->frame, 1);
    EXPECT_NE(f->message.find("leg 1 ((0.75, 0) -> (1.25, 2))"), std::string::npos) << f->message;
    EXPECT_NE(f->message.find("is not the rest of the frame"), std::string::npos) << f->message;
    // The rest of the frame from (0.75, 0.25), not from the printed B_i.
    m.ops.step_ball = &bounce_then<from_elsewhere>;
    const auto g = first_failure(s, *bad, Check::accuracy);
    ASSERT_TRUE(g);
    EXPECT_EQ(g->frame, 1);
    EXPECT_NE(g->message.find("leg 1 starts at (0.75, 0.25), not at (0.75, 0) where the previous leg ended"),
              std::string::npos)
        << g->message;
    // A leg traced moving NaN: the frame leaves the accepted range, so the run stops with a step error, the
    // ball keeping its state (step.hpp), and no check judges that frame: no accuracy failure, and no exact
    // arithmetic on the NaN (GMP's rational of a NaN raises SIGFPE).
    m.ops.step_ball = &bounce_then<nan_velocity>;
    const std::vector<Check> accuracy = {Check::accuracy};
    const CheckedRun n = run_checked(s, *bad, s.frames, accuracy);
    EXPECT_FALSE(n.failure);
    ASSERT_TRUE(n.error);
    EXPECT_EQ(n.error->frame, 1);
    // A hit traced but not printed: there is no printed B_i for the next leg to start at, so accuracy stops
    // its walk there; `oracle` reports the kernel's hits and its trace disagreeing.
    m.ops.step_ball = &bounce_then<whole_frame, false>;
    EXPECT_FALSE(first_failure(s, *bad, Check::accuracy));
    const auto unprinted = first_failure(s, *bad, Check::oracle);
    ASSERT_TRUE(unprinted);
    EXPECT_EQ(unprinted->frame, 1);
}

TEST(Checks, AccuracyFollowsAReflectionOffAContactWall) {
    // replays/robust-endpoint-contact-speed.scene: the ball rests on the wall's end point P0 = (0, 1) and is
    // reflected off it as a contact, without a hit. The leg after such a blocked leg starts where the blocked
    // one started, with the same rest of the frame.
    Scene s;
    s.frames = 3;
    s.walls = {{{0, 1}, {74, 74}}};
    s.balls = {{{1.105431282474736e-75, 1}, {-1.105431282474736e-75, 0}}};
    Ball ball = s.balls[0];
    BallMemory memory;
    std::vector<HitEvent> hits;
    StepTrace trace;
    StepScratch scratch;
    scratch.trace = &trace;
    std::size_t blocked = 0;
    std::vector<FrameStatus> statuses;
    for (std::int64_t f = 0; f < s.frames; ++f) {
        trace.clear();
        statuses.push_back(step_ball(KernelId::robust, ball, memory, s.walls, hits, scratch));
        for (const TracedLeg& leg : trace.legs) blocked += leg.blocked ? 1 : 0;
    }
    // Frame 1 hits P0; frames 2 and 3 reflect off the contact, leg after blocked leg, until the bounce limit
    // keeps the ball at its safe point.
    EXPECT_EQ(statuses, (std::vector<FrameStatus>{FrameStatus::ok, FrameStatus::bounce_limit, FrameStatus::bounce_limit}));
    EXPECT_GT(blocked, 0u);
    EXPECT_FALSE(first_failure(s, KernelId::robust, Check::accuracy));
}

/// robust, except that a frame with a hit ends moving out(v, the first wall hit), v the frame's velocity.
template <Vec2 (*out)(Vec2 v, const Wall& hit)>
FrameStatus robust_leaving(Ball& ball, BallMemory& memory, std::span<const Wall> walls, std::vector<HitEvent>& hits,
                           StepScratch& scratch, const WallIndex* index) {
    const Vec2 v = ball.vel;
    const std::size_t before = hits.size();
    const FrameStatus status = kernel_ops(KernelId::robust).step_ball(ball, memory, walls, hits, scratch, index);
    if (hits.size() > before) ball.vel = out(v, walls[hits[before].wall]);
    return status;
}

/// Going straight back (v' = −v): the bug of mutant 28.
Vec2 straight_back(Vec2 v, const Wall&) { return -v; }

TEST(Checks, AccuracyHoldsTheBounceToTheExactReflection) {
    // The ball ends its first frame exactly on the wall y = 0 (t_i = 1), so the frame's end state carries v'.
    Scene s;
    s.frames = 2;
    s.walls = {{{10, 0}, {-10, 0}}};
    s.balls = {{{0.5, 1}, {0.5, -1}}};
    EXPECT_FALSE(first_failure(s, KernelId::robust, Check::accuracy));
    EXPECT_FALSE(first_failure(s, KernelId::lecture_double, Check::accuracy));
    mutant::Mutation m;
    m.ops.step_ball = &robust_leaving<straight_back>;
    const std::optional<KernelId> bad = mutant::id();
    // Same speed, same side: speed and bounce-side hold; only the bounce's direction is wrong.
    EXPECT_FALSE(first_failure(s, *bad, Check::speed));
    EXPECT_FALSE(first_failure(s, *bad, Check::bounce_side));
    const auto f = first_failure(s, *bad, Check::accuracy);
    ASSERT_TRUE(f);
    EXPECT_EQ(f->frame, 1);
    EXPECT_NE(f->message.find("from the exact reflection"), std::string::npos) << f->message;
    // A bounce off a corner (the point on a second wall) is the corner rule's, not held to one reflection.
    Scene corner = s;
    corner.walls.push_back({{1, 0}, {1, 5}});
    EXPECT_FALSE(first_failure(corner, *bad, Check::accuracy));
}

/// Reflected about the wall hit alone, no corner rule.
Vec2 hit_wall_only(Vec2 v, const Wall& hit) { return kernel_ops(KernelId::robust).reflect(v, hit); }

TEST(Checks, AccuracyHoldsACornerToTheCornerRule) {
    // The frame ends exactly at (1, 0), the corner of the floor y = 0 (wall 0, hit) and the wall x = 1 met
    // from its left. v = (0.5, −1) reflects about the floor to (0.5, 1), which still crosses x = 1, so about
    // that too: (−0.5, 1).
    Scene s;
    s.frames = 1;
    s.walls = {{{10, 0}, {-10, 0}}, {{1, 0}, {1, 5}}};
    s.balls = {{{0.5, 1}, {0.5, -1}}};
    EXPECT_FALSE(first_failure(s, KernelId::robust, Check::accuracy));
    // The lecture has no corner rule: its kernels reflect about the wall they report (kernel.hpp).
    const auto lecture = first_failure(s, KernelId::lecture_double, Check::accuracy);
    ASSERT_TRUE(lecture);
    EXPECT_NE(lecture->message.find("from the corner rule's v'"), std::string::npos) << lecture->message;
    mutant::Mutation m;
    m.ops.step_ball = &robust_leaving<hit_wall_only>;
    const std::optional<KernelId> bad = mutant::id();
    const auto f = first_failure(s, *bad, Check::accuracy);
    ASSERT_TRUE(f);
    EXPECT_EQ(f->frame, 1);
    EXPECT_NE(f->message.find("at the corner (1, 0) (1 other walls there) moving (0.5, -1) and leaves moving (0.5, 1)"),
              std::string::npos)
        << f->message;
    // Away from the corner the same kernel is robust: one reflection is the whole rule.
    Scene lone = s;
    lone.walls[1] = {{2, 0}, {2, 5}};
    EXPECT_FALSE(first_failure(lone, *bad, Check::accuracy));
}

TEST(Checks, OracleHoldsAtTheBounceLimitAndTheTraceSaysItStopped) {
    // A corridor 2^-40 wide crossed at speed 1: every frame needs thousands of bounces and stops at 16.
    // oracle counts the bounces against the spec's 16 and finds the ball at the last point of its path.
    const double h = 0x1p-40;
    Scene s;
    s.frames = 3;
    s.walls = {{{-10, 0}, {10, 0}}, {{10, h}, {-10, h}}};
    s.balls = {{{0, h / 2}, {1, 1}}};
    for (KernelId k : {KernelId::robust, KernelId::lecture_double, KernelId::lecture_float}) {
        // The lecture kernels' first frame only: in the next they take a ball on the wall leaving it for a hit.
        const std::int64_t frames = k == KernelId::robust ? s.frames : 1;
        const CheckedRun run = run_checked(s, k, frames, std::vector<Check>{Check::oracle});
        EXPECT_FALSE(run.failure) << kernel_name(k) << ": " << run.failure->str();
        std::size_t hits = 0;
        for (const Event& e : run.events) hits += e.kind == Event::Kind::hit && e.frame == 1;
        EXPECT_EQ(hits, 16u) << kernel_name(k);
    }
    StepTrace trace;
    StepScratch scratch;
    scratch.trace = &trace;
    Ball ball = s.balls[0];
    BallMemory memory;
    std::vector<HitEvent> hits;
    EXPECT_EQ(step_ball(KernelId::robust, ball, memory, s.walls, hits, scratch), FrameStatus::bounce_limit);
    EXPECT_EQ(trace.legs.size(), 16u) << "robust stops before sweeping a 17th leg";
}

TEST(Checks, NoTunnelFailsWhenTheLectureKernelLeavesThroughAWallEnd) {
    Scene s;
    s.frames = 5;
    s.walls = {{{0, 0}, {0, 4}}};
    s.balls = {{{-3, 7}, {1, -1}}};
    const auto f = first_failure(s, KernelId::lecture_double, Check::no_tunnel);
    ASSERT_TRUE(f);
    EXPECT_EQ(f->frame, 4);
    EXPECT_FALSE(first_failure(s, KernelId::robust, Check::no_tunnel));
}

TEST(Checks, SpeedFailsWhenFloatLosesATinyVelocity) {
    Scene s;
    s.frames = 2;
    s.walls = {{{1, -1}, {1, 1}}};
    s.balls = {{{0.9999999999999999, 0}, {1e-300, 0}}};
    const auto f = first_failure(s, KernelId::lecture_float, Check::speed);
    ASSERT_TRUE(f);
    EXPECT_EQ(f->frame, 1);
    EXPECT_FALSE(first_failure(s, KernelId::robust, Check::speed));
}

TEST(Checks, SpeedCountsContactReflectionsWithoutAHit) {
    // The ball rests on the wall's end point and is reflected off that contact wall every frame without a
    // hit event: robust reports those reflections, so the speed change is allowed.
    Scene s;
    s.frames = 3;
    s.walls = {{{0, 1}, {74, 74}}};
    s.balls = {{{1.105431282474736e-75, 1}, {-1.105431282474736e-75, 0}}};
    EXPECT_FALSE(first_failure(s, KernelId::robust, Check::speed));
    // And the trace does count them.
    Ball b = s.balls[0];
    BallMemory m;
    std::vector<HitEvent> hits;
    StepScratch scratch;
    StepTrace trace;
    for (int frame = 0; frame < 2; ++frame) {
        trace.clear();
        scratch.trace = &trace;
        (void)step_ball(KernelId::robust, b, m, s.walls, hits, scratch);
    }
    EXPECT_TRUE(hits.size() < 2 || trace.reflections > 0);
}

TEST(Checks, OracleFailsOnTheLectureKernelsGrazingBall) {
    Scene s;
    s.frames = 20;
    s.walls = box(0, 10);
    s.walls.push_back({{2, 3}, {8, 3}});
    s.balls = {{{1, 3}, {1, 0}}, {{1, 2.9999999}, {1, 1e-7}}, {{1, 6}, {1, 0}}};
    const auto f = first_failure(s, KernelId::lecture_double, Check::oracle);
    ASSERT_TRUE(f);
    EXPECT_EQ(f->frame, 1);
    EXPECT_FALSE(first_failure(s, KernelId::robust, Check::oracle));
}

TEST(Checks, BoundaryFailsWhenTheLectureSweepHitsTheWallItStartsOn) {
    // Frame 2 ends exactly on the wall (0, 0) → (0, 4) at (0, 4)'s line point; the lecture's sweep from
    // a point on the line computes t_i = 0, a hit.
    Scene s;
    s.frames = 4;
    s.walls = {{{0, 0}, {0, 4}}};
    s.balls = {{{-2, 6}, {1, -1}}};
    const auto f = first_failure(s, KernelId::lecture_double, Check::boundary);
    ASSERT_TRUE(f);
    EXPECT_EQ(f->frame, 2);
    EXPECT_FALSE(first_failure(s, KernelId::robust, Check::boundary));
}

TEST(Checks, TranslationFailsForFloatFarFromTheOrigin) {
    // (1, −2) moves these doubles exactly, but floats are 64 apart here: the ball rounds to 1e9 and the
    // wall to 1e9 + 64, and moved by 1 both round to 1e9 + 64, so the side changes.
    Scene s;
    s.frames = 1;
    s.walls = {{{1e9 + 33, -1e9}, {1e9 + 33, 1e9}}};
    s.balls = {{{1e9 + 31.5, 3}, {0.5, 0}}};
    EXPECT_TRUE(first_failure(s, KernelId::lecture_float, Check::translation));
    EXPECT_FALSE(first_failure(s, KernelId::robust, Check::translation));
}

TEST(Checks, RoundTripFailsForAProvenanceLineThatBreaksTheFormat) {
    Scene s = pinball();
    s.frames = 0;
    EXPECT_FALSE(first_failure(s, KernelId::robust, Check::round_trip));
    s.provenance = {"fuzz x\nball 0 0 0 0"};
    const auto f = first_failure(s, KernelId::robust, Check::round_trip);
    ASSERT_TRUE(f);
    EXPECT_EQ(f->frame, 0);
}

TEST(Checks, NoEscapeAppliesOnlyToClosedWalls) {
    Scene s;
    s.frames = 300;
    s.walls = box(0, 10);
    s.balls = {{{5, 5}, {3.25, 1.5}}};
    EXPECT_FALSE(first_failure(s, KernelId::robust, Check::no_escape));
    // The ball starts outside a closed box and is aimed through its corner: lecture-double gets in.
    Scene far;
    far.frames = 300;
    far.walls = box(0, 10);
    far.balls = {{{-3, 13}, {1, -1}}};
    EXPECT_FALSE(first_failure(far, KernelId::robust, Check::no_escape));
    // Open walls: a ball walking round a wall end changes the even-odd side legitimately.
    Scene open = s;
    open.walls.pop_back();
    EXPECT_FALSE(first_failure(open, KernelId::lecture_double, Check::no_escape));
}

TEST(Checks, SwapSymmetryBroadPhaseAndDeterminismHoldForEveryBuiltInKernel) {
    for (KernelId k : k_all_kernels)
        for (Check c : {Check::swap, Check::broad_phase, Check::deterministic}) {
            const auto f = first_failure(pinball(), k, c);
            EXPECT_FALSE(f) << kernel_name(k) << ": " << f->str();
        }
}

TEST(Checks, TraceIsEmptyWithoutAskingAndFilledWhenAsked) {
    Scene s = pinball();
    Ball b = s.balls[0];
    BallMemory m;
    std::vector<HitEvent> hits;
    StepScratch scratch;
    (void)step_ball(KernelId::robust, b, m, s.walls, hits, scratch);
    EXPECT_EQ(scratch.trace, nullptr);
    StepTrace trace;
    scratch.trace = &trace;
    b = s.balls[0];
    m = {};
    hits.clear();
    (void)step_ball(KernelId::robust, b, m, s.walls, hits, scratch);
    ASSERT_EQ(hits.size(), 1u);  // the lecture's example: (8, 5) + (4, 1) hits the right wall at (10, 5.5)
    ASSERT_EQ(trace.legs.size(), 2u);
    EXPECT_EQ(trace.legs[0].hit, std::optional<std::uint32_t>(2));
    EXPECT_EQ(trace.legs[0].decision_count, s.walls.size());
    EXPECT_FALSE(trace.legs[1].hit);
    EXPECT_EQ(trace.reflections, 1);
}

}  // namespace
}  // namespace ricochet
