// The checks of balls that meet on frames written by hand (frame_check.hpp): ball-overlap on centres one ulp closer
// than R_i + R_j, pass-through on pieces that cross, jump-through on a jump through a ball standing, momentum on
// responses that gain or lose, relabel on a run whose balls renumbered differ; and how the older checks read a meet
// (speed and oracle leave a ball that met to them, ghost-bounce and bounce-side take a meet as a bump, swap and
// translation compare no first contact a meet decided). No kernel makes these mistakes on purpose, so each check is
// fed the broken frame directly.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "checks/frame_check.hpp"
#include "checks/mapped_run.hpp"

namespace ricochet::checks {
namespace {

Event state(std::int64_t f, std::uint32_t ball, Vec2 pos, Vec2 vel = {}) {
    return {Event::Kind::state, f, ball, Event::Shape::none, 0, pos, vel};
}
Event meet(std::int64_t f, std::uint32_t ball, std::uint32_t other, Vec2 pos, Vec2 vel = {}) {
    return {Event::Kind::meet, f, ball, Event::Shape::none, other, pos, vel};
}
Event hit(std::int64_t f, std::uint32_t ball, std::uint32_t wall, Vec2 pos) {
    return {Event::Kind::hit, f, ball, Event::Shape::none, wall, pos, {}};
}

/// Balls of the given centres and radii whose balls collide, at rest.
Scene discs(std::vector<Vec2> at, std::vector<double> radii) {
    Scene s;
    s.balls_collide = true;
    for (std::size_t i = 0; i < at.size(); ++i) s.balls.push_back({at[i], {}, radii[i]});
    return s;
}

/// Frame 0 of the scene: each ball's state.
std::vector<Event> start(const Scene& s) {
    std::vector<Event> out;
    for (std::uint32_t b = 0; b < s.balls.size(); ++b) out.push_back(state(0, b, s.balls[b].pos, s.balls[b].vel));
    return out;
}

/// What a check says over frames 0, 1, … (frame 0: the scene's states; each later frame's events as given, with the
/// balls' states before it taken from the frame before): the first failure, "" if none.
std::string verdict(FrameCheck& check, const Scene& s, const std::vector<std::vector<Event>>& frames) {
    std::vector<Event> zero = start(s);
    if (auto r = check.frame(Frame{0, zero, {}, {}, {}})) return r->str();
    std::vector<Ball> before = s.balls;
    const std::vector<BallMemory> memory(s.balls.size());
    for (std::size_t f = 0; f < frames.size(); ++f) {
        if (auto r = check.frame(Frame{static_cast<std::int64_t>(f + 1), frames[f], before, memory, {}})) return r->str();
        for (const Event& e : frames[f])
            if (e.kind == Event::Kind::state) before[e.ball] = {e.pos, e.vel, s.balls[e.ball].r};
    }
    return "";
}

std::string overlap_verdict(const Scene& s, const std::vector<std::vector<Event>>& frames) {
    return verdict(*make_ball_overlap(s, KernelId::robust, {}), s, frames);
}

bool has(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

const double below_two = std::nextafter(2.0, 0.0);

TEST(BallOverlap, ExactlySApartHoldsOneUlpCloserFails) {
    // Radii 1 and 1, S = 2: from 3 apart to exactly 2 apart holds, to 2 − ulp fails.
    const Scene s = discs({{0, 0}, {3, 0}}, {1, 1});
    EXPECT_EQ(overlap_verdict(s, {{state(1, 0, {0, 0}), state(1, 1, {2, 0})}}), "");
    const std::string bad = overlap_verdict(s, {{state(1, 0, {0, 0}), state(1, 1, {below_two, 0})}});
    EXPECT_TRUE(has(bad, "ball-overlap broke at frame 1 ball 0: balls 0 and 1")) << bad;
    EXPECT_TRUE(has(bad, "the end of frame 1")) << bad;
    // Diagonally, exactly: (1.2, 1.6) is 2 from the origin; one ulp nearer in y is not.
    EXPECT_EQ(overlap_verdict(s, {{state(1, 0, {0, 0}), state(1, 1, {1.2, 1.6})}}), "");
    EXPECT_NE(overlap_verdict(s, {{state(1, 0, {0, 0}), state(1, 1, {1.2, std::nextafter(1.6, 0.0)})}}), "");
    // A point ball meets a disc at its rim: S = 1.
    const Scene point = discs({{0, 0}, {3, 0}}, {0, 1});
    EXPECT_EQ(overlap_verdict(point, {{state(1, 0, {0, 0}), state(1, 1, {1, 0})}}), "");
    EXPECT_NE(overlap_verdict(point, {{state(1, 0, {0, 0}), state(1, 1, {std::nextafter(1.0, 0.0), 0})}}), "");
}

TEST(BallOverlap, AMeetsTwoCentresAreACommonPrintedTime) {
    const Scene s = discs({{0, 0}, {3, 0}}, {1, 1});
    // The ends are clear, the meet's two centres one ulp closer than S are not.
    const std::string bad = overlap_verdict(s, {{meet(1, 0, 1, {0, 0}), state(1, 0, {-1, 0}), meet(1, 1, 0, {below_two, 0}),
                                                 state(1, 1, {5, 0})}});
    EXPECT_TRUE(has(bad, "their meet 0 in frame 1")) << bad;
    EXPECT_EQ(overlap_verdict(s, {{meet(1, 0, 1, {0, 0}), state(1, 0, {-1, 0}), meet(1, 1, 0, {2, 0}), state(1, 1, {5, 0})}}),
              "");
    // The k-th meet under one ball goes with the k-th under the other: the second pair of centres is too close.
    EXPECT_NE(overlap_verdict(s, {{meet(1, 0, 1, {0, 0}), meet(1, 0, 1, {0, 0}), state(1, 0, {-1, 0}),
                                   meet(1, 1, 0, {2, 0}), meet(1, 1, 0, {below_two, 0}), state(1, 1, {5, 0})}}),
              "");
}

TEST(BallOverlap, APairPlacedOverlappingIsHeldOnlyOnceClear) {
    const Scene s = discs({{0, 0}, {1, 0}}, {1, 1});
    // Closer than S from the start: not judged until clear, then held.
    EXPECT_EQ(overlap_verdict(s, {{state(1, 0, {0, 0}), state(1, 1, {1.5, 0})}}), "");
    EXPECT_EQ(overlap_verdict(s, {{state(1, 0, {0, 0}), state(1, 1, {1.5, 0})}, {state(2, 0, {0, 0}), state(2, 1, {2, 0})}}),
              "");
    EXPECT_NE(overlap_verdict(s, {{state(1, 0, {0, 0}), state(1, 1, {1.5, 0})},
                                  {state(2, 0, {0, 0}), state(2, 1, {2, 0})},
                                  {state(3, 0, {0, 0}), state(3, 1, {1.9, 0})}}),
              "");
    // A meet's centres clear arm it too.
    EXPECT_NE(overlap_verdict(s, {{meet(1, 0, 1, {0, 0}), state(1, 0, {0, 0}), meet(1, 1, 0, {2, 0}), state(1, 1, {1.9, 0})}}),
              "");
}

TEST(BallOverlap, TheLowestPairFailsAndOtherScenesPass) {
    // Pairs (1, 2) and (0, 2) both too close: ball 0 is named.
    const Scene s = discs({{0, 0}, {20, 0}, {10, 0}}, {1, 1, 1});
    const std::string bad =
        overlap_verdict(s, {{state(1, 0, {0, 0}), state(1, 1, {3, 0}), state(1, 2, {1.5, 0})}});
    EXPECT_TRUE(has(bad, "ball 0: balls 0 and 2")) << bad;
    // Balls that do not collide may overlap; two point balls never meet.
    Scene apart = s;
    apart.balls_collide = false;
    EXPECT_EQ(overlap_verdict(apart, {{state(1, 0, {0, 0}), state(1, 1, {3.5, 0}), state(1, 2, {0, 0})}}), "");
    const Scene points = discs({{0, 0}, {3, 0}}, {0, -0.0});
    EXPECT_EQ(overlap_verdict(points, {{state(1, 0, {0, 0}), state(1, 1, {0, 0})}}), "");
}

TEST(BallOverlap, AThousandBallsAreSortedNotPaired) {
    // 32 × 32 discs of radius 1 on a grid 2 apart (touching); one moved a quarter closer to its right neighbour fails.
    std::vector<Vec2> at;
    for (int i = 0; i < 32; ++i)
        for (int j = 0; j < 32; ++j) at.push_back({2.0 * i, 2.0 * j});
    const Scene s = discs(at, std::vector<double>(at.size(), 1.0));
    std::vector<Event> same, moved;
    for (std::uint32_t b = 0; b < at.size(); ++b) {
        same.push_back(state(1, b, at[b]));
        moved.push_back(state(1, b, b == 5 ? Vec2{at[b].x + 0.25, at[b].y} : at[b]));
    }
    EXPECT_EQ(overlap_verdict(s, {same}), "");
    // Ball 5 is (0, 10); ball 37 is (2, 10).
    const std::string bad = overlap_verdict(s, {moved});
    EXPECT_TRUE(has(bad, "ball 5: balls 5 and 37")) << bad;
}

// pass-through: a frame with the balls' states before it and their paths.
struct PathFrame {
    std::vector<Ball> before;
    std::vector<Event> events;
    std::vector<std::vector<PathPoint>> paths;  // empty: the World gives none
};

/// Ball 1 jumping: from its place in the scene to `from` by t = 0.5, two hits there (a piece of no duration from
/// `from` to `to`), then to `end` at t = 1; ball 0 from its place to `other_end` over the frame (default: standing).
PathFrame jump_frame(const Scene& s, Vec2 from, Vec2 to, Vec2 end, std::optional<Vec2> other_end = {}) {
    const Vec2 still = other_end.value_or(s.balls[0].pos);
    return {s.balls,
            {state(1, 0, still), hit(1, 1, 0, from), hit(1, 1, 0, to), state(1, 1, end)},
            {{{0, s.balls[0].pos}, {1, still}}, {{0, s.balls[1].pos}, {0.5, from}, {0.5, to}, {1, end}}}};
}

/// What a check of the balls' paths (pass-through, jump-through) says of frame 1: its failure, "" if none.
std::string path_verdict(FrameCheck& check, const Scene& s, const PathFrame& p) {
    std::vector<std::span<const PathPoint>> spans(p.paths.begin(), p.paths.end());
    const std::vector<BallMemory> memory(s.balls.size());
    if (auto r = check.frame(Frame{1, p.events, p.before, memory, {}, {}, spans})) return r->str();
    return "";
}

std::string pass_verdict(const Scene& s, const PathFrame& p) {
    return path_verdict(*make_pass_through(s, KernelId::robust, {}), s, p);
}

TEST(PassThrough, TwoBallsCrossingWithinAFrameFail) {
    Scene s = discs({{0, 0}, {10, 0}}, {1, 1});
    s.balls[0].vel = {10, 0};
    s.balls[1].vel = {-10, 0};
    // Head on through each other with no meet, as a lecture kernel leaves them: straight pieces (no paths given).
    const std::string bad =
        pass_verdict(s, {s.balls, {state(1, 0, {10, 0}, {10, 0}), state(1, 1, {0, 0}, {-10, 0})}, {}});
    EXPECT_TRUE(has(bad, "pass-through broke at frame 1 ball 0: balls 0 and 1 come closer than")) << bad;
    // The same with the World's paths.
    EXPECT_NE(pass_verdict(s, {s.balls, {state(1, 0, {10, 0}, {10, 0}), state(1, 1, {0, 0}, {-10, 0})},
                               {{{0, {0, 0}}, {1, {10, 0}}}, {{0, {10, 0}}, {1, {0, 0}}}}}),
              "");
    // Balls that do not collide pass through each other.
    Scene apart = s;
    apart.balls_collide = false;
    EXPECT_EQ(pass_verdict(apart, {s.balls, {state(1, 0, {10, 0}, {10, 0}), state(1, 1, {0, 0}, {-10, 0})}, {}}), "");
}

TEST(PassThrough, GrazingAtExactlySHoldsOneUlpCloserFails) {
    // Ball 1 passes ball 0 along y = 2: at the closest, when both are at x = 5, exactly S = 2 apart.
    Scene s = discs({{0, 0}, {10, 2}}, {1, 1});
    s.balls[0].vel = {10, 0};
    s.balls[1].vel = {-10, 0};
    EXPECT_EQ(pass_verdict(s, {s.balls, {state(1, 0, {10, 0}, {10, 0}), state(1, 1, {0, 2}, {-10, 0})}, {}}), "");
    Scene closer = s;
    closer.balls[1].pos.y = below_two;
    EXPECT_NE(pass_verdict(closer, {closer.balls, {state(1, 0, {10, 0}, {10, 0}), state(1, 1, {0, below_two}, {-10, 0})}, {}}),
              "");
    // Crossing at an angle, the least distance inside the interval: (D × W)² against S²·(W·W).
    Scene askew = discs({{0, 0}, {10, 3}}, {1, 1});
    EXPECT_EQ(pass_verdict(askew, {askew.balls, {state(1, 0, {10, 0}), state(1, 1, {0, 3.5})}, {}}), "");
    EXPECT_NE(pass_verdict(askew, {askew.balls, {state(1, 0, {10, 0}), state(1, 1, {0, 0.5})}, {}}), "");
}

TEST(PassThrough, AMeetAtSApartSplitsThePathsAndAPathMustBeThePrintedOne) {
    Scene s = discs({{0, 0}, {10, 0}}, {1, 1});
    s.balls[0].vel = {10, 0};
    s.balls[1].vel = {-10, 0};
    // They meet at t = 0.4, centres (4, 0) and (6, 0), exactly S apart, and turn back.
    const std::vector<Event> met = {meet(1, 0, 1, {4, 0}, {-10, 0}), state(1, 0, {-2, 0}, {-10, 0}),
                                    meet(1, 1, 0, {6, 0}, {10, 0}), state(1, 1, {12, 0}, {10, 0})};
    const std::vector<std::vector<PathPoint>> paths = {{{0, {0, 0}}, {0.4, {4, 0}}, {1, {-2, 0}}},
                                                       {{0, {10, 0}}, {0.4, {6, 0}}, {1, {12, 0}}}};
    EXPECT_EQ(pass_verdict(s, {s.balls, met, paths}), "");
    // The meet put half a frame late: both at (5, 0) by then, through each other on the way.
    const std::vector<Event> late = {meet(1, 0, 1, {5, 0}, {-10, 0}), state(1, 0, {0, 0}, {-10, 0}),
                                     meet(1, 1, 0, {5, 0}, {10, 0}), state(1, 1, {10, 0}, {10, 0})};
    const std::string bad = pass_verdict(s, {s.balls, late,
                                             {{{0, {0, 0}}, {0.5, {5, 0}}, {1, {0, 0}}},
                                              {{0, {10, 0}}, {0.5, {5, 0}}, {1, {10, 0}}}}});
    EXPECT_TRUE(has(bad, "between frame times 0 and 0.5")) << bad;
    // A path without the meet point, or not from t = 0 to t = 1, is not the printed path.
    std::vector<std::vector<PathPoint>> short_path = paths;
    short_path[1] = {{0, {10, 0}}, {1, {12, 0}}};
    EXPECT_TRUE(has(pass_verdict(s, {s.balls, met, short_path}), "ball 1: the World's path of ball 1"));
    std::vector<std::vector<PathPoint>> late_start = paths;
    late_start[0][0].t = 0.25;
    EXPECT_TRUE(has(pass_verdict(s, {s.balls, met, late_start}), "ball 0: the World's path of ball 0"));
    // Without paths a ball that printed a meet is not judged (the lines do not say when it met).
    EXPECT_EQ(pass_verdict(s, {s.balls, late, {}}), "");
}

TEST(PassThrough, APairCloserThanSAtAnIntervalsStartIsNotJudgedThere) {
    // Placed overlapping and moving through each other: no interval starts clear.
    Scene s = discs({{0, 0}, {1, 0}}, {1, 1});
    EXPECT_EQ(pass_verdict(s, {s.balls, {state(1, 0, {1, 0}), state(1, 1, {0, 0})}, {}}), "");
    // A piece of zero duration is left out: ball 1's two hits at t = 0.5 (a jump from (10, 11) to (10, 12)); it passes
    // 3 from ball 0, clear, before and after.
    Scene jump = discs({{13, 11.5}, {10, 10}}, {1, 1});
    jump.walls = {{{20, 0}, {20, 20}}};
    EXPECT_EQ(pass_verdict(jump, jump_frame(jump, {10, 11}, {10, 12}, {10, 14})), "");
    // Its piece after the jump, turned to pass 0.5 from ball 0, is judged.
    EXPECT_NE(pass_verdict(jump, jump_frame(jump, {10, 11}, {10, 12}, {16, 12})), "");
}

TEST(PassThrough, AThousandBallsAreSortedNotPaired) {
    // 32 × 32 discs of radius 0.25 on a grid 1 apart, all moving (0.5, 0.25) in the frame; then ball 5, at (0, 5),
    // moving across to (2, 5) through ball 37 at (1, 5).
    std::vector<Vec2> at;
    for (int i = 0; i < 32; ++i)
        for (int j = 0; j < 32; ++j) at.push_back({1.0 * i, 1.0 * j});
    const Scene s = discs(at, std::vector<double>(at.size(), 0.25));
    std::vector<Event> along, across;
    for (std::uint32_t b = 0; b < at.size(); ++b) {
        along.push_back(state(1, b, {at[b].x + 0.5, at[b].y + 0.25}));
        across.push_back(state(1, b, b == 5 ? Vec2{2, 5} : at[b]));
    }
    EXPECT_EQ(pass_verdict(s, {s.balls, along, {}}), "");
    EXPECT_TRUE(has(pass_verdict(s, {s.balls, across, {}}), "ball 5: balls 5 and 37"));
}

// jump-through: the pieces of no duration pass-through leaves out.
std::string jump_verdict(const Scene& s, const PathFrame& p) {
    return path_verdict(*make_jump_through(s, KernelId::robust, {}), s, p);
}

TEST(JumpThrough, AJumpThroughABallStandingFailsOneThatStaysClearHolds) {
    // Ball 1 hits twice at t = 0.5 against a wall at x = 20: a jump from (10, 11) to (16, 11) there, through ball 0
    // standing at (13, 11.5) (0.5 from the jump's line, S = 2), from 3.04 away. pass-through leaves it out.
    Scene s = discs({{13, 11.5}, {10, 10}}, {1, 1});
    s.walls = {{{20, 0}, {20, 20}}};
    const PathFrame through = jump_frame(s, {10, 11}, {16, 11}, {16, 14});
    EXPECT_EQ(pass_verdict(s, through), "");
    const std::string bad = jump_verdict(s, through);
    EXPECT_TRUE(has(bad, "jump-through broke at frame 1 ball 0: balls 0 and 1 come closer than R_i + R_j = 1 + 1 at "
                         "frame time 0.5: ball 1 jumps from (10, 11) to (16, 11) there"))
        << bad;
    // Ball 0 moving from (13, 11.5) to (13, 13.5) over the frame: at t = 0.5 at (13, 12.5), its exact point there,
    // 1.5 from the jump's line.
    EXPECT_NE(jump_verdict(s, jump_frame(s, {10, 11}, {16, 11}, {16, 14}, Vec2{13, 13.5})), "");
    // A jump along y = 9.5, exactly S below ball 0, holds; one ulp closer fails.
    const auto along = [&](double y) { return jump_frame(s, {10, y}, {16, y}, {16, y}); };
    EXPECT_EQ(jump_verdict(s, along(9.5)), "");
    EXPECT_NE(jump_verdict(s, along(std::nextafter(9.5, 10.0))), "");
    // The jump of pass-through's test, from (10, 11) to (10, 12), 3 from ball 0 and clear, holds.
    EXPECT_EQ(jump_verdict(s, jump_frame(s, {10, 11}, {10, 12}, {10, 14})), "");
}

TEST(JumpThrough, AJumpFromWithinReachOrBesideAnotherJumpIsNotJudged) {
    Scene s = discs({{13, 11.5}, {12, 11}}, {1, 1});
    s.walls = {{{20, 0}, {20, 20}}};
    // From (12, 11), within S of ball 0, through it to (16, 11): no entry from outside.
    EXPECT_EQ(jump_verdict(s, jump_frame(s, {12, 11}, {16, 11}, {16, 11})), "");
    // Ball 1 from (10, 11) through ball 0's place while ball 0 also jumps at t = 0.5: their order is not printed.
    Scene both = discs({{13, 11.5}, {10, 11}}, {1, 1});
    both.walls = s.walls;
    EXPECT_EQ(jump_verdict(both, {both.balls,
                                  {hit(1, 0, 0, {13, 11.5}), hit(1, 0, 0, {13, 12}), state(1, 0, {13, 12}),
                                   hit(1, 1, 0, {10, 11}), hit(1, 1, 0, {16, 11}), state(1, 1, {16, 11})},
                                  {{{0, {13, 11.5}}, {0.5, {13, 11.5}}, {0.5, {13, 12}}, {1, {13, 12}}},
                                   {{0, {10, 11}}, {0.5, {10, 11}}, {0.5, {16, 11}}, {1, {16, 11}}}}}),
              "");
    // Balls that do not collide jump through each other.
    Scene apart = discs({{13, 11.5}, {10, 10}}, {1, 1});
    apart.walls = s.walls;
    apart.balls_collide = false;
    EXPECT_EQ(jump_verdict(apart, jump_frame(apart, {10, 11}, {16, 11}, {16, 11})), "");
}

// momentum: a frame's meets as the World records them, and the lines it printed.
std::string momentum_verdict(const Scene& s, const std::vector<MeetRecord>& meets, std::vector<Event> events = {}) {
    // By default the lines the records say: ball a's meet and state, then ball b's (each leaves as it left the meet).
    if (events.empty())
        for (const MeetRecord& m : meets) {
            events.push_back(meet(1, m.a, m.b, m.pos_a, m.out_a));
            events.push_back(state(1, m.a, m.pos_a, m.out_a));
            events.push_back(meet(1, m.b, m.a, m.pos_b, m.out_b));
            events.push_back(state(1, m.b, m.pos_b, m.out_b));
        }
    std::vector<Ball> before = s.balls;
    for (const MeetRecord& m : meets) {
        before[m.a].vel = m.vel_a;
        before[m.b].vel = m.vel_b;
    }
    auto check = make_momentum(s, KernelId::robust, {});
    const std::vector<BallMemory> memory(s.balls.size());
    if (auto r = check->frame(Frame{1, events, before, memory, {}, meets, {}})) return r->str();
    return "";
}

MeetRecord head_on(Vec2 va, Vec2 vb, Vec2 oa, Vec2 ob) { return {0, 1, 0.5, {4, 0}, {6, 0}, va, vb, oa, ob, true}; }

TEST(Momentum, EqualMassesExchangeAndAComponentOffBeyondTheBoundFails) {
    const Scene s = discs({{0, 0}, {10, 0}}, {1, 1});
    EXPECT_EQ(momentum_verdict(s, {head_on({1, 0}, {-1, 0}, {-1, 0}, {1, 0})}), "");
    // Off by 2^−45 in x: within 2^−40 of the momenta (4) and of the energy (2).
    EXPECT_EQ(momentum_verdict(s, {head_on({1, 0}, {-1, 0}, {-1 + 0x1p-45, 0}, {1, 0})}), "");
    // Off by 2^−30 in y: momentum gained beyond 2^−40·4 (energy changes by 2^−60 only).
    const std::string bad = momentum_verdict(s, {head_on({1, 0}, {-1, 0}, {-1, 0}, {1, 0x1p-30})});
    EXPECT_TRUE(has(bad, "momentum broke at frame 1 ball 0: meet 0 of the frame (balls 0 and 1")) << bad;
    // Both faster by 2^−30: momentum kept exactly, kinetic energy gained by about 2^−29 of it.
    EXPECT_TRUE(has(momentum_verdict(s, {head_on({1, 0}, {-1, 0}, {-1 - 0x1p-30, 0}, {1 + 0x1p-30, 0})}),
                    "kinetic energy"));
    // And both slower: energy lost.
    EXPECT_NE(momentum_verdict(s, {head_on({1, 0}, {-1, 0}, {-1 + 0x1p-30, 0}, {1 - 0x1p-30, 0})}), "");
}

TEST(Momentum, AmongTheSubnormalsTheAbsoluteTermDecides) {
    // Velocities of a few 2^−1074: a response rounded among the subnormals is off by an ulp of 2^−1074, far beyond
    // 2^−40 of the momenta but within 2^−1068·(m_a + m_b); 2^−1060 off is beyond both.
    const Scene s = discs({{0, 0}, {10, 0}}, {1, 1});
    const double u = 0x1p-1074;
    EXPECT_EQ(momentum_verdict(s, {head_on({8 * u, 0}, {-8 * u, 0}, {-7 * u, 0}, {8 * u, 0})}), "");
    EXPECT_EQ(momentum_verdict(s, {head_on({8 * u, 0}, {-8 * u, 0}, {-8 * u, u}, {8 * u, 0})}), "");
    EXPECT_TRUE(has(momentum_verdict(s, {head_on({8 * u, 0}, {-8 * u, 0}, {-8 * u, 0x1p-1060}, {8 * u, 0})}),
                    "momentum"));
    // Energy: both leaving faster by 2^−1060 keeps momentum exactly and gains energy beyond the absolute term.
    EXPECT_TRUE(has(momentum_verdict(s, {head_on({8 * u, 0}, {-8 * u, 0}, {-8 * u - 0x1p-1060, 0},
                                                  {8 * u + 0x1p-1060, 0})}),
                    "kinetic energy"));
}

TEST(Momentum, MassesWeighTheResponse) {
    // m_a = 1 at 1 against m_b = 3 at rest: v_a′ = (1 − 3)/4 = −0.5, v_b′ = 2/4 = 0.5, both laws exact.
    Scene s = discs({{0, 0}, {10, 0}}, {1, 1});
    s.masses = {1, 3};
    EXPECT_EQ(momentum_verdict(s, {head_on({1, 0}, {0, 0}, {-0.5, 0}, {0.5, 0})}), "");
    // Exchanging the velocities, as equal masses would, triples the momentum.
    EXPECT_NE(momentum_verdict(s, {head_on({1, 0}, {0, 0}, {0, 0}, {1, 0})}), "");
}

TEST(Momentum, NoResponseLeavesTheVelocitiesAndARecordMustBeWhatPrinted) {
    const Scene s = discs({{0, 0}, {10, 0}}, {1, 1});
    MeetRecord stay = head_on({1, 0}, {2, 0}, {1, 0}, {2, 0});
    stay.responded = false;
    EXPECT_EQ(momentum_verdict(s, {stay}), "");
    MeetRecord changed = stay;
    changed.out_b = {1, 0};
    EXPECT_TRUE(has(momentum_verdict(s, {changed}), "yet the velocities changed"));
    // The record says ball 1 leaves moving (1, 0), the lines (2, 0).
    const MeetRecord r = head_on({1, 0}, {-1, 0}, {-1, 0}, {1, 0});
    EXPECT_TRUE(has(momentum_verdict(s, {r}, {meet(1, 0, 1, {4, 0}, {-1, 0}), state(1, 0, {4, 0}, {-1, 0}),
                                              meet(1, 1, 0, {6, 0}, {2, 0}), state(1, 1, {6, 0}, {2, 0})}),
                    "is not what the frame printed"));
    // A printed meet with no record, and a record with no printed meet.
    EXPECT_TRUE(has(momentum_verdict(s, {}, {meet(1, 0, 1, {4, 0}), state(1, 0, {4, 0}), meet(1, 1, 0, {6, 0}),
                                             state(1, 1, {6, 0})}),
                    "ball 0 prints 1 meet(s) with ball 1, the World recorded 0"));
    EXPECT_TRUE(has(momentum_verdict(s, {r}, {state(1, 0, {4, 0}), state(1, 1, {6, 0})}), "does not print it"));
    // It arrives moving what it moved before the frame (its first contact), or what it left its last meet with.
    Scene moving = s;
    moving.balls[0].vel = {1, 0};
    MeetRecord lying = r;
    lying.vel_a = {3, 0};
    const std::vector<Event> lines = {meet(1, 0, 1, {4, 0}, {-1, 0}), state(1, 0, {4, 0}, {-1, 0}),
                                      meet(1, 1, 0, {6, 0}, {1, 0}), state(1, 1, {6, 0}, {1, 0})};
    auto check = make_momentum(moving, KernelId::robust, {});
    const std::vector<Ball> before = {{{0, 0}, {1, 0}, 1}, {{10, 0}, {-1, 0}, 1}};
    const std::vector<BallMemory> memory(2);
    const std::vector<MeetRecord> records = {lying};
    const auto said = check->frame(Frame{1, lines, before, memory, {}, records, {}});
    ASSERT_TRUE(said.has_value());
    EXPECT_TRUE(has(said->message, "ball 0 arrives moving (3, 0) by the World's record, but (1, 0)")) << said->message;
    // Balls that do not collide: nothing is judged.
    Scene apart = s;
    apart.balls_collide = false;
    EXPECT_EQ(momentum_verdict(apart, {changed}), "");
}

// relabel: the World's own run of a scene that stays apart, and the same run broken by hand.
TEST(Relabel, TheBallsReversedPrintTheSameEventsUntilThreeMeetAtOnce) {
    Scene s = discs({{0, 0}, {10, 0}, {20, 0}}, {1, 2, 1});
    s.balls[0].vel = {-1, 0};
    s.balls[2].vel = {1, 0.5};
    s.masses = {1, 2, 3};
    World world(s, KernelId::robust);
    std::vector<std::vector<Event>> frames(4);
    world.start(frames[0]);
    for (std::size_t f = 1; f < frames.size(); ++f) ASSERT_FALSE(world.step(frames[f]));
    const auto run = [&](const Scene& scene, const std::vector<std::vector<Event>>& events,
                         const std::vector<std::vector<MeetRecord>>& meets) {
        auto check = make_relabel(scene, KernelId::robust, {});
        for (std::size_t f = 0; f < events.size(); ++f) {
            const std::span<const MeetRecord> m = f < meets.size() ? std::span<const MeetRecord>(meets[f]) : std::span<const MeetRecord>{};
            if (auto r = check->frame(Frame{static_cast<std::int64_t>(f), events[f], {}, {}, {}, m, {}})) return r->str();
        }
        return std::string();
    };
    EXPECT_EQ(run(s, frames, {}), "");
    // Ball 2 a little off at frame 2: its image, ball 0, is not.
    std::vector<std::vector<Event>> broken = frames;
    for (Event& e : broken[2])
        if (e.kind == Event::Kind::state && e.ball == 2) e.pos.x += 0.5;
    EXPECT_TRUE(has(run(s, broken, {}), "relabel broke at frame 2 ball 2: the run with its balls in reverse order"));
    // A meet taken while another sharing a ball was due at the same exact time (the World marks it tied) at frame
    // 2: that frame and every later one are not compared.
    const MeetRecord m01{0, 1, 0.25, {}, {}, {}, {}, {}, {}, true, true}, m12{1, 2, 0.25, {}, {}, {}, {}, {}, {}, true};
    EXPECT_EQ(run(s, broken, {{}, {}, {m01, m12}}), "");
    std::vector<std::vector<Event>> later = frames;
    for (Event& e : later[3])
        if (e.kind == Event::Kind::state && e.ball == 0) e.vel.y = 1;
    EXPECT_EQ(run(s, later, {{}, {}, {m01, m12}}), "");
    // Meets at one rounded time that the World did not mark tied are compared.
    const MeetRecord m01_untied{0, 1, 0.25, {}, {}, {}, {}, {}, {}, true};
    EXPECT_NE(run(s, broken, {{}, {}, {m01_untied, m12}}), "");
    EXPECT_NE(run(s, later, {{}, {}, {m01_untied}}), "");
    // Balls that do not collide: nothing is compared.
    Scene apart = s;
    apart.balls_collide = false;
    EXPECT_EQ(run(apart, broken, {}), "");
}

TEST(Relabel, TheImageTakesTheMassesAlong) {
    Scene s = discs({{0, 0}, {10, 0}, {20, 0}}, {1, 2, 3});
    s.masses = {1, 2, 4};
    const Scene image = apply(SceneMap{"reversed", nullptr, false, true, false}, s);
    EXPECT_EQ(image.masses, (std::vector<double>{4, 2, 1}));
    EXPECT_EQ(image.balls[0].r, 3);
    EXPECT_TRUE(image.balls_collide);
}

// The older checks in a frame with a meet.
TEST(MeetsInOlderChecks, SpeedAndOracleLeaveABallThatMetToTheNewChecks) {
    // Ball 0 moving (1, 0) meets ball 1 at rest 2.5 away at t = 1/2 (the oracle judges that first meet too).
    Scene s = discs({{0, 0}, {2.5, 0}}, {1, 1});
    s.walls = {{{-20, -20}, {-20, 20}}};
    s.balls[0].vel = {1, 0};
    const std::vector<Ball> before = s.balls;
    const std::vector<BallMemory> memory(2);
    const std::vector<StepTrace> traces(2);
    // Ball 0 leaves moving (−5, 0) with no reflection: speed's failure, unless it met ball 1.
    const std::vector<Event> alone = {state(1, 0, {1, 0}, {-5, 0}), state(1, 1, {10, 0})};
    const std::vector<Event> met = {meet(1, 0, 1, {1, 0}, {-5, 0}), state(1, 0, {1, 0}, {-5, 0}),
                                    meet(1, 1, 0, {3, 0}), state(1, 1, {10, 0})};
    auto speed = make_speed(s, KernelId::robust, {});
    EXPECT_TRUE(speed->frame(Frame{1, alone, before, memory, traces}).has_value());
    EXPECT_FALSE(speed->frame(Frame{1, met, before, memory, traces}).has_value());
    // A hit with no leg that took it: the oracle's failure, unless the ball met another in the frame.
    const std::vector<Event> hit_alone = {hit(1, 0, 0, {-19, 0}), state(1, 0, {1, 0}, {1, 0}), state(1, 1, {10, 0})};
    const std::vector<Event> hit_met = {hit(1, 0, 0, {-19, 0}), meet(1, 0, 1, {1, 0}, {1, 0}), state(1, 0, {1, 0}, {1, 0}),
                                        meet(1, 1, 0, {3, 0}), state(1, 1, {10, 0})};
    auto oracle = make_oracle(s, KernelId::robust, {});
    ASSERT_FALSE(oracle->frame(Frame{0, start(s), {}, {}, {}}).has_value());
    const auto said = oracle->frame(Frame{1, hit_alone, before, memory, traces});
    ASSERT_TRUE(said.has_value());
    EXPECT_TRUE(has(said->message, "the frame printed 1 hit(s) and bump(s)")) << said->message;
    const std::vector<MeetRecord> taken = {{0, 1, 0.5, {1, 0}, {3, 0}, {1, 0}, {}, {1, 0}, {}, true}};
    EXPECT_FALSE(oracle->frame(Frame{1, hit_met, before, memory, traces, taken}).has_value());
    // The frame's meets at the limit (16 a ball): every ball is left to the new checks.
    const std::vector<MeetRecord> limit(32);
    EXPECT_FALSE(speed->frame(Frame{1, alone, before, memory, traces, limit}).has_value());
}

TEST(MeetsInOlderChecks, GhostBounceAndBounceSideTakeAMeetAsABump) {
    // ghost-bounce (disc_checks_test's sliding disc): a hit after a meet arrives with another velocity, not judged.
    Scene s;
    s.balls_collide = true;
    s.walls = {{{0, 10}, {3, 14}}, {{3, 14}, {6, 18}}};
    s.balls = {{{4, 7}, {0.75, 1}, 5}, {{40, 40}, {}, 1}};
    auto ghost = make_ghost_bounce(s, KernelId::robust, {});
    const std::vector<BallMemory> memory(2);
    const std::vector<Event> hit_first = {hit(1, 0, 1, {7, 11}), state(1, 0, {7, 11}), state(1, 1, {40, 40})};
    const std::vector<Event> met_first = {meet(1, 0, 1, {5, 8}), hit(1, 0, 1, {7, 11}), state(1, 0, {7, 11}),
                                          meet(1, 1, 0, {40, 40}), state(1, 1, {40, 40})};
    EXPECT_TRUE(ghost->frame(Frame{1, hit_first, s.balls, memory, {}}).has_value());
    EXPECT_FALSE(ghost->frame(Frame{1, met_first, s.balls, memory, {}}).has_value());
    // bounce-side: after hitting wall 0's face from below, a state above it fails; a meet between ends the rule, and a
    // meet point above it is judged like a bump point.
    Scene b = discs({{5, -3}, {40, 40}}, {1, 1});
    b.walls = {{{0, 0}, {10, 0}}};
    const auto side = [&](const std::vector<Event>& events) {
        auto check = make_bounce_side(b, KernelId::robust, {});
        const auto r = check->frame(Frame{1, events, b.balls, memory, {}});
        return r ? r->message : std::string();
    };
    EXPECT_NE(side({hit(1, 0, 0, {5, -1}), state(1, 0, {5, 3}), state(1, 1, {40, 40})}), "");
    EXPECT_EQ(side({hit(1, 0, 0, {5, -1}), meet(1, 0, 1, {5, -2}), state(1, 0, {5, 3}), meet(1, 1, 0, {40, 40}),
                    state(1, 1, {40, 40})}),
              "");
    EXPECT_TRUE(has(side({hit(1, 0, 0, {5, -1}), meet(1, 0, 1, {5, 2}), state(1, 0, {5, 3}), meet(1, 1, 0, {40, 40}),
                          state(1, 1, {40, 40})}),
                    "its meet point (5, 2) lies on the other side"));
}

TEST(MeetsInOlderChecks, SwapAndTranslationCompareNoFirstContactAMeetDecided) {
    // Ball 0 (radius 1) moves onto wall 0 at x = 10 in frame 1; ball 1 sits far off.
    Scene s = discs({{5, 5}, {5, 50}}, {1, 1});
    s.walls = {{{10, 0}, {10, 10}}, {{0, 0}, {0, 10}}};
    s.balls[0].vel = {10, 0};
    const auto frames = [&](const std::vector<Event>& first) { return std::vector<std::vector<Event>>{start(s), first}; };
    const std::vector<Event> wrong_wall = {hit(1, 0, 1, {9, 5}), state(1, 0, {8, 5}), state(1, 1, {5, 50})};
    const std::vector<Event> met_then_wrong_wall = {meet(1, 0, 1, {6, 5}), hit(1, 0, 1, {9, 5}), state(1, 0, {8, 5}),
                                                    meet(1, 1, 0, {5, 50}), state(1, 1, {5, 50})};
    const auto say = [&](FrameCheck& check, const std::vector<std::vector<Event>>& events) {
        const std::vector<BallMemory> memory(2);
        for (std::size_t f = 0; f < events.size(); ++f)
            if (auto r = check.frame(Frame{static_cast<std::int64_t>(f), events[f], f ? s.balls : std::vector<Ball>{},
                                           f ? memory : std::vector<BallMemory>{}, {}}))
                return r->message;
        return std::string();
    };
    // swap: the scene with its walls walked the other way meets wall 0 first.
    EXPECT_TRUE(has(say(*make_swap(s, KernelId::robust, {}), frames(wrong_wall)), "meets wall 0 first"));
    EXPECT_EQ(say(*make_swap(s, KernelId::robust, {}), frames(met_then_wrong_wall)), "");
    // translation: the moved scene hits wall 0.
    EXPECT_TRUE(has(say(*make_translation(s, KernelId::robust, {}), frames(wrong_wall)), "changes a hit"));
    EXPECT_EQ(say(*make_translation(s, KernelId::robust, {}), frames(met_then_wrong_wall)), "");
}

}  // namespace
}  // namespace ricochet::checks
