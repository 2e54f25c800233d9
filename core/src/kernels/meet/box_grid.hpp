// Internal: the balls whose path boxes may overlap a given one, for the frame's meets (frame.cpp): a uniform grid
// over the frame's path boxes, so that N balls cost near N box tests, not N². A ball whose box changes (a new path
// after a meet) is entered again where its new box lies; stale entries only cost a box test (the caller tests the
// current boxes). What it returns decides nothing: first_meet does, exactly, on every pair whose boxes overlap.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "ricochet/vec2.hpp"

namespace ricochet::meet {

/// An axis-aligned box.
struct Box {
    Vec2 lo, hi;
};

inline bool boxes_overlap(const Box& a, const Box& b) {
    return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y;
}

/// A uniform grid of cells, each listing the balls entered whose boxes reach it.
class BoxGrid {
public:
    /// A grid over boxes, cells as large as the median box's larger side, at most about 4 cells per ball.
    explicit BoxGrid(const std::vector<Box>& boxes) {
        const std::size_t n = boxes.size();
        if (n == 0) return;
        Box all = boxes[0];
        std::vector<double> sides;
        sides.reserve(n);
        for (const Box& b : boxes) {
            all.lo = {std::min(all.lo.x, b.lo.x), std::min(all.lo.y, b.lo.y)};
            all.hi = {std::max(all.hi.x, b.hi.x), std::max(all.hi.y, b.hi.y)};
            sides.push_back(std::max(b.hi.x - b.lo.x, b.hi.y - b.lo.y));
        }
        std::nth_element(sides.begin(), sides.begin() + static_cast<std::ptrdiff_t>(n / 2), sides.end());
        const double w = all.hi.x - all.lo.x, h = all.hi.y - all.lo.y;
        double cell = sides[n / 2];
        // At most about 4n cells: a median far below the extent (most balls at rest) would make too many.
        const double floor_cell = std::sqrt(std::max(w * h, 0.0) / (4.0 * static_cast<double>(n)));
        cell = std::max(cell, floor_cell);
        if (!(cell > 0.0) || !std::isfinite(cell) || !std::isfinite(w) || !std::isfinite(h)) return;  // one cell
        origin_ = all.lo;
        cell_ = cell;
        nx_ = static_cast<std::size_t>(std::min(w / cell, 4096.0)) + 1;
        ny_ = static_cast<std::size_t>(std::min(h / cell, 4096.0)) + 1;
        cells_.assign(nx_ * ny_, {});
    }

    /// Enters ball i with box b.
    void insert(std::uint32_t i, const Box& b) {
        if (cells_.empty()) return everyone_.push_back(i);
        const Range r = range(b);
        if ((r.x1 - r.x0 + 1) * (r.y1 - r.y0 + 1) > k_big_cells) return everyone_.push_back(i);
        for (std::size_t y = r.y0; y <= r.y1; ++y)
            for (std::size_t x = r.x0; x <= r.x1; ++x) cells_[y * nx_ + x].push_back(i);
    }

    /// Calls f(j) for every ball j entered in a cell b reaches, or entered as reaching everywhere (j may repeat,
    /// and may be a stale entry: f tests the current boxes).
    template <class F>
    void query(const Box& b, F&& f) const {
        for (std::uint32_t j : everyone_) f(j);
        if (cells_.empty()) return;
        const Range r = range(b);
        if ((r.x1 - r.x0 + 1) * (r.y1 - r.y0 + 1) > k_big_cells) {
            for (const auto& c : cells_)
                for (std::uint32_t j : c) f(j);
            return;
        }
        for (std::size_t y = r.y0; y <= r.y1; ++y)
            for (std::size_t x = r.x0; x <= r.x1; ++x)
                for (std::uint32_t j : cells_[y * nx_ + x]) f(j);
    }

private:
    /// A box larger than this many cells is listed as reaching everywhere.
    static constexpr std::size_t k_big_cells = 256;

    struct Range {
        std::size_t x0, x1, y0, y1;
    };

    std::size_t clamp_cell(double v, std::size_t n) const {
        if (!(v > 0.0)) return 0;  // below the origin, or NaN
        return static_cast<std::size_t>(std::min(v, static_cast<double>(n - 1)));
    }

    Range range(const Box& b) const {
        return {clamp_cell((b.lo.x - origin_.x) / cell_, nx_), clamp_cell((b.hi.x - origin_.x) / cell_, nx_),
                clamp_cell((b.lo.y - origin_.y) / cell_, ny_), clamp_cell((b.hi.y - origin_.y) / cell_, ny_)};
    }

    Vec2 origin_{};
    double cell_ = 1.0;
    std::size_t nx_ = 0, ny_ = 0;
    std::vector<std::vector<std::uint32_t>> cells_;
    std::vector<std::uint32_t> everyone_;  // balls whose boxes reach too many cells (or every ball: no grid)
};

}  // namespace ricochet::meet
