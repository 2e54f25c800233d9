// Discs and bumpers in the format and the model (docs/scene-log.md, "Discs and bumpers"): the optional
// radius and the `bump` event read, print, hash and round-trip as specified; a radius of 0 changes nothing;
// every built-in kernel steps them; a kernel or a check that has no meaning for them refuses them instead of
// skipping them.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <random>
#include <string>
#include <variant>

#include <fmt/format.h>

#include "ricochet/bits.hpp"
#include "ricochet/checks.hpp"
#include "ricochet/format.hpp"
#include "ricochet/hash.hpp"
#include "ricochet/kernel.hpp"
#include "ricochet/scene_log.hpp"
#include "ricochet/world.hpp"
#include "scene_text.hpp"

namespace ricochet {
namespace {

using test::diag;
using test::parse_ok;

TEST(DiscFormat, TheRadiusIsOptionalAndZeroIsThePointBall) {
    const Scene s = parse_ok("ricochet 1\nball 1 2 3 4\nball 1 2 3 4 0\nball 1 2 3 4 -0\nball 1 2 3 4 0.5\n");
    ASSERT_EQ(s.balls.size(), 4u);
    EXPECT_TRUE(same_bits(s.balls[0].r, 0.0));
    EXPECT_TRUE(same_bits(s.balls[1].r, 0.0));
    EXPECT_TRUE(same_bits(s.balls[2].r, -0.0));
    EXPECT_EQ(s.balls[3].r, 0.5);
    EXPECT_FALSE(is_disc(s.balls[0]) || is_disc(s.balls[1]) || is_disc(s.balls[2]));
    EXPECT_TRUE(is_disc(s.balls[3]));
    // The radius is written only when its bits are not +0, so a point ball's line is what it always was.
    EXPECT_EQ(write_scene_log(s),
              "ricochet 1\nkernel robust\nframes 0\nball 1 2 3 4\nball 1 2 3 4\nball 1 2 3 4 -0\nball 1 2 3 4 0.5\n");
}

TEST(DiscFormat, AZeroRadiusIsTheSameCaseAndTheSameRun) {
    const std::string point = "ricochet 1\nframes 9\nwall 0 -5 0 5\nwall 3 -5 3 5\nball 1 0 0.7 0.1\ncircle 2 0 1\n";
    const std::string zero = "ricochet 1\nframes 9\nwall 0 -5 0 5\nwall 3 -5 3 5\nball 1 0 0.7 0.1 0\ncircle 2 0 1\n";
    const Scene a = parse_ok(point), b = parse_ok(zero);
    EXPECT_EQ(scene_content_id(a), scene_content_id(b));
    for (KernelId k : k_all_kernels) EXPECT_EQ(hash_events(run_scene(a, k, 9)), hash_events(run_scene(b, k, 9))) << kernel_name(k);
    // −0 is a point ball too: the same events, bit for bit.
    Scene c = a;
    c.balls[0].r = -0.0;
    EXPECT_EQ(hash_events(run_scene(a, KernelId::robust, 9)), hash_events(run_scene(c, KernelId::robust, 9)));
}

TEST(DiscFormat, BumpersRoundTripBitForBit) {
    std::mt19937_64 rng(2024);
    Scene s;
    s.frames = 3;
    for (int i = 0; i < 500; ++i) {
        double v[5];
        for (double& x : v) {
            do x = std::bit_cast<double>(rng());
            while (!in_range(x));
        }
        s.balls.push_back({{v[0], v[1]}, {v[2], v[3]}, std::fabs(v[4])});
        s.bumpers.push_back({{v[3], v[2]}, std::fabs(v[0])});
    }
    s.balls.push_back({{1, 2}, {3, 4}, -0.0});
    s.bumpers.push_back({{1, 2}, -0.0});
    const std::string text = write_scene_log(s);
    const Scene back = parse_ok(text);
    EXPECT_TRUE(same_bits(s, back));
    EXPECT_EQ(write_scene_log(back), text);
    // A bumper's bits count: +0 and −0 radii are different scenes to same_bits, equal ones to ==.
    Scene t = back;
    t.bumpers.back().r = 0.0;
    EXPECT_FALSE(same_bits(back, t));
    EXPECT_TRUE(back == t);
}

TEST(DiscFormat, BadRadiiNameTheirPlace) {
    EXPECT_EQ(diag("ricochet 1\nball 0 0 1 1 -2\n"), "t.scene:2:14: error: negative radius -2");
    EXPECT_EQ(diag("ricochet 1\nball 0 0 1 1 nan\n"),
              "t.scene:2:14: error: R nan is outside the accepted range (finite, magnitude at most 2^256)");
    EXPECT_EQ(diag("ricochet 1\nball 0 0 1 1 0x1p257\n"),
              "t.scene:2:14: error: R 0x1p257 is outside the accepted range (finite, magnitude at most 2^256)");
    EXPECT_EQ(diag("ricochet 1\nball 0 0 1 1 1e999\n"), "t.scene:2:14: error: bad R: '1e999' is out of the range of a double");
    EXPECT_EQ(diag("ricochet 1\nball 0 0 1 1 1 1 1\n"),
              "t.scene:2:18: error: unexpected '1' after 'ball' (X Y VX VY [R [M]] expected)");
    EXPECT_EQ(diag("ricochet 1\nbumper 0 0 -1e-300\n"), "t.scene:2:12: error: negative radius -1e-300");
    EXPECT_EQ(diag("ricochet 1\nbumper 0 0\n"), "t.scene:2:11: error: 'bumper' needs X Y R: missing R");
    EXPECT_EQ(diag("ricochet 1\nbumper 0 0 1 2\n"), "t.scene:2:14: error: unexpected '2' after 'bumper' (X Y R expected)");
    // The largest radius in range is accepted.
    EXPECT_EQ(parse_ok("ricochet 1\nball 0 0 1 1 0x1p256\nbumper 0 0 0x1p256\n").balls[0].r, 0x1p256);
}

TEST(DiscFormat, EveryCheckMayBeListedForDiscsAndBumpers) {
    for (Check c : k_all_checks) {
        EXPECT_EQ(diag(fmt::format("ricochet 1\ncheck {}\nball 0 0 1 1 0.5\n", c)), "parsed") << check_name(c);
        EXPECT_EQ(diag(fmt::format("ricochet 1\nbumper 0 0 1\ncheck {}\n", c)), "parsed") << check_name(c);
        EXPECT_EQ(diag(fmt::format("ricochet 1\ncheck {}\nball 0 0 1 1 0\n", c)), "parsed") << check_name(c);
    }
}

TEST(DiscFormat, BumpPrintsAndHashesAsDocumented) {
    const Event bump{Event::Kind::bump, 4, 2, Event::Shape::none, 9, {0.5, -0.0}, {}};
    EXPECT_EQ(format_event(bump), "bump 4 2 9 0.5 -0");
    unsigned char r[k_event_record_size];
    encode_event(bump, r);
    EXPECT_EQ(r[0], 3);   // kind 3: bump
    EXPECT_EQ(r[1], 0);   // no shape
    EXPECT_EQ(r[16], 9);  // the bumper
    EXPECT_EQ(fmt::format("{}", Bumper{{1, 2}, 0.25}), "1 2 0.25");
    EXPECT_EQ(fmt::format("{}", Ball{{1, 2}, {3, 4}, 0.25}), "1 2 3 4 0.25");
    EXPECT_EQ(fmt::format("{}", Ball{{1, 2}, {3, 4}, -0.0}), "1 2 3 4 -0");
}

// Every built-in kernel steps discs and bumpers (robust and exact with exact decisions, the lecture kernels the
// lecture's way): each accepts them and steps one frame.
TEST(DiscFormat, EveryBuiltInKernelStepsThem) {
    const Scene disc = parse_ok("ricochet 1\nframes 1\nwall 2 -5 2 5\nball 0 0 1 1\nball 0 0 3 0 0.5\n");
    const Scene bumper = parse_ok("ricochet 1\nframes 1\nball 0 0 3 0\nbumper 3 0 1\n");
    for (KernelId k : k_all_kernels) {
        SCOPED_TRACE(kernel_name(k));
        EXPECT_EQ(unsupported_scene(k, disc.balls, 0), std::nullopt);
        EXPECT_EQ(unsupported_scene(k, bumper.balls, 1), std::nullopt);
        EXPECT_NO_THROW(World(disc, k));
        EXPECT_NO_THROW(World(bumper, k));
        EXPECT_EQ(refusal(disc, k), std::nullopt);
        // The disc meets the wall's face (centre at x = 1.5) and bounces back; the point ball meets the bumper.
        Ball b = disc.balls[1];
        BallMemory m;
        std::vector<HitEvent> hits;
        StepScratch scratch;
        EXPECT_EQ(step_ball(k, b, m, Obstacles{disc.walls, {}, nullptr}, hits, scratch), FrameStatus::ok);
        ASSERT_EQ(hits.size(), 1u);
        EXPECT_EQ(hits[0].wall, 0u);
        EXPECT_FALSE(hits[0].bumper);
        EXPECT_LT(b.vel.x, 0.0);
        EXPECT_EQ(b.r, 0.5);
        Ball p = bumper.balls[0];
        hits.clear();
        EXPECT_EQ(step_ball(k, p, m, Obstacles{bumper.walls, bumper.bumpers, nullptr}, hits, scratch), FrameStatus::ok);
        ASSERT_EQ(hits.size(), 1u);
        EXPECT_TRUE(hits[0].bumper);
        EXPECT_LT(p.vel.x, 0.0);
    }
}

/// A kernel of point balls only, as the peers and plug-ins are: robust's point functions, no step_disc.
struct PointsOnlyKernel {
    static Side classify(Vec2 p, const Wall& w) { return ricochet::classify(KernelId::robust, p, w); }
    static bool point_in_circle(Vec2 p, const Circle& c) { return ricochet::point_in_circle(KernelId::robust, p, c); }
    static bool circles_overlap(const Circle& a, const Circle& b) { return ricochet::circles_overlap(KernelId::robust, a, b); }
    static bool point_in_rect(Vec2 p, const Rect& r) { return ricochet::point_in_rect(KernelId::robust, p, r); }
    static bool rects_overlap(const Rect& a, const Rect& b) { return ricochet::rects_overlap(KernelId::robust, a, b); }
    static Sweep sweep(Vec2 bs, Vec2 v, const Wall& w) { return ricochet::sweep(KernelId::robust, bs, v, w); }
    static Vec2 reflect(Vec2 v, const Wall& w) { return ricochet::reflect(KernelId::robust, v, w); }
    static FrameStatus step_ball(Ball& ball, BallMemory& memory, std::span<const Wall> walls,
                                 std::vector<HitEvent>& hits, StepScratch& scratch, const WallIndex* index) {
        return ricochet::step_ball(KernelId::robust, ball, memory, walls, hits, scratch, index);
    }
};

// A kernel without a disc stepper (the peers, plug-ins: KernelOps::step_disc unset) refuses them with a message
// that says which, before stepping anything.
TEST(DiscFormat, AKernelThatCannotStepThemRefusesTheScene) {
    KernelOps ops = make_kernel_ops<PointsOnlyKernel>("test-points-only");
    ASSERT_EQ(ops.step_disc, nullptr);
    ASSERT_FALSE(ops.steps_bumpers);
    static std::optional<KernelId> id = register_kernel(ops);
    ASSERT_TRUE(id.has_value());
    const KernelId k = *id;
    const Scene disc = parse_ok("ricochet 1\nframes 1\nball 0 0 1 1\nball 0 0 1 1 0.5\n");
    const Scene bumper = parse_ok("ricochet 1\nframes 1\nball 0 0 1 1\nbumper 3 3 1\n");
    EXPECT_EQ(unsupported_scene(k, disc.balls, 0), "kernel 'test-points-only' steps point balls only: ball 1 has radius 0.5");
    EXPECT_EQ(unsupported_scene(k, bumper.balls, 1),
              "kernel 'test-points-only' does not step bumpers: the scene has 1 (bumper 0 first)");
    EXPECT_THROW(World(disc, k), UnsupportedScene);
    EXPECT_THROW(World(bumper, k), UnsupportedScene);
    EXPECT_THROW(run_checked(disc, k, 1, {}), UnsupportedScene);
    EXPECT_EQ(refusal(disc, k), unsupported_scene(k, disc.balls, 0));
    Ball b = disc.balls[1];
    BallMemory m;
    std::vector<HitEvent> hits;
    StepScratch scratch;
    EXPECT_THROW(step_ball(k, b, m, Obstacles{disc.walls, {}, nullptr}, hits, scratch), UnsupportedScene);
    EXPECT_TRUE(hits.empty());
}

TEST(DiscFormat, RunCheckedRunsEveryCheckOnADisc) {
    const Scene disc = parse_ok("ricochet 1\nframes 2\nwall 1 -1 1 1\nball 0 0 1 0 0.5\nbumper -1 0 0.25\n");
    EXPECT_EQ(refusal(disc, KernelId::robust), std::nullopt);
    const CheckedRun run = run_checked(disc, KernelId::robust, 2, k_all_checks);
    EXPECT_FALSE(run.failure) << run.failure->str();
    EXPECT_EQ(run.frames_run, 2);
}

}  // namespace
}  // namespace ricochet
