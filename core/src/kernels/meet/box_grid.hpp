// Internal: the balls whose path boxes may overlap a given one, for the frame's meets (frame.cpp): a uniform grid
// over the frame's path boxes, so that N balls cost near N box tests, not N². A ball whose box changes (a new path
// after a meet) is entered again where its new box lies; stale entries only cost a box test (the caller tests the
// current boxes), and once they are many the caller builds the grid afresh over the current boxes (inserted()). What
// it returns decides nothing: first_meet does, exactly, on every pair whose boxes overlap.
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

/// The smallest box holding a and b.
inline Box enclosing(const Box& a, const Box& b) {
    return {{std::min(a.lo.x, b.lo.x), std::min(a.lo.y, b.lo.y)}, {std::max(a.hi.x, b.hi.x), std::max(a.hi.y, b.hi.y)}};
}

/// A uniform grid of cells, each listing the balls entered whose boxes reach it: the frame's boxes in one array in
/// cell order (a counting sort: a few allocations a frame, not one per cell), the boxes entered later (new paths
/// after meets, few) in a list per cell.
class BoxGrid {
public:
    /// The grid made afresh over boxes (its arrays reused), cells as large as the median box's larger side (of a
    /// sample), at most about one cell per ball, with every ball i entered with boxes[i].
    void build(const std::vector<Box>& boxes) {
        build(boxes, [](std::uint32_t, std::uint32_t) {});
    }

    /// build(boxes), calling pair(i, j), i < j, once for every two balls whose boxes overlap (and possibly for a few
    /// that do not: pair tests the boxes), in no order to rely on. Where the grid has cells, a pair is found as its
    /// second ball is entered, in the first cell (lowest row, then column) both boxes reach: two overlapping boxes
    /// reach that cell, since a box's cells grow with its corners.
    template <class F>
    void build(const std::vector<Box>& boxes, F&& pair) {
        everyone_.clear();
        later_.clear();
        inserted_ = 0;
        start_.clear();
        entries_.clear();
        head_.clear();
        nx_ = ny_ = 0;
        const std::size_t n = boxes.size();
        if (n == 0) return;
        Box all = boxes[0];
        for (const Box& b : boxes) all = enclosing(all, b);
        // The median of the larger sides of at most k_sampled boxes spread evenly over the array.
        std::vector<double>& sides = sides_;
        sides.clear();
        const std::size_t stride = (n + k_sampled - 1) / k_sampled;
        for (std::size_t i = 0; i < n; i += stride)
            sides.push_back(std::max(boxes[i].hi.x - boxes[i].lo.x, boxes[i].hi.y - boxes[i].lo.y));
        std::nth_element(sides.begin(), sides.begin() + static_cast<std::ptrdiff_t>(sides.size() / 2), sides.end());
        const double w = all.hi.x - all.lo.x, h = all.hi.y - all.lo.y;
        double cell = sides[sides.size() / 2];
        // At most about n cells: a median far below the extent (most balls at rest) would make too many, and every
        // cell is cleared each frame.
        const double floor_cell = std::sqrt(std::max(w * h, 0.0) / static_cast<double>(n));
        cell = std::max(cell, floor_cell);
        if (!(cell > 0.0) || !std::isfinite(cell) || !std::isfinite(w) || !std::isfinite(h)) {
            // One cell: everyone, and every two of them a pair.
            for (std::uint32_t i = 0; i < n; ++i) everyone_.push_back(i);
            for (std::uint32_t i = 0; i < n; ++i)
                for (std::uint32_t j = i + 1; j < n; ++j) pair(i, j);
            return;
        }
        origin_ = all.lo;
        per_cell_ = 1.0 / cell;
        nx_ = static_cast<std::size_t>(std::min(w / cell, 4096.0)) + 1;
        ny_ = static_cast<std::size_t>(std::min(h / cell, 4096.0)) + 1;
        last_x_ = static_cast<double>(nx_ - 1);
        last_y_ = static_cast<double>(ny_ - 1);
        // Each box's cells once (both passes read them), then each cell's balls counted and placed:
        // start_[c] .. start_[c + 1] are cell c's.
        ranges_.resize(n);
        for (std::size_t i = 0; i < n; ++i) ranges_[i] = range(boxes[i]);
        start_.assign(nx_ * ny_ + 1, 0);
        for_cells(true, [&](std::uint32_t, std::size_t c, std::uint16_t, std::uint16_t) { ++start_[c + 1]; });
        for (std::size_t c = 0; c + 1 < start_.size(); ++c) start_[c + 1] += start_[c];
        entries_.resize(start_.back());
        next_.assign(start_.begin(), start_.end() - 1);
        // Balls are entered in index order: a cell's entries so far are of balls below i.
        for_cells(false, [&](std::uint32_t i, std::size_t c, std::uint16_t x, std::uint16_t y) {
            const Range& r = ranges_[i];
            const std::uint32_t at = next_[c]++;
            for (std::uint32_t k = start_[c]; k < at; ++k) {
                const Entry& e = entries_[k];
                // Found in an earlier cell?
                if (std::max(e.x0, r.x0) != x || std::max(e.y0, r.y0) != y) continue;
                if (boxes_overlap(e.box, boxes[i])) pair(e.ball, i);
            }
            entries_[at] = {boxes[i], i, r.x0, r.y0};
        });
        // The balls listed as reaching everywhere meet every other one.
        if (everyone_.empty()) return;
        std::vector<bool>& big = big_;
        big.assign(n, false);
        for (const std::uint32_t i : everyone_) big[i] = true;
        for (const std::uint32_t i : everyone_)
            for (std::uint32_t j = 0; j < n; ++j) {
                if (j == i || (big[j] && j < i) || !boxes_overlap(boxes[i], boxes[j])) continue;
                pair(std::min(i, j), std::max(i, j));
            }
    }

    /// How many entries insert made since the grid was built (each cell a box reached; a ball reaching everywhere, 1).
    std::size_t inserted() const { return inserted_; }

    /// Enters ball i again with box b (its entries under its old box stay: stale, the caller tests boxes).
    void insert(std::uint32_t i, const Box& b) {
        ++inserted_;
        if (nx_ == 0) return everyone_.push_back(i);
        const Range r = range(b);
        if (cells(r) > k_big_cells) return everyone_.push_back(i);
        inserted_ += cells(r) - 1;
        if (head_.empty()) head_.assign(nx_ * ny_, k_none);  // the first entry made after the build
        for (std::size_t y = r.y0; y <= r.y1; ++y)
            for (std::size_t x = r.x0; x <= r.x1; ++x) {
                std::uint32_t& head = head_[y * nx_ + x];
                later_.push_back({i, head});
                head = static_cast<std::uint32_t>(later_.size() - 1);
            }
    }

    /// Calls f(j) for every ball j entered in a cell b reaches, or entered as reaching everywhere (j may repeat,
    /// and may be a stale entry: f tests the current boxes).
    template <class F>
    void query(const Box& b, F&& f) const {
        for (std::uint32_t j : everyone_) f(j);
        if (nx_ == 0) return;
        const Range r = range(b);
        if (cells(r) > k_big_cells) {
            for (const Entry& e : entries_) f(e.ball);
            for (const Later& e : later_) f(e.ball);
            return;
        }
        for (std::size_t y = r.y0; y <= r.y1; ++y)
            for (std::size_t x = r.x0; x <= r.x1; ++x) {
                const std::size_t c = y * nx_ + x;
                for (std::uint32_t k = start_[c]; k < start_[c + 1]; ++k) f(entries_[k].ball);
                if (head_.empty()) continue;
                for (std::uint32_t e = head_[c]; e != k_none; e = later_[e].next) f(later_[e].ball);
            }
    }

private:
    /// How many boxes' sides the cell size is the median of.
    static constexpr std::size_t k_sampled = 255;
    /// A box larger than this many cells is listed as reaching everywhere.
    static constexpr std::size_t k_big_cells = 256;
    static constexpr std::uint32_t k_none = 0xffffffffu;

    /// The cells a box reaches: columns x0..x1, rows y0..y1 (each below 4097).
    struct Range {
        std::uint16_t x0, x1, y0, y1;
    };
    /// A ball entered by build in a cell: its box and its first cell (x0, y0: below 4097), which build reads as it
    /// enters a later ball in the cell.
    struct Entry {
        Box box;
        std::uint32_t ball;
        std::uint16_t x0, y0;
    };
    /// An entry made after the grid was built: its ball and the cell's previous such entry.
    struct Later {
        std::uint32_t ball, next;
    };

    static std::size_t cells(const Range& r) {
        return static_cast<std::size_t>(r.x1 - r.x0 + 1) * static_cast<std::size_t>(r.y1 - r.y0 + 1);
    }

    /// Calls f(i, c, x, y) for each ball i and each cell c (column x, row y) its box reaches; a ball whose box reaches
    /// too many is entered as reaching everywhere instead (if enter_big: on the first of the two passes).
    template <class F>
    void for_cells(bool enter_big, F&& f) {
        for (std::uint32_t i = 0; i < ranges_.size(); ++i) {
            const Range& r = ranges_[i];
            if (cells(r) > k_big_cells) {
                if (enter_big) everyone_.push_back(i);
                continue;
            }
            for (std::uint16_t y = r.y0; y <= r.y1; ++y)
                for (std::uint16_t x = r.x0; x <= r.x1; ++x) f(i, y * nx_ + x, x, y);
        }
    }

    /// The column or row of v, the coordinate's distance from the origin in cells, at most last.
    static std::uint16_t clamp_cell(double v, double last) {
        if (!(v > 0.0)) return 0;  // below the origin, or NaN
        // (through a signed integer: one instruction, where a double to a 64-bit unsigned one is a branch; the value
        // is below 4097)
        return static_cast<std::uint16_t>(static_cast<std::int32_t>(std::min(v, last)));
    }

    /// A box's cells. (Times 1/cell, not divided by cell: a product's throughput is several times a quotient's. Both
    /// are rounded and monotone in the coordinate, so a box's cells still grow with its corners, all the grid needs.)
    Range range(const Box& b) const {
        const auto cell = [&](double v, double from, double last) { return clamp_cell((v - from) * per_cell_, last); };
        return {cell(b.lo.x, origin_.x, last_x_), cell(b.hi.x, origin_.x, last_x_), cell(b.lo.y, origin_.y, last_y_),
                cell(b.hi.y, origin_.y, last_y_)};
    }

    Vec2 origin_{};
    double per_cell_ = 1.0;               // 1 / the cells' side
    double last_x_ = 0.0, last_y_ = 0.0;  // nx_ − 1 and ny_ − 1
    std::size_t nx_ = 0, ny_ = 0;
    std::vector<std::uint32_t> start_;     // cell c's entries are entries_[start_[c] .. start_[c + 1])
    std::vector<Entry> entries_;           // the frame's boxes, by cell
    std::vector<std::uint32_t> head_;      // cell c's latest later entry, or k_none (empty: none made yet)
    std::vector<Later> later_;             // the boxes entered since
    std::vector<std::uint32_t> everyone_;  // balls whose boxes reach too many cells (or every ball: no grid)
    std::size_t inserted_ = 0;             // entries insert made since build
    std::vector<Range> ranges_;            // the cells each box entered by build reaches
    std::vector<double> sides_;            // build's scratch: the boxes' larger sides
    std::vector<std::uint32_t> next_;      // build's scratch: each cell's next free entry
    std::vector<bool> big_;                // build's scratch: the balls reaching everywhere
};

}  // namespace ricochet::meet
