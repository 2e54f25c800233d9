// The checks that follow a ball's path and its kernel's trace (oracle's legs and bounce limit, accuracy,
// speed, no-escape, bounce-side, deterministic, broad-phase, run_checked's own trace and order) fail when a
// step breaks their invariant: each test wraps robust's step_ball (mutant_kernel.hpp) so that it breaks
// exactly one, and pins the check, frame, ball and what the message names.
#include <gtest/gtest.h>

#include <algorithm>

#include "mutant_kernel.hpp"

namespace ricochet::mutant {
namespace {

// The parameters of a step_ball, for the wrapping lambdas below.
#define STEP_PARAMS                                                                                          \
    Ball &b, BallMemory &mem, std::span<const Wall> walls, std::vector<HitEvent> &hits, StepScratch &scratch, \
        const WallIndex *index
#define STEP_ROBUST robust().step_ball(b, mem, walls, hits, scratch, index)

const Wall k_wall{{5, -1}, {5, 1}};        // the segment x = 5, −1 ≤ y ≤ 1
const Ball k_hitter{{1, 0}, {8, 0}};       // (1, 0) → (9, 0) hits it at t = 0.5, (5, 0)

std::vector<Wall> box(double lo, double hi) {
    return {{{lo, hi}, {lo, lo}}, {{lo, lo}, {hi, lo}}, {{hi, lo}, {hi, hi}}, {{hi, hi}, {lo, hi}}};
}

// ---- oracle: the legs ----

int g_coord = 0;  // which coordinate of the first leg is made infinite: from.x, from.y, to.x, to.y

/// robust, but the first leg of its trace has an infinite coordinate (g_coord): a kernel whose arithmetic
/// overflowed, as lecture-float's can.
FrameStatus infinite_leg(STEP_PARAMS) {
    const FrameStatus st = STEP_ROBUST;
    if (scratch.trace != nullptr) {
        TracedLeg& leg = scratch.trace->legs.front();
        double* c[] = {&leg.from.x, &leg.from.y, &leg.to.x, &leg.to.y};
        *c[g_coord] = INFINITY;
    }
    return st;
}

TEST(CheckFailures, OracleSeesALegWithANonFiniteEnd) {
    Mutation m;
    m.ops.step_ball = &infinite_leg;
    for (g_coord = 0; g_coord < 4; ++g_coord)
        expect_failure(first_failure(scene({k_wall}, {k_hitter}), 1, {Check::oracle}), Check::oracle, 1, 0,
                       "the kernel swept a leg whose end is not finite");
}

TEST(CheckFailures, AccuracyLeavesALegWithANonFiniteEndToOracle) {
    Mutation m;
    m.ops.step_ball = &infinite_leg;
    for (g_coord = 2; g_coord < 4; ++g_coord) {
        const auto f = first_failure(scene({k_wall}, {k_hitter}), 1, {Check::accuracy});
        EXPECT_FALSE(f) << f->str();
    }
}

// Core bug (reported, not fixed here): accuracy.cpp takes truth::side(leg.from, wall) before its test for a
// non-finite leg, and GMP's mpq_set_d raises SIGFPE on an infinite from: the process dies instead of
// accuracy leaving the leg to oracle. Enable when accuracy.cpp tests finiteness first.
TEST(CheckFailures, DISABLED_AccuracyLeavesALegWithANonFiniteStartToOracle) {
    Mutation m;
    m.ops.step_ball = &infinite_leg;
    for (g_coord = 0; g_coord < 2; ++g_coord) {
        const auto f = first_failure(scene({k_wall}, {k_hitter}), 1, {Check::oracle, Check::accuracy});
        expect_failure(f, Check::oracle, 1, 0, "the kernel swept a leg whose end is not finite");
    }
}

TEST(CheckFailures, OracleSeesAContactReflectionOffALegThatDoesNotLeaveTheContact) {
    // The kernel says its first leg ran into contact wall 0's far side and was reflected, but the leg ends
    // on the side it was met from.
    Mutation m;
    m.ops.step_ball = [](STEP_PARAMS) {
        const FrameStatus st = STEP_ROBUST;
        if (scratch.trace != nullptr) {
            TracedLeg& leg = scratch.trace->legs.front();
            leg.blocked = true;
            leg.blocked_wall = 0;
            leg.blocked_side = static_cast<std::int8_t>(sign_of(robust().classify(leg.to, walls[0])));
        }
        return st;
    };
    expect_failure(first_failure(scene({k_wall}, {k_hitter}), 1, {Check::oracle}), Check::oracle, 1, 0,
                   "leg 0 ((1, 0) -> (9, 0)) is taken as leaving contact wall 0 to its far side, but it does not end "
                   "there exactly");
}

TEST(CheckFailures, OracleSeesAStepThatNeverTriesAWall) {
    // The step leaves the last wall out; the leg goes through it.
    Mutation m;
    m.ops.step_ball = [](STEP_PARAMS) {
        (void)index;  // the index knows every wall
        return robust().step_ball(b, mem, walls.first(walls.size() - 1), hits, scratch, nullptr);
    };
    expect_failure(first_failure(scene({{{100, -1}, {100, 1}}, k_wall}, {k_hitter}), 1, {Check::oracle}),
                   Check::oracle, 1, 0, "leg 0 ((1, 0) -> (9, 0)) hits wall 1 exactly, but the kernel never tried it");
}

/// robust on the walls in reverse order, its answers mapped back: a kernel that breaks exact ties between
/// crossings towards the highest wall index.
FrameStatus reversed_walls(STEP_PARAMS) {
    (void)index;  // built for the walls in their order
    const auto n = static_cast<std::uint32_t>(walls.size());
    const auto flip = [n](std::uint32_t& i) { i = n - 1 - i; };
    const auto flip_memory = [&] {
        for (std::uint8_t k = 0; k < mem.count; ++k) flip(mem.contacts[k].wall);
        flip(mem.bounced_wall);
    };
    const std::vector<Wall> reversed(walls.rbegin(), walls.rend());
    const std::size_t h0 = hits.size();
    const std::size_t l0 = scratch.trace != nullptr ? scratch.trace->legs.size() : 0;
    const std::size_t d0 = scratch.trace != nullptr ? scratch.trace->decisions.size() : 0;
    flip_memory();
    const FrameStatus st = robust().step_ball(b, mem, reversed, hits, scratch, nullptr);
    flip_memory();
    for (std::size_t h = h0; h < hits.size(); ++h) flip(hits[h].wall);
    if (StepTrace* t = scratch.trace) {
        for (std::size_t l = l0; l < t->legs.size(); ++l) {
            if (t->legs[l].hit) flip(*t->legs[l].hit);
            flip(t->legs[l].blocked_wall);
        }
        for (std::size_t d = d0; d < t->decisions.size(); ++d) flip(t->decisions[d].wall);
    }
    return st;
}

TEST(CheckFailures, OracleSeesATieBrokenTowardsTheHigherWall) {
    // (5, 5) → (15, 15) meets walls 0 and 1 at their common end (10, 10): the first hit is wall 0.
    Mutation m;
    m.ops.step_ball = &reversed_walls;
    const Scene s = scene({{{10, 0}, {10, 10}}, {{0, 10}, {10, 10}}}, {{{5, 5}, {10, 10}}});
    expect_failure(first_failure(s, 1, {Check::oracle}), Check::oracle, 1, 0,
                   "leg 0 ((5, 5) -> (15, 15)): the kernel hits wall 1 first, exactly wall 0");
}

TEST(CheckFailures, OracleSeesABounceThatPrintsNoHit) {
    Mutation m;
    m.ops.step_ball = [](STEP_PARAMS) {
        const std::size_t h0 = hits.size();
        const FrameStatus st = STEP_ROBUST;
        hits.resize(h0);
        return st;
    };
    expect_failure(first_failure(scene({k_wall}, {k_hitter}), 1, {Check::oracle}), Check::oracle, 1, 0,
                   "the frame printed 0 hit(s), the legs swept give 1");
}

TEST(CheckFailures, OracleSeesTheFirstHitDifferFromTheExactKernels) {
    // The step moves the ball twice as far as its velocity says: its own legs are decided right, but from
    // (1, 0) moving (3, 0) the exact frame ends at (4, 0), short of the wall.
    Mutation m;
    m.ops.step_ball = [](STEP_PARAMS) {
        b.vel = b.vel * 2.0;
        const FrameStatus st = STEP_ROBUST;
        b.vel = b.vel * 0.5;
        return st;
    };
    expect_failure(first_failure(scene({k_wall}, {{{1, 0}, {3, 0}}}), 1, {Check::oracle}), Check::oracle, 1, 0,
                   "from (1, 0) moving (3, 0) the kernel hits wall 0 first, the exact kernel hits no wall");
}

// ---- oracle: the bounce limit ----

/// A corridor 1 wide crossed 20 times a frame: robust stops at its 16th bounce, on wall 0 moving right.
Scene corridor() { return scene({{{0, -1000}, {0, 1000}}, {{1, 1000}, {1, -1000}}}, {{{0.5, 0}, {20, 1}}}); }

TEST(CheckFailures, OracleSeesAFrameStoppedAt15Bounces) {
    Mutation m;
    m.ops.step_ball = [](STEP_PARAMS) {
        const FrameStatus st = STEP_ROBUST;
        if (st == FrameStatus::bounce_limit) {
            hits.pop_back();
            b.pos = hits.back().point;
        }
        return st;
    };
    expect_failure(first_failure(corridor(), 1, {Check::oracle}), Check::oracle, 1, 0,
                   "the frame made 15 bounce(s) (15 hit(s), 0 off contact walls) and stopped at the limit; the limit "
                   "is 16 bounces");
}

TEST(CheckFailures, OracleSeesAFrameAllowed17Bounces) {
    // Past robust's 16th bounce the step goes on for one more crossing of the corridor.
    Mutation m;
    m.ops.step_ball = [](STEP_PARAMS) {
        FrameStatus st = STEP_ROBUST;
        if (st != FrameStatus::bounce_limit) return st;
        b.vel = b.vel * 0.0625;  // 1.25 across: one more hit
        st = STEP_ROBUST;
        b.vel = b.vel * 16.0;
        return st;
    };
    expect_failure(first_failure(corridor(), 1, {Check::oracle}), Check::oracle, 1, 0,
                   "the frame made 17 bounce(s) (17 hit(s), 0 off contact walls) and did not stop at the limit; the "
                   "limit is 16 bounces");
}

TEST(CheckFailures, OracleSeesABallStoppedAtTheLimitAwayFromItsLastHit) {
    // At the limit the step puts the ball back where the frame began instead of at its 16th hit point.
    Mutation m;
    m.ops.step_ball = [](STEP_PARAMS) {
        const Vec2 start = b.pos;
        const FrameStatus st = STEP_ROBUST;
        if (st == FrameStatus::bounce_limit) b.pos = start;
        return st;
    };
    // A second ball at rest and a circle round the start give the frame events that are not ball 0's hits.
    Scene s = corridor();
    s.balls.push_back({{0.5, 500}, {0, 0}});
    s.circles = {{{0.5, 0}, 0.125}};
    const CheckedRun run = run_checked(s, id(), 1, std::vector<Check>{Check::oracle});
    Vec2 last{};
    for (const Event& e : run.events)
        if (e.kind == Event::Kind::hit) last = e.pos;
    expect_failure(run.failure, Check::oracle, 1, 0,
                   fmt::format("stopped at the bounce limit at (0.5, 0), but the last point of its path is {}", last));
}

bool g_moves = false;  // whether the contact-bound step below moves the ball

/// A frame spent reflecting off contact wall 0 sixteen times: the trace's legs all run into its far side, no
/// hit is printed, and the frame stops at the limit with the ball where it began (or, g_moves, one v on).
FrameStatus contact_bounces(STEP_PARAMS) {
    (void)mem, (void)hits, (void)index;
    if (StepTrace* t = scratch.trace) {
        const auto from = static_cast<std::int8_t>(-sign_of(robust().classify(b.pos + b.vel, walls[0])));
        for (int k = 0; k < 16; ++k)
            t->legs.push_back(TracedLeg{b.pos, b.pos + b.vel, true, 0, from, std::nullopt, 0, 0, std::nullopt});
        t->reflections += 16;
    }
    if (g_moves) b.pos = b.pos + b.vel;
    return FrameStatus::bounce_limit;
}

TEST(CheckFailures, OracleTakesAFrameStoppedByContactsAloneToEndWhereItBegan) {
    // (1, 0) → (2, 0) crosses the line x = 1.5 of wall 0 but not the segment: no wall is hit, exactly.
    Mutation m;
    m.ops.step_ball = &contact_bounces;
    const Scene s = scene({{{1.5, 1}, {1.5, 2}}}, {{{1, 0}, {1, 0}}});
    g_moves = false;
    const auto f = first_failure(s, 1, {Check::oracle});
    EXPECT_FALSE(f) << f->str();
    g_moves = true;
    expect_failure(first_failure(s, 1, {Check::oracle}), Check::oracle, 1, 0,
                   "stopped at the bounce limit at (2, 0), but the last point of its path is (1, 0)");
    g_moves = false;
}

// ---- accuracy ----

int g_inserted_legs = 0;  // blocked legs the next step puts before its first leg in the trace

/// robust with every printed hit point 1/1024 along the wall from where robust put it (t_i untouched).
FrameStatus hit_point_off(STEP_PARAMS) {
    const std::size_t h0 = hits.size();
    const FrameStatus st = STEP_ROBUST;
    for (std::size_t h = h0; h < hits.size(); ++h) hits[h].point.y += 0x1p-10;
    if (StepTrace* t = scratch.trace; t != nullptr && g_inserted_legs > 0) {
        const TracedLeg first = t->legs.front();
        t->legs.insert(t->legs.begin(), TracedLeg{first.from, first.to, true, 0, 1, std::nullopt, 0, 0, std::nullopt});
    }
    return st;
}

TEST(CheckFailures, AccuracySeesAHitPointOffTheCrossing) {
    Mutation m;
    m.ops.step_ball = &hit_point_off;
    g_inserted_legs = 0;
    expect_failure(first_failure(scene({k_wall}, {k_hitter}), 1, {Check::accuracy}), Check::accuracy, 1, 0,
                   "leg 0 ((1, 0) -> (9, 0)) hits wall 0 at (5, 0.0009765625), ");
    // A leg the kernel reflected off a contact wall prints no hit: the hit is the next leg's.
    g_inserted_legs = 1;
    expect_failure(first_failure(scene({k_wall}, {k_hitter}), 1, {Check::accuracy}), Check::accuracy, 1, 0,
                   "leg 1 ((1, 0) -> (9, 0)) hits wall 0 at (5, 0.0009765625), ");
    g_inserted_legs = 0;
}

int g_hit_edit = 0;  // 1: the printed hit names wall 99; 2: every hit is printed twice

TEST(CheckFailures, AccuracyLeavesHitsThatDoNotMatchTheLegsToOracle) {
    // Printed hits that are not the legs' (a wall that does not exist, a hit printed twice) have no leg to
    // be measured against: accuracy holds, oracle fails.
    Mutation m;
    m.ops.step_ball = [](STEP_PARAMS) {
        const std::size_t h0 = hits.size();
        const FrameStatus st = STEP_ROBUST;
        const std::size_t h1 = hits.size();
        for (std::size_t h = h0; h < h1; ++h) {
            if (g_hit_edit == 1) hits[h].wall = 99;
            if (g_hit_edit == 2) hits.push_back(hits[h]);
        }
        return st;
    };
    const Scene s = scene({k_wall}, {k_hitter});
    for (g_hit_edit = 1; g_hit_edit <= 2; ++g_hit_edit) {
        const auto f = first_failure(s, 1, {Check::accuracy});
        EXPECT_FALSE(f) << f->str();
        expect_failure(first_failure(s, 1, {Check::oracle}), Check::oracle, 1, 0,
                       fmt::format("the frame printed {} hit(s), the legs swept give 1", g_hit_edit));
    }
    g_hit_edit = 0;
}

TEST(CheckFailures, BounceSideKeepsTheSideAHitFromTheWallsLineDoesNotSay) {
    // lecture-double hits the end (0, 4) of the wall from the left in frame 2 and stops there; in frame 3 it
    // hits the wall again from its line (t_i = 0) and bounces through to the right. The side it last met the
    // wall from still holds, so the end of frame 3 breaks the rule.
    const Scene s = scene({{{0, 0}, {0, 4}}}, {{{-2, 6}, {1, -1}}});
    expect_failure(first_failure(s, 3, {Check::bounce_side}, KernelId::lecture_double), Check::bounce_side, 3, 0,
                   "the ball hit wall 0 from side -1, but its end of frame (1, 3) lies on the other side");
}

TEST(CheckFailures, AHitFromTheWallsLineIsMeasuredAndKeepsNoSide) {
    // A ball starting at (0, 4), on the wall's line, is hit by lecture-double at t_i = 0 from there: accuracy
    // measures the hit (exact: the crossing is the start) and bounce-side keeps no side for it, whether the
    // wall is the one a fresh memory names (index 0) or another, so the bounce to the left breaks nothing.
    const Wall w{{0, 0}, {0, 4}};
    for (const std::vector<Wall>& walls : {std::vector<Wall>{w}, std::vector<Wall>{{{50, 0}, {50, 1}}, w}}) {
        const CheckedRun run = run_checked(scene(walls, {{{0, 4}, {1, -1}}}), KernelId::lecture_double, 1,
                                           std::vector<Check>{Check::accuracy, Check::bounce_side});
        EXPECT_FALSE(run.failure) << run.failure->str();
        const Event hit{Event::Kind::hit, 1, 0, Event::Shape::none, static_cast<std::uint32_t>(walls.size() - 1),
                        {0, 4}, {}};
        EXPECT_NE(std::find(run.events.begin(), run.events.end(), hit), run.events.end());
    }
}

// ---- speed ----

TEST(CheckFailures, SpeedSeesABounceThatLosesHalfTheSpeed) {
    // reflect itself keeps |v| (the first part of the check holds); the step halves v after a hit.
    Mutation m;
    m.ops.step_ball = [](STEP_PARAMS) {
        const std::size_t h0 = hits.size();
        const FrameStatus st = STEP_ROBUST;
        if (hits.size() > h0) b.vel = b.vel * 0.5;
        return st;
    };
    expect_failure(first_failure(scene({k_wall}, {k_hitter}), 1, {Check::speed}), Check::speed, 1, 0,
                   "|v| went from 8 to 4 ((8, 0) -> (-4, 0)) over 1 reflection(s)");
}

// ---- no-escape ----

TEST(CheckFailures, NoEscapeSeesABallLeaveTheBoxAtTheEndOfAFrame) {
    // The step ignores walls. The circle prints an overlap at frame 1, which the check passes over.
    Mutation m;
    m.ops.step_ball = [](STEP_PARAMS) {
        (void)walls, (void)index;
        return robust().step_ball(b, mem, {}, hits, scratch, nullptr);
    };
    expect_failure(first_failure(scene(box(0, 10), {{{5, 5}, {3, 0}}}, {{{8, 5}, 1}}), 2, {Check::no_escape}),
                   Check::no_escape, 2, 0,
                   "the ball started strictly inside the closed walls, but its end of frame (11, 5) is strictly outside");
}

TEST(CheckFailures, NoEscapeSeesAHitPointInsideTheBoxForABallFromOutside) {
    // The step prints its hit points half a unit left of the crossing: into the box for a ball coming from
    // its right.
    Mutation m;
    m.ops.step_ball = [](STEP_PARAMS) {
        const std::size_t h0 = hits.size();
        const FrameStatus st = STEP_ROBUST;
        for (std::size_t h = h0; h < hits.size(); ++h) hits[h].point.x -= 0.5;
        return st;
    };
    expect_failure(first_failure(scene(box(0, 10), {{{15, 5}, {-10, 0}}}), 1, {Check::no_escape}), Check::no_escape,
                   1, 0, "the ball started strictly outside the closed walls, but its hit point (9.5, 5) is strictly inside");
}

// ---- bounce-side ----

TEST(CheckFailures, BounceSideSeesABallGoOnThroughTheWallItHit) {
    // The step prints the hit but does not bounce. Both balls break the rule in frame 1: ball 0 is reported.
    Mutation m;
    m.ops.step_ball = [](STEP_PARAMS) {
        const Ball start = b;
        const std::size_t h0 = hits.size();
        const FrameStatus st = STEP_ROBUST;
        if (hits.size() > h0) b = {start.pos + start.vel, start.vel};
        return st;
    };
    const Scene s = scene({{{5, -100}, {5, 100}}}, {k_hitter, {{1, 10}, {8, 0}}});
    expect_failure(first_failure(s, 1, {Check::bounce_side}), Check::bounce_side, 1, 0,
                   "but its end of frame (9, 0) lies on the other side before its next hit");
}

TEST(CheckFailures, BounceSideSeesTheNextHitPointOnTheFarSide) {
    // (8, 5) moving (4, −8) hits x = 10 at (10, 1), then y = 0 at (9.5, 0); the step prints every hit after
    // the first one unit to the right, past x = 10.
    Mutation m;
    m.ops.step_ball = [](STEP_PARAMS) {
        const std::size_t h0 = hits.size();
        const FrameStatus st = STEP_ROBUST;
        for (std::size_t h = h0 + 1; h < hits.size(); ++h) hits[h].point.x += 1;
        return st;
    };
    const Scene s = scene({{{10, -100}, {10, 100}}, {{-100, 0}, {100, 0}}}, {{{8, 5}, {4, -8}}});
    expect_failure(first_failure(s, 1, {Check::bounce_side}), Check::bounce_side, 1, 0,
                   "the ball hit wall 0 from side -1, but its hit point (10.5, 0) lies on the other side");
}

// ---- deterministic ----

int g_calls = 0;       // calls of the mutant's function in this test
int g_odd_calls = 1;   // 1: the odd calls (the run's World) go wrong; 0: the even ones (the twin's)

TEST(CheckFailures, DeterministicSeesASecondRunPrintAnotherState) {
    // Every second step drifts: the run's World steps first, its twin second.
    Mutation m;
    m.ops.step_ball = [](STEP_PARAMS) {
        const FrameStatus st = STEP_ROBUST;
        if (++g_calls % 2 == 0) b.pos.y += 0.5;
        return st;
    };
    g_calls = 0;
    expect_failure(first_failure(scene({}, {{{0, 0}, {1, 0}}}), 1, {Check::deterministic}), Check::deterministic, 1,
                   0, "a second run gives 'state 1 0 1 0.5 1 0', expected 'state 1 0 1 0 1 0'");
}

TEST(CheckFailures, DeterministicSeesASecondRunPrintMoreOrFewerEvents) {
    // point_in_circle says yes on every second call: one of the two worlds prints an overlap the other does
    // not, at the end of frame 0.
    Mutation m;
    m.ops.point_in_circle = [](Vec2 p, const Circle& c) {
        return ++g_calls % 2 == g_odd_calls || robust().point_in_circle(p, c);
    };
    const Scene s = scene({}, {{{1.9, 1.9}, {0, 1}}}, {{{0, 0}, 2}});
    g_calls = 0;
    g_odd_calls = 1;
    expect_failure(first_failure(s, 1, {Check::deterministic}), Check::deterministic, 0, 0,
                   "a second run has 1 events in this frame, expected 2");
    g_calls = 0;
    g_odd_calls = 0;
    expect_failure(first_failure(s, 1, {Check::deterministic}), Check::deterministic, 0, 0,
                   "a second run has 2 events in this frame, expected 1");
}

// ---- broad-phase ----

TEST(CheckFailures, BroadPhaseSeesAStepThatDependsOnTheWallIndex) {
    // Without a wall index the step drifts: the run with no broad phase differs from the checked run's grid.
    Mutation m;
    m.ops.step_ball = [](STEP_PARAMS) {
        const FrameStatus st = STEP_ROBUST;
        if (index == nullptr) b.pos.y += 0.5;
        return st;
    };
    expect_failure(first_failure(scene({{{100, -1}, {100, 1}}}, {{{0, 0}, {1, 0}}}), 1, {Check::broad_phase}),
                   Check::broad_phase, 1, 0,
                   "the checked run (default options) gives 'state 1 0 1 0 1 0', expected 'state 1 0 1 0.5 1 0'");
}

// ---- run_checked ----

TEST(CheckFailures, TheTracedStepMustEndWhereTheRunDid) {
    // A step that goes elsewhere when asked for a trace: the first check that reads traces (speed, not
    // oracle; no-tunnel reads none) reports it.
    Mutation m;
    m.ops.step_ball = [](STEP_PARAMS) {
        const FrameStatus st = STEP_ROBUST;
        if (scratch.trace != nullptr) b.pos.y += 0.5;
        return st;
    };
    expect_failure(first_failure(scene({}, {{{0, 0}, {1, 0}}}), 1, {Check::no_tunnel, Check::speed, Check::oracle}),
                   Check::speed, 1, 0, "stepping the ball again from 0 0 1 0 with a trace gives 1 0.5 1 0, the run gave 1 0 1 0");
}

TEST(CheckFailures, TheFirstCheckInTheScenesOrderIsReportedWhenTwoFailInOneFrame) {
    // classify is wrong for walls pointing up: oracle and swap both fail at frame 0.
    Mutation m;
    m.ops.classify = [](Vec2 p, const Wall& w) {
        const Side s = robust().classify(p, w);
        return w.p0.y < w.p1.y ? opposite(s) : s;
    };
    const Scene s = scene({k_wall}, {k_hitter});
    expect_failure(first_failure(s, 1, {Check::oracle, Check::swap}), Check::oracle, 0, 0, "classify((1, 0), wall 0)");
    expect_failure(first_failure(s, 1, {Check::swap, Check::oracle}), Check::swap, 0, 0, "walked the other way");
}

// ---- round-trip ----

TEST(CheckFailures, RoundTripSeesALogThatDoesNotReadBack) {
    // A provenance with a line break writes a line that is no directive.
    Scene s = scene({}, {{{0, 0}, {1, 0}}});
    s.provenance = {"fuzz x\nnot-a-directive 1"};
    expect_failure(first_failure(s, 0, {Check::round_trip}, KernelId::robust), Check::round_trip, 0, 0,
                   "the written log does not read back: ");
}

#undef STEP_ROBUST
#undef STEP_PARAMS

}  // namespace
}  // namespace ricochet::mutant
