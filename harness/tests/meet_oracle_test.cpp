// The oracle of meets (oracle_meets.cpp, truth_meets.cpp) on frames written by hand: the World's first meet record
// against the exact first meet of the balls' paths as each is stepped alone. Each way the oracle promises to see a
// wrong first meet is broken on purpose — the wrong pair first, a tie taken by the higher pair, a tangent printed as a
// meet, a meet printed after the double nearest t*, a meet where there is none, none where there is one — and the right
// frame passes. The numbers are worked by hand in the comments.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "checks/frame_check.hpp"

namespace ricochet::checks {
namespace {

/// Discs whose balls collide, in the open: (centre, velocity, radius) each.
Scene moving(std::vector<Ball> balls) {
    Scene s;
    s.balls_collide = true;
    s.balls = std::move(balls);
    return s;
}

Event state(std::uint32_t ball, Vec2 pos, Vec2 vel = {}) {
    return {Event::Kind::state, 1, ball, Event::Shape::none, 0, pos, vel};
}
Event meet(std::uint32_t ball, std::uint32_t other, Vec2 pos) {
    return {Event::Kind::meet, 1, ball, Event::Shape::none, other, pos, {}};
}

/// A record of the meet of a < b at time t (centres and velocities do not matter to the oracle).
MeetRecord record(std::uint32_t a, std::uint32_t b, double t) { return {a, b, t, {}, {}, {}, {}, {}, {}, true}; }

/// What `oracle` says of frame 1 of s under kernel k when the World took `meets` (in order): each taken meet printed
/// under both balls, every ball's state where it ends alone (the oracle judges the meets, not the states). "" if it holds.
std::string verdict(const Scene& s, const std::vector<MeetRecord>& meets, KernelId k = KernelId::robust) {
    auto oracle = make_oracle(s, k, {});
    std::vector<Event> zero;
    for (std::uint32_t b = 0; b < s.balls.size(); ++b) zero.push_back({Event::Kind::state, 0, b, Event::Shape::none, 0,
                                                                       s.balls[b].pos, s.balls[b].vel});
    if (auto r = oracle->frame(Frame{0, zero, {}, {}, {}})) return r->str();
    std::vector<Event> events;
    for (std::uint32_t b = 0; b < s.balls.size(); ++b) {
        for (const MeetRecord& m : meets)
            if (m.a == b || m.b == b) events.push_back(meet(b, m.a == b ? m.b : m.a, s.balls[b].pos));
        events.push_back(state(b, s.balls[b].pos + s.balls[b].vel, s.balls[b].vel));
    }
    const std::vector<BallMemory> memory(s.balls.size());
    const std::vector<StepTrace> traces(s.balls.size());
    if (auto r = oracle->frame(Frame{1, events, s.balls, memory, traces, meets})) return r->str();
    return "";
}

bool has(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

// Ball 0 from (0, 0) moving (4, 0), ball 1 at rest at (5, 0), radii 1: |−5 + 4u| = 2 at t* = 3/4.
const Scene head_on = moving({{{0, 0}, {4, 0}, 1}, {{5, 0}, {}, 1}});

TEST(MeetOracle, TheRightFirstMeetHoldsAtOrBeforeTStarsDouble) {
    EXPECT_EQ(verdict(head_on, {record(0, 1, 0.75)}), "");
    // Walked back earlier (rule 4) is still the meet; the frame's start too.
    EXPECT_EQ(verdict(head_on, {record(0, 1, 0.5)}), "");
    EXPECT_EQ(verdict(head_on, {record(0, 1, 0.0)}), "");
    // Only the first record is judged: what follows is taken on new paths.
    EXPECT_EQ(verdict(head_on, {record(0, 1, 0.75), record(0, 1, 0.9)}), "");
}

TEST(MeetOracle, AMeetPrintedAfterTheDoubleNearestTStarFails) {
    const std::string late = verdict(head_on, {record(0, 1, std::nextafter(0.75, 1.0))});
    EXPECT_TRUE(has(late, "oracle broke at frame 1 ball 0: the frame's first meet is balls 0 and 1 at t = 0.7500000000000001, "
                          "outside [0, t°]"))
        << late;
    EXPECT_NE(verdict(head_on, {record(0, 1, -0.0625)}), "");
    // An irrational t*: ball 1 at (5, 1) is met where (4u − 5)² + 1 = 4, t* = (5 − √3)/4. Its nearest double t° holds
    // and the next one up does not, decided without rounding √3 (long double finds t° here: its 64-bit root is
    // within 2^−60 of t*, far from a midpoint, as asserted).
    const Scene glancing = moving({{{0, 0}, {4, 0}, 1}, {{5, 1}, {}, 1}});
    const long double t_star = (5.0L - std::sqrt(3.0L)) / 4.0L;
    const double t_near = static_cast<double>(t_star);
    ASSERT_LT(std::fabs(t_star - t_near), 0.25L * (std::nextafter(t_near, 1.0) - t_near));
    EXPECT_EQ(verdict(glancing, {record(0, 1, t_near)}), "");
    EXPECT_EQ(verdict(glancing, {record(0, 1, std::nextafter(t_near, 0.0))}), "");
    EXPECT_TRUE(has(verdict(glancing, {record(0, 1, std::nextafter(t_near, 1.0))}), "outside [0, t°]"));
}

TEST(MeetOracle, TheWrongPairFirstFails) {
    // Balls 2 and 3 meet at t* = 1/2 (|−4 + 4u| = 2), before 0 and 1 at 3/4.
    const Scene s = moving({{{0, 0}, {4, 0}, 1}, {{5, 0}, {}, 1}, {{0, 50}, {4, 0}, 1}, {{4, 50}, {}, 1}});
    EXPECT_EQ(verdict(s, {record(2, 3, 0.5), record(0, 1, 0.75)}), "");
    const std::string bad = verdict(s, {record(0, 1, 0.75), record(2, 3, 0.5)});
    EXPECT_TRUE(has(bad, "ball 0: the frame's first meet is balls 0 and 1 at t = 0.75, exactly balls 2 and 3 at t* = 0.5"))
        << bad;
}

TEST(MeetOracle, ATieTakenByTheHigherPairFails) {
    // Two pairs apart from each other, each meeting at t* = 3/4 exactly: the lowest pair is taken first (rule 3).
    const Scene s = moving({{{0, 0}, {4, 0}, 1}, {{5, 0}, {}, 1}, {{0, 50}, {4, 0}, 1}, {{5, 50}, {}, 1}});
    EXPECT_EQ(verdict(s, {record(0, 1, 0.75), record(2, 3, 0.75)}), "");
    const std::string bad = verdict(s, {record(2, 3, 0.75), record(0, 1, 0.75)});
    EXPECT_TRUE(has(bad, "exactly balls 0 and 1 at t* = 0.75, tied with a higher pair at the same exact time")) << bad;
    // Three balls converging on the origin (ThreeAtOnePoint's kind), radii 1: 0 and 1 from the left and the right, 2
    // from below, all reaching it at t = 1. Pairs (0, 2) and (1, 2) close at |W| = 4√2 from 4√2 apart and meet at
    // √2·(4 − 4u) = 2, t* = 1 − √2/4, both at once and before (0, 1) at 3/4: a tie at an irrational time.
    const Scene three = moving({{{-4, 0}, {4, 0}, 1}, {{4, 0}, {-4, 0}, 1}, {{0, -4}, {0, 4}, 1}});
    EXPECT_EQ(verdict(three, {record(0, 2, 0.5)}), "");
    EXPECT_TRUE(has(verdict(three, {record(1, 2, 0.5)}), "exactly balls 0 and 2 at t* = 0.646446609406726"));
    EXPECT_TRUE(has(verdict(three, {record(0, 1, 0.5)}), "exactly balls 0 and 2"));
}

TEST(MeetOracle, ATangentPrintedAsAMeetFails) {
    // Ball 1 from (−3, 1) moving (4, 0) past ball 0 at rest, radii 1/2: the distance √((4u − 3)² + 1) reaches
    // S = 1 only at u = 3/4, a double root: no meet.
    const Scene tangent = moving({{{0, 0}, {}, 0.5}, {{-3, 1}, {4, 0}, 0.5}});
    EXPECT_EQ(verdict(tangent, {}), "");
    const std::string bad = verdict(tangent, {record(0, 1, 0.75)});
    EXPECT_TRUE(has(bad, "ball 0: the frame's first meet is balls 0 and 1 at t = 0.75, but exactly the paths the balls "
                         "make alone never meet"))
        << bad;
    // One ulp of y nearer, the line is a secant: a meet, which must be printed.
    const Scene secant = moving({{{0, 0}, {}, 0.5}, {{-3, std::nextafter(1.0, 0.0)}, {4, 0}, 0.5}});
    EXPECT_TRUE(has(verdict(secant, {}), "the frame printed no meet, but exactly its first meet is balls 0 and 1"));
}

TEST(MeetOracle, AMeetWhereThereIsNoneAndNoneWhereThereIsOneFail) {
    const Scene apart = moving({{{0, 0}, {4, 0}, 1}, {{0, 10}, {}, 1}});
    EXPECT_EQ(verdict(apart, {}), "");
    EXPECT_TRUE(has(verdict(apart, {record(0, 1, 0.5)}), "never meet in this frame"));
    const std::string missed = verdict(head_on, {});
    EXPECT_TRUE(has(missed, "ball 0: the frame printed no meet, but exactly its first meet is balls 0 and 1 at t* = 0.75"))
        << missed;
    // Placed within S: approaching meets at t = 0 (rule 2), moving apart does not.
    const Scene closing = moving({{{0, 0}, {1, 0}, 1}, {{1, 0}, {}, 1}});
    EXPECT_EQ(verdict(closing, {record(0, 1, 0.0)}), "");
    EXPECT_TRUE(has(verdict(closing, {}), "(within R_i + R_j and approaching at a piece's start)"));
    const Scene opening = moving({{{0, 0}, {-1, 0}, 1}, {{1, 0}, {}, 1}});
    EXPECT_EQ(verdict(opening, {}), "");
    // A meet line with no record cannot be timed: the World records every meet it prints.
    auto oracle = make_oracle(head_on, KernelId::robust, {});
    const std::vector<Event> lines = {meet(0, 1, {3, 0}), state(0, {4, 0}), meet(1, 0, {5, 0}), state(1, {5, 0})};
    const std::vector<BallMemory> memory(2);
    const std::vector<StepTrace> traces(2);
    const auto said = oracle->frame(Frame{1, lines, head_on.balls, memory, traces});
    ASSERT_TRUE(said.has_value());
    EXPECT_TRUE(has(said->message, "recorded no meet")) << said->message;
}

TEST(MeetOracle, PathsAreTheBallsStepsAloneThroughWalls) {
    // Ball 0 (radius 1) bounces off the wall x = 3 at t = 1/2, its centre at (2, 0), and ends back at (0, 0). Ball 1 at
    // rest at (−1.5, 0), within S = 2 at the start, is left behind (D·W > 0: no meet on the first piece), then met on
    // the way back where 3.5 − 4u = 2, t* = 1/2 + 3/8 = 7/8. On a straight path there would be no meet at all.
    Scene s = moving({{{0, 0}, {4, 0}, 1}, {{-1.5, 0}, {}, 1}});
    s.walls = {{{3, -10}, {3, 10}}};
    EXPECT_EQ(verdict(s, {record(0, 1, 0.875)}), "");
    EXPECT_TRUE(has(verdict(s, {record(0, 1, std::nextafter(0.875, 1.0))}), "outside [0, t°]"));
    // At (−3.5, 0) it is 5.5 away when ball 0 turns back, 1.5 at the frame's end: no meet.
    s.balls[1].pos = {-3.5, 0};
    EXPECT_TRUE(has(verdict(s, {record(0, 1, 0.875)}), "never meet in this frame"));
}

TEST(MeetOracle, TheLectureKernelsAreJudgedByTheirOwnStaticTestExactly) {
    // Ball 0 ends alone at (4, 0), 1 from ball 1 at rest at (5, 0): within S = 2 and approaching, so the lecture takes
    // the pair at the frame's end; a swept meet at t* = 3/4 is not its rule.
    EXPECT_EQ(verdict(head_on, {record(0, 1, 1.0)}, KernelId::lecture_double), "");
    EXPECT_TRUE(has(verdict(head_on, {}, KernelId::lecture_double),
                    "the frame's first meet at its end (the lecture's static test) is none, exactly balls 0 and 1"));
    // Ball 0 through ball 1 to (8, 0), 3 past it: apart at the end, the lecture lets it pass (and must print nothing).
    const Scene through = moving({{{0, 0}, {8, 0}, 1}, {{5, 0}, {}, 1}});
    EXPECT_EQ(verdict(through, {}, KernelId::lecture_double), "");
    EXPECT_NE(verdict(through, {record(0, 1, 1.0)}, KernelId::lecture_double), "");
}

}  // namespace
}  // namespace ricochet::checks
