// Render: the scene and its run as SVG (y up in the world, y down in SVG: sy = top − y), drawn from one
// pass over the run's events that keeps only what the picture shows.
#include "ricochet/render.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "ricochet/format.hpp"
#include "ricochet/line.hpp"
#include "ricochet/truth.hpp"
#include "ricochet/world.hpp"

namespace ricochet {

namespace {

constexpr std::array<const char*, 8> k_ball_colours = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd",
                                                       "#8c564b", "#e377c2", "#17becf", "#bcbd22"};
/// Padding around the whole scene, as a share of its larger span: the walls stay off the picture's edge.
constexpr double k_all_pad = 0.05;
/// Padding around the failing frame, as a share of its larger span: enough to see where the path came
/// from and went, little enough that the crossing stays large.
constexpr double k_failure_pad = 0.15;
/// Height of one caption line below the picture, in pixels.
constexpr double k_caption_line = 16;
/// Width of one character of the 12 px sans-serif text, a little over its average, in pixels.
constexpr double k_char_px = 7;
/// Balls drawn beyond this many get no label (the failing ball always does): 64 labels hide the paths.
constexpr std::size_t k_max_labels = 16;
/// In the failure view without --frames, the paths drawn are those of the failing frame and this many frames
/// either side: on a long run the ball's other passes through the view would bury the failing piece.
constexpr std::int64_t k_context_frames = 2;
/// A failure whose own size (how far a piece crosses its wall, how far a disc reaches past one) is under this
/// many pixels of the view gets an inset at its own scale: below it the picture cannot show it.
constexpr double k_visible_px = 2;
/// The inset's side in pixels, and how many of the failure's own sizes its half-side spans.
constexpr double k_inset_px = 240;
constexpr double k_inset_spans = 4;

/// An axis-aligned box in the world; empty until a point is added (add() sets x and y together, and a box
/// written out is never inverted, so x alone tells).
struct Box {
    double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
    bool empty() const { return !(x0 <= x1); }
    void add(Vec2 p) {
        // Degenerate: a non-finite point (a lecture kernel's NaN or overflow) bounds nothing.
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
        x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
    void add(const Box& b) {
        if (!b.empty()) add(Vec2{b.x0, b.y0}), add(Vec2{b.x1, b.y1});
    }
    bool holds(Vec2 p) const { return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1; }
    /// Whether b (not empty) shares a point with this box.
    bool meets(const Box& b) const { return b.x0 <= x1 && b.x1 >= x0 && b.y0 <= y1 && b.y1 >= y0; }
    double span() const { return std::max(x1 - x0, y1 - y0); }
};

/// World → picture: sx = (x − x0)·scale + margin, sy = (y1 − y)·scale + margin.
struct View {
    double x0 = 0, y0 = 0, x1 = 1, y1 = 1, scale = 1, margin = 40;
    double sx(double x) const { return (x - x0) * scale + margin; }
    double sy(double y) const { return (y1 - y) * scale + margin; }
};

/// The part of segment a → b inside box c (Liang–Barsky: a + t·d for t in [t0, t1], each edge a bound
/// p·t ≤ q), or nothing. Ends that need no cut are returned as given, bit for bit.
std::optional<std::pair<Vec2, Vec2>> clip(Vec2 a, Vec2 b, const Box& c) {
    // Degenerate: a segment with a non-finite end is not a segment.
    if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(b.x) || !std::isfinite(b.y)) return std::nullopt;
    const Vec2 d = b - a;
    double t0 = 0, t1 = 1;
    const auto edge = [&](double p, double q) {
        if (p == 0) return q >= 0;
        const double r = q / p;
        if (p < 0) {
            if (r > t1) return false;
            t0 = std::max(t0, r);
        } else {
            if (r < t0) return false;
            t1 = std::min(t1, r);
        }
        return true;
    };
    if (!edge(-d.x, a.x - c.x0) || !edge(d.x, c.x1 - a.x) || !edge(-d.y, a.y - c.y0) || !edge(d.y, c.y1 - a.y))
        return std::nullopt;
    return std::pair{t0 == 0 ? a : a + t0 * d, t1 == 1 ? b : a + t1 * d};
}

/// Where the piece from → to meets the line of wall w: with e = P1 − P0 and d = to − from,
/// cross(e, from + s·d − P0) = 0  ⇒  s = cross(e, P0 − from) / cross(e, d), kept in [0, 1].
Vec2 crossing_point(const FailurePiece& piece, const Wall& w) {
    const Vec2 e = w.p1 - w.p0, d = piece.to - piece.from;
    const double den = cross(e, d);
    // Degenerate: a piece along the wall's line (or of zero length) meets it where it starts.
    if (!(den != 0)) return piece.from;
    const double s = cross(e, w.p0 - piece.from) / den;
    // Degenerate: an overflowing quotient says nothing; the piece's start is still on the path.
    if (!std::isfinite(s) || s <= 0) return piece.from;
    if (s >= 1) return piece.to;
    return piece.from + s * d;
}

/// One drawn ball's path over the frames drawn: its points in order, which of them are contacts (hits, bumps and
/// meets) and which of those meets, and whether points were left out at its end (the point budget).
struct Path {
    std::uint32_t ball = 0;
    std::vector<Vec2> points;
    std::vector<bool> hit;
    std::vector<bool> meet;
    std::vector<std::int64_t> frame;  ///< the frame of each point
    bool cut = false;

    void push(Vec2 p, Event::Kind kind, std::int64_t f) {
        points.push_back(p);
        hit.push_back(kind != Event::Kind::state);
        meet.push_back(kind == Event::Kind::meet);
        frame.push_back(f);
    }
    /// Drops the points of the frames before f, and f's contacts (they lie before its state, where the path starts).
    void keep_from(std::int64_t f) {
        std::size_t n = 0;
        while (n < points.size() && (frame[n] < f || (frame[n] == f && hit[n]))) ++n;
        points.erase(points.begin(), points.begin() + static_cast<std::ptrdiff_t>(n));
        hit.erase(hit.begin(), hit.begin() + static_cast<std::ptrdiff_t>(n));
        meet.erase(meet.begin(), meet.begin() + static_cast<std::ptrdiff_t>(n));
        frame.erase(frame.begin(), frame.begin() + static_cast<std::ptrdiff_t>(n));
    }
};

/// What a failure was against, when the check names no piece: the obstacle the failing piece is not clear of, as
/// `penetration` names it (CheckFailure::against).
struct Obstacle {
    bool wall = true;          ///< a wall, else a bumper
    std::uint32_t index = 0;   ///< the wall's or the bumper's index
    Vec2 from, to;             ///< the piece that came too close to it
};

/// The failing frame: the failing ball's path in it (from its state before the frame), the walls it hit
/// there, and where the mark goes.
struct FailingFrame {
    std::vector<Vec2> points;
    std::vector<std::uint32_t> walls;  ///< walls hit in the frame, and the wall a no-tunnel piece went through
    std::optional<Vec2> mark;          ///< the crossing on the wall, else the ball's state at the frame's end
    std::optional<std::uint32_t> crossed;  ///< the wall the mark is on, for a no-tunnel piece
    std::optional<FailurePiece> piece;     ///< the no-tunnel piece through `crossed`
    std::optional<Obstacle> against;       ///< what a disc's failing piece reached into (`penetration`)
    double radius = 0;                     ///< the failing ball's radius
};

/// The point of segment a → b nearest q (in double: for where to look, not for a verdict).
Vec2 nearest_on(Vec2 a, Vec2 b, Vec2 q) {
    const Vec2 d = b - a;
    const double dd = dot(d, d);
    // Degenerate: a zero-length segment is its point.
    if (!(dd > 0)) return a;
    const double t = std::clamp(dot(q - a, d) / dd, 0.0, 1.0);
    return a + t * d;
}

/// The point of piece a → b nearest wall w's segment (in double, for where to look): the least distance between
/// two segments is where they cross, or from an end of one to the other.
Vec2 nearest_to_wall(Vec2 a, Vec2 b, const Wall& w) {
    const Vec2 e = w.p1 - w.p0;
    const double sa = cross(e, a - w.p0), sb = cross(e, b - w.p0);
    std::vector<Vec2> candidates = {a, b, nearest_on(a, b, w.p0), nearest_on(a, b, w.p1)};
    // cross(e, a + s·(b − a) − P0) = 0  ⇒  s = sa / (sa − sb).
    if ((sa < 0) != (sb < 0) && sa != sb) candidates.push_back(a + (sa / (sa - sb)) * (b - a));
    Vec2 best = a;
    double least = std::numeric_limits<double>::infinity();
    for (Vec2 c : candidates)
        if (const double d = length_squared(c - nearest_on(w.p0, w.p1, c)); d < least) least = d, best = c;
    return best;
}

/// The balls whose paths are drawn: the first max by index; the failing ball takes the last place when
/// it is not among them.
std::vector<std::uint32_t> drawn_balls(std::size_t balls, std::uint32_t max, std::optional<std::uint32_t> failing) {
    std::vector<std::uint32_t> drawn;
    const std::size_t n = std::min<std::size_t>(balls, std::max<std::uint32_t>(max, 1));
    for (std::uint32_t b = 0; b < n; ++b) drawn.push_back(b);
    if (failing && *failing < balls && *failing >= n) drawn.back() = *failing;
    return drawn;
}

/// Keeps, frame by frame, the points of the drawn balls in frames first..last and the frame before the
/// current one's positions of every ball (so the failing frame's path can start where it did): memory
/// in the drawn points and the balls, not in the events.
class Recorder {
public:
    Recorder(const Scene& scene, std::int64_t first, std::int64_t last, std::vector<std::uint32_t> drawn,
             std::uint32_t max_points)
        : scene_(scene), first_(first), last_(last), slot_(scene.balls.size(), -1) {
        for (const Ball& b : scene.balls) before_.push_back(b.pos);
        for (std::uint32_t b : drawn) {
            slot_[b] = static_cast<std::int32_t>(paths_.size());
            paths_.push_back({b, {}, {}, {}, {}, false});
        }
        recent_ = paths_;
        // Degenerate: no ball drawn leaves the budget unshared.
        budget_ = std::max<std::size_t>(1, max_points / std::max<std::size_t>(1, drawn.size()));
    }

    /// One frame's events, in the run's order.
    void add_frame(std::span<const Event> events) {
        // The states of the frame before become where this frame starts.
        for (const Event& e : current_)
            if (e.kind == Event::Kind::state && e.ball < before_.size()) before_[e.ball] = e.pos;
        current_.assign(events.begin(), events.end());
        if (events.empty()) return;
        const std::int64_t f = events.front().frame;
        current_frame_ = f;
        // The frames around the failing frame (k_context_frames): the last ones until a failure is found, then
        // the ones after it; a few frames of the balls drawn, outside the point budget.
        if (!window_ || f <= window_->second) {
            for (const Event& e : events) {
                if (e.kind == Event::Kind::overlap || e.ball >= slot_.size() || slot_[e.ball] < 0) continue;
                recent_[static_cast<std::size_t>(slot_[e.ball])].push(e.pos, e.kind, f);
            }
            if (!window_)
                for (Path& p : recent_) p.keep_from(f - k_context_frames);
        }
        if (f < first_ || f > last_) return;
        for (const Event& e : events) {
            if (e.kind == Event::Kind::overlap || e.ball >= slot_.size() || slot_[e.ball] < 0) continue;
            // The first frame's hits, bumps and meets lie before its state, where the path starts.
            if (f == first_ && e.kind != Event::Kind::state) continue;
            Path& p = paths_[static_cast<std::size_t>(slot_[e.ball])];
            if (p.points.size() >= budget_) {
                p.cut = true;
                continue;
            }
            p.push(e.pos, e.kind, f);
        }
    }

    /// Fixes the frames around frame f (the failing one, the last added) whose paths the failure view draws.
    void open_window(std::int64_t f) {
        if (window_) return;
        window_ = std::pair{std::max<std::int64_t>(0, f - k_context_frames), f + k_context_frames};
        for (Path& p : recent_) p.keep_from(window_->first);
    }

    /// The failure found in the frame last added (nothing is kept when that frame had no events, as in a
    /// scene without balls).
    void note_failure(const CheckFailure& failure) {
        if (current_frame_ != failure.frame) return;
        FailingFrame ff;
        if (failure.frame > 0 && failure.ball < before_.size()) ff.points.push_back(before_[failure.ball]);
        for (const Event& e : current_) {
            if (e.ball != failure.ball || e.kind == Event::Kind::overlap) continue;
            ff.points.push_back(e.pos);
            if (e.kind == Event::Kind::hit) ff.walls.push_back(e.index);
            else ff.mark = e.pos;
        }
        if (failure.piece && failure.piece->wall < scene_.walls.size()) {
            ff.mark = crossing_point(*failure.piece, scene_.walls[failure.piece->wall]);
            ff.walls.push_back(failure.piece->wall);
            ff.crossed = failure.piece->wall;
            ff.piece = failure.piece;
        }
        if (failure.ball < scene_.balls.size()) ff.radius = scene_.balls[failure.ball].r;
        // A disc that reached into a wall or a bumper it was clear of: the view shows that obstacle, as the check
        // names it (one the disc started within reach of does not count until a printed point is clear of it), with
        // the disc; the mark goes where the piece comes nearest it.
        if (failure.check == Check::penetration && ff.radius > 0 && failure.against &&
            failure.against->index < (failure.against->bumper ? scene_.bumpers.size() : scene_.walls.size())) {
            const FailureObstacle& a = *failure.against;
            ff.against = Obstacle{!a.bumper, a.index, a.from, a.to};
            if (!a.bumper) {
                ff.walls.push_back(a.index);
                ff.mark = nearest_to_wall(a.from, a.to, scene_.walls[a.index]);
            } else {
                ff.mark = nearest_on(a.from, a.to, scene_.bumpers[a.index].c);
            }
        }
        failing_ = std::move(ff);
        open_window(failure.frame);
    }

    /// Path i, moved out.
    Path take_path(std::size_t i) { return std::move(paths_[i]); }

    /// Path i around the failing frame, moved out.
    Path take_window_path(std::size_t i) { return std::move(recent_[i]); }

    /// Draws path (ball b's) in place of the last ball drawn (there is one: the scene has a ball b), and window
    /// as its frames around the failing frame.
    void replace_last(Path path, Path window, std::uint32_t b) {
        slot_[paths_.back().ball] = -1;
        path.ball = b;
        window.ball = b;
        paths_.back() = std::move(path);
        recent_.back() = std::move(window);
        slot_[b] = static_cast<std::int32_t>(paths_.size() - 1);
    }

    /// Whether ball b (a ball of the scene) has its path drawn.
    bool draws(std::uint32_t b) const { return slot_[b] >= 0; }

    const std::vector<Path>& paths() const { return paths_; }
    /// The drawn balls' paths in the frames around the failing frame (window()), once it is found.
    const std::vector<Path>& window_paths() const { return recent_; }
    /// The frames window_paths() cover, once a failure opened them.
    const std::optional<std::pair<std::int64_t, std::int64_t>>& window() const { return window_; }
    const std::optional<FailingFrame>& failing() const { return failing_; }
    std::size_t budget() const { return budget_; }

private:
    const Scene& scene_;
    std::int64_t first_, last_;
    std::vector<std::int32_t> slot_;  ///< ball → its place in paths_, −1 if not drawn
    std::vector<Path> paths_;
    std::vector<Path> recent_;        ///< the drawn balls' last frames, then the frames around the failing one
    std::optional<std::pair<std::int64_t, std::int64_t>> window_;  ///< the frames around the failing one
    std::vector<Vec2> before_;        ///< every ball's position before the current frame
    std::vector<Event> current_;      ///< the frame last added
    std::optional<std::int64_t> current_frame_;
    std::optional<FailingFrame> failing_;
    std::size_t budget_ = 0;
};

std::string xml_escaped(std::string_view text) {
    std::string escaped;
    for (char ch : text) {
        if (ch == '<') escaped += "&lt;";
        else if (ch == '>') escaped += "&gt;";
        else if (ch == '&') escaped += "&amp;";
        else escaped += ch;
    }
    return escaped;
}

/// Writes a path as polylines through the picture, split where it leaves the clip box.
void draw_polyline(std::string& out, const std::vector<Vec2>& points, const View& v, const Box& clip_box,
                   std::string_view style) {
    std::string run;
    std::size_t in_run = 0;
    const auto flush = [&] {
        if (in_run > 0) fmt::format_to(std::back_inserter(out), "<polyline points=\"{}\" {}/>\n", run, style);
        run.clear();
        in_run = 0;
    };
    const auto put = [&](Vec2 p) {
        fmt::format_to(std::back_inserter(run), "{:.3f},{:.3f} ", v.sx(p.x), v.sy(p.y));
        ++in_run;
    };
    if (points.size() == 1) {
        if (clip_box.holds(points[0])) put(points[0]);
        flush();
        return;
    }
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        const auto c = clip(points[i], points[i + 1], clip_box);
        if (!c) {
            flush();
            continue;
        }
        if (c->first != points[i]) flush();
        if (in_run == 0) put(c->first);
        put(c->second);
        if (c->second != points[i + 1]) flush();
    }
    flush();
}

}  // namespace

namespace {

/// A double-double: hi + lo, |lo| ≤ ulp(hi)/2, for the few sums and products the inset needs past a double's
/// precision (Dekker and Knuth's error-free transformations; std::fma gives a product's exact error).
struct DD {
    double hi = 0, lo = 0;
};
DD two_sum(double a, double b) {
    const double s = a + b, bb = s - a;
    return {s, (a - (s - bb)) + (b - bb)};
}
DD dd_add(DD a, DD b) {
    const DD s = two_sum(a.hi, b.hi);
    return two_sum(s.hi, s.lo + a.lo + b.lo);
}
DD dd_neg(DD a) { return {-a.hi, -a.lo}; }
DD dd_mul(DD a, DD b) {
    const double p = a.hi * b.hi;
    return two_sum(p, std::fma(a.hi, b.hi, -p) + a.hi * b.lo + a.lo * b.hi);
}

/// BC = n·(p − P0), n = (e_y, −e_x), e = P1 − P0, in double-double: p's side of w's line and, over |n|, its
/// distance, to about 2^−100 of the terms (the differences are exact, the products carry their errors).
DD boundary_dd(Vec2 p, const Wall& w) {
    const DD ex = two_sum(w.p1.x, -w.p0.x), ey = two_sum(w.p1.y, -w.p0.y);
    const DD dx = two_sum(p.x, -w.p0.x), dy = two_sum(p.y, -w.p0.y);
    return dd_add(dd_mul(ey, dx), dd_neg(dd_mul(ex, dy)));
}

/// |n|² = e·e in double-double.
DD normal_squared_dd(const Wall& w) {
    const DD ex = two_sum(w.p1.x, -w.p0.x), ey = two_sum(w.p1.y, -w.p0.y);
    return dd_add(dd_mul(ex, ex), dd_mul(ey, ey));
}

/// The failure drawn again at its own scale, in coordinates local to it (x along the wall, y across it, the
/// origin on the wall's line): what the view's scale cannot show.
struct Inset {
    double half = 0;                 ///< the half-side in world units: the inset shows [−half, half]²
    double size = 0;                 ///< the failure's own size: how far past the wall, in world units
    std::pair<Vec2, Vec2> wall;      ///< the wall's part along y = 0 (its ends, clipped later)
    std::vector<Vec2> path;          ///< the failing piece (red), or the disc's edge near the wall (dashed)
    bool disc = false;               ///< path is a disc's edge, not the ball's path
    Vec2 mark;                       ///< where the failure is, in the inset
    std::uint32_t wall_index = 0;
};

/// The inset of a failure too small for a view of scale px per world unit: a no-tunnel piece whose nearer end
/// lies less than k_visible_px across its wall's line, or a disc reaching less than that past a wall it
/// penetrated. Nothing when the failure shows at that scale, or is of another kind.
std::optional<Inset> make_inset(const Scene& scene, const FailingFrame& f, double px) {
    Inset in;
    Vec2 p, q;          // the piece's end nearer the line, and its other end (no-tunnel); the nearest point (disc)
    double bc_over_n;   // p's signed distance from the line
    const Wall* wall = nullptr;
    if (f.piece && f.crossed && *f.crossed < scene.walls.size()) {
        wall = &scene.walls[*f.crossed];
        in.wall_index = *f.crossed;
        const int sf = truth::side(f.piece->from, *wall), st = truth::side(f.piece->to, *wall);
        // Degenerate: ends on one side, or both on the line: no crossing to show.
        if (sf == st) return std::nullopt;
        const double n = std::hypot(wall->p1.x - wall->p0.x, wall->p1.y - wall->p0.y);
        const DD bf = boundary_dd(f.piece->from, *wall), bt = boundary_dd(f.piece->to, *wall);
        const double df = (bf.hi + bf.lo) / n, dt = (bt.hi + bt.lo) / n;
        const bool from_nearer = std::fabs(df) <= std::fabs(dt);
        p = from_nearer ? f.piece->from : f.piece->to;
        q = from_nearer ? f.piece->to : f.piece->from;
        bc_over_n = from_nearer ? df : dt;
        in.size = std::fabs(bc_over_n);
        // Degenerate: an end exactly on the line (the crossing is the next piece's), or past the precision here.
        if (!(in.size > 0)) return std::nullopt;
    } else if (f.against && f.against->wall && f.against->index < scene.walls.size() && f.radius > 0) {
        wall = &scene.walls[f.against->index];
        in.wall_index = f.against->index;
        p = nearest_to_wall(f.against->from, f.against->to, *wall);
        const Vec2 e = wall->p1 - wall->p0;
        // Degenerate: the disc nearest an end of the wall, not its line: the view shows it.
        if (const double t = dot(p - wall->p0, e); !(t >= 0 && t <= dot(e, e))) return std::nullopt;
        // How far the disc reaches past the line: δ = R − |BC|/|n| = (R²·|n|² − BC²) / (|n|²·(R + |BC|/|n|)),
        // the numerator in double-double so that a sub-ulp δ is not lost to cancellation.
        const DD bc = boundary_dd(p, *wall), nn = normal_squared_dd(*wall);
        const DD r2 = dd_mul(two_sum(f.radius, 0), two_sum(f.radius, 0));
        const DD num = dd_add(dd_mul(r2, nn), dd_neg(dd_mul(bc, bc)));
        bc_over_n = (bc.hi + bc.lo) / std::sqrt(nn.hi);
        in.size = (num.hi + num.lo) / (nn.hi * (f.radius + std::fabs(bc_over_n)));
        in.disc = true;
        // Degenerate: clear of the line in double after all (the check's exact verdict is about the segment).
        if (!(in.size > 0)) return std::nullopt;
    } else {
        return std::nullopt;
    }
    if (in.size * px >= k_visible_px) return std::nullopt;
    in.half = k_inset_spans * in.size;
    // The local frame: x along ê, y along n̂, both turned half a turn when p is inside, so that p is at +y.
    const Vec2 e = wall->p1 - wall->p0;
    const double len = std::hypot(e.x, e.y);
    const double turn = bc_over_n < 0 ? -1.0 : 1.0;
    const Vec2 ex = (turn / len) * e, ny = (turn / len) * Vec2{e.y, -e.x};
    const double py = std::fabs(bc_over_n);
    const auto local = [&](Vec2 w) { return Vec2{dot(w - p, ex), py + dot(w - p, ny)}; };
    // Far ends are cut here, not by clip(): a + t·d from an end far off the inset would carry that end's
    // rounding, as large as the inset itself. Along y = 0 the wall's part is its ends' x limited to the inset.
    const double wa = dot(wall->p0 - p, ex), wb = dot(wall->p1 - p, ex);
    in.wall = {Vec2{std::clamp(wa, -in.half, in.half), 0}, Vec2{std::clamp(wb, -in.half, in.half), 0}};
    if (!in.disc) {
        // The piece from its near end p, so that clip() cuts it from there: the far end only gives the direction.
        const Vec2 a = Vec2{0, py}, b = local(q);
        in.path = {a, b};
        // y = 0 on the piece a → b: s = a_y / (a_y − b_y).
        in.mark = a + (py / (py - b.y)) * (b - a);
    } else {
        // The disc's edge near the line: centre (0, py), radius R, y(x) = py − √(R² − x²) = −δ + x²/(R + √(R² − x²)).
        const double R = f.radius, reach = std::min(in.half, R);
        for (int i = -16; i <= 16; ++i) {
            const double x = reach * i / 16.0;
            in.path.push_back({x, -in.size + x * x / (R + std::sqrt(R * R - x * x))});
        }
        in.mark = Vec2{0, -in.size};
    }
    return in;
}

/// Draws inset in the square of k_inset_px whose top-left corner is (left, top) in the picture: a frame, the wall
/// along y = 0, the piece or the disc's edge, and a red cross at the failure. Coordinates are local (Inset), so
/// a crossing of 10^−17 near 10^15 is drawn as well as one near 0.
void draw_inset(std::string& out, const Inset& in, double left, double top) {
    auto it = std::back_inserter(out);
    const double scale = k_inset_px / (2 * in.half);
    // sx = (x + half)·scale + left, sy = (half − y)·scale + top, as a View with no margin.
    View v;
    v.x0 = -in.half - left / scale, v.x1 = in.half, v.y0 = -in.half, v.y1 = in.half + top / scale;
    v.scale = scale;
    v.margin = 0;
    const Box box{-in.half, -in.half, in.half, in.half};
    fmt::format_to(it,
                   "<g class=\"inset\"><rect x=\"{:.3f}\" y=\"{:.3f}\" width=\"{:.3f}\" height=\"{:.3f}\" fill=\"white\" "
                   "stroke=\"#888\"/>\n",
                   left, top, k_inset_px, k_inset_px);
    if (const auto seen = in.wall.first.x != in.wall.second.x ? clip(in.wall.first, in.wall.second, box) : std::nullopt)
        fmt::format_to(it,
                       "<line x1=\"{:.3f}\" y1=\"{:.3f}\" x2=\"{:.3f}\" y2=\"{:.3f}\" stroke=\"black\" stroke-width=\"2.5\"/>"
                       "<text x=\"{:.3f}\" y=\"{:.3f}\" fill=\"#555\">w{}</text>\n",
                       v.sx(seen->first.x), v.sy(seen->first.y), v.sx(seen->second.x), v.sy(seen->second.y),
                       v.sx(seen->first.x) + 4, v.sy(0) - 4, in.wall_index);
    draw_polyline(out, in.path, v, box,
                  in.disc ? "fill=\"none\" stroke=\"red\" stroke-width=\"1.5\" stroke-dasharray=\"6 3\""
                          : "fill=\"none\" stroke=\"red\" stroke-width=\"3\" stroke-opacity=\"0.5\"");
    const double cx = v.sx(in.mark.x), cy = v.sy(in.mark.y);
    fmt::format_to(it,
                   "<g class=\"inset-mark\" stroke=\"red\" stroke-width=\"2\"><line x1=\"{:.3f}\" y1=\"{:.3f}\" x2=\"{:.3f}\" y2=\"{:.3f}\"/>"
                   "<line x1=\"{:.3f}\" y1=\"{:.3f}\" x2=\"{:.3f}\" y2=\"{:.3f}\"/></g></g>\n",
                   cx - 6, cy - 6, cx + 6, cy + 6, cx - 6, cy + 6, cx + 6, cy - 6);
}

/// The picture of what a recorder kept.
std::string draw(const Scene& scene, const Recorder& rec, const std::optional<CheckFailure>& failure,
                 const RenderOptions& options, std::int64_t first, std::int64_t last) {
    // Bounds of everything drawn.
    Box all;
    for (const Wall& w : scene.walls) all.add(w.p0), all.add(w.p1);
    for (const Circle& c : scene.circles) all.add(Vec2{c.c.x - c.r, c.c.y - c.r}), all.add(Vec2{c.c.x + c.r, c.c.y + c.r});
    for (const Bumper& b : scene.bumpers) all.add(Vec2{b.c.x - b.r, b.c.y - b.r}), all.add(Vec2{b.c.x + b.r, b.c.y + b.r});
    for (const Rect& r : scene.rects) all.add(Vec2{r.left, r.bottom}), all.add(Vec2{r.right, r.top});
    for (const Path& p : rec.paths()) {
        // A disc's path takes its radius around each point it drew.
        const double R = p.ball < scene.balls.size() ? scene.balls[p.ball].r : 0.0;
        for (Vec2 q : p.points) all.add(Vec2{q.x - R, q.y - R}), all.add(Vec2{q.x + R, q.y + R});
    }
    const std::optional<FailingFrame>& failing = rec.failing();
    if (failing)
        for (Vec2 q : failing->points) all.add(q);

    // The failing frame's box: its path and mark, and the walls it met as far as they run near it
    // (a long wall would otherwise pull the view back out to the whole scene).
    Box near;
    if (options.view == RenderView::failure && failing) {
        // A disc is seen whole: its radius around each point of the failing frame.
        const double R = failing->radius;
        for (Vec2 q : failing->points) near.add(Vec2{q.x - R, q.y - R}), near.add(Vec2{q.x + R, q.y + R});
        if (failing->mark) near.add(*failing->mark);
        if (!near.empty()) {
            const double s = near.span();
            const Box reach{near.x0 - s, near.y0 - s, near.x1 + s, near.y1 + s};
            Box walls;
            for (std::uint32_t w : failing->walls)
                if (w < scene.walls.size())
                    if (auto c = clip(scene.walls[w].p0, scene.walls[w].p1, reach)) walls.add(c->first), walls.add(c->second);
            // A bumper the disc reached into, as far as it lies within reach.
            if (failing->against && !failing->against->wall && failing->against->index < scene.bumpers.size()) {
                const Bumper& k = scene.bumpers[failing->against->index];
                const Box in{std::max(k.c.x - k.r, reach.x0), std::max(k.c.y - k.r, reach.y0),
                             std::min(k.c.x + k.r, reach.x1), std::min(k.c.y + k.r, reach.y1)};
                if (in.x0 <= in.x1 && in.y0 <= in.y1) walls.add(in);
            }
            near.add(walls);
        }
        // Degenerate: a failing frame of one point (frame 0, a ball at rest) has no extent to frame.
        if (!(near.span() > 0)) near = Box{};
    }
    const bool framed = !near.empty();
    // The failing frame is seen at least as wide as it is tall: the picture keeps its width (and its
    // captions room), and the walls beside a steep path stay in view.
    if (framed && near.x1 - near.x0 < near.y1 - near.y0) {
        const double mid = 0.5 * near.x0 + 0.5 * near.x1, half = 0.5 * (near.y1 - near.y0);
        near.x0 = mid - half, near.x1 = mid + half;
    }
    Box b = framed ? near : all;
    if (b.empty()) b = Box{0, 0, 1, 1};
    // Degenerate: a scene of one point still gets a unit-sized picture around it. (Within the accepted
    // range, |x| <= 2^256, the span is finite.)
    double span = b.span();
    if (!(span > 0)) span = std::max(1.0, std::fabs(b.x0) * 1e-12);
    const double pad = span * (framed ? k_failure_pad : k_all_pad);
    View v;
    v.x0 = b.x0 - pad, v.x1 = b.x1 + pad, v.y0 = b.y0 - pad, v.y1 = b.y1 + pad;
    const double w_world = v.x1 - v.x0, h_world = v.y1 - v.y0;
    const double inner = options.width - 2 * v.margin;
    v.scale = inner / std::max(w_world, h_world);
    // What may be drawn: the picture's own extent in the world, margins included.
    const double m = v.margin / v.scale;
    const Box clip_box{v.x0 - m, v.y0 - m, v.x1 + m, v.y1 + m};
    // Normals are 4 % of the larger world span long, in picture units: far from the origin a world-sized
    // step would round away (at 1e15 the ulp is 0.125).
    const double normal_px = 0.04 * std::max(w_world, h_world) * v.scale;

    // Caption lines under the picture: what it shows, then what it leaves out.
    std::vector<std::string> caption;
    caption.push_back(fmt::format("kernel {}, frames {}..{}, x in [{}, {}], y in [{}, {}]", scene.kernel,
                                  first, last, b.x0, b.x1, b.y0, b.y1));
    if (framed)
        caption.push_back(fmt::format("view: the failing frame {} of ball {} (--view all shows the whole scene)",
                                      failure->frame, failure->ball));
    if (failing && failing->mark)
        caption.push_back(failing->crossed
                              ? fmt::format("marked at ({}, {}), where the piece crosses wall {}", failing->mark->x,
                                            failing->mark->y, *failing->crossed)
                          : failing->against
                              ? fmt::format("marked at ({}, {}), where the disc of radius {} comes nearest {} {}",
                                            failing->mark->x, failing->mark->y, failing->radius,
                                            failing->against->wall ? "wall" : "bumper", failing->against->index)
                              : fmt::format("marked at ({}, {}), the ball's state at the end of frame {}",
                                            failing->mark->x, failing->mark->y, failure->frame));
    // On a long run the ball's other passes through the view would bury the failing piece: without --frames the
    // failure view draws the frames around it.
    const auto& window = rec.window();
    const bool windowed = framed && !options.last_frame && options.first_frame == 0 && window &&
                          (window->first > first || window->second < last);
    const std::vector<Path>& drawn_paths = windowed ? rec.window_paths() : rec.paths();
    if (windowed)
        caption.push_back(fmt::format("paths of frames {}..{} only, around the failing frame (--frames A:B draws others)",
                                      window->first, std::min(window->second, last)));
    // A failure smaller than the view can show, drawn again at its own scale below the picture.
    const std::optional<Inset> inset = framed && failing ? make_inset(scene, *failing, v.scale) : std::nullopt;
    if (inset)
        caption.push_back(fmt::format("inset: {} {} past wall {}, enlarged {:.3g} times (1 px = {:.3g})",
                                      inset->disc ? "the disc reaches" : "the piece ends", inset->size,
                                      inset->wall_index, k_inset_px / (2 * inset->half) / v.scale,
                                      2 * inset->half / k_inset_px));
    const std::size_t drawn = rec.paths().size();
    if (drawn < scene.balls.size()) {
        const std::uint32_t lastb = rec.paths().back().ball;
        const bool swapped = lastb != drawn - 1;
        const std::string which = !swapped ? fmt::format("balls 0..{}", drawn - 1)
                                  : drawn >= 2 ? fmt::format("balls 0..{} and the failing ball {}", drawn - 2, lastb)
                                               : fmt::format("the failing ball {}", lastb);
        caption.push_back(fmt::format("paths of {} of {} balls drawn ({}), {} left out (--max-balls)", drawn,
                                      scene.balls.size(), which, scene.balls.size() - drawn));
    }
    std::size_t cut = 0;
    for (const Path& p : rec.paths()) cut += p.cut;
    if (cut > 0)
        caption.push_back(fmt::format("{} path(s) end after their first {} points (--max-points {} shared by the balls drawn)",
                                      cut, rec.budget(), options.max_points));

    const double width = w_world * v.scale + 2 * v.margin;
    // The inset sits under the picture, above the captions.
    const double inset_top = h_world * v.scale + 2 * v.margin;
    const double inset_block = inset ? k_inset_px + 10 : 0;
    const double height = h_world * v.scale + 2 * v.margin + inset_block + 30 +
                          k_caption_line * static_cast<double>(caption.size() - 1);
    std::string out;
    auto it = std::back_inserter(out);
    fmt::format_to(it,
                   "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" "
                   "viewBox=\"0 0 {:.0f} {:.0f}\" font-family=\"sans-serif\" font-size=\"12\">\n"
                   "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n",
                   width, height, width, height);
    for (std::size_t i = 0; i < caption.size(); ++i)
        fmt::format_to(it, "<text x=\"8\" y=\"{:.1f}\">{}</text>\n",
                       height - 10 - k_caption_line * static_cast<double>(caption.size() - 1 - i), caption[i]);
    // Statics first, so paths are drawn over them; each cut to the picture.
    for (std::size_t i = 0; i < scene.rects.size(); ++i) {
        const Rect& r = scene.rects[i];
        const double left = std::max(r.left, clip_box.x0), right = std::min(r.right, clip_box.x1);
        const double bottom = std::max(r.bottom, clip_box.y0), top = std::min(r.top, clip_box.y1);
        if (!(left <= right && bottom <= top)) continue;
        fmt::format_to(it,
                       "<rect x=\"{:.3f}\" y=\"{:.3f}\" width=\"{:.3f}\" height=\"{:.3f}\" fill=\"#2ca02c\" "
                       "fill-opacity=\"0.15\" stroke=\"#2ca02c\" stroke-width=\"1.5\"/>"
                       "<text x=\"{:.3f}\" y=\"{:.3f}\" fill=\"#2ca02c\">r{}</text>\n",
                       v.sx(left), v.sy(top), (right - left) * v.scale, (top - bottom) * v.scale, v.sx(left) + 3,
                       v.sy(top) + 13, i);
    }
    // A circle of the scene, centre c and radius r, in its style, labelled name (at least 1.5 px across).
    const auto round_shape = [&](Vec2 c, double r, std::string_view style, std::string_view ink, std::string_view name) {
        if (!clip_box.meets(Box{c.x - r, c.y - r, c.x + r, c.y + r})) return;
        fmt::format_to(it, "<circle cx=\"{:.3f}\" cy=\"{:.3f}\" r=\"{:.3f}\" {}/><text x=\"{:.3f}\" y=\"{:.3f}\" fill=\"{}\">{}</text>\n",
                       v.sx(c.x), v.sy(c.y), std::max(r * v.scale, 1.5), style, v.sx(c.x) + 3, v.sy(c.y) - 3, ink, name);
    };
    for (std::size_t i = 0; i < scene.circles.size(); ++i)
        round_shape(scene.circles[i].c, scene.circles[i].r,
                    "fill=\"#ff7f0e\" fill-opacity=\"0.15\" stroke=\"#ff7f0e\" stroke-width=\"1.5\"", "#ff7f0e",
                    fmt::format("c{}", i));
    // Bumpers: solid circles, darker than the sensors.
    for (std::size_t i = 0; i < scene.bumpers.size(); ++i)
        round_shape(scene.bumpers[i].c, scene.bumpers[i].r,
                    "fill=\"#8c564b\" fill-opacity=\"0.45\" stroke=\"#5c3a32\" stroke-width=\"2\"", "#5c3a32",
                    fmt::format("k{}", i));
    for (std::size_t i = 0; i < scene.walls.size(); ++i) {
        const Wall& w = scene.walls[i];
        const auto seen = clip(w.p0, w.p1, clip_box);
        if (!seen) continue;
        const auto [a, z] = *seen;
        fmt::format_to(it,
                       "<line x1=\"{:.3f}\" y1=\"{:.3f}\" x2=\"{:.3f}\" y2=\"{:.3f}\" stroke=\"black\" stroke-width=\"2.5\" "
                       "stroke-linecap=\"round\"/>\n",
                       v.sx(a.x), v.sy(a.y), v.sx(z.x), v.sy(z.y));
        // The outward normal n̂ = (e_y, −e_x)/|e| drawn from the midpoint of the part shown; P0 marked by a
        // small square where it is shown.
        const Vec2 n = unit_normal(w);
        // (y up in the world is y down in the picture: the tip is mid + len·(n̂x, −n̂y).)
        const double mx = 0.5 * (v.sx(a.x) + v.sx(z.x)), my = 0.5 * (v.sy(a.y) + v.sy(z.y));
        const double tx = mx + normal_px * n.x, ty = my - normal_px * n.y;
        if (n != Vec2{})
            fmt::format_to(it,
                           "<line x1=\"{:.3f}\" y1=\"{:.3f}\" x2=\"{:.3f}\" y2=\"{:.3f}\" stroke=\"#888\" stroke-width=\"1.2\"/>"
                           "<circle cx=\"{:.3f}\" cy=\"{:.3f}\" r=\"2\" fill=\"#888\"/>\n",
                           mx, my, tx, ty, tx, ty);
        if (a == w.p0) fmt::format_to(it, "<rect x=\"{:.3f}\" y=\"{:.3f}\" width=\"4\" height=\"4\" fill=\"black\"/>",
                                      v.sx(w.p0.x) - 2, v.sy(w.p0.y) - 2);
        fmt::format_to(it, "<text x=\"{:.3f}\" y=\"{:.3f}\" fill=\"#555\">w{}</text>\n", tx + 4, ty + 4, i);
    }
    // Ball paths: the state at the first frame, then each frame's hits and its state.
    for (const Path& p : drawn_paths) {
        if (p.points.empty()) continue;
        const char* colour = k_ball_colours[p.ball % k_ball_colours.size()];
        draw_polyline(out, p.points, v, clip_box,
                      fmt::format("fill=\"none\" stroke=\"{}\" stroke-width=\"1.5\"", colour));
        // A hit or a bump: a dot; a meet with another ball: a ring.
        for (std::size_t i = 0; i < p.points.size(); ++i) {
            if (!p.hit[i] || !clip_box.holds(p.points[i])) continue;
            const double cx = v.sx(p.points[i].x), cy = v.sy(p.points[i].y);
            if (p.meet[i])
                fmt::format_to(it,
                               "<circle cx=\"{:.3f}\" cy=\"{:.3f}\" r=\"4\" fill=\"white\" stroke=\"{}\" "
                               "stroke-width=\"2\"/>\n",
                               cx, cy, colour);
            else
                fmt::format_to(it, "<circle cx=\"{:.3f}\" cy=\"{:.3f}\" r=\"3\" fill=\"{}\"/>\n", cx, cy, colour);
        }
        const Vec2 start = p.points.front(), end = p.points.back();
        // A disc at its size where the path starts, bounces and ends: dashed outlines around its centre.
        const double R = p.ball < scene.balls.size() ? scene.balls[p.ball].r : 0.0;
        if (R > 0.0)
            for (std::size_t i = 0; i < p.points.size(); ++i) {
                const Vec2 c = p.points[i];
                const bool shown = i == 0 || i + 1 == p.points.size() || p.hit[i];
                if (!shown || !clip_box.meets(Box{c.x - R, c.y - R, c.x + R, c.y + R})) continue;
                fmt::format_to(it,
                               "<circle cx=\"{:.3f}\" cy=\"{:.3f}\" r=\"{:.3f}\" fill=\"none\" stroke=\"{}\" "
                               "stroke-opacity=\"0.6\" stroke-dasharray=\"4 3\"/>\n",
                               v.sx(c.x), v.sy(c.y), R * v.scale, colour);
            }
        const bool label = drawn_paths.size() <= k_max_labels || (failure && failure->ball == p.ball);
        if (clip_box.holds(start)) {
            fmt::format_to(it,
                           "<circle cx=\"{:.3f}\" cy=\"{:.3f}\" r=\"5\" fill=\"white\" stroke=\"{}\" stroke-width=\"2\"/>",
                           v.sx(start.x), v.sy(start.y), colour);
            if (label)
                fmt::format_to(it, "<text x=\"{:.3f}\" y=\"{:.3f}\" fill=\"{}\">b{}</text>", v.sx(start.x) + 7,
                               v.sy(start.y) - 7, colour, p.ball);
            out += '\n';
        }
        if (clip_box.holds(end))
            fmt::format_to(it, "<circle cx=\"{:.3f}\" cy=\"{:.3f}\" r=\"5\" fill=\"{}\"/>\n", v.sx(end.x), v.sy(end.y),
                           colour);
    }
    // The failure: the failing frame's path drawn over the rest, and a red cross where it happened (on
    // the wall for a piece that went through one, else at the ball's state at the frame's end).
    if (failure) {
        if (failing && failing->points.size() > 1)
            draw_polyline(out, failing->points, v, clip_box,
                          "fill=\"none\" stroke=\"red\" stroke-width=\"3\" stroke-opacity=\"0.5\"");
        // A disc that reached into something: its outline, red, where it came nearest.
        if (failing && failing->against && failing->mark && failing->radius > 0)
            fmt::format_to(it,
                           "<circle cx=\"{:.3f}\" cy=\"{:.3f}\" r=\"{:.3f}\" fill=\"none\" stroke=\"red\" "
                           "stroke-width=\"1.5\" stroke-dasharray=\"6 3\"/>\n",
                           v.sx(failing->mark->x), v.sy(failing->mark->y), failing->radius * v.scale);
        if (failing && failing->mark && clip_box.holds(*failing->mark)) {
            const double cx = v.sx(failing->mark->x), cy = v.sy(failing->mark->y);
            fmt::format_to(it,
                           "<g stroke=\"red\" stroke-width=\"3\" data-x=\"{}\" data-y=\"{}\"><line x1=\"{:.3f}\" y1=\"{:.3f}\" x2=\"{:.3f}\" "
                           "y2=\"{:.3f}\"/><line x1=\"{:.3f}\" y1=\"{:.3f}\" x2=\"{:.3f}\" y2=\"{:.3f}\"/></g>\n",
                           failing->mark->x, failing->mark->y, cx - 9, cy - 9, cx + 9, cy + 9, cx - 9, cy + 9, cx + 9,
                           cy - 9);
        }
        // The message in at most two lines above the picture, broken at a space, cut with "..." when longer.
        const std::size_t per_line = std::max<std::size_t>(20, static_cast<std::size_t>((width - 16) / k_char_px));
        std::string text = failure->str();
        if (text.size() > 2 * per_line) text = text.substr(0, 2 * per_line - 3) + "...";
        std::string second;
        if (text.size() > per_line) {
            std::size_t at = text.rfind(' ', per_line);
            // (Never npos: str() starts "CHECK broke at", and a line holds at least 20 characters.)
            if (at == std::string::npos || at < per_line / 2) at = per_line;
            second = text.substr(at + (text[at] == ' ' ? 1 : 0));
            text.resize(at);
            if (second.size() > per_line) second = second.substr(0, per_line - 3) + "...";
        }
        // XML-escape the message: it quotes path pieces like "(0, 8) -> (-4, 9)".
        fmt::format_to(it, "<text x=\"8\" y=\"18\" fill=\"red\">{}</text>\n", xml_escaped(text));
        if (!second.empty()) fmt::format_to(it, "<text x=\"8\" y=\"32\" fill=\"red\">{}</text>\n", xml_escaped(second));
    }
    if (inset) draw_inset(out, *inset, v.margin, inset_top);
    out += "</svg>\n";
    return out;
}

}  // namespace

std::string render_svg(const Scene& scene, const CheckedRun& run, const RenderOptions& options) {
    const std::int64_t first = options.first_frame;
    const std::int64_t last = options.last_frame.value_or(run.frames_run);
    std::optional<std::uint32_t> failing_ball;
    if (run.failure) failing_ball = run.failure->ball;
    Recorder rec(scene, first, last, drawn_balls(scene.balls.size(), options.max_balls, failing_ball),
                 options.max_points);
    // The events come frame after frame: each frame is handed over whole, in one pass; the failing frame
    // is the first run of events with the failure's frame number.
    const std::span<const Event> events = run.events;
    bool noted = false;
    for (std::size_t at = 0; at < events.size();) {
        std::size_t end = at;
        while (end < events.size() && events[end].frame == events[at].frame) ++end;
        rec.add_frame(events.subspan(at, end - at));
        if (run.failure && !noted && run.failure->frame == events[at].frame) {
            rec.note_failure(*run.failure);
            noted = true;
        }
        at = end;
    }
    return draw(scene, rec, run.failure, options, first, last);
}

RenderResult render_run(const Scene& scene, KernelId kernel, const RenderOptions& options,
                        const RenderProgress& progress) {
    const std::int64_t first = options.first_frame;
    const std::int64_t last = std::min(options.last_frame.value_or(scene.frames), scene.frames);
    Recorder rec(scene, first, last, drawn_balls(scene.balls.size(), options.max_balls, std::nullopt),
                 options.max_points);
    bool noted = false;
    CheckOptions co;
    co.keep_events = false;
    co.on_frame = [&](std::span<const Event> events) { rec.add_frame(events); };
    co.stop_after = [&](const CheckedRun& r) {
        if (r.failure && !noted) {
            rec.note_failure(*r.failure);
            noted = true;
        }
        if (progress) progress(r.frames_run, scene.frames);
        // Past the last frame drawn the run goes on only to find the first failure.
        return r.frames_run >= last && (r.failure || options.view == RenderView::all);
    };
    const CheckedRun run = run_checked(scene, kernel, scene.frames, scene.checks, co);
    RenderResult result;
    result.frames_run = run.frames_run;
    result.failure = run.failure;
    result.error = run.error;
    // A failure of the scene's statics (oracle at frame 0, round-trip) names ball 0 even with no balls.
    const bool of_a_ball = run.failure && run.failure->ball < scene.balls.size();
    if (of_a_ball && !rec.draws(run.failure->ball)) {
        // The failing ball was not known while its path went by: step it again alone, without checks and
        // as run_checked's World did (CheckOptions' default WorldOptions), and draw it in place of the
        // last ball drawn. The same bits: balls that do not meet are independent and options change no event (world.hpp).
        const std::uint32_t failing = run.failure->ball;
        // Balls that meet are not independent: then every ball is stepped again and the failing one drawn.
        const bool together = scene.balls_collide;
        Scene alone = scene;
        if (!together) {
            alone.balls = {scene.balls[failing]};
            if (!scene.masses.empty()) alone.masses = {scene.masses[failing]};
        }
        Recorder solo(alone, first, last, {together ? failing : 0u}, static_cast<std::uint32_t>(rec.budget()));
        World world(alone, kernel, CheckOptions{}.world);
        std::vector<Event> events;
        world.start(events);
        solo.add_frame(events);
        if (run.failure->frame == 0) solo.open_window(0);
        // As far as the frames drawn, and the frames around the failing one.
        const std::int64_t to = std::min(std::max(last, run.failure->frame + k_context_frames), run.frames_run);
        for (std::int64_t f = 1; f <= to; ++f) {
            events.clear();
            // (A guard no input reaches: these frames stepped without error in the run, the same bits alone.)
            if (world.step(events)) break;
            solo.add_frame(events);
            if (f == run.failure->frame) solo.open_window(f);
        }
        rec.replace_last(solo.take_path(0), solo.take_window_path(0), failing);
    }
    result.svg = draw(scene, rec, run.failure, options, first, options.last_frame.value_or(run.frames_run));
    return result;
}

}  // namespace ricochet
