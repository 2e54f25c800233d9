// Render at its edges: runs no sound kernel makes but render_svg accepts (balls and walls out of range, a
// hit in the failing frame, NaN and infinite points), what lies beyond each side of the failure view, the
// captions' rarer lines, and render_run on a scene without balls. Positions are worked by hand as in
// render_coverage_test.cpp.
#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

#include "render_events.hpp"
#include "ricochet/render.hpp"
#include "text_search.hpp"

namespace ricochet {
namespace {

using test::count;
using test::has;
using test::hit;
using test::overlap;
using test::state;

constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

TEST(RenderEdges, NonFiniteYCoordinatesBoundNothingAndDrawNoPiece) {
    // (0, 0) → (0, ∞) → (0, 10): no piece to or from the infinite point; the bounds are the finite two.
    Scene s;
    s.balls = {{{0, 0}, {0, 1}}};
    CheckedRun run;
    run.frames_run = 2;
    run.events = {state(0, 0, {0, 0}), state(1, 0, {0, inf}), state(2, 0, {0, 10})};
    const std::string svg = render_svg(s, run);
    EXPECT_TRUE(has(svg, "x in [0, 0], y in [0, 10]")) << svg;
    EXPECT_EQ(count(svg, "<polyline"), 0u) << svg;
}

TEST(RenderEdges, EventsAndAFailureOfABallTheSceneDoesNotHaveAreLeftOut) {
    // Ball 5 of a one-ball scene: its state at frame 0 bounds and draws nothing, and its failure at frame 1
    // (where it has no event) has no path and no mark, so the picture is the whole scene with the message.
    Scene s;
    s.balls = {{{0, 0}, {1, 0}}};
    CheckedRun run;
    run.frames_run = 1;
    run.events = {state(0, 0, {0, 0}), state(0, 5, {30, 30}), state(1, 0, {1, 0})};
    CheckFailure f;
    f.frame = 1;
    f.ball = 5;
    f.message = "of no ball";
    run.failure = f;
    const std::string svg = render_svg(s, run);
    EXPECT_TRUE(has(svg, "x in [0, 1], y in [0, 0]")) << svg;
    EXPECT_EQ(count(svg, "<polyline"), 1u) << svg;
    EXPECT_FALSE(has(svg, ">b5<"));
    EXPECT_FALSE(has(svg, "view: the failing frame"));
    EXPECT_FALSE(has(svg, "marked at"));
    EXPECT_EQ(count(svg, "<g stroke=\"red\""), 0u);
    EXPECT_TRUE(has(svg, "ball 5: of no ball</text>")) << svg;
}

// Wall 0 along y = 0 from (0, 0) to (10, 0), wall 1 far off at x = 100; the ball goes (2, 2) → (4, −2) in
// frame 1, so the failure view is [0, 8] × [−2, 2] (render_coverage_test.cpp): the view [−1.2, 9.2] ×
// [−3.2, 3.2], scale 720/10.4, and the picture's edges 40/scale = 0.578 further out: x in [−1.778, 9.778],
// y in [−3.778, 3.778].
Scene edge_scene() {
    Scene s;
    s.walls = {{{0, 0}, {10, 0}}, {{100, 0}, {100, 1}}};
    s.balls = {{{2, 2}, {2, -4}}};
    return s;
}

CheckedRun edge_run() {
    CheckedRun run;
    run.frames_run = 1;
    run.events = {state(0, 0, {2, 2}), state(1, 0, {4, -2})};
    CheckFailure f;
    f.frame = 1;
    f.piece = FailurePiece{{2, 2}, {4, -2}, 0};
    run.failure = f;
    return run;
}

TEST(RenderEdges, WhatLiesBeyondEachSideOfTheFailureViewIsNotDrawn) {
    Scene s = edge_scene();
    // Walls wholly left, below, above and right of the picture; one that passes below its lower right
    // corner ((5, −10) → (15, 0) leaves x ≤ 9.778 before it rises to y ≥ −3.778); one whose P0 is cut off.
    s.walls.push_back({{-5, -1}, {-5, 1}});
    s.walls.push_back({{1, -20}, {3, -20}});
    s.walls.push_back({{1, 20}, {3, 20}});
    s.walls.push_back({{5, -10}, {15, 0}});
    s.walls.push_back({{-20, 1}, {3, 1}});
    // Circles beyond the left, bottom and top; a rect across the view in x but above it.
    s.circles = {{{-10, 0}, 1}, {{3, -10}, 1}, {{3, 10}, 1}, {{3, 0}, 0.5}};
    s.rects = {{1, 10, 3, 11}, {1, -1, 3, 1}};
    const std::string svg = render_svg(s, edge_run());
    EXPECT_TRUE(has(svg, "x in [0, 8], y in [-2, 2]")) << svg;
    for (const char* gone : {">w1<", ">w2<", ">w3<", ">w4<", ">w5<", ">c0<", ">c1<", ">c2<", ">r0<"})
        EXPECT_FALSE(has(svg, gone)) << gone;
    EXPECT_TRUE(has(svg, ">c3<"));
    EXPECT_TRUE(has(svg, ">r1<"));
    // Wall 6 is drawn from the picture's left edge (sx = 0) to its P1 (3, 1) ↦ (4.2·720/10.4 + 40, 2.2·720/10.4 + 40):
    // without the P0 square, so the one square is wall 0's. (The edge's sx rounds to ±0.000.)
    EXPECT_TRUE(has(svg, ">w6<"));
    EXPECT_TRUE(has(svg, "0.000\" y1=\"192.308\" x2=\"330.769\" y2=\"192.308\"")) << svg;
    EXPECT_EQ(count(svg, "width=\"4\" height=\"4\""), 1u);
}

TEST(RenderEdges, APathFromOutsideTheViewIsCutWhereItEntersAndItsHitsOutsideAreNotMarked) {
    // Ball 1 goes (20, 1) → hit at (12, 1) → (5, 1): its path starts, and its hit lies, right of the
    // picture (x > 9.778), so the polyline starts at the edge (sx = 800), with no start marker and no hit
    // dot, and ends at (5, 1) ↦ (469.231, 192.308).
    Scene s = edge_scene();
    s.balls.push_back({{20, 1}, {-15, 0}});
    CheckedRun run = edge_run();
    run.events = {state(0, 0, {2, 2}), state(0, 1, {20, 1}), state(1, 0, {4, -2}), hit(1, 1, 1, {12, 1}),
                  state(1, 1, {5, 1})};
    const std::string svg = render_svg(s, run);
    EXPECT_TRUE(has(svg, "<polyline points=\"800.000,192.308 469.231,192.308 \" fill=\"none\" stroke=\"#d62728\""))
        << svg;
    EXPECT_EQ(count(svg, "r=\"3\""), 0u);
    EXPECT_FALSE(has(svg, ">b1<"));
    EXPECT_TRUE(has(svg, "<circle cx=\"469.231\" cy=\"192.308\" r=\"5\" fill=\"#d62728\"/>"));
}

TEST(RenderEdges, TheFailingFramesHitsOverlapsAndWallsShapeItsView) {
    // Frame 1 of the failing ball: an overlap (not a point), a hit on wall 0 at (3, 0), a hit on a wall
    // the scene does not have (9) and on the far wall 1 (beyond one span of the frame: not in the view),
    // then its state. No piece: the mark is the state, and the frame's box is the points' [2, 4] × [−2, 2]
    // with wall 0 within a span (4) of it: x in [0, 8].
    Scene s = edge_scene();
    CheckedRun run = edge_run();
    run.failure->piece.reset();
    run.events = {state(0, 0, {2, 2}), overlap(1, 0, 0), hit(1, 0, 0, {3, 0}), hit(1, 0, 9, {3.5, -1}),
                  hit(1, 0, 1, {3.75, -1.5}), state(1, 0, {4, -2})};
    const std::string svg = render_svg(s, run);
    EXPECT_TRUE(has(svg, "x in [0, 8], y in [-2, 2]")) << svg;
    EXPECT_TRUE(has(svg, "marked at (4, -2), the ball's state at the end of frame 1"));
    // The red path: (2, 2), the three hits, the state.
    EXPECT_TRUE(has(svg, "<polyline points=\"261.538,123.077 330.769,261.538 365.385,330.769 382.692,365.385 "
                         "400.000,400.000 \" fill=\"none\" stroke=\"red\""))
        << svg;
}

TEST(RenderEdges, APieceThroughAWallTheSceneDoesNotHaveMarksTheBallsState) {
    Scene s = edge_scene();
    CheckedRun run = edge_run();
    run.failure->piece->wall = 7;
    const std::string svg = render_svg(s, run);
    EXPECT_TRUE(has(svg, "marked at (4, -2), the ball's state at the end of frame 1")) << svg;
}

TEST(RenderEdges, ACrossingTooFarAlongThePieceToComputeMarksItsStart) {
    // Wall (0, 0) → (1, 1) and the piece (0, 1e300) → (1e-300, 1e300): s = cross(e, P0 − from) / cross(e, d)
    // = −1e300 / −1e-300 overflows, so the mark is the piece's start.
    Scene s;
    s.walls = {{{0, 0}, {1, 1}}};
    s.balls = {{{0, 1e300}, {1e-300, 0}}};
    CheckedRun run;
    run.frames_run = 1;
    run.events = {state(0, 0, {0, 1e300}), state(1, 0, {1e-300, 1e300})};
    CheckFailure f;
    f.frame = 1;
    f.piece = FailurePiece{{0, 1e300}, {1e-300, 1e300}, 0};
    run.failure = f;
    const std::string svg = render_svg(s, run);
    EXPECT_TRUE(has(svg, "data-x=\"0\" data-y=\"1e+300\"")) << svg;
}

TEST(RenderEdges, ANonFiniteStateIsNotMarkedAndFramesNothing) {
    // A lecture kernel's NaN at the failing frame's end: the mark would be there; it is not drawn.
    Scene s = edge_scene();
    CheckedRun run = edge_run();
    run.failure->piece.reset();
    run.events = {state(0, 0, {2, 2}), state(1, 0, {nan, nan})};
    const std::string svg = render_svg(s, run);
    EXPECT_EQ(count(svg, "<g stroke=\"red\""), 0u) << svg;
    EXPECT_TRUE(has(svg, "marked at (nan, nan)")) << svg;
}

TEST(RenderEdges, TheBallsCaptionSaysWhichAreDrawn) {
    Scene s = edge_scene();
    s.balls.push_back({{3, 3}, {0, 0}});
    s.balls.push_back({{5, 3}, {0, 0}});
    CheckedRun run = edge_run();
    run.events = {state(0, 0, {2, 2}), state(0, 1, {3, 3}), state(0, 2, {5, 3}),
                  state(1, 0, {4, -2}), state(1, 1, {3, 3}), state(1, 2, {5, 3})};
    RenderOptions o;
    o.max_balls = 2;
    run.failure.reset();
    EXPECT_TRUE(has(render_svg(s, run, o), "paths of 2 of 3 balls drawn (balls 0..1), 1 left out (--max-balls)"));
    // One path only, the failing ball's (2).
    run.failure = edge_run().failure;
    run.failure->ball = 2;
    run.failure->piece.reset();
    o.max_balls = 1;
    const std::string svg = render_svg(s, run, o);
    EXPECT_TRUE(has(svg, "paths of 1 of 3 balls drawn (the failing ball 2), 2 left out (--max-balls)")) << svg;
    EXPECT_TRUE(has(svg, ">b2<"));
    EXPECT_FALSE(has(svg, ">b0<"));
}

TEST(RenderEdges, BeyondSixteenPathsOnlyTheFailingBallIsLabelled) {
    Scene s;
    CheckedRun run;
    for (std::uint32_t b = 0; b < 20; ++b) {
        s.balls.push_back({{double(b), 0}, {0, 1}});
        run.events.push_back(state(0, b, {double(b), 0}));
    }
    for (std::uint32_t b = 0; b < 20; ++b) run.events.push_back(state(1, b, {double(b), 1}));
    run.frames_run = 1;
    CheckFailure f;
    f.frame = 1;
    f.ball = 3;
    run.failure = f;
    RenderOptions o;
    o.view = RenderView::all;
    const std::string svg = render_svg(s, run, o);
    EXPECT_EQ(count(svg, "<polyline"), 21u);  // and the failing frame's, in red
    EXPECT_TRUE(has(svg, ">b3<"));
    EXPECT_FALSE(has(svg, ">b0<"));
    EXPECT_FALSE(has(svg, ">b19<"));
    // Without a failure, no ball is labelled.
    run.failure.reset();
    EXPECT_EQ(count(render_svg(s, run, o), ">b"), 0u);
}

TEST(RenderEdges, ASecondLineTooLongAfterAnEarlyBreakIsCut) {
    // 800 px: 112 characters a line. "no-tunnel broke at frame 1 ball 0: " (35) + 60 "a", a space, 300
    // "b": cut to 221 + "...", broken at the space (95), the second line 128 long, cut to 109 + "...".
    CheckedRun run = edge_run();
    run.failure->message = std::string(60, 'a') + " " + std::string(300, 'b');
    const std::string svg = render_svg(edge_scene(), run);
    EXPECT_TRUE(has(svg, "ball 0: " + std::string(60, 'a') + "</text>")) << svg;
    EXPECT_TRUE(has(svg, "<text x=\"8\" y=\"32\" fill=\"red\">" + std::string(109, 'b') + "...</text>")) << svg;
}

TEST(RenderEdges, ASceneWithoutBallsDrawsItsStaticsAndTheirFailure) {
    // The scene's statics break `oracle` at frame 0 for "ball 0" with no ball in the scene (lecture-float
    // rounds 2 + 1e-9 to 2: circles 1e-9 apart touch); every frame has no event. The picture is the statics'
    // with the message, and progress is told every frame.
    Scene s;
    s.kernel = KernelId::lecture_float;
    s.frames = 3;
    s.circles = {{{0, 0}, 1}, {{2.000000001, 0}, 1}};
    s.checks = {Check::oracle};
    std::vector<std::pair<std::int64_t, std::int64_t>> told;
    const RenderResult r = render_run(s, s.kernel, {}, [&](std::int64_t done, std::int64_t total) {
        told.push_back({done, total});
    });
    ASSERT_TRUE(r.failure);
    EXPECT_EQ(r.failure->check, Check::oracle);
    EXPECT_EQ(r.failure->frame, 0);
    EXPECT_TRUE(has(r.svg, ">c1<"));
    EXPECT_TRUE(has(r.svg, "oracle broke at frame 0 ball 0: circles_overlap(circle 0, circle 1)")) << r.svg;
    EXPECT_EQ(count(r.svg, "<polyline"), 0u);
    EXPECT_EQ(count(r.svg, "<g stroke=\"red\""), 0u);
    ASSERT_FALSE(told.empty());
    EXPECT_EQ(told.front(), (std::pair<std::int64_t, std::int64_t>{0, 3}));
    EXPECT_EQ(told.back(), (std::pair<std::int64_t, std::int64_t>{r.frames_run, 3}));
}

}  // namespace
}  // namespace ricochet
