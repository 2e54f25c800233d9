// Render: the scene and its run as SVG (y up in the world, y down in SVG: sy = top − y).
#include "ricochet/render.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "ricochet/format.hpp"

namespace ricochet {

namespace {

constexpr std::array<const char*, 8> k_ball_colours = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                                       "#8c564b", "#e377c2", "#17becf", "#bcbd22"};

/// World → picture: sx = (x − x0)·scale + margin, sy = (y1 − y)·scale + margin.
struct View {
    double x0 = 0, y0 = 0, x1 = 1, y1 = 1, scale = 1, margin = 40;
    double sx(double x) const { return (x - x0) * scale + margin; }
    double sy(double y) const { return (y1 - y) * scale + margin; }
};

void grow(double& lo, double& hi, double v) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
}

}  // namespace

std::string render_svg(const Scene& scene, const CheckedRun& run, const RenderOptions& options) {
    const std::int64_t first = options.first_frame;
    const std::int64_t last = options.last_frame.value_or(run.frames_run);
    const auto in_frames = [&](std::int64_t f) { return f >= first && f <= last; };

    // Bounds of everything drawn.
    double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
    for (const Wall& w : scene.walls) {
        grow(x0, x1, w.p0.x), grow(x0, x1, w.p1.x), grow(y0, y1, w.p0.y), grow(y0, y1, w.p1.y);
    }
    for (const Circle& c : scene.circles) {
        grow(x0, x1, c.c.x - c.r), grow(x0, x1, c.c.x + c.r), grow(y0, y1, c.c.y - c.r), grow(y0, y1, c.c.y + c.r);
    }
    for (const Rect& r : scene.rects) {
        grow(x0, x1, r.left), grow(x0, x1, r.right), grow(y0, y1, r.bottom), grow(y0, y1, r.top);
    }
    for (const Event& e : run.events)
        if (e.kind != Event::Kind::overlap && in_frames(e.frame)) grow(x0, x1, e.pos.x), grow(y0, y1, e.pos.y);
    if (!(x0 <= x1)) x0 = 0, x1 = 1, y0 = 0, y1 = 1;
    // Degenerate: a scene of one point still gets a unit-sized picture around it. (Within the accepted
    // range, |x| <= 2^256, the span is finite.)
    double span = std::max(x1 - x0, y1 - y0);
    if (!(span > 0)) span = std::max(1.0, std::fabs(x0) * 1e-12);
    const double pad = span * 0.05;
    View v;
    v.x0 = x0 - pad, v.x1 = x1 + pad, v.y0 = y0 - pad, v.y1 = y1 + pad;
    const double w_world = v.x1 - v.x0, h_world = v.y1 - v.y0;
    const double inner = options.width - 2 * v.margin;
    v.scale = inner / std::max(w_world, h_world);
    const double width = w_world * v.scale + 2 * v.margin;
    const double height = h_world * v.scale + 2 * v.margin + 30;
    const double normal_len = 0.04 * std::max(w_world, h_world);

    std::string out;
    auto it = std::back_inserter(out);
    fmt::format_to(it,
                   "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" "
                   "viewBox=\"0 0 {:.0f} {:.0f}\" font-family=\"sans-serif\" font-size=\"12\">\n"
                   "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
                   width, height, width, height);
    fmt::format_to(it, "<text x=\"8\" y=\"{:.1f}\">kernel {}, frames {}..{}, x in [{:.6g}, {:.6g}], y in [{:.6g}, {:.6g}]</text>\n",
                   height - 10, scene.kernel, first, last, x0, x1, y0, y1);
    // Statics first, so paths are drawn over them.
    for (std::size_t i = 0; i < scene.rects.size(); ++i) {
        const Rect& r = scene.rects[i];
        fmt::format_to(it,
                       "<rect x=\"{:.3f}\" y=\"{:.3f}\" width=\"{:.3f}\" height=\"{:.3f}\" fill=\"#2ca02c\" "
                       "fill-opacity=\"0.15\" stroke=\"#2ca02c\" stroke-width=\"1.5\"/>"
                       "<text x=\"{:.3f}\" y=\"{:.3f}\" fill=\"#2ca02c\">r{}</text>\n",
                       v.sx(r.left), v.sy(r.top), (r.right - r.left) * v.scale, (r.top - r.bottom) * v.scale,
                       v.sx(r.left) + 3, v.sy(r.top) + 13, i);
    }
    for (std::size_t i = 0; i < scene.circles.size(); ++i) {
        const Circle& c = scene.circles[i];
        fmt::format_to(it,
                       "<circle cx=\"{:.3f}\" cy=\"{:.3f}\" r=\"{:.3f}\" fill=\"#ff7f0e\" fill-opacity=\"0.15\" "
                       "stroke=\"#ff7f0e\" stroke-width=\"1.5\"/><text x=\"{:.3f}\" y=\"{:.3f}\" fill=\"#ff7f0e\">c{}</text>\n",
                       v.sx(c.c.x), v.sy(c.c.y), std::max(c.r * v.scale, 1.5), v.sx(c.c.x) + 3, v.sy(c.c.y) - 3, i);
    }
    for (std::size_t i = 0; i < scene.walls.size(); ++i) {
        const Wall& w = scene.walls[i];
        fmt::format_to(it,
                       "<line x1=\"{:.3f}\" y1=\"{:.3f}\" x2=\"{:.3f}\" y2=\"{:.3f}\" stroke=\"black\" stroke-width=\"2.5\" "
                       "stroke-linecap=\"round\"/>\n",
                       v.sx(w.p0.x), v.sy(w.p0.y), v.sx(w.p1.x), v.sy(w.p1.y));
        // The outward normal n̂ = (e_y, −e_x)/|e| drawn from the midpoint; P0 marked by a small square.
        const Vec2 n = unit_normal(w);
        const Vec2 m = 0.5 * (w.p0 + w.p1);
        const Vec2 tip = m + normal_len * n;
        if (n != Vec2{})
            fmt::format_to(it,
                           "<line x1=\"{:.3f}\" y1=\"{:.3f}\" x2=\"{:.3f}\" y2=\"{:.3f}\" stroke=\"#888\" stroke-width=\"1.2\"/>"
                           "<circle cx=\"{:.3f}\" cy=\"{:.3f}\" r=\"2\" fill=\"#888\"/>\n",
                           v.sx(m.x), v.sy(m.y), v.sx(tip.x), v.sy(tip.y), v.sx(tip.x), v.sy(tip.y));
        fmt::format_to(it,
                       "<rect x=\"{:.3f}\" y=\"{:.3f}\" width=\"4\" height=\"4\" fill=\"black\"/>"
                       "<text x=\"{:.3f}\" y=\"{:.3f}\" fill=\"#555\">w{}</text>\n",
                       v.sx(w.p0.x) - 2, v.sy(w.p0.y) - 2, v.sx(tip.x) + 4, v.sy(tip.y) + 4, i);
    }
    // Ball paths: the state at the first frame, then each frame's hits and its state.
    for (std::size_t b = 0; b < scene.balls.size(); ++b) {
        const char* colour = k_ball_colours[b % k_ball_colours.size()];
        std::string points;
        std::vector<Vec2> hits;
        Vec2 start{}, end{};
        bool have = false;
        for (const Event& e : run.events) {
            if (e.ball != b || e.kind == Event::Kind::overlap || !in_frames(e.frame)) continue;
            if (e.frame == first && e.kind == Event::Kind::hit) continue;
            if (!have) start = e.pos;
            have = true;
            end = e.pos;
            fmt::format_to(std::back_inserter(points), "{:.3f},{:.3f} ", v.sx(e.pos.x), v.sy(e.pos.y));
            if (e.kind == Event::Kind::hit) hits.push_back(e.pos);
        }
        if (!have) continue;
        fmt::format_to(it, "<polyline points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"1.5\"/>\n", points,
                       colour);
        for (const Vec2& h : hits)
            fmt::format_to(it, "<circle cx=\"{:.3f}\" cy=\"{:.3f}\" r=\"3\" fill=\"{}\"/>\n", v.sx(h.x), v.sy(h.y),
                           colour);
        fmt::format_to(it,
                       "<circle cx=\"{:.3f}\" cy=\"{:.3f}\" r=\"5\" fill=\"white\" stroke=\"{}\" stroke-width=\"2\"/>"
                       "<text x=\"{:.3f}\" y=\"{:.3f}\" fill=\"{}\">b{}</text>\n"
                       "<circle cx=\"{:.3f}\" cy=\"{:.3f}\" r=\"5\" fill=\"{}\"/>\n",
                       v.sx(start.x), v.sy(start.y), colour, v.sx(start.x) + 7, v.sy(start.y) - 7, colour, b,
                       v.sx(end.x), v.sy(end.y), colour);
    }
    // The failure: a red cross at the failing ball's state in the failing frame.
    if (run.failure) {
        const CheckFailure& f = *run.failure;
        for (const Event& e : run.events)
            if (e.kind == Event::Kind::state && e.frame == f.frame && e.ball == f.ball) {
                const double cx = v.sx(e.pos.x), cy = v.sy(e.pos.y);
                fmt::format_to(it,
                               "<g stroke=\"red\" stroke-width=\"3\"><line x1=\"{:.3f}\" y1=\"{:.3f}\" x2=\"{:.3f}\" "
                               "y2=\"{:.3f}\"/><line x1=\"{:.3f}\" y1=\"{:.3f}\" x2=\"{:.3f}\" y2=\"{:.3f}\"/></g>\n",
                               cx - 9, cy - 9, cx + 9, cy + 9, cx - 9, cy + 9, cx + 9, cy - 9);
            }
        std::string text = f.str();
        if (text.size() > 140) text = text.substr(0, 137) + "...";
        // XML-escape the message: it quotes path pieces like "(0, 8) -> (-4, 9)".
        std::string escaped;
        for (char ch : text) {
            if (ch == '<') escaped += "&lt;";
            else if (ch == '>') escaped += "&gt;";
            else if (ch == '&') escaped += "&amp;";
            else escaped += ch;
        }
        fmt::format_to(it, "<text x=\"8\" y=\"18\" fill=\"red\">{}</text>\n", escaped);
    }
    out += "</svg>\n";
    return out;
}

}  // namespace ricochet
