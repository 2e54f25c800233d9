// The wall grid (wall_grid.hpp states why it is conservative).
#include "ricochet/wall_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "world/index_math.hpp"

namespace ricochet {

using detail::clamp_floor;
using detail::dedupe_tail;
using detail::finite;
using detail::max_abs;

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
    // About four cells per wall: h² · 4n ≈ area (measured on mazes: 0.5 of the wall pitch beat 0.7, 1 and 2
    // by 8–60%, as fewer walls share a leg's cells). The grid has three cells of border per axis (the
    // half-cell origin shift and the two cells added to nx, ny). A cell size the caller gives is grown
    // only to fit max_cells (memory); a chosen one also to fit grid_budget (time).
    const double aim = 4.0 * static_cast<double>(walls.size()), max_cells = static_cast<double>(options.max_cells);
    const bool given = options.cell_size > 0.0 && std::isfinite(options.cell_size);
    double h = given ? detail::grid_fit(options.cell_size, width, height, 3.0, max_cells)
                     : detail::grid_fit(detail::grid_cell_size(width, height, aim), width, height, 3.0,
                                        detail::grid_budget(aim, max_cells));
    const auto lay_out = [&] {
        inv_ = 1.0 / h;
        // Half a cell of border: walls on a lattice of pitch h then lie mid-cell, not on cell edges.
        ox_ = xmin - 0.5 * h;
        oy_ = ymin - 0.5 * h;
        o_mag_ = std::max(std::fabs(ox_), std::fabs(oy_)) * inv_;
        nx_ = static_cast<std::uint32_t>(std::floor((xmax - ox_) * inv_)) + 2;
        ny_ = static_cast<std::uint32_t>(std::floor((ymax - oy_) * inv_)) + 2;
    };
    lay_out();

    // Two passes (count, then fill) into the CSR arrays. With a chosen cell size the count stops past
    // k_max_references_per_wall references a wall on average (1024 at least): long walls that cross the whole
    // scene (10^5 copies of one diagonal) would fill the cells quadratically (each wall √n cells), so the cells
    // grow until they fit. A bigger cell keeps the grid conservative (wall_grid.hpp); it only hands each query
    // more walls. A cell size the caller gives is kept.
    const std::size_t max_references = given ? std::numeric_limits<std::size_t>::max()
                                             : std::max<std::size_t>(1024, k_max_references_per_wall * walls.size());
    std::vector<std::uint32_t> count;
    for (;;) {
        count.assign(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
        std::size_t references = 0;
        for (const Wall& w : walls) {
            visit(w.p0, w.p1, 0.0, [&](std::size_t c) { ++count[c]; ++references; });
            if (references > max_references) break;
        }
        if (references <= max_references) break;
        h *= 2.0;
        lay_out();
    }
    const std::size_t cells = static_cast<std::size_t>(nx_) * ny_;
    start_.assign(cells + 1, 0);
    for (std::size_t c = 0; c < cells; ++c) start_[c + 1] = start_[c] + count[c];
    items_.resize(start_[cells]);
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (std::uint32_t i = 0; i < walls.size(); ++i)
        visit(walls[i].p0, walls[i].p1, 0.0, [&](std::size_t c) { items_[fill[c]++] = i; });
}

template <class F>
void WallGrid::visit(Vec2 a, Vec2 b, double reach, F&& f) const {
    // Grid coordinates G̃ = (p − o)·inv, rounded; m covers their error and the per-column y error
    // (wall_grid.hpp), with 2^13 ulps to spare, plus reach: a disc's radius in cells (query_near).
    const double ax = (a.x - ox_) * inv_, ay = (a.y - oy_) * inv_;
    const double bx = (b.x - ox_) * inv_, by = (b.y - oy_) * inv_;
    const double m = margin_ * (1.0 + (max_abs(a) + max_abs(b)) * inv_ + o_mag_) + reach;
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

void WallGrid::query(Vec2 a, Vec2 b, std::vector<std::uint32_t>& out) const { collect(a, b, 0.0, out); }

void WallGrid::query_near(Vec2 a, Vec2 b, double r, std::vector<std::uint32_t>& out) const {
    // r in cells, widened by 2^-40 for the product's rounding (wall_grid.hpp).
    collect(a, b, r * inv_ * (1.0 + 0x1p-40), out);
}

void WallGrid::collect(Vec2 a, Vec2 b, double reach, std::vector<std::uint32_t>& out) const {
    if (wall_count_ == 0) return;
    if (!finite(a) || !finite(b) || !std::isfinite((max_abs(a) + max_abs(b)) * inv_ + reach)) {
        // Outside what the grid can reason about: every wall (the contract allows a superset).
        for (std::uint32_t i = 0; i < wall_count_; ++i) out.push_back(i);
        return;
    }
    const std::size_t base = out.size();
    int cells = 0;
    visit(a, b, reach, [&](std::size_t c) {
        ++cells;
        // A cell holds a few walls: element by element beats insert's range copy (a memmove call) here.
        for (std::uint32_t k = start_[c], end = start_[c + 1]; k < end; ++k) out.push_back(items_[k]);
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
    for (std::uint32_t k = first; k < std::min(last, first + 4); ++k) __builtin_prefetch(&walls[items_[k]]);
}

}  // namespace ricochet
