// World and its parallel stepper: the same events, worked by hand, on every thread count (more threads
// than balls, no thread at all, a moved World); what a World says it skips; which ball a range error names;
// five walls meeting at one point; record's choice of frames; check names, hash digits and format specs.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ricochet/format.hpp"
#include "ricochet/hash.hpp"
#include "ricochet/record.hpp"
#include "ricochet/world.hpp"

namespace ricochet {
namespace {

std::vector<std::string> lines(const std::vector<Event>& events) {
    std::vector<std::string> out;
    for (const Event& e : events) out.push_back(format_event(e));
    return out;
}

// Balls k = 0..n−1 at (8, k) moving (4, 0) towards the wall x = 10, ball n−1 at rest. A moving ball's leg
// (8, k) → (12, k) meets the wall at s = 0.5, B_i = (10, k); n̂ = (1, 0), so v' = (−4, 0) and the other
// half of the frame takes it back to (8, k). Frame 2 goes on to (4, k).
Scene column(std::uint32_t n) {
    Scene s;
    s.walls = {{{10, -100}, {10, 100}}};
    for (std::uint32_t k = 0; k + 1 < n; ++k) s.balls.push_back({{8, double(k)}, {4, 0}});
    s.balls.push_back({{0, -1}, {0, 0}});
    return s;
}

std::vector<std::string> column_by_hand(std::uint32_t n) {
    std::vector<std::string> want;
    for (std::uint32_t k = 0; k + 1 < n; ++k) want.push_back(fmt::format("state 0 {} 8 {} 4 0", k, k));
    want.push_back(fmt::format("state 0 {} 0 -1 0 0", n - 1));
    for (std::uint32_t k = 0; k + 1 < n; ++k) {
        want.push_back(fmt::format("hit 1 {} 0 10 {}", k, k));
        want.push_back(fmt::format("state 1 {} 8 {} -4 0", k, k));
    }
    want.push_back(fmt::format("state 1 {} 0 -1 0 0", n - 1));
    for (std::uint32_t k = 0; k + 1 < n; ++k) want.push_back(fmt::format("state 2 {} 4 {} -4 0", k, k));
    want.push_back(fmt::format("state 2 {} 0 -1 0 0", n - 1));
    return want;
}

TEST(WorldThreads, EveryThreadCountGivesTheEventsWorkedByHand) {
    // 7 balls: 3 threads share them (parts of 2, 2 and 3 balls); 16 threads are more than 7/2, so one
    // thread steps every part, most of them empty; 0 threads is one.
    for (BroadPhase bp : {BroadPhase::none, BroadPhase::grid, BroadPhase::bvh})
        for (unsigned threads : {0u, 1u, 2u, 3u, 16u}) {
            EXPECT_EQ(lines(run_scene(column(7), KernelId::robust, 2, {.broad_phase = bp, .threads = threads})),
                      column_by_hand(7))
                << threads << " threads, broad phase " << int(bp);
        }
}

TEST(WorldThreads, OneBallOnManyThreads) {
    EXPECT_EQ(lines(run_scene(column(1), KernelId::robust, 2, {.threads = 4})), column_by_hand(1));
    EXPECT_EQ(lines(run_scene(column(2), KernelId::exact, 2, {.threads = 4})), column_by_hand(2));
}

TEST(WorldThreads, AnEmptySceneHasNoEventsAndNothingToSkipButTheFallback) {
    const World w(Scene{}, KernelId::robust, {.threads = 3});
    EXPECT_EQ(w.wall_index(), nullptr);
    EXPECT_EQ(w.skipped(), "no static-test pass (no circles or rectangles); exact fallback: kept (no filter-only proof)");
    EXPECT_TRUE(run_scene(Scene{}, KernelId::robust, 5, {.threads = 3}).empty());
}

TEST(WorldThreads, AMovedWorldStepsOnFromWhereItWas) {
    World a(column(3), KernelId::robust, {.threads = 2});
    std::vector<Event> events;
    a.start(events);
    ASSERT_FALSE(a.step(events));
    World b(std::move(a));
    ASSERT_FALSE(b.step(events));
    EXPECT_EQ(b.frame(), 2);
    EXPECT_EQ(lines(events), column_by_hand(3));
    World c(Scene{}, KernelId::exact);
    c = std::move(b);
    EXPECT_EQ(c.frame(), 2);
    EXPECT_EQ(c.kernel(), KernelId::robust);
    ASSERT_EQ(c.balls().size(), 3u);
    EXPECT_EQ(c.balls()[0], (Ball{{4, 0}, {-4, 0}}));
}

TEST(WorldSkips, EachConfigurationSaysWhatItSkips) {
    Scene s = column(2);
    EXPECT_EQ(World(s, KernelId::robust).skipped(),
              "no static-test pass (no circles or rectangles); walls: uniform-grid broad phase; "
              "exact fallback: kept (no filter-only proof)");
    s.circles = {{{0, 0}, 1}};
    EXPECT_EQ(World(s, KernelId::robust, {.broad_phase = BroadPhase::bvh}).skipped(),
              "static tests: one cell lookup per ball; walls: BVH broad phase; exact fallback: kept (no filter-only proof)");
    // No broad phase: neither an index for the walls nor one for the statics, so no clause for either.
    EXPECT_EQ(World(s, KernelId::robust, {.broad_phase = BroadPhase::none}).skipped(),
              "exact fallback: kept (no filter-only proof)");
    // The exact kernel never gets a wall index, but the statics still get theirs.
    EXPECT_EQ(World(s, KernelId::exact).skipped(),
              "static tests: one cell lookup per ball; exact fallback: kept (no filter-only proof)");
}

TEST(WorldStatics, OverlapsWithAndWithoutTheStaticIndexAgree) {
    // A ball resting at (1, 1) lies in circle 1 (centre (1, 2), r = 1: distance exactly 1) and rect 0,
    // not in circle 0; the overlaps follow the states, circles before rects.
    Scene s;
    s.balls = {{{1, 1}, {0, 0}}, {{5, 5}, {0, 0}}};
    s.circles = {{{4, 4}, 0.5}, {{1, 2}, 1}};
    s.rects = {{0, 0, 1, 1}, {2, 2, 3, 3}};
    const std::vector<std::string> want = {"state 0 0 1 1 0 0", "state 0 1 5 5 0 0", "overlap 0 0 circle 1",
                                           "overlap 0 0 rect 0",  "state 1 0 1 1 0 0", "state 1 1 5 5 0 0",
                                           "overlap 1 0 circle 1", "overlap 1 0 rect 0"};
    for (BroadPhase bp : {BroadPhase::none, BroadPhase::grid})
        EXPECT_EQ(lines(run_scene(s, KernelId::robust, 1, {.broad_phase = bp})), want) << int(bp);
}

TEST(WorldRange, TheErrorNamesTheFirstBallThatWouldLeaveAndEveryBallKeepsItsState) {
    // Balls 1 and 2 would pass 2^256 ≈ 1.158e77 in frame 1; ball 0 moves on. The error is ball 1's, and
    // both keep their states of frame 0 (still printed).
    Scene s;
    s.balls = {{{0, 0}, {1, 0}}, {{0, 1e77}, {0, 1e77}}, {{-1e77, 0}, {-1e77, 0}}};
    World w(s, KernelId::robust, {.threads = 2});
    std::vector<Event> events;
    w.start(events);
    events.clear();
    const auto error = w.step(events);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->frame, 1);
    EXPECT_EQ(error->ball, 1u);
    EXPECT_EQ(error->status, FrameStatus::out_of_range);
    EXPECT_EQ(error->state, s.balls[1]);
    EXPECT_EQ(error->message(),
              "frame 1 ball 1: the ball at (0, 1e+77) moving (0, 1e+77) would leave the accepted range "
              "(|coordinate| <= 2^256, finite); the run stops here");
    EXPECT_EQ(lines(events), (std::vector<std::string>{"state 1 0 1 0 1 0", "state 1 1 0 1e+77 0 1e+77",
                                                       "state 1 2 -1e+77 0 -1e+77 0"}));
    try {
        (void)run_scene(s, KernelId::robust, 1);
        ADD_FAILURE() << "expected StepFailure";
    } catch (const StepFailure& f) {
        EXPECT_EQ(std::string(f.what()), error->message());
        EXPECT_EQ(f.error().ball, 1u);
    }
}

TEST(WorldRange, ABallAlreadyOutOfRangeIsAnErrorInFrameOne) {
    Scene s;
    s.balls = {{{0x1p257, 0}, {0, 0}}};
    World w(s, KernelId::lecture_double);
    std::vector<Event> events;
    const auto error = w.step(events);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->ball, 0u);
    EXPECT_EQ(lines(events), (std::vector<std::string>{fmt::format("state 1 0 {} 0 0 0", 0x1p257)}));
}

}  // namespace
}  // namespace ricochet

namespace ricochet {
namespace {

TEST(WorldSkips, RectsAloneGetTheStaticIndex) {
    Scene s;
    s.rects = {{0, 0, 1, 1}};
    EXPECT_EQ(World(s, KernelId::robust).skipped(),
              "static tests: one cell lookup per ball; exact fallback: kept (no filter-only proof)");
}

TEST(WorldContacts, FiveWallsMeetingAtTheEndPointAreMoreThanMemoryHolds) {
    // Five walls through the origin (slopes 1, −1, 0, ∞, 1/2); the ball's leg (3, 1) → (0, 0), of slope
    // 1/3, crosses none of them before its end, where all five meet: more contacts than BallMemory's four,
    // so the end is walked back by one ulp of M = 3, as a fraction g = 3·2^-52 / 3 = 2^-52 of the piece:
    // q + (1 − 2^-52)·(−3, −1), where (1 − 2^-52)·(−3) = −3 + 1.5·2^-51 is a tie that rounds to even,
    // −3 + 2^-50, so the point is (2^-50, 2^-52); and the hit is wall 0's (the lowest index of a tie).
    Scene s;
    s.walls = {{{-4, -4}, {4, 4}}, {{-4, 4}, {4, -4}}, {{-4, 0}, {4, 0}}, {{0, -4}, {0, 4}}, {{-4, -2}, {4, 2}}};
    s.balls = {{{3, 1}, {-3, -1}}};
    const std::vector<Event> ev = run_scene(s, KernelId::robust, 1, {.broad_phase = BroadPhase::none});
    ASSERT_GE(ev.size(), 3u);
    EXPECT_EQ(ev[1].kind, Event::Kind::hit);
    EXPECT_EQ(ev[1].index, 0u);
    EXPECT_EQ(ev[1].pos, (Vec2{0x1p-50, 0x1p-52}));
}

TEST(Record, LongRunsRecordEightSpreadFramesOfTheFirstEightBalls) {
    // 9 balls × 17 frames > 64: frames 16·k/8 for k = 1..8 (2, 4, …, 16), balls 0..7 only.
    Scene s;
    s.frames = 16;
    for (int k = 0; k < 9; ++k) s.balls.push_back({{double(k), 0}, {0, 1}});
    const CheckedRun run = record_expectations(s);
    ASSERT_FALSE(run.error);
    ASSERT_EQ(s.expect_states.size(), 64u);
    EXPECT_EQ(s.expect_hash, run.hash);
    for (std::size_t i = 0; i < s.expect_states.size(); ++i) {
        const ExpectState& e = s.expect_states[i];
        EXPECT_EQ(e.frame, std::int64_t(2 * (i / 8 + 1))) << i;
        EXPECT_EQ(e.ball, std::uint32_t(i % 8)) << i;
        EXPECT_EQ(e.state, (Ball{{double(i % 8), double(e.frame)}, {0, 1}})) << i;
    }
}

TEST(Record, ARunThatLeavesTheRangeRecordsNothing) {
    Scene s;
    s.frames = 3;
    s.balls = {{{0, 1e77}, {0, 1e77}}};
    s.expect_hash = 7;
    const CheckedRun run = record_expectations(s);
    ASSERT_TRUE(run.error);
    EXPECT_EQ(run.error->frame, 1);
    EXPECT_EQ(s.expect_hash, 7u);
    EXPECT_TRUE(s.expect_states.empty());
}

TEST(NamesAndHashes, OutOfEnumChecksAndHashDigitsOutsideTheAlphabet) {
    EXPECT_EQ(check_name(static_cast<Check>(99)), "?");
    EXPECT_EQ(parse_check("?"), std::nullopt);
    // ' ' sorts below '0', ':' just above '9', '`' just below 'a', 'g' just above 'f'; uppercase is not taken.
    EXPECT_FALSE(parse_hash("000000000000000 "));
    EXPECT_FALSE(parse_hash("000000000000000:"));
    EXPECT_FALSE(parse_hash("000000000000000`"));
    EXPECT_FALSE(parse_hash("000000000000000g"));
    EXPECT_FALSE(parse_hash("00000000000000aF"));
    EXPECT_EQ(parse_hash("00000000000000af"), 0xafULL);
}

TEST(FormatSpecs, CoreValuesAcceptAnEmptySpecAndRefuseAnyOther) {
    EXPECT_EQ(fmt::format("{:}", Vec2{1, -0.5}), "(1, -0.5)");
    EXPECT_THROW((void)fmt::format(fmt::runtime("{:>9}"), Vec2{1, 2}), fmt::format_error);
    EXPECT_THROW((void)fmt::format(fmt::runtime("{:x}"), Wall{}), fmt::format_error);
}

}  // namespace
}  // namespace ricochet
