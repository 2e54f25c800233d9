// The failure view shows the failure: a disc's penetration framed with the wall and the disc, the frames around
// the failing one on a long run, and an inset at the failure's own scale when it is too small for the view.
// Runs written by hand (render_events.hpp); every assertion is on the picture's text, positions worked by hand.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "render_events.hpp"
#include "ricochet/render.hpp"
#include "text_search.hpp"

namespace ricochet {
namespace {

using test::count;
using test::has;
using test::hit;
using test::state;

/// The text of the caption line starting with prefix, or "" if none.
std::string caption_after(const std::string& svg, const std::string& prefix) {
    const std::size_t at = svg.find(">" + prefix);
    if (at == std::string::npos) return {};
    return svg.substr(at + 1, svg.find("</text>", at) - at - 1);
}

/// The points of the first polyline whose style holds style, in picture coordinates.
std::vector<std::pair<double, double>> polyline_with(const std::string& svg, const std::string& style) {
    std::vector<std::pair<double, double>> points;
    const std::size_t at = svg.find(style);
    if (at == std::string::npos) return points;
    const std::size_t open = svg.rfind("<polyline points=\"", at);
    const char* p = svg.data() + open + 18;
    while (*p != '"') {
        double x = 0, y = 0;
        p = std::from_chars(p, svg.data() + svg.size(), x).ptr + 1;
        p = std::from_chars(p, svg.data() + svg.size(), y).ptr + 1;
        points.push_back({x, y});
    }
    return points;
}

// A disc of radius 1 falls straight onto the wall (−4, 0) → (4, 0): (0, 3), (0, 2), (0, 1) touching it, then
// (0, 0.5), half its radius into it: penetration breaks at frame 3. The failing frame's path alone is the
// piece (0, 1) → (0, 0.5), half a unit tall, a full unit from the wall.
Scene falling_disc() {
    Scene s;
    s.walls = {{{-4, 0}, {4, 0}}};
    s.balls = {{{0, 3}, {0, -1}, 1}};
    s.checks = {Check::penetration};
    return s;
}

/// The disc's fall, failing `penetration` at frame 3 against wall 0 (or bumper 0), as the check names it.
CheckedRun falling_run(bool bumper = false) {
    CheckedRun run;
    run.frames_run = 3;
    run.events = {state(0, 0, {0, 3}), state(1, 0, {0, 2}), state(2, 0, {0, 1}), state(3, 0, {0, 0.5})};
    CheckFailure f;
    f.check = Check::penetration;
    f.frame = 3;
    f.message = "the path piece (0, 1) -> (0, 0.5) comes closer than the radius 1 to wall 0";
    f.against = FailureObstacle{bumper, 0, {0, 1}, {0, 0.5}};
    run.failure = f;
    return run;
}

TEST(RenderView, ADiscsPenetrationIsFramedWithTheWallAndTheDisc) {
    const std::string svg = render_svg(falling_disc(), falling_run());
    // The frame's points with the radius around them, [−1, 1] × [−0.5, 2], and the wall as far as it runs
    // within one span (2.5) of that: x in [−3.5, 3.5]. The wall is drawn, and the disc where it came nearest
    // (0, 0.5), in red.
    EXPECT_TRUE(has(svg, "x in [-3.5, 3.5], y in [-0.5, 2]")) << svg;
    EXPECT_TRUE(has(svg, ">w0</text>")) << svg;
    EXPECT_TRUE(has(svg, "marked at (0, 0.5), where the disc of radius 1 comes nearest wall 0")) << svg;
    EXPECT_TRUE(has(svg, "data-x=\"0\" data-y=\"0.5\""));
    // The view [−3.5, 3.5] padded by 15 % of 7: [−4.55, 4.55], scale 720/9.1; the disc's outline r = 79.121 px.
    EXPECT_TRUE(has(svg, "r=\"79.121\" fill=\"none\" stroke=\"red\" stroke-width=\"1.5\" stroke-dasharray=\"6 3\""))
        << svg;
}

TEST(RenderView, ABumperADiscReachedIntoIsInTheView) {
    // The same fall onto a bumper of radius 2 at (0, −2) instead of the wall: its top (0, 0) is 0.5 inside the
    // disc at (0, 0.5). The bumper's box within reach (one span, 2.5, of [−1, 1] × [−0.5, 2]), [−2, 2] × [−3, 0],
    // joins the view, widened about x = 0 to as wide as it is tall.
    Scene s = falling_disc();
    s.walls.clear();
    s.bumpers = {{{0, -2}, 2}};
    const std::string svg = render_svg(s, falling_run(true));
    EXPECT_TRUE(has(svg, "marked at (0, 0.5), where the disc of radius 1 comes nearest bumper 0")) << svg;
    EXPECT_TRUE(has(svg, "x in [-2.5, 2.5], y in [-3, 2]")) << svg;
    EXPECT_TRUE(has(svg, ">k0</text>"));
}

TEST(RenderView, ThePenetratedObstacleIsTheOneTheCheckNames) {
    // The disc starts within reach of wall 0 (a post at x = 0.5 from y = 0 to 5), so `penetration` holds it to
    // wall 0 only once a printed point is clear of it, which none is: the failure is wall 1, the floor, which the
    // view marks, though the piece comes closer than R to wall 0 first in the scene's order.
    Scene s = falling_disc();
    s.walls = {{{0.5, 0}, {0.5, 5}}, {{-4, 0}, {4, 0}}};
    CheckedRun run = falling_run();
    run.failure->message = "the path piece (0, 1) -> (0, 0.5) comes closer than the radius 1 to wall 1";
    run.failure->against = FailureObstacle{false, 1, {0, 1}, {0, 0.5}};
    const std::string svg = render_svg(s, run);
    EXPECT_TRUE(has(svg, "marked at (0, 0.5), where the disc of radius 1 comes nearest wall 1")) << svg;
    // Without the check's word (a failure built by hand with no obstacle) nothing is marked as reached into.
    run.failure->against.reset();
    EXPECT_FALSE(has(render_svg(s, run), "comes nearest wall"));
}

TEST(RenderView, OnALongRunOnlyTheFramesAroundTheFailingOneAreDrawn) {
    // A ball bounces between walls x = 0 and x = 10 for 100 frames, 4 units a frame, and "fails" at frame 50
    // (a hand-written failure with no piece: the view frames the frame's points). Its path passes through the
    // failing frame's view 20 times; drawn are frames 48..52 only: their 5 states and the hits between them.
    Scene s;
    s.walls = {{{0, -5}, {0, 5}}, {{10, 5}, {10, -5}}};
    s.balls = {{{1, 0}, {4, 0}}};
    CheckedRun run;
    run.frames_run = 100;
    double x = 1, v = 4;
    for (std::int64_t f = 0; f <= 100; ++f) {
        if (f > 0) {
            double to = x + v;
            if (to > 10) to = 20 - to, v = -v, run.events.push_back(hit(f, 0, 1, {10, 0}));
            if (to < 0) to = -to, v = -v, run.events.push_back(hit(f, 0, 0, {0, 0}));
            x = to;
        }
        run.events.push_back(state(f, 0, {x, 0}, {v, 0}));
    }
    CheckFailure f;
    f.check = Check::speed;
    f.frame = 50;
    run.failure = f;
    const std::string svg = render_svg(s, run);
    EXPECT_TRUE(has(svg, "view: the failing frame 50 of ball 0")) << svg;
    EXPECT_TRUE(has(svg, "paths of frames 48..52 only, around the failing frame (--frames A:B draws others)")) << svg;
    // Frame 50's hit on wall 0 at (0, 0) is the one hit drawn (every fifth frame hits there), and the path is one
    // polyline: it leaves the view once, not twenty times.
    EXPECT_EQ(count(svg, "r=\"3\" fill=\"#1f77b4\""), 1u) << svg;
    EXPECT_EQ(count(svg, "stroke=\"#1f77b4\" stroke-width=\"1.5\""), 1u) << svg;
    // The whole run is one flag away, and a range given draws that range.
    RenderOptions all;
    all.view = RenderView::all;
    EXPECT_FALSE(has(render_svg(s, run, all), "paths of frames"));
    RenderOptions range;
    range.first_frame = 0;
    range.last_frame = 100;
    EXPECT_FALSE(has(render_svg(s, run, range), "paths of frames"));
    // The falling disc's frames 1..3 (its failure at 3): frame 0 left out, and said so.
    EXPECT_TRUE(has(render_svg(falling_disc(), falling_run()), "paths of frames 1..3 only")) << svg;
    // A short run around its failure is drawn as it always was: nothing to leave out.
    Scene two;
    two.walls = {{{0, 0}, {10, 0}}};
    two.balls = {{{2, 2}, {2, -4}}};
    CheckedRun crossing;
    crossing.frames_run = 1;
    crossing.events = {state(0, 0, {2, 2}), state(1, 0, {4, -2})};
    crossing.failure = CheckFailure{};
    crossing.failure->frame = 1;
    crossing.failure->piece = FailurePiece{{2, 2}, {4, -2}, 0};
    EXPECT_FALSE(has(render_svg(two, crossing), "paths of frames"));
}

/// The SVG's width and height.
std::pair<double, double> picture_size(const std::string& svg) {
    const std::size_t at = svg.find("viewBox=\"0 0 ") + 13;
    double w = 0, h = 0;
    const char* p = std::from_chars(svg.data() + at, svg.data() + svg.size(), w).ptr;
    std::from_chars(p + 1, svg.data() + svg.size(), h);
    return {w, h};
}

/// The inset's top edge in the picture (the y of its frame), or −1.
double inset_top(const std::string& svg) {
    const std::string open = "<g class=\"inset\"><rect x=\"40.000\" y=\"";
    const std::size_t at = svg.find(open);
    if (at == std::string::npos) return -1;
    double y = -1;
    std::from_chars(svg.data() + at + open.size(), svg.data() + svg.size(), y);
    return y;
}

TEST(RenderView, ASubUlpCrossingGetsAnInsetAtItsOwnScale) {
    // Wall 0 from (0, 0) to (9, 3); the piece (6, 3) → (6, 2 − 2^−52) ends one ulp below (6, 2), which is on the
    // wall: across it by |n·(p − P0)|/|n| = 9·2^−52/√90 = 3·2^−52/√10 ≈ 2.1e−16, some 10^−13 of a pixel at the
    // view's scale. In double, n·(p − P0) = 3·6 − 9·(2 − 2^−52) rounds to a multiple of 2^−48: the inset needs
    // the exact distance.
    Scene s;
    s.walls = {{{0, 0}, {9, 3}}};
    const Vec2 from{6, 3}, to{6, 2 - 0x1p-52};
    s.balls = {{from, to - from}};
    CheckedRun run;
    run.frames_run = 1;
    run.events = {state(0, 0, from), state(1, 0, to)};
    CheckFailure f;
    f.frame = 1;
    f.piece = FailurePiece{from, to, 0};
    run.failure = f;
    const std::string svg = render_svg(s, run);
    const std::string line = caption_after(svg, "inset: the piece ends ");
    ASSERT_FALSE(line.empty()) << svg;
    double depth = 0;
    const std::string number = line.substr(std::string("inset: the piece ends ").size());
    std::from_chars(number.data(), number.data() + number.size(), depth);
    EXPECT_NEAR(depth, 3 * 0x1p-52 / std::sqrt(10.0), 1e-12 * depth) << line;
    EXPECT_TRUE(has(line, " past wall 0, enlarged ")) << line;
    // The inset, 240 px square under the picture at the 40 px margin, shows [−4δ, 4δ]²: the wall along its middle
    // row (top + 120), edge to edge; the piece from its end δ outside, 30 px (240/8) above the wall, back to
    // where it comes in at the inset's bottom edge, crossing the wall where the cross is.
    const double top = inset_top(svg);
    ASSERT_GT(top, 0) << svg;
    EXPECT_TRUE(has(svg, fmt::format("x1=\"40.000\" y1=\"{:.3f}\" x2=\"280.000\" y2=\"{:.3f}\" stroke=\"black\"", top + 120,
                                     top + 120)))
        << svg;
    const auto piece = polyline_with(svg.substr(svg.find("<g class=\"inset\">")), "stroke-opacity=\"0.5\"");
    ASSERT_EQ(piece.size(), 2u) << svg;
    EXPECT_NEAR(piece[0].second, top + 90, 1e-3);
    EXPECT_NEAR(piece[1].second, top + 240, 1e-3);
    // The cross on the wall's row: its first stroke from 6 px above it.
    const std::string mark = svg.substr(svg.find("<g class=\"inset-mark\""));
    EXPECT_TRUE(has(mark.substr(0, mark.find("</g>")), fmt::format("y1=\"{:.3f}\" x2=", top + 114))) << mark;
    EXPECT_EQ(count(svg, "<g class=\"inset-mark\" stroke=\"red\""), 1u);
    // The picture grows by the inset and its caption line: 250 px and 16 more under the inset's top.
    EXPECT_NEAR(picture_size(svg).second, top + 250 + 30 + 16 * 3, 0.5);
    // A crossing the view shows needs none: the same wall crossed a unit deep.
    f.piece = FailurePiece{from, {6, 1}, 0};
    run.events[1] = state(1, 0, {6, 1});
    run.failure = f;
    EXPECT_FALSE(has(render_svg(s, run), "inset"));
}

TEST(RenderView, ADiscReachingASubUlpDistancePastAWallGetsAnInset) {
    // A disc of radius 1 whose centre ends at (0, 1 − 2^−53): 2^−53 past the wall y = 0, a tenth of a
    // picometre of the view. The inset shows its edge along y = −δ at the middle, rising away from it.
    Scene s = falling_disc();
    CheckedRun run = falling_run();
    run.events.back() = state(3, 0, {0, 1 - 0x1p-53});
    run.failure->against->to = {0, 1 - 0x1p-53};
    const std::string svg = render_svg(s, run);
    const std::string line = caption_after(svg, "inset: the disc reaches ");
    ASSERT_FALSE(line.empty()) << svg;
    EXPECT_TRUE(has(line, "inset: the disc reaches 1.1102230246251565e-16 past wall 0")) << line;
    // Its edge, dashed red: 30 px (δ at 240/(8δ) px per unit) under the wall's row at the middle column, and flat
    // across the inset (x²/2R is 10^−15 of δ there).
    const double top = inset_top(svg);
    ASSERT_GT(top, 0) << svg;
    const std::string in = svg.substr(svg.find("<g class=\"inset\">"));
    // (Half a turn: the disc is on the wall's inner side, so the wall runs from right to left.)
    EXPECT_TRUE(has(in, fmt::format("x1=\"280.000\" y1=\"{:.3f}\" x2=\"40.000\" y2=\"{:.3f}\" stroke=\"black\"", top + 120,
                                    top + 120)))
        << in;
    const auto edge = polyline_with(in, "stroke-dasharray=\"6 3\"");
    ASSERT_EQ(edge.size(), 33u) << in;
    EXPECT_NEAR(edge[16].second, top + 150, 1e-3);
    EXPECT_NEAR(edge[0].second, top + 150, 1e-3);
}

}  // namespace
}  // namespace ricochet
