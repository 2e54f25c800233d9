// The wall grid, the wall BVH and the static-shape index (grid.hpp states why each is conservative).
#include "ricochet/grid.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace ricochet {
namespace {

double max_abs(Vec2 p) { return std::max(std::fabs(p.x), std::fabs(p.y)); }

bool finite(Vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

/// Keeps the first occurrence of each value in out[base..], in order; sorts when there are many.
void dedupe_tail(std::vector<std::uint32_t>& out, std::size_t base) {
    const std::size_t n = out.size() - base;
    if (n < 2) return;
    if (n <= 48) {
        // Few candidates (the usual case): a quadratic scan beats sorting and keeps no state.
        std::size_t kept = base + 1;
        for (std::size_t i = base + 1; i < out.size(); ++i) {
            const std::uint32_t w = out[i];
            bool seen = false;
            for (std::size_t j = base; j < kept && !seen; ++j) seen = out[j] == w;
            if (!seen) out[kept++] = w;
        }
        out.resize(kept);
        return;
    }
    std::sort(out.begin() + static_cast<std::ptrdiff_t>(base), out.end());
    out.erase(std::unique(out.begin() + static_cast<std::ptrdiff_t>(base), out.end()), out.end());
}

/// ⌊g⌋ clamped to [lo, hi] (g may be far outside, or ±inf).
std::int64_t clamp_floor(double g, std::int64_t lo, std::int64_t hi) {
    if (!(g >= static_cast<double>(lo))) return lo;
    if (g >= static_cast<double>(hi)) return hi;
    // lo ≥ 0 here, so g ≥ 0 and truncation is ⌊g⌋ (no libm call on the hot path).
    return lo >= 0 ? static_cast<std::int64_t>(g) : static_cast<std::int64_t>(std::floor(g));
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// WallGrid

WallGrid::WallGrid(std::span<const Wall> walls, GridOptions options)
    : wall_count_(static_cast<std::uint32_t>(walls.size())), margin_(options.margin) {
    if (walls.empty()) return;
    double xmin = walls[0].p0.x, xmax = xmin, ymin = walls[0].p0.y, ymax = ymin;
    for (const Wall& w : walls)
        for (Vec2 p : {w.p0, w.p1}) {
            xmin = std::min(xmin, p.x);
            xmax = std::max(xmax, p.x);
            ymin = std::min(ymin, p.y);
            ymax = std::max(ymax, p.y);
        }
    const double width = xmax - xmin, height = ymax - ymin;
    double h = options.cell_size;
    if (!(h > 0.0) || !std::isfinite(h)) {
        // About four cells per wall: h² · 4n ≈ area (measured on mazes: 0.5 of the wall pitch beat 0.7,
        // 1 and 2 by 8–60%, as fewer walls share a leg's cells). A line has no area: its length / 4n.
        const double n = 4.0 * static_cast<double>(walls.size());
        h = width > 0.0 && height > 0.0 ? std::sqrt(width * height / n) : std::max(width, height) / n;
        if (!(h > 0.0) || !std::isfinite(h)) h = 1.0;
    }
    // Cap the cell count: grow h until (width/h + 2)(height/h + 2) fits.
    const auto cells_for = [&](double c) { return (width / c + 3.0) * (height / c + 3.0); };
    while (cells_for(h) > static_cast<double>(options.max_cells)) h *= 1.5;
    inv_ = 1.0 / h;
    // Half a cell of border: walls on a lattice of pitch h then lie mid-cell, not on cell edges.
    ox_ = xmin - 0.5 * h;
    oy_ = ymin - 0.5 * h;
    o_mag_ = std::max(std::fabs(ox_), std::fabs(oy_)) * inv_;
    nx_ = static_cast<std::uint32_t>(std::floor((xmax - ox_) * inv_)) + 2;
    ny_ = static_cast<std::uint32_t>(std::floor((ymax - oy_) * inv_)) + 2;

    // Two passes (count, then fill) into the CSR arrays.
    const std::size_t cells = static_cast<std::size_t>(nx_) * ny_;
    std::vector<std::uint32_t> count(cells + 1, 0);
    for (const Wall& w : walls) visit(w.p0, w.p1, [&](std::size_t c) { ++count[c]; });
    start_.assign(cells + 1, 0);
    for (std::size_t c = 0; c < cells; ++c) start_[c + 1] = start_[c] + count[c];
    items_.resize(start_[cells]);
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (std::uint32_t i = 0; i < walls.size(); ++i)
        visit(walls[i].p0, walls[i].p1, [&](std::size_t c) { items_[fill[c]++] = i; });
}

template <class F>
void WallGrid::visit(Vec2 a, Vec2 b, F&& f) const {
    // Grid coordinates G̃ = (p − o)·inv, rounded; m covers their error and the per-column y error
    // (grid.hpp), with 2^13 ulps to spare.
    const double ax = (a.x - ox_) * inv_, ay = (a.y - oy_) * inv_;
    const double bx = (b.x - ox_) * inv_, by = (b.y - oy_) * inv_;
    const double m = margin_ * (1.0 + (max_abs(a) + max_abs(b)) * inv_ + o_mag_);
    const double xs_lo = std::min(ax, bx), xs_hi = std::max(ax, bx);
    const double ys_lo = std::min(ay, by) - m, ys_hi = std::max(ay, by) + m;
    const double nxd = nx_, nyd = ny_;
    if (xs_hi + m < 0.0 || xs_lo - m >= nxd || ys_hi < 0.0 || ys_lo >= nyd) return;
    const std::int64_t c0 = clamp_floor(xs_lo - m, 0, nx_ - 1), c1 = clamp_floor(xs_hi + m, 0, nx_ - 1);
    const double dx = bx - ax, dy = by - ay;
    for (std::int64_t c = c0; c <= c1; ++c) {
        double yl = ys_lo, yh = ys_hi;
        if (c0 != c1 && dx != 0.0) {
            // The segment's points with x in [c − m, c + 1 + m]: y(x) = ay + t·dy, t = (x − ax)/dx,
            // monotone in x, so its extremes are at the interval's ends.
            const double x_from = std::max(xs_lo, static_cast<double>(c) - m);
            const double x_to = std::max(x_from, std::min(xs_hi, static_cast<double>(c + 1) + m));
            const double t_from = std::clamp((x_from - ax) / dx, 0.0, 1.0);
            const double t_to = std::clamp((x_to - ax) / dx, 0.0, 1.0);
            const double y_from = ay + t_from * dy, y_to = ay + t_to * dy;
            yl = std::min(y_from, y_to) - m;
            yh = std::max(y_from, y_to) + m;
            if (yh < 0.0 || yl >= nyd) continue;
        }
        const std::int64_t r0 = clamp_floor(yl, 0, ny_ - 1), r1 = clamp_floor(yh, 0, ny_ - 1);
        const std::size_t base = static_cast<std::size_t>(c) * ny_;
        for (std::int64_t r = r0; r <= r1; ++r) f(base + static_cast<std::size_t>(r));
    }
}

void WallGrid::query(Vec2 a, Vec2 b, std::vector<std::uint32_t>& out) const {
    if (wall_count_ == 0) return;
    if (!finite(a) || !finite(b) || !std::isfinite((max_abs(a) + max_abs(b)) * inv_)) {
        // Outside what the grid can reason about: every wall (the contract allows a superset).
        for (std::uint32_t i = 0; i < wall_count_; ++i) out.push_back(i);
        return;
    }
    const std::size_t base = out.size();
    int cells = 0;
    visit(a, b, [&](std::size_t c) {
        ++cells;
        out.insert(out.end(), items_.begin() + start_[c], items_.begin() + start_[c + 1]);
    });
    // One cell holds each wall once; several cells may share walls.
    if (cells > 1) dedupe_tail(out, base);
}

void WallGrid::prefetch(Vec2 p, int stage, std::span<const Wall> walls) const {
    if (wall_count_ == 0) return;
    const std::size_t c = static_cast<std::size_t>(clamp_floor((p.x - ox_) * inv_, 0, nx_ - 1)) * ny_ +
                          static_cast<std::size_t>(clamp_floor((p.y - oy_) * inv_, 0, ny_ - 1));
    if (stage == 0) {
        __builtin_prefetch(&start_[c]);
        return;
    }
    const std::uint32_t first = start_[c], last = start_[c + 1];
    if (first == last) return;
    if (stage == 1) {
        __builtin_prefetch(&items_[first]);
        return;
    }
    for (std::uint32_t k = first; k < last && k < first + 4; ++k) __builtin_prefetch(&walls[items_[k]]);
}

// ---------------------------------------------------------------------------------------------
// WallBvh

WallBvh::WallBvh(std::span<const Wall> walls, double margin) : margin_(margin) {
    items_.resize(walls.size());
    std::iota(items_.begin(), items_.end(), std::uint32_t{0});
    if (walls.empty()) return;
    nodes_.reserve(walls.size() / 2 + 2);
    nodes_.push_back({});
    build(walls, 0, 0, static_cast<std::uint32_t>(walls.size()));
}

void WallBvh::build(std::span<const Wall> walls, std::uint32_t slot, std::uint32_t first, std::uint32_t count) {
    Node node{};
    node.lo_x = node.lo_y = INFINITY;
    node.hi_x = node.hi_y = -INFINITY;
    double clo_x = INFINITY, clo_y = INFINITY, chi_x = -INFINITY, chi_y = -INFINITY;
    for (std::uint32_t k = first; k < first + count; ++k) {
        const Wall& w = walls[items_[k]];
        node.lo_x = std::min({node.lo_x, w.p0.x, w.p1.x});
        node.lo_y = std::min({node.lo_y, w.p0.y, w.p1.y});
        node.hi_x = std::max({node.hi_x, w.p0.x, w.p1.x});
        node.hi_y = std::max({node.hi_y, w.p0.y, w.p1.y});
        const double cx = 0.5 * w.p0.x + 0.5 * w.p1.x, cy = 0.5 * w.p0.y + 0.5 * w.p1.y;
        clo_x = std::min(clo_x, cx);
        chi_x = std::max(chi_x, cx);
        clo_y = std::min(clo_y, cy);
        chi_y = std::max(chi_y, cy);
    }
    if (count <= 4) {
        node.first = first;
        node.count = count;
        nodes_[slot] = node;
        return;
    }
    // Median split of the centres along the longer axis of their box (ties by index: deterministic).
    const bool split_x = chi_x - clo_x >= chi_y - clo_y;
    const auto key = [&](std::uint32_t i) {
        const Wall& w = walls[i];
        return split_x ? 0.5 * w.p0.x + 0.5 * w.p1.x : 0.5 * w.p0.y + 0.5 * w.p1.y;
    };
    const std::uint32_t half = count / 2;
    const auto at = [&](std::uint32_t k) { return items_.begin() + static_cast<std::ptrdiff_t>(k); };
    std::nth_element(at(first), at(first + half), at(first + count),
                     [&](std::uint32_t l, std::uint32_t r) { return key(l) < key(r) || (key(l) == key(r) && l < r); });
    // The children sit side by side: left at node.first, right at node.first + 1.
    node.first = static_cast<std::uint32_t>(nodes_.size());
    node.count = 0;
    nodes_[slot] = node;
    nodes_.push_back({});
    nodes_.push_back({});
    build(walls, node.first, first, half);
    build(walls, node.first + 1, first + half, count - half);
}

void WallBvh::query(Vec2 a, Vec2 b, std::vector<std::uint32_t>& out) const {
    if (nodes_.empty()) return;
    if (!finite(a) || !finite(b)) {
        out.insert(out.end(), items_.begin(), items_.end());
        return;
    }
    const double m = margin_ * (1.0 + max_abs(a) + max_abs(b));
    const double sx_lo = std::min(a.x, b.x) - m, sx_hi = std::max(a.x, b.x) + m;
    const double sy_lo = std::min(a.y, b.y) - m, sy_hi = std::max(a.y, b.y) + m;
    const Vec2 d = b - a;
    const double adx = std::fabs(d.x), ady = std::fabs(d.y);
    std::uint32_t stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& n = nodes_[stack[--top]];
        // Boxes of doubles against the segment's box: exact comparisons.
        if (n.hi_x < sx_lo || n.lo_x > sx_hi || n.hi_y < sy_lo || n.lo_y > sy_hi) continue;
        // The segment's line misses the box if |d × (c − a)| > |d_x|·h_y + |d_y|·h_x (c the centre, h
        // the half sizes, inflated by m); tol bounds the rounding of both sides, 2^13 times over.
        const double hx = 0.5 * (n.hi_x - n.lo_x) + m, hy = 0.5 * (n.hi_y - n.lo_y) + m;
        const double cx = 0.5 * n.lo_x + 0.5 * n.hi_x - a.x, cy = 0.5 * n.lo_y + 0.5 * n.hi_y - a.y;
        const double tol = 0x1p-40 * (adx + ady) * (std::fabs(cx) + std::fabs(cy) + hx + hy);
        if (std::fabs(d.x * cy - d.y * cx) > adx * hy + ady * hx + tol) continue;
        if (n.count > 0) {
            out.insert(out.end(), items_.begin() + n.first, items_.begin() + n.first + n.count);
        } else {
            stack[top++] = n.first;
            stack[top++] = n.first + 1;
        }
    }
}

// ---------------------------------------------------------------------------------------------
// StaticIndex

namespace {

// Relative and absolute slack of the static boxes: covers lecture-float's rounding (2^-24 relative)
// and the underflow of its squares (|CP| < 2^-75 squares to 0), with room to spare.
constexpr double k_static_rel = 0x1p-18;
constexpr double k_static_abs = 0x1p-60;
// Bounds beyond this are pushed out to ±k_static_far (past float's range, where lecture-float
// rounds to ±inf); query points are clamped to the same range, so monotonicity keeps the cover.
constexpr double k_static_big = 0x1p100;
constexpr double k_static_far = 0x1p120;

double clamp_far(double x) { return std::clamp(x, -k_static_far, k_static_far); }
double push_lo(double x) { return x <= -k_static_big ? -k_static_far : clamp_far(x); }
double push_hi(double x) { return x >= k_static_big ? k_static_far : clamp_far(x); }

struct Box {
    double lo_x, lo_y, hi_x, hi_y;
};

}  // namespace

StaticIndex::StaticIndex(std::span<const Circle> circles, std::span<const Rect> rects) {
    empty_ = circles.empty() && rects.empty();
    if (empty_) return;
    std::vector<Box> cboxes, rboxes;
    for (const Circle& c : circles) {
        const double s = k_static_rel * (max_abs(c.c) + c.r) + k_static_abs + c.r;
        cboxes.push_back({push_lo(c.c.x - s), push_lo(c.c.y - s), push_hi(c.c.x + s), push_hi(c.c.y + s)});
    }
    for (const Rect& r : rects) {
        const double mag = std::max({std::fabs(r.left), std::fabs(r.right), std::fabs(r.bottom), std::fabs(r.top)});
        const double s = k_static_rel * mag + k_static_abs;
        rboxes.push_back({push_lo(r.left - s), push_lo(r.bottom - s), push_hi(r.right + s), push_hi(r.top + s)});
    }
    double xmin = INFINITY, ymin = INFINITY, xmax = -INFINITY, ymax = -INFINITY;
    for (const auto* boxes : {&cboxes, &rboxes})
        for (const Box& b : *boxes) {
            xmin = std::min(xmin, b.lo_x);
            ymin = std::min(ymin, b.lo_y);
            xmax = std::max(xmax, b.hi_x);
            ymax = std::max(ymax, b.hi_y);
        }
    const double n = static_cast<double>(circles.size() + rects.size());
    const double width = xmax - xmin, height = ymax - ymin;
    double h = width > 0.0 && height > 0.0 ? std::sqrt(width * height / n) : std::max(width, height) / n;
    if (!(h > 0.0) || !std::isfinite(h)) h = 1.0;
    while ((width / h + 2.0) * (height / h + 2.0) > double(1 << 22)) h *= 1.5;
    inv_ = 1.0 / h;
    ox_ = xmin;
    oy_ = ymin;
    nx_ = static_cast<std::uint32_t>(std::floor(width * inv_)) + 1;
    ny_ = static_cast<std::uint32_t>(std::floor(height * inv_)) + 1;
    const std::size_t cells = static_cast<std::size_t>(nx_) * ny_;
    // The cell of x is ⌊(x − o)·inv⌋ clamped: monotone in x, so lo ≤ p ≤ hi gives cell(lo) ≤ cell(p) ≤ cell(hi).
    const auto fill = [&](const std::vector<Box>& boxes, std::vector<std::uint32_t>& start,
                          std::vector<std::uint32_t>& items) {
        std::vector<std::uint32_t> count(cells, 0);
        const auto each = [&](const Box& b, auto&& f) {
            const std::int64_t c0 = clamp_floor((b.lo_x - ox_) * inv_, 0, nx_ - 1);
            const std::int64_t c1 = clamp_floor((b.hi_x - ox_) * inv_, 0, nx_ - 1);
            const std::int64_t r0 = clamp_floor((b.lo_y - oy_) * inv_, 0, ny_ - 1);
            const std::int64_t r1 = clamp_floor((b.hi_y - oy_) * inv_, 0, ny_ - 1);
            for (std::int64_t c = c0; c <= c1; ++c)
                for (std::int64_t r = r0; r <= r1; ++r) f(static_cast<std::size_t>(c) * ny_ + static_cast<std::size_t>(r));
        };
        for (const Box& b : boxes) each(b, [&](std::size_t c) { ++count[c]; });
        start.assign(cells + 1, 0);
        for (std::size_t c = 0; c < cells; ++c) start[c + 1] = start[c] + count[c];
        items.resize(start[cells]);
        std::vector<std::uint32_t> at(start.begin(), start.end() - 1);
        // Filled in index order, so each cell's list is sorted.
        for (std::uint32_t i = 0; i < boxes.size(); ++i) each(boxes[i], [&](std::size_t c) { items[at[c]++] = i; });
    };
    fill(cboxes, circle_start_, circle_items_);
    fill(rboxes, rect_start_, rect_items_);
}

StaticIndex::Candidates StaticIndex::query(Vec2 p) const {
    if (empty_) return {};
    // NaN goes to cell 0 of clamp_floor; a NaN point is never inside anything.
    const std::int64_t c = clamp_floor((clamp_far(p.x) - ox_) * inv_, 0, nx_ - 1);
    const std::int64_t r = clamp_floor((clamp_far(p.y) - oy_) * inv_, 0, ny_ - 1);
    const std::size_t cell = static_cast<std::size_t>(c) * ny_ + static_cast<std::size_t>(r);
    return {{circle_items_.data() + circle_start_[cell], circle_items_.data() + circle_start_[cell + 1]},
            {rect_items_.data() + rect_start_[cell], rect_items_.data() + rect_start_[cell + 1]}};
}

}  // namespace ricochet
