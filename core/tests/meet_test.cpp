// Balls that meet (docs/scene-log.md, "Balls that meet"; kernels/meet/): the swept rule of robust and exact on
// scenes worked by hand — head-on, unequal masses, a Newton's cradle, a glancing meet, fast balls that the lecture's
// static test lets pass through, balls boxed in by walls — and the exact root order (root.hpp) on its own.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <string>

#include <fmt/format.h>

#include "kernels/meet/root.hpp"
#include "ricochet/format.hpp"
#include "ricochet/world.hpp"

namespace ricochet {
namespace {

Scene meeting(std::vector<Ball> balls, std::int64_t frames = 1) {
    Scene s;
    s.frames = frames;
    s.balls = std::move(balls);
    s.balls_collide = true;
    return s;
}

std::vector<Event> kinds(const std::vector<Event>& events, Event::Kind kind) {
    std::vector<Event> out;
    for (const Event& e : events)
        if (e.kind == kind) out.push_back(e);
    return out;
}

/// The balls' states at the end of the run.
std::vector<Ball> last_states(const Scene& s, KernelId k) {
    World w(s, k);
    std::vector<Event> events;
    w.start(events);
    for (std::int64_t f = 0; f < s.frames; ++f) EXPECT_FALSE(w.step(events));
    return {w.balls().begin(), w.balls().end()};
}

TEST(Meet, HeadOnEqualMassesExchangeVelocities) {
    // Two unit discs 4 apart closing at 4 per frame: they touch (distance 2) at t = 0.5, at x = −1 and 1, and
    // exchange velocities; the rest of the frame takes each back to where it started.
    for (const KernelId k : {KernelId::robust, KernelId::exact}) {
        const Scene s = meeting({{{-2, 0}, {2, 0}, 1}, {{2, 0}, {-2, 0}, 1}});
        const std::vector<Event> events = run_scene(s, k, 1);
        const std::vector<Event> meets = kinds(events, Event::Kind::meet);
        ASSERT_EQ(meets.size(), 2u) << kernel_name(k);
        EXPECT_EQ(meets[0].ball, 0u);
        EXPECT_EQ(meets[0].index, 1u);
        EXPECT_EQ(meets[0].pos, (Vec2{-1, 0}));
        EXPECT_EQ(meets[0].vel, (Vec2{-2, 0}));
        EXPECT_EQ(meets[1].ball, 1u);
        EXPECT_EQ(meets[1].index, 0u);
        EXPECT_EQ(meets[1].pos, (Vec2{1, 0}));
        const std::vector<Ball> end = last_states(s, k);
        EXPECT_EQ(end[0].pos, (Vec2{-2, 0}));
        EXPECT_EQ(end[0].vel, (Vec2{-2, 0}));
        EXPECT_EQ(end[1].pos, (Vec2{2, 0}));
        EXPECT_EQ(end[1].vel, (Vec2{2, 0}));
    }
}

TEST(Meet, WithoutBallsCollideTheyPassThrough) {
    Scene s = meeting({{{-2, 0}, {2, 0}, 1}, {{2, 0}, {-2, 0}, 1}});
    s.balls_collide = false;
    const std::vector<Event> events = run_scene(s, KernelId::robust, 1);
    EXPECT_TRUE(kinds(events, Event::Kind::meet).empty());
    EXPECT_EQ(last_states(s, KernelId::robust)[0].pos, (Vec2{0, 0}));
}

TEST(Meet, UnequalMassesKeepMomentumAndEnergy) {
    // m_a = 3 at 1, m_b = 1 at rest, head-on: v_a′ = (m_a − m_b)/(m_a + m_b)·1 = 0.5, v_b′ = 2m_a/(m_a + m_b) = 1.5.
    Scene s = meeting({{{0, 0}, {1, 0}, 0.5}, {{1.5, 0}, {0, 0}, 0.5}});
    s.masses = {3, 1};
    for (const KernelId k : {KernelId::robust, KernelId::exact}) {
        World w(s, k);
        std::vector<Event> events;
        w.start(events);
        ASSERT_FALSE(w.step(events));
        ASSERT_EQ(w.meets().size(), 1u);
        const MeetRecord& m = w.meets()[0];
        EXPECT_EQ(m.t, 0.5);
        EXPECT_TRUE(m.responded);
        EXPECT_EQ(m.out_a, (Vec2{0.5, 0}));
        EXPECT_EQ(m.out_b, (Vec2{1.5, 0}));
    }
}

TEST(Meet, SubnormalVelocitiesAreExchangedExactly) {
    // A disc of radius 2.9e7 touching a point ball at rest, moving 2e−316 a frame toward it: u = (Δv·n)/(n·n) is
    // 6.9e−324 in doubles, one ulp of the subnormals, and the response made from it kept a fraction of the speed.
    // Equal masses exchange their normal components: exactly (0, 0) and (2e−316, 0).
    for (const KernelId k : {KernelId::robust, KernelId::exact}) {
        const Scene s = meeting({{{0, 80}, {2e-316, 0}, 29000000}, {{29000000, 80}, {0, 0}, 0}});
        const std::vector<Ball> end = last_states(s, k);
        EXPECT_EQ(end[0].vel, (Vec2{0, 0})) << kernel_name(k);
        EXPECT_EQ(end[1].vel, (Vec2{2e-316, 0})) << kernel_name(k);
    }
}

TEST(Meet, NewtonsCradlePassesTheMomentumDownTheLine) {
    // Five unit discs, four touching in a row, the first one arriving at 1 per frame: it meets the row at the end of
    // frame 1 and stops there; the last one leaves at 1, within the same time; the middle ones do not move.
    std::vector<Ball> balls{{{-3, 0}, {1, 0}, 1}};
    for (int i = 0; i < 4; ++i) balls.push_back({{2.0 * i, 0}, {0, 0}, 1});
    const Scene s = meeting(balls, 3);
    for (const KernelId k : {KernelId::robust, KernelId::exact}) {
        // The meet is at the very end of frame 1 (t = 1): the whole cascade happens then, and ball 4 ends frame 1
        // already moving.
        World w(s, k);
        std::vector<Event> events;
        w.start(events);
        ASSERT_FALSE(w.step(events));
        EXPECT_EQ(w.meets().size(), 4u) << kernel_name(k);
        EXPECT_EQ(w.balls()[4].vel, (Vec2{1, 0}));
        EXPECT_EQ(w.balls()[0].vel, (Vec2{0, 0}));
        const std::vector<Ball> end = last_states(s, k);
        EXPECT_EQ(end[0].vel, (Vec2{0, 0})) << kernel_name(k);
        EXPECT_EQ(end[0].pos, (Vec2{-2, 0}));
        for (int i = 1; i < 4; ++i) {
            EXPECT_EQ(end[i].vel, (Vec2{0, 0})) << i;
            EXPECT_EQ(end[i].pos, (Vec2{2.0 * (i - 1), 0})) << i;
        }
        EXPECT_EQ(end[4].vel, (Vec2{1, 0}));
        EXPECT_EQ(end[4].pos, (Vec2{8, 0}));  // left ball 3's place (6) at the end of frame 1
    }
}

TEST(Meet, AMeetTakenWhileAnotherSharingABallIsDueAtTheSameTimeIsMarkedTied) {
    // Balls 0 and 2 reach ball 1, at rest between them, at t = 1/2 exactly: the pair (0, 1) is taken first, tied.
    const Scene three = meeting({{{-4, 0}, {4, 0}, 1}, {{0, 0}, {0, 0}, 1}, {{4, 0}, {-4, 0}, 1}});
    // One pair only, and two pairs at one time that share no ball: nothing tied.
    const Scene two = meeting({{{-2, 0}, {2, 0}, 1}, {{2, 0}, {-2, 0}, 1}});
    const Scene apart = meeting({{{-2, 0}, {2, 0}, 1}, {{2, 0}, {-2, 0}, 1}, {{-2, 10}, {2, 0}, 1}, {{2, 10}, {-2, 0}, 1}});
    for (const KernelId k : {KernelId::robust, KernelId::exact}) {
        World w(three, k);
        std::vector<Event> events;
        w.start(events);
        ASSERT_FALSE(w.step(events));
        ASSERT_GE(w.meets().size(), 2u) << kernel_name(k);
        EXPECT_EQ(std::pair(w.meets()[0].a, w.meets()[0].b), std::pair(0u, 1u));
        EXPECT_TRUE(w.meets()[0].tied);
        for (const Scene* s : {&two, &apart}) {
            World v(*s, k);
            v.start(events);
            ASSERT_FALSE(v.step(events));
            ASSERT_FALSE(v.meets().empty());
            for (const MeetRecord& m : v.meets()) EXPECT_FALSE(m.tied) << m.a << " " << m.b;
        }
    }
}

TEST(Meet, GlancingMeetTurnsBothAlongTheLineOfCentres) {
    // Ball 0 moving along x meets ball 1 at rest offset by 1 in y (S = 2): at contact the line of centres is at 30°
    // to the motion; afterwards both move, their velocities at right angles (equal masses), momentum kept.
    const Scene s = meeting({{{-4, 1}, {4, 0}, 1}, {{0, 0}, {0, 0}, 1}});
    World w(s, KernelId::robust);
    std::vector<Event> events;
    w.start(events);
    ASSERT_FALSE(w.step(events));
    ASSERT_EQ(w.meets().size(), 1u);
    const MeetRecord& m = w.meets()[0];
    EXPECT_NEAR(m.out_a.x + m.out_b.x, 4.0, 1e-12);
    EXPECT_NEAR(m.out_a.y + m.out_b.y, 0.0, 1e-12);
    EXPECT_NEAR(dot(m.out_a, m.out_b), 0.0, 1e-12);
    // The printed centres are no closer than S.
    EXPECT_FALSE(meet::closer_than(m.pos_a, m.pos_b, {1.0, 1.0}));
}

TEST(Meet, FastBallsMeetUnderRobustAndPassThroughTheLecturesTest) {
    // Two small discs crossing each other within one frame: robust meets them; the lecture's static test at the
    // frame's end sees them far apart and lets them through.
    const Scene s = meeting({{{-10, 0}, {20, 0}, 0.5}, {{10, 0}, {-20, 0}, 0.5}});
    EXPECT_EQ(kinds(run_scene(s, KernelId::robust, 1), Event::Kind::meet).size(), 2u);
    for (const KernelId k : {KernelId::lecture_double, KernelId::lecture_float}) {
        EXPECT_TRUE(kinds(run_scene(s, k, 1), Event::Kind::meet).empty()) << kernel_name(k);
        EXPECT_EQ(last_states(s, k)[0].pos, (Vec2{10, 0}));
    }
}

TEST(Meet, LectureOverlapAtTheFrameEndIsPushedApart) {
    // Slow balls that overlap at the frame's end: the lecture pushes them apart to S and bounces them.
    const Scene s = meeting({{{-1.3, 0}, {0.5, 0}, 1}, {{1.3, 0}, {-0.5, 0}, 1}});
    for (const KernelId k : {KernelId::lecture_double, KernelId::lecture_float}) {
        const std::vector<Ball> end = last_states(s, k);
        EXPECT_NEAR(end[0].pos.x, -1.0, 1e-6) << kernel_name(k);
        EXPECT_NEAR(end[1].pos.x, 1.0, 1e-6);
        EXPECT_EQ(end[0].vel, (Vec2{-0.5, 0}));
        EXPECT_EQ(end[1].vel, (Vec2{0.5, 0}));
    }
}

TEST(Meet, BallsInACorridorBounceBetweenWallsAndEachOther) {
    // Two discs in a corridor closed at x = ±10, fast: over many frames they stay inside, never closer than S,
    // and the total momentum along x changes only at the walls.
    Scene s = meeting({{{-5, 0}, {3.7, 0}, 1}, {{5, 0}, {-2.3, 0}, 1}}, 200);
    s.walls = {{{-10, -5}, {-10, 5}}, {{10, 5}, {10, -5}}, {{-10, 5}, {10, 5}}, {{10, -5}, {-10, -5}}};
    for (const KernelId k : {KernelId::robust, KernelId::exact}) {
        World w(s, k);
        std::vector<Event> events;
        w.start(events);
        int meets = 0;
        for (std::int64_t f = 0; f < s.frames; ++f) {
            ASSERT_FALSE(w.step(events));
            meets += static_cast<int>(w.meets().size());
            const auto b = w.balls();
            ASSERT_FALSE(meet::closer_than(b[0].pos, b[1].pos, {1.0, 1.0})) << kernel_name(k) << " frame " << f + 1;
            for (const Ball& ball : b) ASSERT_LE(std::fabs(ball.pos.x), 9.0) << f + 1;
            for (const MeetRecord& m : w.meets()) ASSERT_FALSE(meet::closer_than(m.pos_a, m.pos_b, {1.0, 1.0}));
        }
        EXPECT_GT(meets, 20) << kernel_name(k);
    }
}

TEST(Meet, TwoBallsTouchingWhosePathsStillCloseInAfterTheMeetStayWhereTheyMet) {
    // A point ball and a disc of radius 0.02 touching, both moving −9e18 a frame: the exact paths keep them 0.02
    // apart, but an ulp there is 2048, so both ends round to −9e18 and the printed paths close in. They meet at
    // t = 0 with no response (equal velocities), and the new paths close in at once again: both stay at their
    // centres to the frame's end, keeping their velocities, never closer than S (rule 6).
    const Scene s = meeting({{{0, 0}, {-9e18, 0}, 0}, {{0.02, 0}, {-9e18, 0}, 0.02}}, 3);
    for (const KernelId k : {KernelId::robust, KernelId::exact}) {
        World w(s, k);
        std::vector<Event> events;
        w.start(events);
        for (std::int64_t f = 0; f < s.frames; ++f) {
            ASSERT_FALSE(w.step(events));
            ASSERT_EQ(w.meets().size(), 1u) << kernel_name(k) << " frame " << f + 1;
            EXPECT_EQ(w.meets()[0].t, 0.0);
            EXPECT_FALSE(w.meets()[0].responded);
            const auto b = w.balls();
            EXPECT_EQ(b[0].pos, (Vec2{0, 0})) << kernel_name(k);
            EXPECT_EQ(b[1].pos, (Vec2{0.02, 0})) << kernel_name(k);
            EXPECT_EQ(b[0].vel, (Vec2{-9e18, 0}));
            EXPECT_EQ(b[1].vel, (Vec2{-9e18, 0}));
            EXPECT_FALSE(meet::closer_than(b[0].pos, b[1].pos, {0.0, 0.02}));
        }
    }
    // Two discs the scene places overlapping, moving alike, are no such pair: they are searched past the meet and
    // move (a scene may start balls overlapping; they stay as they are).
    const Scene overlapping = meeting({{{0, 0}, {-9e18, 0}, 0.01}, {{0.015, 0}, {-9e18, 0}, 0.01}}, 1);
    EXPECT_EQ(last_states(overlapping, KernelId::robust)[0].pos, (Vec2{-9e18, 0}));
}

/// Whether two printed paths come within S of each other from outside it, pass-through's rule: on a common interval
/// of their pieces, at least S apart at its start and closer within it (an interval that starts closer is not judged).
bool enters(std::span<const PathPoint> a, std::span<const PathPoint> b, meet::Radii S) {
    double from = 0.0;
    while (from < 1.0) {
        const std::optional<meet::Root> m = meet::first_meet(a, b, S, from);
        if (!m) return false;
        if (!m->at_start || !meet::closer_on_paths(a, b, m->c, S)) return true;
        double next = 1.0;
        for (const std::span<const PathPoint> path : {a, b})
            for (const PathPoint& q : path)
                if (q.t > m->c) {
                    next = std::min(next, q.t);
                    break;
                }
        from = next;
    }
    return false;
}

TEST(Meet, ASafeStopsPieceEntersNoOtherBall) {
    // Far out (an ulp of y is 1024 to 2048) a point ball jammed between two discs and walls meets them until the
    // bound (16·N meets) stops the frame. Disc 0 moves 4e17 a frame in y, far less than an ulp since its last printed
    // point: its stop rounded to its path's point would print it standing still at that y while ball 2 passed along
    // it, through it. Rule 7 stops it a neighbouring double away instead, and no printed path enters another's.
    Scene s = meeting({{{0, -9.223372036854776e18}, {-9e18, 0}, 1},
                       {{1, -9.223372036854776e18}, {0, 0}, 1},
                       {{1, -9.223372036854776e18}, {0, 0}, 0}});
    s.walls = {{{0, 0}, {10, -9.2234e18}}, {{6, -9.22337203685478e18}, {-6, -9.223372036854776e18}}};
    World w(s, KernelId::robust);
    std::vector<Event> events;
    w.start(events);
    ASSERT_FALSE(w.step(events));
    EXPECT_EQ(w.meets().size(), 16u * 3u);
    for (std::size_t i = 0; i < 3; ++i)
        for (std::size_t j = i + 1; j < 3; ++j)
            EXPECT_FALSE(enters(w.path(i), w.path(j), {s.balls[i].r, s.balls[j].r})) << i << " " << j;
}

TEST(Meet, TheSameRunOnEveryThreadCountAndBroadPhase) {
    std::vector<Ball> balls;
    for (int i = 0; i < 40; ++i) balls.push_back({{i * 2.5 - 50, (i % 7) * 3.0}, {(i % 5) - 2.0, (i % 3) - 1.0}, 1});
    Scene s = meeting(balls, 30);
    s.walls = {{{-60, -30}, {-60, 40}}, {{60, 40}, {60, -30}}, {{-60, 40}, {60, 40}}, {{60, -30}, {-60, -30}}};
    const std::vector<Event> plain = run_scene(s, KernelId::robust, s.frames, {BroadPhase::none, 1});
    EXPECT_FALSE(kinds(plain, Event::Kind::meet).empty());
    EXPECT_EQ(run_scene(s, KernelId::robust, s.frames, {BroadPhase::grid, 2}), plain);
}

TEST(Meet, KernelsWithoutARuleRefuseTheScene) {
    // The four built-in kernels step it; a kernel with no MeetRule refuses it before stepping anything.
    const Scene s = meeting({{{-2, 0}, {2, 0}, 1}, {{2, 0}, {-2, 0}, 1}});
    for (const KernelId k : k_all_kernels) EXPECT_NO_THROW(World(s, k)) << kernel_name(k);
    KernelOps ops = kernel_ops(KernelId::robust);
    ops.name = "test-no-meets";
    ops.meet_rule = MeetRule::none;
    const std::optional<KernelId> k = register_kernel(ops);
    ASSERT_TRUE(k);
    try {
        World w(s, *k);
        ADD_FAILURE() << "no refusal";
    } catch (const UnsupportedScene& e) {
        EXPECT_STREQ(e.what(), "kernel 'test-no-meets' does not step balls that meet ('balls collide')");
    }
    Scene apart = s;
    apart.balls_collide = false;
    EXPECT_NO_THROW(World(apart, *k));
}

TEST(MeetRoot, MeetTimesAreDecidedExactly) {
    // Ball 0 from (−4, 0) to (0, 0), ball 1 at rest at the origin, S = 2: they touch at t = 1/2 exactly.
    const std::vector<PathPoint> a0{{0, {-4, 0}}, {1, {0, 0}}}, still{{0, {0, 0}}, {1, {0, 0}}};
    const auto ra = meet::first_meet(a0, still, {1.0, 1.0}, 0.0);
    ASSERT_TRUE(ra);
    EXPECT_EQ(ra->estimate, 0.5);
    EXPECT_EQ(meet::compare(*ra, 0.5), 0);
    EXPECT_EQ(meet::compare(*ra, std::nextafter(0.5, 1.0)), -1);
    EXPECT_EQ(meet::compare(*ra, std::nextafter(0.5, 0.0)), 1);
    // Searched from 3/4, where ball 0 is already within S and still approaching: a meet there (a scene that
    // places balls overlapping).
    const auto late = meet::first_meet(a0, still, {1.0, 1.0}, 0.75);
    ASSERT_TRUE(late);
    EXPECT_EQ(meet::compare(*late, 0.75), 0);
    // A tangent is no meet: a path passing at exactly S.
    const std::vector<PathPoint> b0{{0, {-2, 2}}, {1, {2, 2}}};
    EXPECT_FALSE(meet::first_meet(b0, still, {1.0, 1.0}, 0.0));
    // One ulp inside it: a meet, at t = 1/2 − √(4 − y²)/4, an irrational time just before 1/2.
    const double y = std::nextafter(2.0, 0.0);
    const std::vector<PathPoint> c0{{0, {-2, y}}, {1, {2, y}}};
    const auto rc = meet::first_meet(c0, still, {1.0, 1.0}, 0.0);
    ASSERT_TRUE(rc);
    EXPECT_EQ(meet::compare(*rc, *ra), -1);
    EXPECT_EQ(meet::compare(*ra, *rc), 1);
    EXPECT_EQ(meet::compare(*rc, *rc), 0);
    EXPECT_LT(rc->estimate, 0.5);
    // Two balls touching and approaching meet at once; touching and leaving, never.
    const std::vector<PathPoint> d0{{0, {-2, 0}}, {1, {-1, 0}}}, e0{{0, {-2, 0}}, {1, {-3, 0}}};
    const auto rd = meet::first_meet(d0, still, {1.0, 1.0}, 0.0);
    ASSERT_TRUE(rd);
    EXPECT_EQ(meet::compare(*rd, 0.0), 0);
    EXPECT_FALSE(meet::first_meet(e0, still, {1.0, 1.0}, 0.0));
}

TEST(MeetRoot, AnEntryAfterTheBallsLeftEachOthersReachIsFound) {
    // Ball 1 starts within S = 2 of ball 0 (at rest at the origin) and approaching: from (1, 0) through it to
    // (−3, 0) at t = 1/2, out of reach from x = −2 on, then back to (1, 0), into reach again at x = −2, t = 5/8.
    const meet::Radii S{1.0, 1.0};
    const std::vector<PathPoint> still{{0, {0, 0}}, {1, {0, 0}}};
    const std::vector<PathPoint> back{{0, {1, 0}}, {0.5, {-3, 0}}, {1, {1, 0}}};
    // The first meet is at the start, where the two are closer than S already: no entry.
    const auto first = meet::first_meet(back, still, S, 0.0);
    ASSERT_TRUE(first);
    EXPECT_EQ(meet::compare(*first, 0.0), 0);
    EXPECT_FALSE(meet::entered(*first, back, still, S));
    // The first entry from outside is the return.
    const auto entry = meet::first_entry(back, still, S, 0.0);
    ASSERT_TRUE(entry);
    EXPECT_EQ(meet::compare(*entry, 0.625), 0);
    EXPECT_TRUE(meet::entered(*entry, back, still, S));
    // Up to 0.6 there is none; from 0.5, the same.
    EXPECT_FALSE(meet::first_entry(back, still, S, 0.0, 0.6));
    const auto later = meet::first_entry(back, still, S, 0.5);
    ASSERT_TRUE(later);
    EXPECT_EQ(meet::compare(*later, 0.625), 0);
    // A ball that never leaves reach (to (−1, 0) and back) enters nothing, though it approaches again at t = 1/2.
    const std::vector<PathPoint> stays{{0, {1, 0}}, {0.5, {-1, 0}}, {1, {1, 0}}};
    EXPECT_FALSE(meet::first_entry(stays, still, S, 0.0));
    // Touching and approaching at the start is an entry there.
    const std::vector<PathPoint> touching{{0, {-2, 0}}, {1, {-1, 0}}};
    const auto at_once = meet::first_entry(touching, still, S, 0.0);
    ASSERT_TRUE(at_once);
    EXPECT_EQ(meet::compare(*at_once, 0.0), 0);
}

TEST(MeetRoot, PointsOnAPathAreCorrectlyRounded) {
    const std::vector<PathPoint> p{{0, {0, 0}}, {0.25, {1, 0}}, {1, {1, 3}}};
    EXPECT_EQ(meet::point_at(p, 0.25).x, (Vec2{1, 0}));
    EXPECT_EQ(meet::point_at(p, 0.25).from, 1u);
    EXPECT_EQ(meet::point_at(p, 0.125).x, (Vec2{0.5, 0}));
    // t = 0.5 on the second piece: 1/3 of the way, y = 1 exactly.
    EXPECT_EQ(meet::point_at(p, 0.5).x, (Vec2{1, 1}));
    EXPECT_EQ(meet::point_at(p, 1.0).x, (Vec2{1, 3}));
    EXPECT_TRUE(meet::closer_than({0, 0}, {std::nextafter(2.0, 0.0), 0}, {1.0, 1.0}));
    EXPECT_FALSE(meet::closer_than({0, 0}, {2, 0}, {1.0, 1.0}));
}

TEST(MeetRoot, TheRadiiAreSummedExactly) {
    // R_i = 1 and R_j = 2^−80: their sum rounds to 1, yet the balls are wider than that.
    const meet::Radii S{1.0, 0x1p-80};
    ASSERT_EQ(S.rounded(), 1.0);
    EXPECT_TRUE(meet::closer_than({0, 0}, {1, 0}, S));
    EXPECT_FALSE(meet::closer_than({0, 0}, {1 + 0x1p-52, 0}, S));
    // Ball 1 from (3, 0) toward ball 0 at rest at the origin at 5/2 a frame: at distance 1 at t = 4/5 exactly, at
    // the exact sum 1 + 2^−80 a little before.
    const std::vector<PathPoint> still{{0, {0, 0}}, {1, {0, 0}}}, in{{0, {3, 0}}, {1, {0.5, 0}}};
    const auto r = meet::first_meet(in, still, S, 0.0);
    ASSERT_TRUE(r);
    EXPECT_EQ(meet::compare(*r, 0.8), -1);
    // The World's meet prints centres no closer than the exact sum.
    const Scene s = meeting({{{0, 0}, {0, 0}, 1}, {{3, 0}, {-2.5, 0}, 0x1p-80}});
    World w(s, KernelId::robust);
    std::vector<Event> events;
    w.start(events);
    ASSERT_FALSE(w.step(events));
    ASSERT_EQ(w.meets().size(), 1u);
    EXPECT_FALSE(meet::closer_than(w.meets()[0].pos_a, w.meets()[0].pos_b, S));
}

}  // namespace
}  // namespace ricochet
