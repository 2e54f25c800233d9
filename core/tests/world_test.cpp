// World stepping, event order, the run hash, checks and replay.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "ricochet/checks.hpp"
#include "ricochet/format.hpp"
#include "ricochet/hash.hpp"
#include "ricochet/record.hpp"
#include "ricochet/replay.hpp"
#include "ricochet/scene_log.hpp"
#include "ricochet/world.hpp"

namespace ricochet {
namespace {

std::vector<Wall> box(double lo, double hi) {
    return {{{lo, hi}, {lo, lo}}, {{lo, lo}, {hi, lo}}, {{hi, lo}, {hi, hi}}, {{hi, hi}, {lo, hi}}};
}

Scene lecture_pinball() {
    Scene s;
    s.frames = 3;
    s.walls = box(0, 10);
    s.balls = {{{8, 5}, {4, 1}}, {{1, 1}, {0, 0}}};
    s.circles = {{{8, 6}, 0.0}};
    s.rects = {{0, 0, 1, 1}};
    return s;
}

TEST(World, EventsComeInTheSpecsOrder) {
    const std::vector<Event> ev = run_scene(lecture_pinball(), KernelId::robust, 1);
    std::vector<std::string> lines;
    for (const Event& e : ev) lines.push_back(format_event(e));
    // Frame 0: states, then overlaps. Frame 1: ball 0's hit then state, ball 1's state, then overlaps.
    // The lecture's example: t_i = 0.5, B_i = (10, 5.5), v' = (-4, 1), end (8, 6) on the radius-0 circle.
    const std::vector<std::string> want = {
        "state 0 0 8 5 4 1",     "state 0 1 1 1 0 0",     "overlap 0 1 rect 0",    "hit 1 0 2 10 5.5",
        "state 1 0 8 6 -4 1",    "state 1 1 1 1 0 0",     "overlap 1 0 circle 0",  "overlap 1 1 rect 0"};
    EXPECT_EQ(lines, want);
}

TEST(World, LeavingTheRangeIsAnError) {
    Scene s;
    s.frames = 5;
    s.balls = {{{1e77, 0}, {1e76, 0}}, {{0, 0}, {1, 0}}};
    try {
        (void)run_scene(s, KernelId::robust, 5);
        FAIL() << "expected StepFailure";
    } catch (const StepFailure& f) {
        // 1e77 + 1e76·k passes 2^256 ≈ 1.158e77 in frame 2.
        EXPECT_EQ(f.error().frame, 2);
        EXPECT_EQ(f.error().ball, 0u);
        EXPECT_NE(std::string(f.what()).find("accepted range"), std::string::npos);
    }
    const CheckedRun run = run_checked(s, KernelId::robust, 5, {});
    ASSERT_TRUE(run.error);
    EXPECT_EQ(run.frames_run, 2);
}

TEST(World, PicksItsIndicesFromItsOptionsAndKernel) {
    const Scene s = lecture_pinball();
    const World grid(s, KernelId::robust);  // the defaults: broad phase on
    EXPECT_NE(grid.wall_index(), nullptr);
    EXPECT_NE(grid.skipped().find("uniform-grid"), std::string::npos) << grid.skipped();
    EXPECT_NE(grid.skipped().find("one cell lookup"), std::string::npos) << grid.skipped();
    const World bvh(s, KernelId::robust, {.broad_phase = BroadPhase::bvh});
    EXPECT_NE(bvh.wall_index(), nullptr);
    EXPECT_NE(bvh.skipped().find("BVH"), std::string::npos) << bvh.skipped();
    const World none(s, KernelId::robust, {.broad_phase = BroadPhase::none});
    EXPECT_EQ(none.wall_index(), nullptr);
    EXPECT_EQ(none.skipped().find("one cell lookup"), std::string::npos) << none.skipped();
    // The exact kernel tries every wall: no index is built for it.
    EXPECT_EQ(World(s, KernelId::exact).wall_index(), nullptr);
}

TEST(World, StopsAtTheBounceLimitOnAnyThreadCount) {
    // Ball 0 flies 100 units a frame between walls 1 apart: past k_max_bounces in frame 1. Ball 1 rests.
    Scene s;
    s.walls = {{{0, -10}, {0, 10}}, {{1, 10}, {1, -10}}};
    s.balls = {{{0.5, 0}, {100, 0.25}}, {{0.25, 0}, {0, 0}}};
    for (unsigned threads : {1u, 2u}) {
        World w(s, KernelId::robust, {.threads = threads});
        std::vector<Event> events;
        w.start(events);
        ASSERT_FALSE(w.step(events));
        std::size_t hits = 0;
        for (const Event& e : events) hits += e.kind == Event::Kind::hit && e.ball == 0;
        EXPECT_EQ(hits, static_cast<std::size_t>(k_max_bounces)) << threads << " threads";
    }
}

TEST(Format, CoreTypesPrintInShortestRoundTripForm) {
    EXPECT_EQ(fmt::format("{}", Vec2{1, -0.1}), "(1, -0.1)");
    EXPECT_EQ(fmt::format("{}", Wall{{0, 1}, {2.5, -0.0}}), "0 1 2.5 -0");
    EXPECT_EQ(fmt::format("{}", Ball{{1e300, 2}, {3, 0x1p-1074}}), "1e+300 2 3 5e-324");
    EXPECT_EQ(fmt::format("{}", Circle{{1, 2}, 0.5}), "1 2 0.5");
    EXPECT_EQ(fmt::format("{}", Rect{-1, -2, 3, 4}), "-1 -2 3 4");
    EXPECT_EQ(fmt::format("[{:>8}]", KernelId::exact), "[   exact]");
    EXPECT_EQ(fmt::format("{} {}", Check::no_tunnel, Miss::both_inside), "no-tunnel both-inside");
    EXPECT_EQ(fmt::format("{} {} {}", side_from_sign(1), side_from_sign(-1), side_from_sign(0)), "outside inside on");
    const Event overlap{Event::Kind::overlap, 3, 1, Event::Shape::circle, 7, {}, {}};
    EXPECT_EQ(fmt::format("{}", overlap), "overlap 3 1 circle 7");
    EXPECT_EQ(format_event(overlap), "overlap 3 1 circle 7");
}

TEST(Hash, RecordLayoutIsAsDocumented) {
    Event e{Event::Kind::hit, -2, 0x01020304, Event::Shape::rect, 0x0a0b0c0d, {1.0, -0.0}, {0.0, 2.0}};
    unsigned char r[k_event_record_size];
    encode_event(e, r);
    const unsigned char want[k_event_record_size] = {
        1, 2, 0, 0, 4, 3, 2, 1,                             // kind, shape, pad, ball
        0xfe, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff,     // frame −2
        0x0d, 0x0c, 0x0b, 0x0a, 0, 0, 0, 0,                 // index, pad
        0, 0, 0, 0, 0, 0, 0xf0, 0x3f,                       // 1.0
        0, 0, 0, 0, 0, 0, 0, 0x80,                          // −0.0
        0, 0, 0, 0, 0, 0, 0, 0,                             // 0.0
        0, 0, 0, 0, 0, 0, 0, 0x40};                         // 2.0
    EXPECT_TRUE(std::equal(r, r + k_event_record_size, want));
}

TEST(Hash, IsXxh64SeedZeroAndStable) {
    // XXH64 of no bytes with seed 0 (the published known answer).
    EXPECT_EQ(hash_events({}), 0xef46db3751d8e999ULL);
    const Scene s = lecture_pinball();
    const auto a = run_scene(s, KernelId::robust, 50);
    EXPECT_EQ(hash_events(a), hash_events(run_scene(s, KernelId::robust, 50)));
    RunHasher h;
    for (const Event& e : a) h.add(e);
    EXPECT_EQ(h.digest(), hash_events(a));
    // Bit patterns, not values: −0 and +0 hash differently.
    Event z;
    Event nz = z;
    nz.pos.x = -0.0;
    EXPECT_NE(hash_events(std::span(&z, 1)), hash_events(std::span(&nz, 1)));
}

TEST(Hash, FormatsAndParses) {
    EXPECT_EQ(format_hash(0x1a), "000000000000001a");
    EXPECT_EQ(parse_hash("000000000000001a"), 0x1aULL);
    EXPECT_FALSE(parse_hash("000000000000001A"));  // docs/scene-log.md: lowercase only
    EXPECT_EQ(parse_hash(format_hash(0xfedcba9876543210ULL)), 0xfedcba9876543210ULL);
    EXPECT_FALSE(parse_hash("00000000000001a"));
    EXPECT_FALSE(parse_hash("00000000000000001a"));
    EXPECT_FALSE(parse_hash("000000000000001g"));
}

TEST(Checks, NamesRoundTrip) {
    for (Check c : {Check::no_tunnel, Check::symmetry, Check::boundary, Check::speed, Check::deterministic,
                    Check::oracle})
        EXPECT_EQ(parse_check(check_name(c)), c);
    EXPECT_FALSE(parse_check("no_tunnel"));
}

TEST(Checks, RobustKeepsEveryInvariantOnThePinball) {
    Scene s = lecture_pinball();
    s.walls.push_back({{0, 2}, {3, 0.5}});
    s.circles.push_back({{3, 7}, 1});
    const std::vector<Check> all = {Check::no_tunnel, Check::symmetry, Check::boundary, Check::speed,
                                    Check::deterministic, Check::oracle};
    const CheckedRun run = run_checked(s, KernelId::robust, 300, all);
    EXPECT_FALSE(run.failure) << run.failure->str();
    EXPECT_EQ(run.hash, hash_events(run.events));
}

TEST(Checks, MirrorIsAnInvolution) {
    Scene s = lecture_pinball();
    s.rects = {{-1, 2, 3, 4}};
    EXPECT_TRUE(same_bits(mirror_x(mirror_x(s)), s));
    EXPECT_EQ(mirror_x(s).rects[0], (Rect{-3, 2, 1, 4}));
}

TEST(Checks, NoTunnelCatchesTheLectureKernelAtAWallEnd) {
    // Ends frame 3 exactly on wall 0's end point (0, 4), then leaves through it (replays/lecture too).
    Scene s;
    s.walls = {{{0, 0}, {0, 4}}};
    s.balls = {{{-3, 7}, {1, -1}}};
    const CheckedRun run = run_checked(s, KernelId::lecture_double, 5, std::vector<Check>{Check::no_tunnel});
    ASSERT_TRUE(run.failure);
    EXPECT_EQ(run.failure->check, Check::no_tunnel);
    EXPECT_EQ(run.failure->frame, 4);
    EXPECT_FALSE(run_checked(s, KernelId::robust, 5, std::vector<Check>{Check::no_tunnel}).failure);
}

TEST(Replay, NamesTheFirstDivergingFrameAndTheHash) {
    Scene s = lecture_pinball();
    s.frames = 4;
    s.checks = {Check::no_tunnel};
    CheckedRun rec = record_expectations(s);
    ASSERT_FALSE(rec.error);
    EXPECT_TRUE(replay_scene(s).passed) << replay_scene(s).message;
    // A recorded log read back replays too.
    auto back = parse_scene_log(write_scene_log(s), "x");
    ASSERT_TRUE(std::holds_alternative<Scene>(back));
    EXPECT_TRUE(replay_scene(std::get<Scene>(back)).passed);

    Scene bad = s;
    bad.expect_states[3].state.pos.y = std::nextafter(bad.expect_states[3].state.pos.y, 100.0);
    const ReplayResult r = replay_scene(bad);
    EXPECT_FALSE(r.passed);
    EXPECT_NE(r.message.find(fmt::format("first diverging frame {}", bad.expect_states[3].frame)), std::string::npos)
        << r.message;

    Scene bad_hash = s;
    *bad_hash.expect_hash ^= 1;
    const ReplayResult h = replay_scene(bad_hash);
    EXPECT_FALSE(h.passed);
    EXPECT_NE(h.message.find("hash expected"), std::string::npos) << h.message;
}

TEST(Replay, ExpectFailurePassesOnlyWhileThatFailureReproduces) {
    Scene s;
    s.frames = 5;
    s.kernel = KernelId::lecture_double;
    s.walls = {{{0, 0}, {0, 4}}};
    s.balls = {{{-3, 7}, {1, -1}}};
    s.checks = {Check::no_tunnel};
    record_expectations(s);
    ASSERT_TRUE(s.expect_failure);
    EXPECT_TRUE(replay_scene(s).passed);
    Scene wrong_frame = s;
    wrong_frame.expect_failure->frame += 1;
    EXPECT_FALSE(replay_scene(wrong_frame).passed);
    // Under the robust kernel the failure no longer reproduces: the log fails (and says so).
    const ReplayResult r = replay_scene(s, KernelId::robust);
    EXPECT_FALSE(r.passed);
    EXPECT_NE(r.message.find("every check held"), std::string::npos) << r.message;
}

}  // namespace
}  // namespace ricochet
