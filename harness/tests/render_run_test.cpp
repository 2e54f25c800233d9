// render_run: the picture made while the run streams by. What it keeps (only frames A..B, at most
// max_balls paths, the failing ball always), where it stops, where it looks (the failing frame) and where
// it marks (the exact crossing, worked by hand). No timing: every assertion is on the picture's text.
#include <gtest/gtest.h>

#include <charconv>
#include <string>
#include <vector>

#include "mutant_kernel.hpp"
#include "ricochet/render.hpp"
#include "text_search.hpp"

namespace ricochet {
namespace {

using test::count;
using test::has;

/// The points of the first polyline after `after` in svg, in picture coordinates.
std::vector<std::pair<double, double>> polyline_after(const std::string& svg, const std::string& after) {
    std::vector<std::pair<double, double>> points;
    const std::size_t from = svg.find(after);
    if (from == std::string::npos) return points;
    const std::size_t open = svg.rfind("<polyline points=\"", from);
    if (open == std::string::npos) return points;
    const char* p = svg.data() + open + 18;
    while (*p != '"') {
        double x = 0, y = 0;
        p = std::from_chars(p, svg.data() + svg.size(), x).ptr;
        ++p;  // ','
        p = std::from_chars(p, svg.data() + svg.size(), y).ptr;
        ++p;  // ' '
        points.push_back({x, y});
    }
    return points;
}

/// The picture's width and height from its viewBox.
std::pair<double, double> picture_size(const std::string& svg) {
    const std::size_t at = svg.find("viewBox=\"0 0 ") + 13;
    double w = 0, h = 0;
    const char* p = std::from_chars(svg.data() + at, svg.data() + svg.size(), w).ptr;
    std::from_chars(p + 1, svg.data() + svg.size(), h);
    return {w, h};
}

/// The mutant kernel steps every ball straight through every wall: robust's step with no walls.
void walls_ignored(mutant::Mutation& m) {
    m.ops.step_ball = [](STEP_PARAMS) {
        (void)walls;
        (void)index;
        return ::ricochet::mutant::robust().step_ball(b, mem, {}, hits, scratch, nullptr);
    };
}

// The hand-worked crossing: wall 0 runs (−4, 0) → (4, 0); the last ball starts at (1, 3) moving (2, −4),
// so frame 1's piece (1, 3) → (3, −1) meets y = 0 at s = 3/4 of the way: (1 + 2·3/4, 0) = (2.5, 0).
// Every other ball sits still at (x, 5) above the wall. No-tunnel breaks at frame 1 for the last ball.
Scene crossing_scene(std::uint32_t balls) {
    Scene s;
    s.frames = 2;
    s.walls = {{{-4, 0}, {4, 0}}};
    for (std::uint32_t i = 0; i + 1 < balls; ++i) s.balls.push_back({{-4 + 8.0 * i / balls, 5}, {0, 0}});
    s.balls.push_back({{1, 3}, {2, -4}});
    s.checks = {Check::no_tunnel};
    return s;
}

TEST(RenderRun, TheMarkIsTheExactCrossingOnTheWallItWentThrough) {
    mutant::Mutation m;
    walls_ignored(m);
    const RenderResult r = render_run(crossing_scene(3), mutant::id());
    ASSERT_TRUE(r.failure);
    EXPECT_EQ(r.failure->check, Check::no_tunnel);
    EXPECT_EQ(r.failure->frame, 1);
    EXPECT_EQ(r.failure->ball, 2u);
    ASSERT_TRUE(r.failure->piece);
    EXPECT_EQ(r.failure->piece->wall, 0u);
    EXPECT_EQ(r.failure->piece->from, (Vec2{1, 3}));
    EXPECT_EQ(r.failure->piece->to, (Vec2{3, -1}));
    // The mark's world point, printed exactly, and the caption saying where it is.
    EXPECT_TRUE(has(r.svg, "<g stroke=\"red\" stroke-width=\"3\" data-x=\"2.5\" data-y=\"0\">")) << r.svg;
    EXPECT_TRUE(has(r.svg, "marked at (2.5, 0), where the piece crosses wall 0")) << r.svg;
    // The view: the frame's path (1, 3) → (3, −1), the mark, and wall 0 as far as it runs within one span
    // (4) of that box: x in [−3, 7] ∩ [−4, 4] = [−3, 4]. So x in [−3, 4], y in [−1, 3]; padded by 15 % of
    // 7, 1.05: [−4.05, 5.05] × [−2.05, 4.05], scale 720 / 9.1. The cross is at
    // sx = (2.5 + 4.05)·720/9.1 + 40 = 558.242, sy = (4.05 − 0)·720/9.1 + 40 = 360.440, 9 px each way.
    EXPECT_TRUE(has(r.svg, "x in [-3, 4], y in [-1, 3]")) << r.svg;
    EXPECT_TRUE(has(r.svg, "<line x1=\"549.242\" y1=\"351.440\" x2=\"567.242\" y2=\"369.440\"/>")) << r.svg;
}

TEST(RenderRun, TheViewFramesTheFailingFramesPointsNotTheWholeRun) {
    // A far wall at x = 10^6 would shrink the failing frame to a dot in the whole scene's view.
    mutant::Mutation m;
    walls_ignored(m);
    Scene s = crossing_scene(2);
    s.walls.push_back({{1e6, -1}, {1e6, 1}});
    const RenderResult r = render_run(s, mutant::id());
    const auto [w, h] = picture_size(r.svg);
    const auto failing = polyline_after(r.svg, "stroke=\"red\" stroke-width=\"3\" stroke-opacity");
    ASSERT_EQ(failing.size(), 2u) << r.svg;
    for (const auto& [x, y] : failing) {
        EXPECT_GE(x, 0);
        EXPECT_LE(x, w);
        EXPECT_GE(y, 0);
        EXPECT_LE(y, h);
    }
    // The piece spans 2 of the box's 9.1 world units across: 2·720/9.1 = 158 px, not a dot.
    EXPECT_GT(failing[1].first - failing[0].first, 150);
    // The far wall is outside the view and not drawn at all; the whole scene is one flag away.
    EXPECT_EQ(count(r.svg, "stroke=\"black\" stroke-width=\"2.5\""), 1u);
    RenderOptions all;
    all.view = RenderView::all;
    const RenderResult whole = render_run(s, mutant::id(), all);
    EXPECT_EQ(count(whole.svg, "stroke=\"black\" stroke-width=\"2.5\""), 2u);
    EXPECT_FALSE(has(whole.svg, "view: the failing frame"));
    EXPECT_TRUE(has(whole.svg, "data-x=\"2.5\" data-y=\"0\""));
}

TEST(RenderRun, ASteepFailingFrameIsSeenAsWideAsItIsTall) {
    // The piece (0, 3) → (0, −3) through the short wall (−0.5, 0) → (0.5, 0): the frame's box
    // [−0.5, 0.5] × [−3, 3] is widened about x = 0 to [−3, 3], so the picture keeps its 800 px.
    mutant::Mutation m;
    walls_ignored(m);
    Scene s;
    s.frames = 1;
    s.walls = {{{-0.5, 0}, {0.5, 0}}};
    s.balls = {{{0, 3}, {0, -6}}};
    s.checks = {Check::no_tunnel};
    const RenderResult r = render_run(s, mutant::id());
    EXPECT_TRUE(has(r.svg, "x in [-3, 3], y in [-3, 3]")) << r.svg;
    EXPECT_EQ(picture_size(r.svg).first, 800);
    EXPECT_TRUE(has(r.svg, "data-x=\"0\" data-y=\"0\""));
}

TEST(RenderRun, AHundredThousandBallsGiveABoundedPictureWithTheFailingBall) {
    // 10^5 balls, the failing one last: 64 paths drawn (balls 0..62 and ball 99999), the rest counted.
    mutant::Mutation m;
    walls_ignored(m);
    const Scene s = crossing_scene(100000);
    const RenderResult r = render_run(s, mutant::id());
    ASSERT_TRUE(r.failure);
    EXPECT_EQ(r.failure->ball, 99999u);
    EXPECT_TRUE(has(r.svg, "paths of 64 of 100000 balls drawn (balls 0..62 and the failing ball 99999), 99936 left out"))
        << r.svg.substr(0, 2000);
    EXPECT_TRUE(has(r.svg, ">b99999</text>"));
    EXPECT_FALSE(has(r.svg, ">b63</text>"));
    EXPECT_FALSE(has(r.svg, ">b0</text>"));  // 64 labels would hide the paths: only the failing ball's
    // Every ball drawn has at most 3 points (frames 0..2) and 3 markers: bounded by the balls drawn, not
    // the balls run. Each drawn element is under 200 bytes.
    EXPECT_LE(count(r.svg, "<polyline"), 65u);
    EXPECT_LT(r.svg.size(), 64u * 4 * 200 + 4000);
    // The failing ball's path is its real one, stepped again alone: frame 0 (1, 3), frame 1 (3, −1),
    // frame 2 (5, −5), in the whole-scene view.
    RenderOptions all;
    all.view = RenderView::all;
    const RenderResult whole = render_run(s, mutant::id(), all);
    EXPECT_TRUE(has(whole.svg, ">b99999</text>"));
    const std::size_t label = whole.svg.find(">b99999</text>");
    const std::size_t line = whole.svg.rfind("<polyline points=\"", label);
    const std::size_t stop = whole.svg.find('"', line + 18);
    const std::string pts = whole.svg.substr(line + 18, stop - line - 18);
    // The whole view bounds x in [−4, 5] (wall 0, the failing path), y in [−5, 5]: padded to
    // [−4.5, 5.5] × [−5.5, 5.5], scale 720/11; (1, 3) ↦ (400, 203.636), (3, −1) ↦ (530.909, 465.455),
    // (5, −5) ↦ (661.818, 727.273).
    EXPECT_EQ(pts, "400.000,203.636 530.909,465.455 661.818,727.273 ");
}

TEST(RenderRun, AFrameRangeKeepsOnlyItsFramesAndTheAllViewStopsAtItsEnd) {
    // One ball in free space for 100 frames, moving (1, 0): --frames 2:5 draws (2, 0) … (5, 0), 4 points.
    Scene s;
    s.frames = 100;
    s.balls = {{{0, 0}, {1, 0}}};
    s.checks = {Check::no_tunnel};
    RenderOptions o;
    o.first_frame = 2;
    o.last_frame = 5;
    o.view = RenderView::all;
    const RenderResult r = render_run(s, KernelId::robust, o);
    EXPECT_EQ(r.frames_run, 5);  // nothing to find past frame 5 in the whole-scene view
    EXPECT_TRUE(has(r.svg, "frames 2..5, x in [2, 5], y in [0, 0]")) << r.svg;
    const auto path = polyline_after(r.svg, "fill=\"none\" stroke=\"#1f77b4\"");
    EXPECT_EQ(path.size(), 4u) << r.svg;
    // The failure view goes on to the log's end looking for a failure (none here), drawing the same.
    o.view = RenderView::failure;
    const RenderResult f = render_run(s, KernelId::robust, o);
    EXPECT_EQ(f.frames_run, 100);
    EXPECT_FALSE(f.failure);
    EXPECT_TRUE(has(f.svg, "frames 2..5, x in [2, 5], y in [0, 0]")) << f.svg;
}

TEST(RenderRun, AFailureAfterTheRangeIsFoundAndTheRunStopsThere) {
    // The crossing ball of crossing_scene fails at frame 1; frames 0:0 draw only frame 0, and the run
    // goes on to frame 1 for the failure, then stops (the log has 50 frames).
    mutant::Mutation m;
    walls_ignored(m);
    Scene s = crossing_scene(2);
    s.frames = 50;
    RenderOptions o;
    o.last_frame = 0;
    const RenderResult r = render_run(s, mutant::id(), o);
    ASSERT_TRUE(r.failure);
    EXPECT_EQ(r.failure->frame, 1);
    EXPECT_EQ(r.frames_run, 1);
    EXPECT_TRUE(has(r.svg, "data-x=\"2.5\" data-y=\"0\""));
    // The whole-scene view with the same range stops at frame 0: no failure searched past it.
    o.view = RenderView::all;
    const RenderResult all = render_run(s, mutant::id(), o);
    EXPECT_EQ(all.frames_run, 0);
    EXPECT_FALSE(all.failure);
}

/// The r of the first <circle …> element holding attr, or −1.
double circle_radius_with(const std::string& svg, const std::string& attr) {
    const std::size_t at = svg.find(attr);
    if (at == std::string::npos) return -1;
    const std::size_t open = svg.rfind("<circle ", at);
    const std::size_t r = svg.find(" r=\"", open);
    double v = -1;
    std::from_chars(svg.data() + r + 4, svg.data() + svg.size(), v);
    return v;
}

TEST(RenderRun, ADiscIsDrawnAtItsSizeAndABumperAsASolidCircle) {
    // A disc of radius 0.5 at (−5, 0) moving (4, 0) meets the bumper of radius 1 at the origin when its centre is
    // 1.5 from it, at (−1.5, 0) (t = 3.5/4), and goes back: its path is (−5, 0), the bump, its end (−2, 0).
    Scene s;
    s.frames = 1;
    s.bumpers = {{{0, 0}, 1}};
    s.balls = {{{-5, 0}, {4, 0}, 0.5}};
    s.checks = {Check::penetration};
    const RenderResult r = render_run(s, KernelId::robust);
    ASSERT_FALSE(r.failure);
    // The bumper: one solid circle; the disc: a dashed outline where it starts, bounces and ends, half the
    // bumper's radius in the picture; the bump marked as a hit is.
    EXPECT_EQ(count(r.svg, "fill=\"#8c564b\""), 1);
    EXPECT_EQ(count(r.svg, "stroke-dasharray=\"4 3\""), 3);
    const double bumper = circle_radius_with(r.svg, "fill=\"#8c564b\"");
    const double disc = circle_radius_with(r.svg, "stroke-dasharray=\"4 3\"");
    ASSERT_GT(bumper, 0);
    EXPECT_NEAR(disc / bumper, 0.5, 1e-3);
    EXPECT_EQ(count(r.svg, "r=\"3\" fill=\"#1f77b4\""), 1);
    // A point ball draws no outline.
    s.balls[0].r = 0;
    EXPECT_EQ(count(render_run(s, KernelId::robust).svg, "stroke-dasharray"), 0);
}

TEST(RenderRun, ThePointBudgetCutsLongPathsAndSaysSo) {
    Scene s;
    s.frames = 100;
    s.balls = {{{0, 0}, {1, 0}}, {{0, 1}, {1, 0}}};
    RenderOptions o;
    o.max_points = 20;  // 10 per ball
    const RenderResult r = render_run(s, KernelId::robust, o);
    EXPECT_TRUE(has(r.svg, "2 path(s) end after their first 10 points (--max-points 20 shared by the balls drawn)"))
        << r.svg;
    EXPECT_EQ(polyline_after(r.svg, "stroke=\"#1f77b4\"").size(), 10u);
}

// The hook render_run stops the run with: asked after every frame, 0 included, with the checks done.
TEST(RunCheckedStop, StopAfterEndsTheRunAfterThatFrameWithTheSameEventsAndHash) {
    Scene s;
    s.frames = 10;
    s.walls = {{{5, -1}, {5, 1}}};
    s.balls = {{{1, 0}, {1, 0}}};
    s.checks = {Check::no_tunnel, Check::speed};
    std::vector<std::int64_t> asked;
    std::size_t frames_seen = 0;
    CheckOptions o;
    o.on_frame = [&](std::span<const Event>) { ++frames_seen; };
    o.stop_after = [&](const CheckedRun& r) {
        asked.push_back(r.frames_run);
        return r.frames_run == 3;
    };
    const CheckedRun stopped = run_checked(s, KernelId::robust, s.frames, s.checks, o);
    EXPECT_EQ(stopped.frames_run, 3);
    EXPECT_EQ(asked, (std::vector<std::int64_t>{0, 1, 2, 3}));
    EXPECT_EQ(frames_seen, 4u);
    // The same as a run of 3 frames: events and hash.
    const CheckedRun three = run_checked(s, KernelId::robust, 3, s.checks);
    EXPECT_EQ(stopped.events, three.events);
    EXPECT_EQ(stopped.hash, three.hash);
    EXPECT_FALSE(stopped.failure);
    // Stopping at frame 0 steps nothing.
    o.stop_after = [](const CheckedRun&) { return true; };
    EXPECT_EQ(run_checked(s, KernelId::robust, s.frames, s.checks, o).frames_run, 0);
}

}  // namespace
}  // namespace ricochet
