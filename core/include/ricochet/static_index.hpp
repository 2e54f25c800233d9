// StaticIndex: which static circles and rectangles may hold a point, one cell lookup per ball.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "ricochet/shapes.hpp"
#include "ricochet/vec2.hpp"

namespace ricochet {

/// Which static shapes may hold a point: a uniform grid over the circles' and rectangles' boxes,
/// inflated by 2^-18 of their magnitude so that every kernel's test (lecture-float included) is
/// covered. Lists come back in index order, so overlap events come out as the brute-force loop
/// makes them.
class StaticIndex {
public:
    /// Builds the index (empty shapes: every query answers nothing at once).
    StaticIndex(std::span<const Circle> circles, std::span<const Rect> rects);
    /// The circles and rectangles that may hold p, each in increasing index order.
    struct Candidates {
        std::span<const std::uint32_t> circles;
        std::span<const std::uint32_t> rects;
    };
    /// One cell lookup.
    Candidates query(Vec2 p) const;
    /// True if there are no static shapes at all (the overlap pass can be skipped).
    bool empty() const { return empty_; }

private:
    bool empty_ = true;
    double ox_ = 0, oy_ = 0, inv_ = 1;
    std::uint32_t nx_ = 0, ny_ = 0;
    std::vector<std::uint32_t> circle_start_, circle_items_, rect_start_, rect_items_;
};

}  // namespace ricochet
