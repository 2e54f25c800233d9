// The reducer (reduce.hpp): small cases worked by hand, the numbers it tries, what it keeps of the input,
// refusals, step errors, the budget and a stop, determinism, and a 10^3-wall ring that reduces to a handful
// of entities. Every reduced log is checked the way the harness's logs are (fuzz_failures_reproduce): it
// reads back, replay passes it where it expects its failure, and without `expect failure` replay fails it
// at its `found` check, frame and ball.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include "mutant_kernel.hpp"
#include "reduce/passes.hpp"
#include "ricochet/reduce.hpp"
#include "ricochet/replay.hpp"
#include "ricochet/scene_log.hpp"
#include "ring_scene.hpp"
#include "scene_text.hpp"

namespace ricochet {
namespace {

using test::parse_ok;

/// The reduced log of scene; a refusal is a test failure.
ReducedLog reduced(const Scene& scene, const ReduceOptions& options = {}) {
    auto r = reduce_log(scene, options);
    if (const auto* refused = std::get_if<ReduceRefusal>(&r)) ADD_FAILURE() << "refused: " << refused->message;
    return std::holds_alternative<ReducedLog>(r) ? std::get<ReducedLog>(std::move(r)) : ReducedLog{};
}

/// The refusal's message for scene; a reduction is a test failure.
std::string refusal(const Scene& scene) {
    auto r = reduce_log(scene);
    if (std::holds_alternative<ReducedLog>(r)) ADD_FAILURE() << "reduced:\n" << std::get<ReducedLog>(r).log.text();
    return std::holds_alternative<ReduceRefusal>(r) ? std::get<ReduceRefusal>(r).message : std::string();
}

/// The reduced log is a failure log that replay reproduces at its found check, frame and ball.
void expect_reproduces(const ReducedLog& r) {
    const Scene back = parse_ok(r.log.text());
    EXPECT_TRUE(same_bits(back, r.log.scene)) << r.log.text();
    ASSERT_TRUE(back.found) << r.log.text();
    ASSERT_EQ(back.checks, std::vector<Check>{back.found->check});
    EXPECT_EQ(back.frames, back.found->frame);
    EXPECT_TRUE(r.log.reproduces()) << r.log.text();
    if (back.expect_failure) {
        const ReplayResult ok = replay_scene(back);
        EXPECT_TRUE(ok.passed) << ok.message;
    }
    Scene bare = back;
    bare.expect_failure.reset();
    const ReplayResult bad = replay_scene(bare);
    EXPECT_FALSE(bad.passed);
    EXPECT_NE(bad.message.find(fmt::format("invariant {} broke at frame {} ball {}:", back.found->check,
                                           back.found->frame, back.found->ball)),
              std::string::npos)
        << bad.message;
    EXPECT_EQ(bad.message.find("when saved"), std::string::npos) << bad.message;
}

// --- Small cases worked by hand

TEST(Reduce, ATunnelThroughOneOfManyWallsKeepsThatWallAndThatBall) {
    // replays/lecture/double-endpoint-tunnel.scene's ball aimed at the end P1 = (0, 4) of the wall x = 0,
    // among 40 walls and 6 balls that never meet anything (x ≥ 100), the wall at index 20, the ball at 3.
    Scene s;
    s.kernel = KernelId::lecture_double;
    s.frames = 10;
    for (int i = 0; i < 40; ++i) {
        if (i == 20) s.walls.push_back({{0, 0}, {0, 4}});
        s.walls.push_back({{100.0 + 3 * i, 50}, {100.0 + 3 * i, 51}});
    }
    for (int i = 0; i < 6; ++i) {
        if (i == 3) s.balls.push_back({{-2, 6}, {1, -1}});
        s.balls.push_back({{500.0 + i, 500}, {0, 0.5}});
    }
    s.checks = {Check::no_tunnel};
    const ReducedLog r = reduced(s);
    // Reduced to that wall and that ball, then to the simplest numbers that fail: the ball −1 0 moving
    // (1, 0) reaches the wall's end P0 = (0, 0) at the end of frame 1 (touching is a hit: v′ = (−1, 0));
    // in frame 2 lecture-double hits the same wall again at t = 0 and reflects v′ back to (1, 0), so the path
    // arrives on the wall from the left and leaves to the right, a tunnel. P1.y = 1: 0 would make a
    // zero-length wall, which is never hit.
    EXPECT_EQ(r.log.scene.walls, (std::vector<Wall>{{{0, 0}, {0, 1}}}));
    EXPECT_EQ(r.log.scene.balls, (std::vector<Ball>{{{-1, 0}, {1, 0}}}));
    EXPECT_EQ(r.log.scene.frames, 2);
    ASSERT_TRUE(r.log.scene.found);
    EXPECT_EQ(*r.log.scene.found, (Found{Check::no_tunnel, 2, 0}));
    // A lecture kernel documents its failures: the log expects this one.
    ASSERT_TRUE(r.log.scene.expect_failure);
    EXPECT_EQ(*r.log.scene.expect_failure, (ExpectFailure{Check::no_tunnel, 2}));
    EXPECT_EQ(r.before, (SceneSize{41, 7, 0, 0, 10}));
    EXPECT_EQ(r.after, (SceneSize{1, 1, 0, 0, 2}));
    EXPECT_EQ(r.end, ReduceEnd::fixed_point);
    expect_reproduces(r);
}

TEST(Reduce, NumbersBecomeIntegersWhereTheFailureAllows) {
    // replays/lecture/float-far-1e9-tunnel.scene: a box at 1e9 with fractional coordinates under lecture-float.
    const Scene s = parse_ok(R"(ricochet 1
kernel lecture-float
frames 200
wall 1000000000.125 1000000010.375 1000000000.125 1000000000.125
wall 1000000000.125 1000000000.125 1000000010.375 1000000000.125
wall 1000000010.375 1000000000.125 1000000010.375 1000000010.375
wall 1000000010.375 1000000010.375 1000000000.125 1000000010.375
ball 1000000005 1000000005 3.3 1.7
check no-tunnel
)");
    const ReducedLog r = reduced(s);
    // Float has 24 bits: at 1e9 (a multiple of 64) it rounds y = 1e9 + 5 down to 1e9, so a ball at rest at
    // (1e9, 1e9 + 5) is printed at (1e9, 1e9) after frame 1, and that piece crosses a wall through the points
    // (0, 0) and (1e9, 1e9 + 1) at its end P1. Every number is an integer.
    EXPECT_EQ(r.log.scene.walls, (std::vector<Wall>{{{0, 0}, {1e9, 1e9 + 1}}}));
    EXPECT_EQ(r.log.scene.balls, (std::vector<Ball>{{{1e9, 1e9 + 5}, {0, 0}}}));
    EXPECT_EQ(r.log.scene.frames, 1);
    expect_reproduces(r);
}

TEST(Reduce, SimplerNumbersComeSimplestFirst) {
    using detail::reduce::simpler_numbers;
    // "-2.5" (4 characters): 0 and 1 (1 character), then −1, −2 (trunc, ceil, one digit: 2.5 rounds to even)
    // and −3 (round, floor), then 2.5 without its sign (3 characters).
    EXPECT_EQ(simpler_numbers(-2.5), (std::vector<double>{0, 1, -1, -2, -3, 2.5}));
    // 0.1 + 0.2 = 0.30000000000000004: 0, 1, −1, then 0.3 (1 to 16 digits) before the dyadic 0.5 (j = 1), then
    // 0.25 (j = 2, 3), 0.3125 (j = 4, 5), 0.296875 (j = 6, 7), …: every one shorter than 19 characters.
    const std::vector<double> tenths = simpler_numbers(0.1 + 0.2);
    ASSERT_GE(tenths.size(), 8u);
    EXPECT_EQ(std::vector<double>(tenths.begin(), tenths.begin() + 8),
              (std::vector<double>{0, 1, -1, 0.3, 0.5, 0.25, 0.3125, 0.296875}));
    // An integer has only 0 and 1 below it; 0 has nothing; "-0" (2 characters) has 0 and 1.
    EXPECT_EQ(simpler_numbers(5), (std::vector<double>{0, 1}));
    EXPECT_TRUE(simpler_numbers(0.0).empty());
    const std::vector<double> minus_zero = simpler_numbers(-0.0);
    ASSERT_EQ(minus_zero, (std::vector<double>{0, 1}));
    EXPECT_FALSE(std::signbit(minus_zero[0]));
    // At the range's end every candidate stays in range (1e77 rounded to one digit is itself).
    for (const double v : simpler_numbers(-1.1579208923731619e77)) EXPECT_TRUE(in_range(v)) << v;
}

TEST(Reduce, StaticShapesAreFoundAmongHundredsWithoutHints) {
    // replays/lecture/float-statics-no-balls.scene's pair of circles, 2.000000001 apart with radii 1: float
    // rounds the distance to 2 and lecture-float calls them overlapping. Here at indices 100 and 400 of 600
    // circles on a grid 10 apart (every other pair clearly apart), with 50 rects: delta debugging alone.
    Scene s;
    s.kernel = KernelId::lecture_float;
    for (int i = 0; i < 600; ++i) s.circles.push_back({{1000.0 + 10 * (i % 30), 1000.0 + 10 * (i / 30)}, 1});
    s.circles[100] = {{0, 0}, 1};
    s.circles[400] = {{2.000000001, 0}, 1};
    for (int i = 0; i < 50; ++i) s.rects.push_back({-500.0 - 10 * i, -500, -495.0 - 10 * i, -495});
    s.checks = {Check::oracle};
    const ReducedLog r = reduced(s);
    EXPECT_EQ(r.after, (SceneSize{0, 0, 2, 0, 0}));
    ASSERT_EQ(r.log.scene.circles.size(), 2u);
    EXPECT_EQ(r.log.scene.circles[0], (Circle{{0, 0}, 1}));
    // 2.000000001: no simpler number keeps the distance within float's rounding of 2 yet above it.
    EXPECT_EQ(r.log.scene.circles[1], (Circle{{2.000000001, 0}, 1}));
    // Delta debugging over 600 circles for 2: tens of tries, not hundreds.
    EXPECT_LT(r.tries, 200u);
    expect_reproduces(r);
}

// --- Balls that meet: a mass goes with its ball, `balls collide` stays

/// ATunnelThroughOneOfManyWallsKeepsThatWallAndThatBall's scene, each ball with a mass (ball 3, the one that
/// tunnels, has mass 5).
Scene tunnel_among_masses() {
    Scene s;
    s.kernel = KernelId::lecture_double;
    s.frames = 10;
    for (int i = 0; i < 40; ++i) {
        if (i == 20) s.walls.push_back({{0, 0}, {0, 4}});
        s.walls.push_back({{100.0 + 3 * i, 50}, {100.0 + 3 * i, 51}});
    }
    for (int i = 0; i < 6; ++i) {
        if (i == 3) s.balls.push_back({{-2, 6}, {1, -1}});
        s.balls.push_back({{500.0 + i, 500}, {0, 0.5}});
    }
    s.masses = {2, 3, 4, 5, 6, 7, 8};
    s.checks = {Check::no_tunnel};
    return s;
}

TEST(Reduce, ABallCutOutTakesItsMassWithIt) {
    using namespace detail::reduce;
    const Scene s = tunnel_among_masses();
    const Target target{Check::no_tunnel, {Check::no_tunnel}, std::nullopt};
    std::optional<Failing> start = judge(s, s.kernel, target);
    ASSERT_TRUE(start);
    ReduceOptions options;
    Trials trials(s.kernel, target, std::move(*start), options, 1);
    cut_balls(trials);
    // The failing ball alone, with its own mass: the masses stay one per ball.
    EXPECT_EQ(trials.current().scene.balls, (std::vector<Ball>{{{-2, 6}, {1, -1}}}));
    EXPECT_EQ(trials.current().scene.masses, std::vector<double>{5});
}

TEST(Reduce, MassesThatDoNotMatterAreDropped) {
    // Without `balls collide` no mass changes the run: the reduced log is the one without masses.
    const ReducedLog r = reduced(tunnel_among_masses());
    EXPECT_EQ(r.log.scene.walls, (std::vector<Wall>{{{0, 0}, {0, 1}}}));
    EXPECT_EQ(r.log.scene.balls, (std::vector<Ball>{{{-1, 0}, {1, 0}}}));
    EXPECT_TRUE(r.log.scene.masses.empty());
    EXPECT_NE(r.log.text().find("\nball -1 0 1 0\n"), std::string::npos) << r.log.text();
    expect_reproduces(r);
}

TEST(Reduce, BallsCollideIsKept) {
    // replays/lecture/float-statics-no-balls.scene's circles (oracle at frame 0, no ball to meet), the balls solid:
    // the reduced log is still a case of solid balls.
    Scene s = parse_ok("ricochet 1\nkernel lecture-float\nballs collide\ncircle 0 0 1\ncircle 2.000000001 0 1\n"
                       "circle 50 50 1\ncheck oracle\n");
    const ReducedLog r = reduced(s);
    EXPECT_TRUE(r.log.scene.balls_collide);
    EXPECT_EQ(r.after.circles, 2u);
    EXPECT_NE(r.log.text().find("\nballs collide\n"), std::string::npos) << r.log.text();
    expect_reproduces(r);
}

// --- What the reduced log keeps of the input

TEST(Reduce, KeepsProvenanceAndAddsTheInputsContentId) {
    Scene s = parse_ok(test::k_corners);
    s.provenance = {"property Corners seed 7"};
    const ReducedLog r = reduced(s);
    EXPECT_EQ(r.log.scene.provenance,
              (std::vector<std::string>{"property Corners seed 7", "reduce " + scene_content_id(s)}));
    // k_corners breaks oracle first (of no-tunnel, speed and oracle): the reduced log checks oracle only.
    EXPECT_EQ(r.log.scene.checks, std::vector<Check>{Check::oracle});
    expect_reproduces(r);
}

TEST(Reduce, AnExpectedFailureStaysExpectedUnderAnyKernel) {
    // The mutant kernel (a plug-in held to the guarantees: its failures are not documented) calls every pair
    // of circles overlapping: oracle breaks at frame 0.
    mutant::Mutation m;
    m.ops.circles_overlap = [](const Circle&, const Circle&) { return true; };
    Scene s = parse_ok("ricochet 1\ncircle 0 0 1\ncircle 10 0 1\ncircle 20 0 1\ncheck oracle\n");
    ReduceOptions options;
    options.kernel = mutant::id();
    const ReducedLog plain = reduced(s, options);
    EXPECT_EQ(plain.log.scene.kernel, mutant::id());
    EXPECT_FALSE(plain.log.scene.expect_failure);
    EXPECT_EQ(plain.after.circles, 2u);
    expect_reproduces(plain);
    // The same log expecting its failure: the reduced log expects the reduced failure.
    s.expect_failure = ExpectFailure{Check::oracle, 0};
    const ReducedLog expected = reduced(s, options);
    ASSERT_TRUE(expected.log.scene.expect_failure);
    EXPECT_EQ(*expected.log.scene.expect_failure, (ExpectFailure{Check::oracle, 0}));
    expect_reproduces(expected);
}

// --- What made the failure: a disc stays a disc, a bumper a bumper

/// Steps every ball as if nothing were in its way: a point's and a disc's paths go through everything.
FrameStatus ghost_point(STEP_PARAMS) {
    (void)walls, (void)index;
    return mutant::robust().step_ball(b, mem, {}, hits, scratch, nullptr);
}
FrameStatus ghost_disc(Ball& b, BallMemory& mem, const Obstacles&, std::vector<HitEvent>& hits, StepScratch& scratch) {
    return mutant::robust().step_disc(b, mem, Obstacles{}, hits, scratch);
}

TEST(Reduce, ADiscFailureStaysADiscWhereAPointWouldFailToo) {
    // A disc of radius 0.375 goes through the wall at x = 0 in frame 1. A point ball there tunnels too, and 0 is
    // the simplest radius: only the culprit rule keeps R > 0.
    mutant::Mutation m;
    m.ops.step_ball = &ghost_point;
    m.ops.step_disc = &ghost_disc;
    const Scene s = parse_ok("ricochet 1\nframes 1\nwall 0 -5 0 5\nball -1.75 0.3125 3 0 0.375\ncheck no-tunnel\n");
    ReduceOptions options;
    options.kernel = mutant::id();
    Scene point = s;
    point.balls[0].r = 0.0;
    ASSERT_TRUE(run_checked(point, mutant::id(), 1, point.checks).failure) << "the point would fail as well";
    const ReducedLog r = reduced(s, options);
    ASSERT_EQ(r.log.scene.balls.size(), 1u) << r.log.text();
    EXPECT_GT(r.log.scene.balls[0].r, 0.0) << r.log.text();
    EXPECT_EQ(r.log.scene.found->check, Check::no_tunnel);
    expect_reproduces(r);
}

TEST(Reduce, ACandidateFailingForAnotherKindOfBallOrObstacleIsAnotherFailure) {
    using detail::reduce::Culprit;
    using detail::reduce::judge;
    using detail::reduce::Target;
    // Under lecture-double, a disc of radius 1 reaches into a bumper (replays/discs/lecture/
    // double-bumper-penetration.scene) and one of radius 5 into a wall's cap (double-cap-penetration.scene).
    const Scene bumper = parse_ok("ricochet 1\nkernel lecture-double\nframes 1\nball 13 18 1 -3 1\nbumper 14 14 1\n"
                                  "check penetration\n");
    const Scene cap = parse_ok("ricochet 1\nkernel lecture-double\nframes 1\nwall 0 14 0 18\nball 1 9 0 1 5\n"
                               "check penetration\n");
    const Target into_bumper{Check::penetration, {Check::penetration}, Culprit{true, true}};
    const Target into_wall{Check::penetration, {Check::penetration}, Culprit{true, false}};
    EXPECT_TRUE(judge(bumper, KernelId::lecture_double, into_bumper));
    EXPECT_FALSE(judge(bumper, KernelId::lecture_double, into_wall));
    EXPECT_TRUE(judge(cap, KernelId::lecture_double, into_wall));
    EXPECT_FALSE(judge(cap, KernelId::lecture_double, into_bumper));
    // The point ball of the same check is another culprit; without one (a step error's target) any failure
    // of the check counts.
    const Target point_into_wall{Check::penetration, {Check::penetration}, Culprit{false, false}};
    EXPECT_FALSE(judge(cap, KernelId::lecture_double, point_into_wall));
    EXPECT_TRUE(judge(cap, KernelId::lecture_double, Target{Check::penetration, {Check::penetration}, std::nullopt}));
}

TEST(Reduce, TheLectureKernelsDiscFailuresReduceToDiscFailuresThatReplay) {
    // Every disc failure the lecture kernels leave in the corpus, its expect lines dropped: reduced, it fails the
    // same check for a disc, against the same kind of obstacle, and replays.
    std::vector<std::filesystem::path> logs;
    for (const auto& e : std::filesystem::directory_iterator(RICOCHET_DISC_LECTURE_DIR))
        if (e.path().extension() == ".scene") logs.push_back(e.path());
    std::sort(logs.begin(), logs.end());
    ASSERT_GE(logs.size(), 6u);
    for (const std::filesystem::path& path : logs) {
        SCOPED_TRACE(path.string());
        std::ifstream in(path);
        std::stringstream text;
        text << in.rdbuf();
        Scene log = parse_ok(text.str());
        log.expect_failure.reset();
        log.expect_hash.reset();
        log.expect_states.clear();
        const CheckedRun run = run_checked(log, log.kernel, log.frames, log.checks);
        ASSERT_TRUE(run.failure);
        const ReducedLog r = reduced(log);
        ASSERT_TRUE(r.log.scene.found) << r.log.text();
        EXPECT_EQ(r.log.scene.found->check, run.failure->check) << r.log.text();
        const CheckedRun again = run_checked(r.log.scene, r.log.scene.kernel, r.log.scene.frames, r.log.scene.checks);
        ASSERT_TRUE(again.failure) << r.log.text();
        using detail::reduce::culprit_of;
        EXPECT_EQ(culprit_of(r.log.scene, *again.failure), culprit_of(log, *run.failure)) << r.log.text();
        expect_reproduces(r);
    }
}

// --- Refusals and step errors

/// A bug on one path of the broad phase: with a wall index (the grid, as replay steps by default) the last wall is
/// never tried; with every wall tried (no index) the kernel is right.
FrameStatus blind_with_index(Ball& ball, BallMemory& memory, std::span<const Wall> walls, std::vector<HitEvent>& hits,
                             StepScratch& scratch, const WallIndex* index) {
    if (index != nullptr && !walls.empty())
        return mutant::robust().step_ball(ball, memory, walls.first(walls.size() - 1), hits, scratch, nullptr);
    return mutant::robust().step_ball(ball, memory, walls, hits, scratch, index);
}

TEST(Reduce, JudgesAsReplayStepsSoABugOnOneBroadPhasePathKeepsItsLog) {
    // The ball crosses wall 1 in frame 1. Reduce tried every wall of small scenes (a quicker path that gives the
    // same bits on a correct core): it found no failure here, while replay, stepping with the grid, sees the
    // tunnel. It now steps as replay does, so the failure a harness reports is the one its log replays.
    const Scene s = parse_ok("ricochet 1\nframes 2\nwall -9 -9 -9 -8\nwall 2 -1 2 1\nball 0 0 3 0\ncheck no-tunnel\n");
    mutant::Mutation m;
    m.ops.step_ball = blind_with_index;
    Scene scene = s;
    scene.kernel = mutant::id();
    const ReducedLog r = reduced(scene);
    expect_reproduces(r);
    // Fixed (robust): the log passes.
    EXPECT_TRUE(replay_scene(r.log.scene, KernelId::robust).passed);
}

TEST(Reduce, ALogWhoseChecksHoldIsRefused) {
    Scene s = parse_ok("ricochet 1\nframes 10\nwall 0 -5 0 5\nball -1 0 0.5 0\ncheck no-tunnel\ncheck oracle\n");
    EXPECT_EQ(refusal(s), "every check holds under robust through frame 10: nothing to reduce");
    s.checks.clear();
    EXPECT_EQ(refusal(s), "the log names no check and its run under robust ends at frame 10 without an error: nothing to reduce");
    // Its expect lines play no part: a wrong hash is no check's failure.
    s.expect_hash = 0x0123456789abcdefULL;
    EXPECT_FALSE(replay_scene(s).passed);
    EXPECT_NE(refusal(s).find("nothing to reduce"), std::string::npos);
}

TEST(Reduce, AStepErrorReducesToARunThatStopsTheSameWay) {
    // Ball 1 bounces off the wall at x = 5 and leaves the accepted range (|x| ≤ 2^256 ≈ 1.16e77) in frame 2;
    // no check breaks before.
    const Scene s = parse_ok(R"(ricochet 1
frames 5
wall 5 -1 5 1
wall 7 -1 7 1
ball 0 0 1 0
ball 0 0 1e77 0.3
circle 3 3 1
check no-tunnel
check oracle
)");
    const ReducedLog r = reduced(s);
    ASSERT_TRUE(r.error);
    EXPECT_EQ(r.error->frame, 1);
    // One ball, started where the run had it before frame 2, numbers simplified: it leaves at once.
    EXPECT_EQ(r.after, (SceneSize{0, 1, 0, 0, 1}));
    const Scene back = parse_ok(r.log.text());
    EXPECT_FALSE(back.found);
    EXPECT_FALSE(back.expect_failure);
    EXPECT_TRUE(back.expect_states.empty());
    // The log's checks, kept: they held up to the error, and still do.
    EXPECT_EQ(back.checks, (std::vector<Check>{Check::no_tunnel, Check::oracle}));
    const ReplayResult replay = replay_scene(back);
    EXPECT_FALSE(replay.passed);
    EXPECT_NE(replay.message.find("frame 1 ball 0:"), std::string::npos) << replay.message;
    EXPECT_NE(replay.message.find("would leave the accepted range"), std::string::npos) << replay.message;
    EXPECT_FALSE(replay.run.failure) << replay.message;
}

// --- The budget, a stop, progress and determinism

TEST(Reduce, TheBudgetAndAStopEndItWithAFailureLogOfWhatItHas) {
    const Scene ring = test::ring_scene(1000, KernelId::lecture_double, 3000);
    ReduceOptions budget;
    budget.max_tries = 10;
    const ReducedLog spent = reduced(ring, budget);
    EXPECT_EQ(spent.end, ReduceEnd::budget);
    EXPECT_EQ(spent.tries, 10u);
    expect_reproduces(spent);

    // A stop asked once 5 tries are made (as Ctrl-C would be, between two tries).
    ReduceOptions stop;
    std::uint64_t tries = 0;
    stop.on_progress = [&](const ReduceProgress& p) { tries = p.tries; };
    stop.stop = [&] { return tries >= 5; };
    const ReducedLog stopped = reduced(ring, stop);
    EXPECT_EQ(stopped.end, ReduceEnd::stopped);
    EXPECT_EQ(stopped.tries, 5u);
    expect_reproduces(stopped);
}

TEST(Reduce, ProgressCountsEveryTryAndTheSameLogGivesTheSameBytes) {
    const Scene ring = test::ring_scene(1000, KernelId::lecture_double, 3000);
    std::vector<ReduceProgress> seen;
    ReduceOptions options;
    options.on_progress = [&](const ReduceProgress& p) { seen.push_back(p); };
    const ReducedLog a = reduced(ring, options);
    ASSERT_FALSE(seen.empty());
    // One call per try after the first two runs, tries counting up, the scene never growing.
    EXPECT_EQ(seen.front().tries, 3u);
    EXPECT_EQ(seen.back().tries, a.tries);
    for (std::size_t i = 1; i < seen.size(); ++i) {
        EXPECT_EQ(seen[i].tries, seen[i - 1].tries + 1);
        EXPECT_LE(seen[i].size.entities(), seen[i - 1].size.entities());
        EXPECT_LE(seen[i].size.frames, seen[i - 1].size.frames);
    }
    const ReducedLog b = reduced(ring);
    EXPECT_EQ(a.log.text(), b.log.text());
    EXPECT_EQ(a.tries, b.tries);
}

// --- Scale

TEST(Reduce, ARingOfAThousandWallsReducesToAHandfulOfEntities) {
    // A closed chain of 1000 walls, lecture-double: the ball bounces round it and tunnels out at frame 7.
    const Scene ring = test::ring_scene(1000, KernelId::lecture_double, 3000);
    ASSERT_EQ(ring.walls.size(), 1000u);
    const CheckedRun run = run_checked(ring, ring.kernel, ring.frames, ring.checks);
    ASSERT_TRUE(run.failure);
    ASSERT_EQ(run.failure->frame, 7);
    const ReducedLog r = reduced(ring);
    EXPECT_EQ(r.end, ReduceEnd::fixed_point);
    EXPECT_LE(r.after.entities(), 4u) << r.log.text();
    EXPECT_EQ(r.after.balls, 1u);
    // Frames cut from the front too: it fails before frame 7.
    EXPECT_LT(r.after.frames, 7);
    EXPECT_EQ(r.log.scene.found->check, Check::no_tunnel);
    expect_reproduces(r);
}

}  // namespace
}  // namespace ricochet
