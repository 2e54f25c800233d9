// oracle fails when a step's legs break its invariant: each decision and first hit exact, every wall
// tried or missed, the hits printed as swept, the bounce limit of the spec (16) and the ball at the last
// point of its path there. Each test wraps robust's step_ball (mutant_kernel.hpp) so that it breaks one.
#include <gtest/gtest.h>

#include "mutant_kernel.hpp"

namespace ricochet::mutant {
namespace {

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

// accuracy once took truth::side(leg.from, wall) before its test for a non-finite leg, and GMP's mpq_set_d
// raised SIGFPE on an infinite start: the process died instead of accuracy leaving the leg to oracle.
TEST(CheckFailures, AccuracyLeavesALegWithANonFiniteStartToOracle) {
    Mutation m;
    m.ops.step_ball = &infinite_leg;
    for (g_coord = 0; g_coord < 2; ++g_coord) {
        const auto alone = first_failure(scene({k_wall}, {k_hitter}), 1, {Check::accuracy});
        EXPECT_FALSE(alone) << alone->str();
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

}  // namespace
}  // namespace ricochet::mutant
