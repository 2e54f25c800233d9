// The disc checks themselves on paths written by hand (frame_check.hpp), which no sound kernel gives: penetration
// fails on a piece that comes too close, ghost-bounce on a hit only a tangent could make, boundary on a touching
// disc that moves closer without a contact, bounce-side on a disc back across a face it bounced off; and the
// images (symmetry, swap, translation) and the oracle on mutant kernels that prefer a direction, a wall's
// direction or a place, step another radius or miss the bumpers; accuracy on mutant kernels whose contact time,
// contact point or bounce is off.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "checks/frame_check.hpp"
#include "mutant_kernel.hpp"
#include "ricochet/checks.hpp"

namespace ricochet {
namespace {

// The penetration check on paths written by hand (frame_check.hpp): the kernel never gives such a path.
std::string penetration_verdict(const Scene& s, const std::vector<std::vector<Event>>& frames) {
    auto check = checks::make_penetration(s, KernelId::robust, {});
    std::vector<Event> start;
    for (std::uint32_t b = 0; b < s.balls.size(); ++b)
        start.push_back({Event::Kind::state, 0, b, Event::Shape::none, 0, s.balls[b].pos, s.balls[b].vel});
    if (auto r = check->frame({0, start, {}, {}, {}})) return r->message;
    for (std::size_t f = 0; f < frames.size(); ++f)
        if (auto r = check->frame({static_cast<std::int64_t>(f + 1), frames[f], {}, {}, {}})) return r->message;
    return "";
}

Event state(std::int64_t f, Vec2 p) { return {Event::Kind::state, f, 0, Event::Shape::none, 0, p, {}}; }
Event hit(std::int64_t f, Vec2 p) { return {Event::Kind::hit, f, 0, Event::Shape::none, 0, p, {}}; }

TEST(DiscChecks, PenetrationCatchesAPieceTooClose) {
    Scene s;
    s.walls = {{{0, 0}, {10, 0}}};
    s.bumpers = {{{20, 20}, 2}};
    s.balls = {{{5, 3}, {}, 1}};
    // Down to exactly R and back: clear (δ = 0, touching allowed).
    EXPECT_EQ(penetration_verdict(s, {{hit(1, {5, 1}), state(1, {5, 3})}}), "");
    // One ulp closer than R at a hit point.
    EXPECT_NE(penetration_verdict(s, {{hit(1, {5, std::nextafter(1.0, 0.0)}), state(1, {5, 3})}}), "");
    // Both ends clear, the piece between them not: from (8, 2) to (12, −2) it passes through P1 = (10, 0).
    EXPECT_EQ(penetration_verdict(s, {{state(1, {8, 2})}}), "");
    EXPECT_NE(penetration_verdict(s, {{state(1, {8, 2})}, {state(2, {12, -2})}}), "");
    // A bumper: R + r = 3 from (20, 20); 17 is exactly 3 away, 17.5 is not.
    EXPECT_EQ(penetration_verdict(s, {{state(1, {17, 20})}}), "");
    EXPECT_NE(penetration_verdict(s, {{state(1, {17.5, 20})}}), "");
    // Starting overlapping the wall: held to it only once a printed point is clear.
    Scene deep = s;
    deep.balls = {{{5, 0.5}, {}, 1}};
    EXPECT_EQ(penetration_verdict(deep, {{state(1, {5, 0.25})}, {state(2, {5, 1})}}), "");
    EXPECT_NE(penetration_verdict(deep, {{state(1, {5, 1})}, {state(2, {5, 0.75})}}), "");
    // A point ball and a bumper: r from the centre, exactly; a wall holds nothing for it (R = 0).
    Scene point_bumper = s;
    point_bumper.balls = {{{25, 20}, {}, 0}};
    EXPECT_EQ(penetration_verdict(point_bumper, {{state(1, {22, 20})}, {hit(2, {30, 10}), state(2, {6, 10})},
                                                 {state(3, {5, -3})}}),
              "");
    EXPECT_NE(penetration_verdict(point_bumper, {{state(1, {std::nextafter(22.0, 0.0), 20})}}), "");
    EXPECT_NE(penetration_verdict(point_bumper, {{state(1, {22, 22})}, {state(2, {18, 18})}}), "");
    // Point balls among walls alone: nothing to hold.
    Scene point = s;
    point.bumpers.clear();
    point.balls = {{{5, 3}, {}, 0}};
    EXPECT_EQ(penetration_verdict(point, {{state(1, {5, -3})}}), "");
}


// The ghost-bounce check on frames written by hand: what makes a first hit a ghost, and what does not.
std::string ghost_verdict(const Scene& s, std::vector<Ball> before, const std::vector<Event>& frame1) {
    auto check = checks::make_ghost_bounce(s, KernelId::robust, {});
    if (auto r = check->frame({0, {}, {}, {}, {}})) return r->message;
    if (auto r = check->frame({1, frame1, before, {}, {}})) return r->message;
    return "";
}

Event hit_wall(std::uint32_t w, Vec2 p) { return {Event::Kind::hit, 1, 0, Event::Shape::none, w, p, {}}; }

TEST(DiscChecks, GhostBounceCatchesAHitOnlyATangentCouldMake) {
    Scene s;
    // A 3-4-5 chain through (0, 10): the disc of radius 5 moves along (0.75, 1), exactly 5 from the line.
    s.walls = {{{0, 10}, {3, 14}}, {{3, 14}, {6, 18}}};
    s.balls = {{{4, 7}, {0.75, 1}, 5}};
    const std::vector<Ball> sliding = s.balls;
    EXPECT_NE(ghost_verdict(s, sliding, {hit_wall(1, {7, 11}), state(1, {7, 11})}), "");
    EXPECT_NE(ghost_verdict(s, sliding, {hit_wall(0, {7, 11}), state(1, {7, 11})}), "");
    // One ulp closer than R to the line: it can enter a cap, a real hit.
    std::vector<Ball> closer = sliding;
    closer[0].pos.x = std::nextafter(4.0, 0.0);
    EXPECT_EQ(ghost_verdict(s, closer, {hit_wall(1, {7, 11})}), "");
    // A leg not parallel by an ulp of its end (8 + 2^−48): not judged (it may cross the line at a grazing angle).
    // Off by less, the rounded leg is parallel again and judged.
    std::vector<Ball> askew = sliding;
    askew[0].vel.y = 1 + std::ldexp(1.0, -48);
    EXPECT_EQ(ghost_verdict(s, askew, {hit_wall(1, {7, 11})}), "");
    askew[0].vel.y = std::nextafter(1.0, 2.0);
    EXPECT_NE(ghost_verdict(s, askew, {hit_wall(1, {7, 11})}), "");
    // Only the first hit or bump of a frame is judged: its velocity is the one before the frame.
    Scene with_bumper = s;
    with_bumper.bumpers = {{{20, 20}, 1}};
    const Event bump{Event::Kind::bump, 1, 0, Event::Shape::none, 0, {7, 11}, {}};
    EXPECT_EQ(ghost_verdict(with_bumper, sliding, {bump, hit_wall(1, {7, 11})}), "");
    // A point ball moving along a wall's own line (R = 0, on the line): a hit there is a ghost too.
    Scene point;
    point.walls = {{{0, 0}, {10, 0}}};
    point.balls = {{{-5, 0}, {1, 0}, 0}};
    EXPECT_NE(ghost_verdict(point, point.balls, {hit_wall(0, {0, 0})}), "");
    // The leg is Bs → Bs + v as rounded, not v: v = (1.8e16, 1.8e16) is parallel to the wall along y = x, but from
    // (123, 124) the leg ends at (1.8e16 + 124, 1.8e16 + 124) (the ulp there is 4), on the wall's line: it meets
    // the wall, a real hit (found by the disc campaign when the check read v).
    Scene far;
    far.walls = {{{1e16, 1e16}, {2e16, 2e16}}};
    far.balls = {{{123, 124}, {1.8e16, 1.8e16}, 0}};
    EXPECT_EQ(ghost_verdict(far, far.balls, {hit_wall(0, {1.8000000000000124e16, 1.8000000000000124e16})}), "");
    Scene far_run = far;
    far_run.frames = 1;
    far_run.checks = {Check::ghost_bounce};
    EXPECT_FALSE(run_checked(far_run, KernelId::robust, 1, far_run.checks).failure);
    // A ball that does not move, or a wall of no length: not judged.
    std::vector<Ball> resting = point.balls;
    resting[0].vel = {0, 0};
    EXPECT_EQ(ghost_verdict(point, resting, {hit_wall(0, {0, 0})}), "");
    Scene dot = point;
    dot.walls = {{{3, 0}, {3, 0}}};
    EXPECT_EQ(ghost_verdict(dot, point.balls, {hit_wall(0, {3, 0})}), "");
}


// The boundary check's touching rule on frames written by hand: the ball's state before frame 1 and its events.
std::string touching_verdict(const Scene& s, const std::vector<Event>& frame1) {
    auto check = checks::make_boundary(s, KernelId::robust, {});
    if (auto r = check->frame({0, {}, {}, {}, {}})) return r->message;
    if (auto r = check->frame({1, frame1, s.balls, {}, {}})) return r->message;
    return "";
}

Event bump_at(Vec2 p) { return {Event::Kind::bump, 1, 0, Event::Shape::none, 0, p, {}}; }

TEST(DiscChecks, BoundaryTouchingIsContact) {
    Scene s;
    s.walls = {{{0, 0}, {10, 0}}};
    s.balls = {{{5, 1}, {0, -1}, 1}};
    // Exactly R above the face, moving closer: a contact at the start point, nothing else.
    EXPECT_EQ(touching_verdict(s, {hit(1, {5, 1}), state(1, {5, 2})}), "");
    EXPECT_NE(touching_verdict(s, {state(1, {5, 0})}), "");
    EXPECT_NE(touching_verdict(s, {hit(1, {5, 0.5}), state(1, {5, 1})}), "");
    // Moving away or along: no contact owed.
    for (const Vec2 v : {Vec2{0, 1}, Vec2{1, 0}}) {
        Scene away = s;
        away.balls[0].vel = v;
        EXPECT_EQ(touching_verdict(away, {state(1, s.balls[0].pos + v)}), "") << v.x << " " << v.y;
    }
    // One ulp farther than R: not touching.
    Scene farther = s;
    farther.balls[0].pos.y = std::nextafter(1.0, 2.0);
    EXPECT_EQ(touching_verdict(farther, {state(1, {5, 0})}), "");
    // Within reach (a start overlapping the wall), moving closer: a contact too; the centre on the segment has no
    // normal, so nothing is owed.
    Scene within = s;
    within.balls[0].pos = {5, 0.5};
    EXPECT_NE(touching_verdict(within, {state(1, {5, -0.5})}), "");
    within.balls[0].pos = {5, 0};
    EXPECT_EQ(touching_verdict(within, {state(1, {5, -1})}), "");
    // A cap: R beyond P1 along the wall's line, moving back toward it.
    Scene cap = s;
    cap.balls = {{{11, 0}, {-1, 0}, 1}};
    EXPECT_NE(touching_verdict(cap, {state(1, {10, 0})}), "");
    EXPECT_EQ(touching_verdict(cap, {hit(1, {11, 0}), state(1, {12, 0})}), "");
    // A bumper: R + r from its centre, the exact sum; the leg is Bs → Bs + v as rounded, so a velocity too small to
    // move the ball owes nothing.
    Scene bumper;
    bumper.bumpers = {{{20, 20}, 2}};
    bumper.balls = {{{17, 20}, {1, 0}, 1}};
    EXPECT_NE(touching_verdict(bumper, {state(1, {18, 20})}), "");
    EXPECT_EQ(touching_verdict(bumper, {bump_at({17, 20}), state(1, {16, 20})}), "");
    bumper.balls[0].vel = {5e-324, 0};
    EXPECT_EQ(touching_verdict(bumper, {state(1, {17, 20})}), "");
    // A point ball on a bumper's rim (R = 0) is held to it; to walls, the point rules' parts of boundary only.
    Scene point = bumper;
    point.walls = s.walls;
    point.balls = {{{18, 20}, {1, 0}, 0}};
    EXPECT_NE(touching_verdict(point, {state(1, {19, 20})}), "");
    // The kernels: robust meets a touching disc at once; lecture-double passes over a point it is within reach of.
    Scene run = s;
    run.frames = 1;
    EXPECT_FALSE(run_checked(run, KernelId::robust, 1, std::vector<Check>{Check::boundary}).failure);
    run.walls = {{{0, 0}, {0, 0}}};
    run.balls = {{{0, 0.004}, {0, -1}, 1}};
    EXPECT_FALSE(run_checked(run, KernelId::robust, 1, std::vector<Check>{Check::boundary}).failure);
    const auto lecture = run_checked(run, KernelId::lecture_double, 1, std::vector<Check>{Check::boundary}).failure;
    ASSERT_TRUE(lecture);
    EXPECT_EQ(lecture->check, Check::boundary);
}

// bounce-side for discs on paths written by hand: held after a face contact, not after a cap or a bump.
std::string side_verdict(const Scene& s, const std::vector<std::vector<Event>>& frames) {
    auto check = checks::make_bounce_side(s, KernelId::robust, {});
    for (std::size_t f = 0; f < frames.size(); ++f)
        if (auto r = check->frame({static_cast<std::int64_t>(f + 1), frames[f], {}, {}, {}})) return r->message;
    return "";
}

TEST(DiscChecks, BounceSideHoldsADiscToAFaceItBouncedOff) {
    Scene s;
    s.walls = {{{0, 0}, {10, 0}}};
    s.balls = {{{5, 3}, {0, -4}, 1}};
    // A face contact from above, then a point below the wall's line: back across the face.
    EXPECT_NE(side_verdict(s, {{hit(1, {5, 1}), state(1, {5, -3})}}), "");
    EXPECT_EQ(side_verdict(s, {{hit(1, {5, 1}), state(1, {5, 3})}}), "");
    // At the face's end (the foot on P1 itself) the face's rule holds.
    EXPECT_NE(side_verdict(s, {{hit(1, {10, 1}), state(1, {10, -3})}}), "");
    // A cap (the foot beyond P1) has no side: below the line later is no failure.
    Scene cap = s;
    cap.balls = {{{13, 4}, {-3, -4}, 1}};
    EXPECT_EQ(side_verdict(cap, {{hit(1, {10.6, 0.8}), state(1, {12, -3})}}), "");
    // A bump ends the rule, as a hit does.
    Scene bumper = s;
    bumper.bumpers = {{{5, -20}, 1}};
    EXPECT_EQ(side_verdict(bumper, {{hit(1, {5, 1}), bump_at({5, 2}), state(1, {5, -3})}}), "");
    // A point ball: held after any hit, as always.
    Scene point = s;
    point.balls[0].r = 0;
    EXPECT_NE(side_verdict(point, {{hit(1, {11, 0}), state(1, {12, -3})}}), "");
    // Stepped by the disc frame (a disc, or a point ball among bumpers): beyond the wall's end the path may pass
    // around it, so only points whose foot is on the segment are held.
    EXPECT_EQ(side_verdict(s, {{hit(1, {9.5, 1}), state(1, {12, -3})}}), "");
    Scene point_bumper = point;
    point_bumper.bumpers = {{{5, -20}, 1}};
    EXPECT_EQ(side_verdict(point_bumper, {{hit(1, {10, 0}), state(1, {12, -3})}}), "");
    EXPECT_NE(side_verdict(point_bumper, {{hit(1, {10, 0}), state(1, {9, -3})}}), "");
}

// The images a disc run is held to, on the mutant kernel: robust's disc step with one direction-dependent bug each.
namespace bugs {
/// Nudges the end state one ulp toward +x after a contact: a preference for one direction.
FrameStatus toward_plus_x(Ball& ball, BallMemory& memory, const Obstacles& o, std::vector<HitEvent>& hits,
                          StepScratch& scratch) {
    const FrameStatus st = mutant::robust().step_disc(ball, memory, o, hits, scratch);
    if (!hits.empty()) ball.pos.x = std::nextafter(ball.pos.x, HUGE_VAL);
    return st;
}
/// Sees each wall from P0 to its midpoint only: the wall's direction decides which half is there.
FrameStatus half_walls(Ball& ball, BallMemory& memory, const Obstacles& o, std::vector<HitEvent>& hits,
                       StepScratch& scratch) {
    std::vector<Wall> halves(o.walls.begin(), o.walls.end());
    for (Wall& w : halves) w.p1 = 0.5 * (w.p0 + w.p1);
    Obstacles cut = o;
    cut.walls = halves;
    cut.index = nullptr;
    return mutant::robust().step_disc(ball, memory, cut, hits, scratch);
}
/// Forgets the bumpers once the ball is past x = 1000: where the scene is decides what it meets.
FrameStatus place(Ball& ball, BallMemory& memory, const Obstacles& o, std::vector<HitEvent>& hits,
                  StepScratch& scratch) {
    Obstacles far = o;
    if (ball.pos.x > 1000) {
        far.bumpers = {};
        far.bumper_index = nullptr;
    }
    return mutant::robust().step_disc(ball, memory, far, hits, scratch);
}
/// Steps the disc as if its radius were half what it is: every contact decision is another disc's.
FrameStatus half_radius(Ball& ball, BallMemory& memory, const Obstacles& o, std::vector<HitEvent>& hits,
                        StepScratch& scratch) {
    const double R = ball.r;
    ball.r = R / 2;
    const FrameStatus st = mutant::robust().step_disc(ball, memory, o, hits, scratch);
    ball.r = R;
    return st;
}
/// Never sees the bumpers.
FrameStatus no_bumpers(Ball& ball, BallMemory& memory, const Obstacles& o, std::vector<HitEvent>& hits,
                       StepScratch& scratch) {
    Obstacles walls_only = o;
    walls_only.bumpers = {};
    walls_only.bumper_index = nullptr;
    return mutant::robust().step_disc(ball, memory, walls_only, hits, scratch);
}
/// Scales the traced t_i of every contact by 1 + k_t_error (the printed run is robust's): a contact time off.
double k_t_error = 0.0;
FrameStatus t_off(Ball& ball, BallMemory& memory, const Obstacles& o, std::vector<HitEvent>& hits,
                  StepScratch& scratch) {
    const FrameStatus st = mutant::robust().step_disc(ball, memory, o, hits, scratch);
    if (scratch.trace != nullptr)
        for (TracedLeg& leg : scratch.trace->legs)
            if (leg.hit || leg.bumped) leg.hit_t *= 1.0 + k_t_error;
    return st;
}
/// Prints each contact point 2^−30 further along x than robust put it: a contact point off, its time right.
FrameStatus point_off(Ball& ball, BallMemory& memory, const Obstacles& o, std::vector<HitEvent>& hits,
                      StepScratch& scratch) {
    const std::size_t before = hits.size();
    const FrameStatus st = mutant::robust().step_disc(ball, memory, o, hits, scratch);
    for (std::size_t i = before; i < hits.size(); ++i) hits[i].point.x += 0x1p-30;
    return st;
}
/// Leaves a frame of one contact with v′ turned by about 2^−20 radians: a bounce about another normal (as the
/// check sees it where the contact ends the frame; after it, the next leg's velocity is the one judged).
FrameStatus bounce_off(Ball& ball, BallMemory& memory, const Obstacles& o, std::vector<HitEvent>& hits,
                       StepScratch& scratch) {
    const std::size_t before = hits.size();
    const FrameStatus st = mutant::robust().step_disc(ball, memory, o, hits, scratch);
    if (hits.size() == before + 1) ball.vel = {ball.vel.x - 0x1p-20 * ball.vel.y, ball.vel.y + 0x1p-20 * ball.vel.x};
    return st;
}
}  // namespace bugs

/// With the disc step replaced by bug, check c fails first at frame 1 for ball, its message containing text.
void expect_caught(const Scene& s, decltype(KernelOps::step_disc) bug, Check c, std::uint32_t ball,
                   std::string_view text) {
    mutant::Mutation m;
    m.ops.step_disc = bug;
    mutant::expect_failure(mutant::first_failure(s, 1, {c}), c, 1, ball, text);
}

TEST(DiscChecks, AccuracyCatchesAContactOffInTimePointOrBounce) {
    // Each contact at t = 1, the frame's end, so that no leg follows it (a traced t_i off would also break the
    // rest of the frame) and the end state's velocity is the one the ball left the contact with: ball 0, R = 0.5,
    // reaches wall 0's face (x = 1.5) with its centre at (1, 0.25); ball 1, R = 0.25, the bumper of radius 0.75 at
    // (10, 0) head-on, its centre at (9, 0).
    Scene s = mutant::scene({{{1.5, -2}, {1.5, 2}}}, {{{0, 0}, {1, 0.25}, 0.5}, {{8, 0}, {1, 0}, 0.25}});
    s.bumpers = {{{10, 0}, 0.75}};
    s.frames = 1;
    EXPECT_FALSE(mutant::first_failure(s, 1, {Check::accuracy}, KernelId::robust));
    EXPECT_FALSE(mutant::first_failure(s, 1, {Check::accuracy}, KernelId::exact));
    {
        // Within the bound (2^16·2^−53·M, M = 2 for ball 0, along a leg of |d|∞ = 1): t_i off by 2^−40.
        mutant::Mutation m;
        m.ops.step_disc = bugs::t_off;
        bugs::k_t_error = 0x1p-40;
        EXPECT_FALSE(mutant::first_failure(s, 1, {Check::accuracy}));
        // Past it: 2^−34.
        bugs::k_t_error = 0x1p-34;
        mutant::expect_failure(mutant::first_failure(s, 1, {Check::accuracy}), Check::accuracy, 1, 0,
                               "meets wall 0 at t_i = 1.00000000");
    }
    expect_caught(s, bugs::point_off, Check::accuracy, 0, "eps*M from the exact contact point");
    expect_caught(s, bugs::bounce_off, Check::accuracy, 0, "meets wall 0 at (1, 0.25) moving (1, 0.25)");
    Scene bumper_only = s;
    bumper_only.balls.erase(bumper_only.balls.begin());
    expect_caught(bumper_only, bugs::bounce_off, Check::accuracy, 0, "meets bumper 0 at (9, 0) moving (1, 0)");
}

TEST(DiscChecks, OracleCatchesAKernelThatDecidesForAnotherDiscOrMissesABumper) {
    // A disc of radius 1 coming down from (5, 2.5) to (5, 0.75), within R of the floor (a disc of radius 1/2 would
    // stop short of it); a bumper in the way of another.
    Scene s = mutant::scene({{{0, 0}, {10, 0}}}, {{{5, 2.5}, {0, -1.75}, 1}, {{20, 5}, {0, -4}, 1}});
    s.bumpers = {{{20, 0}, 1}};
    s.frames = 1;
    EXPECT_FALSE(mutant::first_failure(s, 1, {Check::oracle}, KernelId::robust));
    EXPECT_FALSE(mutant::first_failure(s, 1, {Check::oracle}, KernelId::exact));
    expect_caught(s, bugs::half_radius, Check::oracle, 0, "against wall 0: the kernel says no contact, exactly a contact");
    expect_caught(s, bugs::no_bumpers, Check::oracle, 1, "the kernel meets nothing first, exactly bumper 0 (its rim)");
}

TEST(DiscChecks, ImagesCatchAKernelThatPrefersADirectionAWallsDirectionOrAPlace) {
    Scene s = mutant::scene({{{0, 0}, {10, 0}}}, {{{8, 3}, {0.5, -4}, 1}});
    s.frames = 2;
    for (Check c : {Check::symmetry, Check::swap, Check::translation})
        EXPECT_FALSE(mutant::first_failure(s, 2, {c}, KernelId::robust)) << check_name(c);
    {
        mutant::Mutation m;
        m.ops.step_disc = bugs::toward_plus_x;
        mutant::expect_failure(mutant::first_failure(s, 2, {Check::symmetry}), Check::symmetry, 1, 0,
                               "mirrored across x = 0");
    }
    {
        mutant::Mutation m;
        m.ops.step_disc = bugs::half_walls;
        mutant::expect_failure(mutant::first_failure(s, 2, {Check::swap}), Check::swap, 1, 0,
                               "the run with every wall walked the other way meets wall 0 first in this frame, the "
                               "run nothing");
    }
    Scene b = mutant::scene({}, {{{3, 0}, {-2, 0}, 1}});
    b.bumpers = {{{0, 0}, 1}};
    b.frames = 1;
    EXPECT_FALSE(mutant::first_failure(b, 1, {Check::translation}, KernelId::robust));
    {
        mutant::Mutation m;
        m.ops.step_disc = bugs::place;
        mutant::expect_failure(mutant::first_failure(b, 1, {Check::translation}), Check::translation, 1, 0,
                               "changes a hit, a bump or an overlap");
    }
}

}  // namespace
}  // namespace ricochet
