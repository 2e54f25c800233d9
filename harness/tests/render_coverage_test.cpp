// Render: what the SVG draws, where, and from which frames. Positions are worked by hand from the
// picture's mapping: bounds padded by 5 % of the larger span, scale = (width − 80) / padded span,
// sx = (x − x0)·scale + 40, sy = (y1 − y)·scale + 40 (y up in the world, down in SVG).
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "render_events.hpp"
#include "ricochet/render.hpp"
#include "text_search.hpp"

namespace ricochet {
namespace {

using test::count;
using test::has;
using test::hit;
using test::state;

TEST(Render, AnEmptySceneIsTheUnitSquarePictureAndNothingElse) {
    // Nothing to bound: [0, 1]², padded by 0.05 to a span of 1.1, 720 px across: 800 × (800 + 30).
    const std::string svg = render_svg(Scene{}, CheckedRun{});
    EXPECT_EQ(svg,
              "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"800\" height=\"830\" viewBox=\"0 0 800 830\" "
              "font-family=\"sans-serif\" font-size=\"12\">\n"
              "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
              "<text x=\"8\" y=\"820.0\">kernel robust, frames 0..0, x in [0, 1], y in [0, 1]</text>\n"
              "</svg>\n");
}

TEST(Render, TheWidthOptionScalesThePicture) {
    // 400 px: 320 px for the padded span, 400 × 430.
    RenderOptions o;
    o.width = 400;
    const std::string svg = render_svg(Scene{}, CheckedRun{}, o);
    EXPECT_TRUE(has(svg, "width=\"400\" height=\"430\" viewBox=\"0 0 400 430\"")) << svg;
}

// The box [0, 10]²: padded to [−0.5, 10.5]², scale 720/11, so 0 ↦ 72.727 and 10 ↦ 727.273 (sx), and
// 10 ↦ 72.727, 0 ↦ 727.273 (sy). One ball; what it draws depends on the run's events.
Scene box_scene() {
    Scene s;
    s.kernel = KernelId::lecture_double;
    s.walls = {{{0, 0}, {10, 0}}, {{10, 10}, {0, 10}}};
    s.rects = {{1, 1, 3, 2}};
    s.circles = {{{5, 5}, 1}};
    s.balls = {{{0, 0}, {5, 0}}};
    return s;
}

TEST(Render, WallsNormalsRectsAndCirclesSitWhereTheMappingPutsThem) {
    const std::string svg = render_svg(box_scene(), CheckedRun{});
    EXPECT_TRUE(has(svg, "<text x=\"8\" y=\"820.0\">kernel lecture-double, frames 0..0, x in [0, 10], y in [0, 10]</text>"))
        << svg;
    // Wall 0, (0, 0) → (10, 0): along the bottom.
    EXPECT_TRUE(has(svg, "<line x1=\"72.727\" y1=\"727.273\" x2=\"727.273\" y2=\"727.273\" stroke=\"black\""));
    // Its normal (e_y, −e_x)/|e| = (0, −1) from the midpoint (5, 0), 0.04·11 = 0.44 long: tip (5, −0.44),
    // sy = 10.94·720/11 + 40 = 756.073.
    EXPECT_TRUE(has(svg, "<line x1=\"400.000\" y1=\"727.273\" x2=\"400.000\" y2=\"756.073\" stroke=\"#888\""));
    // P0 marked 2 px up and left of (72.727, 727.273); the label 4 px right and down of the tip.
    EXPECT_TRUE(has(svg, "<rect x=\"70.727\" y=\"725.273\" width=\"4\" height=\"4\" fill=\"black\"/>"
                         "<text x=\"404.000\" y=\"760.073\" fill=\"#555\">w0</text>"));
    // Wall 1, (10, 10) → (0, 10): normal (0, 1), tip (5, 10.44), sy = 0.06·720/11 + 40 = 43.927.
    EXPECT_TRUE(has(svg, "<line x1=\"400.000\" y1=\"72.727\" x2=\"400.000\" y2=\"43.927\" stroke=\"#888\""));
    EXPECT_TRUE(has(svg, ">w1</text>"));
    // The rect [1, 3] × [1, 2]: top-left (1, 2) ↦ (1.5·720/11 + 40, 8.5·720/11 + 40), 2 × 1 world units.
    EXPECT_TRUE(has(svg, "<rect x=\"138.182\" y=\"596.364\" width=\"130.909\" height=\"65.455\" fill=\"#2ca02c\""));
    EXPECT_TRUE(has(svg, "<text x=\"141.182\" y=\"609.364\" fill=\"#2ca02c\">r0</text>"));
    // The circle at (5, 5), r = 1: centre (400, 400), radius 65.455; label 3 px right and up.
    EXPECT_TRUE(has(svg, "<circle cx=\"400.000\" cy=\"400.000\" r=\"65.455\" fill=\"#ff7f0e\""));
    EXPECT_TRUE(has(svg, "<text x=\"403.000\" y=\"397.000\" fill=\"#ff7f0e\">c0</text>"));
    // Statics before walls, so walls are drawn over them; no ball, no path, no failure.
    EXPECT_LT(svg.find(">r0<"), svg.find(">c0<"));
    EXPECT_LT(svg.find(">c0<"), svg.find(">w0<"));
    EXPECT_EQ(count(svg, "<polyline"), 0u);
    EXPECT_FALSE(has(svg, "red"));
}

TEST(Render, AZeroLengthWallHasNoNormalAndATinyCircleStaysVisible) {
    Scene s = box_scene();
    s.walls.push_back({{4, 4}, {4, 4}});
    s.circles.push_back({{6, 6}, 0.0});
    const std::string svg = render_svg(s, CheckedRun{});
    // Three walls drawn, two normals (the zero-length one has none), but all three labelled.
    EXPECT_EQ(count(svg, "stroke=\"black\" stroke-width=\"2.5\""), 3u);
    EXPECT_EQ(count(svg, "stroke=\"#888\""), 2u);
    EXPECT_TRUE(has(svg, ">w2</text>"));
    // A radius-0 circle is drawn 1.5 px wide.
    EXPECT_TRUE(has(svg, "r=\"1.500\" fill=\"#ff7f0e\""));
}

TEST(Render, ASinglePointSceneGetsAUnitSpanAroundIt) {
    // One ball at rest at (2, 3): no span, so a span of 1, padded to [1.95, 2.05] × [2.95, 3.05]; the
    // point maps to the picture's centre (400, 400) and the picture is 800 × 830.
    Scene s;
    s.balls = {{{2, 3}, {0, 0}}};
    CheckedRun run;
    run.events = {state(0, 0, {2, 3})};
    const std::string svg = render_svg(s, run);
    EXPECT_TRUE(has(svg, "width=\"800\" height=\"830\""));
    EXPECT_TRUE(has(svg, "x in [2, 2], y in [3, 3]"));
    EXPECT_TRUE(has(svg, "<polyline points=\"400.000,400.000 \" fill=\"none\" stroke=\"#1f77b4\""));
    // Start (hollow, labelled) and end (filled) markers at the same point.
    EXPECT_TRUE(has(svg, "<circle cx=\"400.000\" cy=\"400.000\" r=\"5\" fill=\"white\" stroke=\"#1f77b4\""));
    EXPECT_TRUE(has(svg, "<text x=\"407.000\" y=\"393.000\" fill=\"#1f77b4\">b0</text>"));
    EXPECT_TRUE(has(svg, "<circle cx=\"400.000\" cy=\"400.000\" r=\"5\" fill=\"#1f77b4\"/>"));
}

// A ball in [0, 10]² (walls give the bounds) with states at frames 0..3 and a hit in frames 1 and 3.
CheckedRun path_run() {
    CheckedRun run;
    run.frames_run = 3;
    run.events = {state(0, 0, {0, 0}, {5, 0}),
                  test::overlap(0, 0, 0),
                  hit(1, 0, 0, {5, 0}),
                  state(1, 0, {5, 5}),
                  state(2, 0, {10, 5}),
                  hit(3, 0, 1, {10, 10}),
                  state(3, 0, {0, 10})};
    return run;
}

TEST(Render, APathRunsThroughEveryStateAndHitInOrder) {
    const std::string svg = render_svg(box_scene(), path_run());
    EXPECT_TRUE(has(svg, "frames 0..3"));
    // (0,0) (5,0) (5,5) (10,5) (10,10) (0,10), the overlap skipped.
    EXPECT_TRUE(has(svg, "<polyline points=\"72.727,727.273 400.000,727.273 400.000,400.000 727.273,400.000 "
                         "727.273,72.727 72.727,72.727 \" fill=\"none\" stroke=\"#1f77b4\""));
    // Both hits marked; start at (0, 0), end at (0, 10).
    EXPECT_TRUE(has(svg, "<circle cx=\"400.000\" cy=\"727.273\" r=\"3\" fill=\"#1f77b4\"/>"));
    EXPECT_TRUE(has(svg, "<circle cx=\"727.273\" cy=\"72.727\" r=\"3\" fill=\"#1f77b4\"/>"));
    EXPECT_EQ(count(svg, "r=\"3\""), 2u);
    EXPECT_TRUE(has(svg, "<circle cx=\"72.727\" cy=\"727.273\" r=\"5\" fill=\"white\""));
    EXPECT_TRUE(has(svg, "<circle cx=\"72.727\" cy=\"72.727\" r=\"5\" fill=\"#1f77b4\"/>"));
}

TEST(Render, AMeetIsARingOnThePathAndAHitADot) {
    // Discs of radius 0.5 (their outlines stay inside the box, so the mapping is the box's): ball 0 meets ball 1 at
    // (4, 1) in frame 1 and turns up to (4, 5); ball 1 meets it at (5, 1), bounces off wall 0 at (7, 0.5), ends at (9, 1).
    Scene s = box_scene();
    s.balls = {{{1, 1}, {4, 0}, 0.5}, {{9, 1}, {-4, 0}, 0.5}};
    s.balls_collide = true;
    CheckedRun run;
    run.frames_run = 1;
    run.events = {state(0, 0, {1, 1}), state(0, 1, {9, 1}),
                  {Event::Kind::meet, 1, 0, Event::Shape::none, 1, {4, 1}, {0, 4}}, state(1, 0, {4, 5}),
                  {Event::Kind::meet, 1, 1, Event::Shape::none, 0, {5, 1}, {4, 0}}, hit(1, 1, 0, {7, 0.5}),
                  state(1, 1, {9, 1})};
    const std::string svg = render_svg(s, run);
    // A ring in each ball's colour where it met: (4, 1) ↦ (334.545, 661.818), (5, 1) ↦ (400, 661.818); ball 1's hit
    // at (7, 0.5) ↦ (530.909, 694.545) a dot.
    EXPECT_TRUE(has(svg, "<circle cx=\"334.545\" cy=\"661.818\" r=\"4\" fill=\"white\" stroke=\"#1f77b4\"")) << svg;
    EXPECT_TRUE(has(svg, "<circle cx=\"400.000\" cy=\"661.818\" r=\"4\" fill=\"white\" stroke=\"#d62728\"")) << svg;
    EXPECT_TRUE(has(svg, "<circle cx=\"530.909\" cy=\"694.545\" r=\"3\" fill=\"#d62728\"/>")) << svg;
    EXPECT_EQ(count(svg, "r=\"4\""), 2u);
}

TEST(Render, AFrameRangeDrawsFromTheFirstFramesStateToTheLastFrames) {
    // Frames 1..2: frame 1's hit lies before its state (the ball reached it in frame 1), so the path
    // starts at frame 1's state (5, 5) and ends at frame 2's (10, 5); frame 3 is not drawn.
    RenderOptions o;
    o.first_frame = 1;
    o.last_frame = 2;
    const std::string svg = render_svg(box_scene(), path_run(), o);
    EXPECT_TRUE(has(svg, "frames 1..2"));
    EXPECT_TRUE(has(svg, "<polyline points=\"400.000,400.000 727.273,400.000 \""));
    EXPECT_EQ(count(svg, "r=\"3\""), 0u);
    EXPECT_TRUE(has(svg, "<circle cx=\"400.000\" cy=\"400.000\" r=\"5\" fill=\"white\""));
    EXPECT_TRUE(has(svg, "<circle cx=\"727.273\" cy=\"400.000\" r=\"5\" fill=\"#1f77b4\"/>"));
}

TEST(Render, BoundsCoverOnlyTheFramesDrawn) {
    // No statics: the bounds are the drawn events'. Frames 2..3 hold (10, 5), (10, 10), (0, 10): x in
    // [0, 10], y in [5, 10]; the point (0, 0) of frame 0 is left out.
    RenderOptions o;
    o.first_frame = 2;
    Scene s;
    s.balls = {{{0, 0}, {5, 0}}};
    const std::string svg = render_svg(s, path_run(), o);
    EXPECT_TRUE(has(svg, "frames 2..3, x in [0, 10], y in [5, 10]")) << svg;
}

TEST(Render, ABallWithNothingInRangeDrawsNoPathAndColoursCycleByEight) {
    // Nine balls, only balls 0 and 8 have events: ball 8 takes ball 0's colour; balls 1..7 draw nothing.
    Scene s;
    s.balls.assign(9, Ball{});
    CheckedRun run;
    run.events = {state(0, 0, {0, 0}), state(0, 8, {1, 1})};
    const std::string svg = render_svg(s, run);
    EXPECT_EQ(count(svg, "<polyline"), 2u);
    EXPECT_EQ(count(svg, "stroke=\"#1f77b4\" stroke-width=\"1.5\""), 2u);
    EXPECT_TRUE(has(svg, ">b0</text>"));
    EXPECT_TRUE(has(svg, ">b8</text>"));
    EXPECT_FALSE(has(svg, ">b1</text>"));
}

TEST(Render, AFailureIsACrossAtTheBallsStateAndItsMessageIsEscaped) {
    // Ball 1 also has a state in frame 2, at (0, 5): the cross is only at ball 0's.
    Scene s = box_scene();
    s.balls.push_back({{0, 5}, {0, 0}});
    CheckedRun run = path_run();
    run.events.push_back(state(2, 1, {0, 5}));
    CheckFailure f;
    f.check = Check::no_tunnel;
    f.frame = 2;
    f.ball = 0;
    f.message = "piece (0, 8) -> (-4, 9) < wall & more";
    run.failure = f;
    // The whole scene's view, so the mapping is the box's (the failure view is render_run_test's).
    RenderOptions o;
    o.view = RenderView::all;
    const std::string svg = render_svg(s, run, o);
    // Frame 2's state (10, 5) ↦ (727.273, 400): a cross 9 px each way; no piece, so no crossing.
    EXPECT_TRUE(has(svg, "marked at (10, 5), the ball's state at the end of frame 2"));
    EXPECT_TRUE(has(svg, "<g stroke=\"red\" stroke-width=\"3\" data-x=\"10\" data-y=\"5\"><line x1=\"718.273\" y1=\"391.000\" x2=\"736.273\" "
                         "y2=\"409.000\"/><line x1=\"718.273\" y1=\"409.000\" x2=\"736.273\" y2=\"391.000\"/></g>"));
    EXPECT_EQ(count(svg, "<g stroke=\"red\""), 1u);
    EXPECT_TRUE(has(svg, "piece (0, 8) -&gt; (-4, 9) &lt; wall &amp; more</text>"));
    EXPECT_FALSE(has(svg, "-> (-4"));
}

TEST(Render, ALongFailureMessageIsCutToTwoLinesOfThePicturesWidth) {
    // 800 px hold (800 − 16) / 7 = 112 characters a line: a message of 300 without a space is cut to
    // 221 and "...", and broken at 112.
    CheckedRun run = path_run();
    CheckFailure f;
    f.frame = 7;  // no state at frame 7: no cross, only the message
    f.message = std::string(300, 'x');
    run.failure = f;
    const std::string svg = render_svg(box_scene(), run);
    EXPECT_EQ(count(svg, "<g stroke=\"red\""), 0u);
    const auto line = [&](const std::string& open) {
        const std::size_t from = svg.find(open);
        if (from == std::string::npos) return std::string("(none)");
        const std::size_t to = svg.find("</text>", from);
        return svg.substr(from + open.size(), to - from - open.size());
    };
    const std::string first = line("<text x=\"8\" y=\"18\" fill=\"red\">");
    const std::string second = line("<text x=\"8\" y=\"32\" fill=\"red\">");
    EXPECT_EQ(first, f.str().substr(0, 112));
    EXPECT_EQ(second, f.str().substr(112, 109) + "...");
    // A shorter message breaks at its last space before the 112th character.
    f.message = std::string(60, 'a') + " " + std::string(60, 'b');
    run.failure = f;
    const std::string two = render_svg(box_scene(), run);
    EXPECT_TRUE(has(two, "ball 0: " + std::string(60, 'a') + "</text>")) << two;
    EXPECT_TRUE(has(two, "<text x=\"8\" y=\"32\" fill=\"red\">" + std::string(60, 'b') + "</text>"));
}

}  // namespace
}  // namespace ricochet

namespace ricochet {
namespace {

// The failure's mark and view from a run written by hand: one wall along y = 0 from (0, 0) to (10, 0),
// one ball whose frame 1 goes from `from` to `to`, and a no-tunnel failure naming that piece.
std::string piece_svg(Vec2 from, Vec2 to, RenderView view = RenderView::failure) {
    Scene s;
    s.walls = {{{0, 0}, {10, 0}}};
    s.balls = {{from, to - from}};
    CheckedRun run;
    run.frames_run = 1;
    run.events = {state(0, 0, from, to - from), state(1, 0, to, to - from)};
    CheckFailure f;
    f.frame = 1;
    f.piece = FailurePiece{from, to, 0};
    run.failure = f;
    RenderOptions o;
    o.view = view;
    return render_svg(s, run, o);
}

TEST(Render, TheMarkStaysOnThePieceWhenItsLineMeetsTheWallOutsideIt) {
    // (2, 3) → (6, 1): the line meets y = 0 at s = 3/2, past the piece's end: the mark is the end (6, 1).
    EXPECT_TRUE(has(piece_svg({2, 3}, {6, 1}), "data-x=\"6\" data-y=\"1\""));
    // (2, −1) → (2, −5) moves away from the line (s = −1/4): the mark is the start.
    EXPECT_TRUE(has(piece_svg({2, -1}, {2, -5}), "data-x=\"2\" data-y=\"-1\""));
    // Along the wall's line (e × d = 0): the start.
    EXPECT_TRUE(has(piece_svg({2, 0}, {5, 0}), "data-x=\"2\" data-y=\"0\""));
    // A crossing inside: (2, 2) → (4, −2) meets y = 0 halfway, at (3, 0); "where the piece crosses".
    const std::string svg = piece_svg({2, 2}, {4, -2});
    EXPECT_TRUE(has(svg, "data-x=\"3\" data-y=\"0\""));
    EXPECT_TRUE(has(svg, "marked at (3, 0), where the piece crosses wall 0"));
}

TEST(Render, TheFailureViewLeavesOutWhatLiesOutsideItAndCutsWhatCrossesIt) {
    // The piece (2, 2) → (4, −2): box [2, 4] × [−2, 2] with the wall's part within one span (4) of it,
    // x in [0, 8]; widened in nothing (8 ≥ 4). A circle and a rect far off are not drawn; a rect across
    // the view's edge is cut to it; a path far off draws no polyline, no marker and no label.
    Scene s;
    s.walls = {{{0, 0}, {10, 0}}, {{100, 100}, {101, 100}}};
    s.circles = {{{50, 50}, 1}};
    s.rects = {{-100, -1, 1, 1}, {60, 60, 61, 61}};
    s.balls = {{{2, 2}, {2, -4}}, {{70, 70}, {1, 0}}};
    CheckedRun run;
    run.frames_run = 1;
    run.events = {state(0, 0, {2, 2}), state(0, 1, {70, 70}), state(1, 0, {4, -2}), state(1, 1, {71, 70})};
    CheckFailure f;
    f.frame = 1;
    f.piece = FailurePiece{{2, 2}, {4, -2}, 0};
    run.failure = f;
    const std::string svg = render_svg(s, run);
    EXPECT_TRUE(has(svg, "x in [0, 8], y in [-2, 2]")) << svg;
    EXPECT_FALSE(has(svg, ">c0<"));
    EXPECT_FALSE(has(svg, ">r1<"));
    EXPECT_FALSE(has(svg, ">w1<"));
    EXPECT_FALSE(has(svg, ">b1<"));
    EXPECT_TRUE(has(svg, ">b0<"));
    // The view [−1.2, 9.2] × [−3.2, 3.2], scale 720/10.4, margins 40/scale = 0.578 world units: rect 0's
    // left side −100 is cut to −1.778 (the picture's left edge), so it is 2.778·720/10.4 = 192.308 wide.
    EXPECT_TRUE(has(svg, "width=\"192.308\" height=\"138.462\" fill=\"#2ca02c\"")) << svg;
    // Wall 0 runs past the view on the right (10 > 9.2 + 0.578): cut at the picture's edge, x = 800, so
    // its far end P1 is not there; its P0 square is.
    EXPECT_TRUE(has(svg, "x2=\"800.000\"")) << svg;
    EXPECT_EQ(count(svg, "width=\"4\" height=\"4\""), 1u);
}

TEST(Render, NonFinitePointsBoundNothingAndDrawNoPiece) {
    // A lecture kernel's NaN: the path (0, 0) → NaN → (10, 0) draws no piece to or from the NaN, and the
    // bounds are the finite points' ([0, 10] × [0, 0]).
    Scene s;
    s.balls = {{{0, 0}, {1, 0}}};
    CheckedRun run;
    run.frames_run = 2;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    run.events = {state(0, 0, {0, 0}), state(1, 0, {nan, 0}), state(2, 0, {10, 0})};
    const std::string svg = render_svg(s, run);
    EXPECT_TRUE(has(svg, "x in [0, 10], y in [0, 0]")) << svg;
    EXPECT_EQ(count(svg, "<polyline"), 0u) << svg;
}

TEST(Render, AFailureAtFrameZeroWithOnePointIsShownInTheWholeView) {
    // Nothing to frame (one point): the whole scene's view, the mark at the ball's state.
    Scene s = box_scene();
    CheckedRun run;
    run.events = {state(0, 0, {5, 5})};
    CheckFailure f;
    f.check = Check::boundary;
    run.failure = f;
    const std::string svg = render_svg(s, run);
    EXPECT_FALSE(has(svg, "view: the failing frame"));
    EXPECT_TRUE(has(svg, "x in [0, 10], y in [0, 10]"));
    EXPECT_TRUE(has(svg, "data-x=\"5\" data-y=\"5\""));
}

}  // namespace
}  // namespace ricochet
