// Internal: the pairs of balls that may come within R_i + R_j of each other, found by sorting their boxes along x, so
// that ball-overlap and pass-through judge a scene of 10^3 balls without asking every pair exactly.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "ricochet/vec2.hpp"

namespace ricochet::checks {

/// A closed box of the plane; empty (x0 > x1) for a ball not judged.
struct PairBox {
    double x0 = 1, y0 = 1, x1 = 0, y1 = 0;
    bool empty() const { return !(x0 <= x1); }
    void add(Vec2 p) {
        if (empty()) x0 = x1 = p.x, y0 = y1 = p.y;
        x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
};

/// A ball's radius as a reach: R, or 0 for a point ball (whose R may be −0).
inline double reach_of(double r) { return r > 0 ? r : 0.0; }

/// Every pair i < j with S = R_i + R_j > 0 whose boxes come within S of each other on both axes. Decided on doubles
/// with a margin: a computed gap g > 0 is at least g/(1 + 2^−53) exactly, and S·(1 + 2^−48) as rounded is above S,
/// so no pair whose boxes are within S is left out. radii: each ball's reach (reach_of).
inline std::vector<std::pair<std::uint32_t, std::uint32_t>> near_pairs(std::span<const PairBox> boxes,
                                                                        std::span<const double> radii) {
    std::vector<std::uint32_t> order;
    for (std::uint32_t i = 0; i < boxes.size(); ++i)
        if (!boxes[i].empty()) order.push_back(i);
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return boxes[a].x0 < boxes[b].x0; });
    const double widest = radii.empty() ? 0.0 : *std::max_element(radii.begin(), radii.end());
    std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
    for (std::size_t k = 0; k < order.size(); ++k) {
        const std::uint32_t i = order[k];
        const PairBox& a = boxes[i];
        // Sorted by x0: past the first box farther along x than any reach, every later one is too.
        const double reach_any = (radii[i] + widest) * (1.0 + 0x1p-48);
        for (std::size_t m = k + 1; m < order.size() && boxes[order[m]].x0 - a.x1 <= reach_any; ++m) {
            const std::uint32_t j = order[m];
            const PairBox& b = boxes[j];
            if (!(radii[i] > 0) && !(radii[j] > 0)) continue;  // two point balls never meet
            const double reach = (radii[i] + radii[j]) * (1.0 + 0x1p-48);
            if (b.x0 - a.x1 > reach || b.y0 - a.y1 > reach || a.y0 - b.y1 > reach) continue;
            out.emplace_back(std::min(i, j), std::max(i, j));
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace ricochet::checks
