// The checks that follow a ball's path and its kernel's trace (accuracy, speed, no-escape, bounce-side,
// deterministic, broad-phase, run_checked's own trace and order; oracle's are in check_oracle_failures_test)
// and round-trip fail when their invariant breaks: each test wraps robust's step_ball (mutant_kernel.hpp) so
// that it breaks exactly one, and pins the check, frame, ball and what the message names.
#include <gtest/gtest.h>

#include <algorithm>

#include "mutant_kernel.hpp"

namespace ricochet::mutant {
namespace {

std::vector<Wall> box(double lo, double hi) {
    return {{{lo, hi}, {lo, lo}}, {{lo, lo}, {hi, lo}}, {{hi, lo}, {hi, hi}}, {{hi, hi}, {lo, hi}}};
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

}  // namespace
}  // namespace ricochet::mutant
