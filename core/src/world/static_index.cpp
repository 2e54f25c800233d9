// The static-shape index (static_index.hpp states why it is conservative).
#include "ricochet/static_index.hpp"

#include <algorithm>
#include <cmath>

#include "world/index_math.hpp"

namespace ricochet {

using detail::clamp_floor;
using detail::max_abs;

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
    // Bounds lie in ±k_static_far, so the width and height are finite.
    // About one cell per static, two cells of border per axis, at most 2^22 cells.
    const double h = detail::grid_fit(detail::grid_cell_size(width, height, n), width, height, 2.0,
                                      detail::grid_budget(n, double(1 << 22)));
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
