// The checks that ask the kernel's static answers (boundary, symmetry, swap, translation, oracle's static
// part) fail when one answer breaks their invariant: each test breaks exactly one function of robust
// (mutant_kernel.hpp) and pins the check, frame, ball and what the message names.
#include <gtest/gtest.h>

#include <cmath>

#include "mutant_kernel.hpp"

namespace ricochet::mutant {
namespace {

const Wall k_vertical{{0, 0}, {0, 4}};  // the line x = 0, the segment 0 ≤ y ≤ 4

// ---- boundary ----

TEST(CheckFailures, BoundarySeesARadiusZeroCircleThatLosesItsCentre) {
    Mutation m;
    m.ops.point_in_circle = [](Vec2 p, const Circle& c) { return c.r != 0 && robust().point_in_circle(p, c); };
    expect_failure(first_failure(scene({}, {{{1, 1}, {1, 0}}}), 1, {Check::boundary}), Check::boundary, 0, 0,
                   "the radius-0 circle at (1, 1) says it no longer holds (1, 1)");
}

TEST(CheckFailures, BoundarySeesARadiusZeroCircleThatHoldsAnotherPoint) {
    Mutation m;
    m.ops.point_in_circle = [](Vec2 p, const Circle& c) { return c.r == 0 || robust().point_in_circle(p, c); };
    expect_failure(first_failure(scene({}, {{{1, 1}, {1, 0}}, {{2, 2}, {1, 0}}}), 1, {Check::boundary}),
                   Check::boundary, 0, 0, "the radius-0 circle at (1, 1) says it holds (2, 2)");
}

TEST(CheckFailures, BoundarySeesAZeroSizeRectThatLosesItsPoint) {
    Mutation m;
    m.ops.point_in_rect = [](Vec2 p, const Rect& r) { return r.left != r.right && robust().point_in_rect(p, r); };
    expect_failure(first_failure(scene({}, {{{1, 1}, {1, 0}}}), 1, {Check::boundary}), Check::boundary, 0, 0,
                   "the zero-size rect at (1, 1) says it no longer holds (1, 1)");
}

TEST(CheckFailures, BoundarySeesAZeroSizeRectThatHoldsAnotherPoint) {
    Mutation m;
    m.ops.point_in_rect = [](Vec2 p, const Rect& r) { return r.left == r.right || robust().point_in_rect(p, r); };
    expect_failure(first_failure(scene({}, {{{1, 1}, {1, 0}}, {{2, 2}, {1, 0}}}), 1, {Check::boundary}),
                   Check::boundary, 0, 0, "the zero-size rect at (1, 1) says it holds (2, 2)");
}

TEST(CheckFailures, BoundarySeesCircleOverlapDisagreeWithPointInCircleForARadiusZeroCircle) {
    // circles_overlap is wrong whenever one circle has radius 0: inside and outside both show.
    Mutation m;
    m.ops.circles_overlap = [](const Circle& a, const Circle& b) {
        return (a.r == 0) != robust().circles_overlap(a, b);
    };
    expect_failure(first_failure(scene({}, {{{1, 1}, {1, 0}}}, {{{1, 2}, 2}}), 1, {Check::boundary}), Check::boundary,
                   0, 0, "point/circle says inside but circle/circle with radius 0 says apart for circle 0");
    expect_failure(first_failure(scene({}, {{{1, 1}, {1, 0}}}, {{{9, 2}, 2}}), 1, {Check::boundary}), Check::boundary,
                   0, 0, "point/circle says outside but circle/circle with radius 0 says overlap for circle 0");
}

/// point_in_circle is wrong for circles centred on (5, 5), the ball's start: it is not symmetric in the
/// point and the centre.
bool centred_on_start_wrong(Vec2 p, const Circle& c) {
    return (c.c == Vec2{5, 5} && c.r > 0) != robust().point_in_circle(p, c);
}

TEST(CheckFailures, BoundarySeesAPointInCircleThatIsNotSymmetricInPointAndCentre) {
    Mutation m;
    m.ops.point_in_circle = &centred_on_start_wrong;
    expect_failure(first_failure(scene({}, {{{5, 5}, {1, 0}}}, {{{6, 5}, 2}}), 1, {Check::boundary}), Check::boundary,
                   0, 0, "(5, 5) is in circle 0 but its centre is not in the circle of radius 2 about it");
    expect_failure(first_failure(scene({}, {{{5, 5}, {1, 0}}}, {{{9, 5}, 2}}), 1, {Check::boundary}), Check::boundary,
                   0, 0, "(5, 5) is not in circle 0 but its centre is in the circle of radius 2 about it");
}

TEST(CheckFailures, BoundarySeesRectOverlapDisagreeWithPointInRectForAZeroSizeRect) {
    Mutation m;
    m.ops.rects_overlap = [](const Rect& a, const Rect& b) {
        return (a.left == a.right) != robust().rects_overlap(a, b);
    };
    expect_failure(first_failure(scene({}, {{{1, 1}, {1, 0}}}, {}, {{0, 0, 2, 2}}), 1, {Check::boundary}),
                   Check::boundary, 0, 0, "point/rect says inside but rect/rect with a zero-size rect says apart for rect 0");
    expect_failure(first_failure(scene({}, {{{1, 1}, {1, 0}}}, {}, {{3, 0, 4, 2}}), 1, {Check::boundary}),
                   Check::boundary, 0, 0,
                   "point/rect says outside but rect/rect with a zero-size rect says overlap for rect 0");
}

Miss g_forced = Miss::none;  // the Miss the forced sweep reports

TEST(CheckFailures, BoundarySeesASweepWhoseFirstTestsContradictClassify) {
    // The sweep reports test 1 or 2 (both ends on one side) against classify's side of Bs: a ball on the
    // wall's line can be neither, one inside never both-outside, one outside never both-inside.
    Mutation m;
    m.ops.sweep = [](Vec2, Vec2, const Wall&) { return Sweep{g_forced, 0.0, {}}; };
    for (Miss forced : {Miss::both_inside, Miss::both_outside}) {
        g_forced = forced;
        expect_failure(first_failure(scene({k_vertical}, {{{0, 2}, {1, 0}}}), 1, {Check::boundary}), Check::boundary,
                       0, 0, fmt::format("classify says (0, 2) is on wall 0 but the sweep from it says {}", forced));
    }
    for (Vec2 p : {Vec2{1, 2}, Vec2{-1, 2}}) {
        const Side s = robust().classify(p, k_vertical);
        g_forced = s == Side::inside ? Miss::both_outside : Miss::both_inside;
        expect_failure(first_failure(scene({k_vertical}, {{p, {0, 1}}}), 1, {Check::boundary}), Check::boundary, 0, 0,
                       fmt::format("classify says {} is {} wall 0 but the sweep from it says {}", p, s, g_forced));
    }
}

int g_sweep_error = 0;  // 1: t_i one ulp short; 2: B_i a quarter off along the wall

TEST(CheckFailures, BoundarySeesALegEndingOnTheLineHitAnywhereButItsEnd) {
    Mutation m;
    m.ops.sweep = [](Vec2 bs, Vec2 v, const Wall& w) {
        Sweep s = robust().sweep(bs, v, w);
        if (s.hit() && g_sweep_error == 1) s.t = std::nextafter(s.t, 0.0);
        if (s.hit() && g_sweep_error == 2) s.point.y += 0.25;
        return s;
    };
    // (−1, 2) + (1, 0) ends on the line x = 0: the hit is at t = 1, at (0, 2) itself.
    const Scene s = scene({k_vertical}, {{{-1, 2}, {1, 0}}});
    g_sweep_error = 1;
    expect_failure(first_failure(s, 1, {Check::boundary}), Check::boundary, 0, 0,
                   "the leg ends on wall 0's line at (0, 2), but the hit is at t 0.9999999999999999 point (0, 2)");
    g_sweep_error = 2;
    expect_failure(first_failure(s, 1, {Check::boundary}), Check::boundary, 0, 0,
                   "the leg ends on wall 0's line at (0, 2), but the hit is at t 1 point (0, 2.25)");
    g_sweep_error = 0;
}

// ---- symmetry ----

TEST(CheckFailures, SymmetrySeesARunThatIsNotItsMirror) {
    // A step that drifts balls moving right upwards: the mirrored ball moves left and does not drift.
    Mutation m;
    m.ops.step_ball = [](Ball& b, BallMemory& mem, std::span<const Wall> walls, std::vector<HitEvent>& hits,
                         StepScratch& scratch, const WallIndex* index) {
        const bool right = b.vel.x > 0;
        const FrameStatus st = robust().step_ball(b, mem, walls, hits, scratch, index);
        if (right) b.pos.y += 0.5;
        return st;
    };
    expect_failure(first_failure(scene({}, {{{0, 0}, {1, 0}}}), 1, {Check::symmetry}), Check::symmetry, 1, 0,
                   "the run mirrored across x = 0 gives 'state 1 0 -1 0 -1 0', expected 'state 1 0 -1 0.5 -1 0'");
}

TEST(CheckFailures, SymmetrySeesStaticOverlapsThatChangeUnderTheMirror) {
    // Two circles (and two rects) apart; the mirrored pair, left of x = 0, is said to overlap.
    Mutation m;
    m.ops.circles_overlap = [](const Circle& a, const Circle& b) {
        return (a.c.x < 0 && b.c.x < 0) || robust().circles_overlap(a, b);
    };
    m.ops.rects_overlap = [](const Rect& a, const Rect& b) {
        return (a.right < 0 && b.right < 0) || robust().rects_overlap(a, b);
    };
    const std::vector<Ball> ball = {{{0, 50}, {0, 1}}};
    expect_failure(first_failure(scene({}, ball, {{{10, 0}, 1}, {{20, 0}, 1}}), 1, {Check::symmetry}),
                   Check::symmetry, 0, 0, "circles_overlap(10 0 1, 20 0 1) changes under the mirror across x = 0");
    expect_failure(first_failure(scene({}, ball, {}, {{10, 0, 11, 1}, {20, 0, 21, 1}}), 1, {Check::symmetry}),
                   Check::symmetry, 0, 0, "rects_overlap(10 0 11 1, 20 0 21 1) changes under the mirror across x = 0");
}

TEST(CheckFailures, SymmetrySeesPointTestsThatChangeUnderTheMirror) {
    // Left of x = 0 a point is said to be in every shape far away; the shapes at ±1000 are so far from the
    // ball that the world's overlap pass never asks about them (its static index has them in other cells),
    // so only the check's own question sees the answer.
    Mutation m;
    m.ops.point_in_circle = [](Vec2 p, const Circle& c) {
        return (p.x < 0 && c.c.x < -100) || robust().point_in_circle(p, c);
    };
    m.ops.point_in_rect = [](Vec2 p, const Rect& r) {
        return (p.x < 0 && r.right < -100) || robust().point_in_rect(p, r);
    };
    const std::vector<Ball> ball = {{{1, 0}, {0, 0.5}}};
    expect_failure(first_failure(scene({}, ball, {{{1000, 0}, 1}, {{-1000, 0}, 1}}), 1, {Check::symmetry}),
                   Check::symmetry, 0, 0, "point_in_circle((1, 0), 1000 0 1) changes under the mirror across x = 0");
    expect_failure(
        first_failure(scene({}, ball, {}, {{1000, 0, 1001, 1}, {-1001, 0, -1000, 1}}), 1, {Check::symmetry}),
        Check::symmetry, 0, 0, "point_in_rect((1, 0), 1000 0 1001 1) changes under the mirror across x = 0");
}

TEST(CheckFailures, SymmetrySeesAClassifyThatChangesUnderTheMirror) {
    Mutation m;
    m.ops.classify = [](Vec2 p, const Wall& w) {
        const Side s = robust().classify(p, w);
        return p.x < 0 ? opposite(s) : s;
    };
    expect_failure(first_failure(scene({{{5, -1}, {5, 1}}}, {{{1, 0}, {1, 0}}}), 1, {Check::symmetry}),
                   Check::symmetry, 0, 0, "the side of (1, 0) against wall 0 changes under the mirror across x = 0");
}

int g_mirror_error = 0;  // 1: a miss becomes past-p1; 2: t_i one ulp short; 3: B_i off along the wall

TEST(CheckFailures, SymmetrySeesASweepThatChangesUnderTheMirror) {
    Mutation m;
    m.ops.sweep = [](Vec2 bs, Vec2 v, const Wall& w) {
        Sweep s = robust().sweep(bs, v, w);
        if (bs.x >= 0) return s;
        if (!s.hit() && g_mirror_error == 1) s.miss = Miss::past_p1;
        if (s.hit() && g_mirror_error == 2) s.t = std::nextafter(s.t, 0.0);
        if (s.hit() && g_mirror_error == 3) s.point.y += 0.25;
        return s;
    };
    const Wall w{{5, -1}, {5, 1}};
    g_mirror_error = 1;
    // (1, 0) → (2, 0) stays on one side of x = 5: test 1 or 2, and under the mirror the other one.
    const Side s = robust().classify({1, 0}, w);
    expect_failure(first_failure(scene({w}, {{{1, 0}, {1, 0}}}), 1, {Check::symmetry}), Check::symmetry, 0, 0,
                   fmt::format("from (1, 0) moving (1, 0) against wall 0: {}, but past-p1 under the mirror",
                               s == Side::inside ? Miss::both_inside : Miss::both_outside));
    // (1, 0) → (9, 0) hits x = 5 at t = 0.5, (5, 0).
    g_mirror_error = 2;
    expect_failure(first_failure(scene({w}, {{{1, 0}, {8, 0}}}), 1, {Check::symmetry}), Check::symmetry, 0, 0,
                   "hit at t 0.5 point (5, 0), under the mirror across x = 0 at t 0.49999999999999994 point (-5, 0)");
    g_mirror_error = 3;
    expect_failure(first_failure(scene({w}, {{{1, 0}, {8, 0}}}), 1, {Check::symmetry}), Check::symmetry, 0, 0,
                   "hit at t 0.5 point (5, 0), under the mirror across x = 0 at t 0.5 point (-5, 0.25)");
    g_mirror_error = 0;
}

// ---- swap ----

TEST(CheckFailures, SwapSeesStaticOverlapsThatDependOnArgumentOrder) {
    Mutation m;
    m.ops.circles_overlap = [](const Circle& a, const Circle& b) { return a.r > b.r || robust().circles_overlap(a, b); };
    m.ops.rects_overlap = [](const Rect& a, const Rect& b) { return a.left < b.left || robust().rects_overlap(a, b); };
    const std::vector<Ball> ball = {{{0, 50}, {0, 1}}};
    expect_failure(first_failure(scene({}, ball, {{{0, 0}, 2}, {{10, 0}, 1}}), 1, {Check::swap}), Check::swap, 0, 0,
                   "circles_overlap(0 0 2, 10 0 1) = true but swapped false");
    expect_failure(first_failure(scene({}, ball, {}, {{0, 0, 1, 1}, {5, 0, 6, 1}}), 1, {Check::swap}), Check::swap, 0,
                   0, "rects_overlap(0 0 1 1, 5 0 6 1) = true but swapped false");
}

TEST(CheckFailures, SwapSeesAWallWalkedBackwardsChangeItsAnswers) {
    // classify and the sweep say "on" and "parallel" for every wall pointing down.
    Mutation m;
    m.ops.classify = [](Vec2 p, const Wall& w) { return w.p0.y > w.p1.y ? Side::on : robust().classify(p, w); };
    const Wall up{{5, -1}, {5, 1}};
    expect_failure(first_failure(scene({up}, {{{1, 0}, {8, 0}}}), 1, {Check::swap}), Check::swap, 0, 0,
                   fmt::format("(1, 0) is {} wall 0 but on it walked the other way", robust().classify({1, 0}, up)));
    m.ops.classify = robust().classify;
    m.ops.sweep = [](Vec2 bs, Vec2 v, const Wall& w) {
        return w.p0.y > w.p1.y ? Sweep{Miss::parallel, 0.0, {}} : robust().sweep(bs, v, w);
    };
    expect_failure(first_failure(scene({up}, {{{1, 0}, {8, 0}}}), 1, {Check::swap}), Check::swap, 0, 0,
                   "from (1, 0) moving (8, 0) against wall 0: hit, but parallel walked the other way");
}

// ---- translation ----

constexpr double k_far = 0x1p29;  // the mutants below go wrong only this far from the origin

TEST(CheckFailures, TranslationSeesAStepThatChangesItsHitFarAway) {
    // Far from the origin the step tries no wall: the scene moved by (1024, 4096) still hits, this one not.
    Mutation m;
    m.ops.step_ball = [](Ball& b, BallMemory& mem, std::span<const Wall> walls, std::vector<HitEvent>& hits,
                         StepScratch& scratch, const WallIndex* index) {
        if (std::fabs(b.pos.x) >= 512) return robust().step_ball(b, mem, {}, hits, scratch, nullptr);
        return robust().step_ball(b, mem, walls, hits, scratch, index);
    };
    expect_failure(first_failure(scene({{{5, -1}, {5, 1}}}, {{{1, 0}, {8, 0}}}), 1, {Check::translation}),
                   Check::translation, 1, 0, "moving the scene by (1024, 4096) (exactly) changes a hit, a bump or an overlap");
}

TEST(CheckFailures, TranslationSeesASweepThatChangesFarAway) {
    Mutation m;
    m.ops.sweep = [](Vec2 bs, Vec2 v, const Wall& w) {
        Sweep s = robust().sweep(bs, v, w);
        if (std::fabs(bs.x) >= k_far && !s.hit()) s.miss = Miss::past_p1;
        return s;
    };
    expect_failure(first_failure(scene({{{5, -1}, {5, 1}}}, {{{1, 0}, {1, 0}}}), 1, {Check::translation}),
                   Check::translation, 0, 0,
                   "moving by (-3221225472, 2147483648): the sweep from (1, 0) moving (1, 0) against wall 0 changes");
}

TEST(CheckFailures, TranslationSeesPointTestsThatChangeFarAway) {
    // Far away every point is in every shape; the shapes at ±10^9 lie in other cells of the world's static
    // index than the ball (even moved by 2^40, when its cells grow), so only the check's own question sees it.
    Mutation m;
    m.ops.point_in_circle = [](Vec2 p, const Circle& c) {
        return std::fabs(p.x) >= k_far || robust().point_in_circle(p, c);
    };
    m.ops.point_in_rect = [](Vec2 p, const Rect& r) { return std::fabs(p.x) >= k_far || robust().point_in_rect(p, r); };
    const std::vector<Ball> ball = {{{1, 0}, {0, 0.5}}};
    expect_failure(first_failure(scene({}, ball, {{{1e9, 0}, 1}, {{-1e9, 0}, 1}}), 1, {Check::translation}),
                   Check::translation, 0, 0, "moving by (-3221225472, 2147483648): point_in_circle((1, 0), circle 0) changes");
    expect_failure(
        first_failure(scene({}, ball, {}, {{1e9, 0, 1e9 + 1, 1}, {-1e9 - 1, 0, -1e9, 1}}), 1, {Check::translation}),
        Check::translation, 0, 0, "moving by (-3221225472, 2147483648): point_in_rect((1, 0), rect 0) changes");
}

TEST(CheckFailures, TranslationLeavesOutOffsetsThatWouldRoundAStaticShape) {
    // classify is wrong far away, which only the offsets (−3·2^30, 2^31) and (2^40, −5·2^40) reach. A
    // circle centre or a rect corner at 2^-30 is not moved exactly by them (2^31 + 2^-30 needs 62 bits),
    // so those offsets are left out and the wrong classify goes unseen; (1, −2) and (1024, 4096) still apply.
    Mutation m;
    m.ops.classify = [](Vec2 p, const Wall& w) {
        const Side s = robust().classify(p, w);
        return std::fabs(p.x) >= k_far ? opposite(s) : s;
    };
    const double tiny = 0x1p-30;
    const Scene plain = scene({{{5, -1}, {5, 1}}}, {{{1, 0}, {1, 0}}});
    expect_failure(first_failure(plain, 1, {Check::translation}), Check::translation, 0, 0,
                   "moving by (-3221225472, 2147483648): the side of (1, 0) against wall 0 changes");
    Scene circle = plain, low_corner = plain, high_corner = plain;
    circle.circles = {{{tiny, 20}, 1}};
    low_corner.rects = {{tiny, 20, 1, 21}};      // left, bottom not moved exactly
    high_corner.rects = {{-1, 20, tiny, 21}};    // right, top not moved exactly
    for (const Scene* s : {&circle, &low_corner, &high_corner}) {
        const auto f = first_failure(*s, 1, {Check::translation});
        EXPECT_FALSE(f) << f->str();
    }
}

// ---- oracle, its static part ----

TEST(CheckFailures, OracleSeesWrongStaticOverlaps) {
    Mutation m;
    m.ops.circles_overlap = [](const Circle&, const Circle&) { return false; };
    expect_failure(first_failure(scene({}, {{{0, 50}, {0, 1}}}, {{{0, 0}, 1}}), 1, {Check::oracle}), Check::oracle, 0,
                   0, "circles_overlap(circle 0, circle 0) = false, exactly true");
    m.ops.circles_overlap = robust().circles_overlap;
    m.ops.rects_overlap = [](const Rect&, const Rect&) { return false; };
    expect_failure(first_failure(scene({}, {{{0, 50}, {0, 1}}}, {}, {{0, 0, 1, 1}}), 1, {Check::oracle}),
                   Check::oracle, 0, 0, "rects_overlap(rect 0, rect 0) = false, exactly true");
}

TEST(CheckFailures, OracleSeesAWrongSide) {
    Mutation m;
    m.ops.classify = [](Vec2 p, const Wall& w) { return opposite(robust().classify(p, w)); };
    const Wall w{{5, -1}, {5, 1}};
    expect_failure(first_failure(scene({w}, {{{1, 0}, {1, 0}}}), 1, {Check::oracle}), Check::oracle, 0, 0,
                   fmt::format("classify((1, 0), wall 0) = {}, exactly {}", opposite(robust().classify({1, 0}, w)),
                               robust().classify({1, 0}, w)));
}

TEST(CheckFailures, OracleSeesWrongOverlapEvents) {
    // The ball at (1, 1) lies in circle 0 and rect 0; a point_in_circle that says no prints only the rect.
    Mutation m;
    m.ops.point_in_circle = [](Vec2, const Circle&) { return false; };
    expect_failure(first_failure(scene({}, {{{1, 1}, {0, 1}}}, {{{1, 2}, 2}}, {{0, 0, 2, 2}}), 1, {Check::oracle}),
                   Check::oracle, 0, 0, "at (1, 1) the frame's overlaps are [rect 0], exactly [circle 0, rect 0]");
    m.ops.point_in_circle = robust().point_in_circle;
    m.ops.point_in_rect = [](Vec2, const Rect&) { return false; };
    expect_failure(first_failure(scene({}, {{{1, 1}, {0, 1}}}, {}, {{0, 0, 2, 2}}), 1, {Check::oracle}), Check::oracle,
                   0, 0, "at (1, 1) the frame's overlaps are [none], exactly [rect 0]");
}

}  // namespace
}  // namespace ricochet::mutant
