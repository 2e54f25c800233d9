// Internal: the small numeric helpers the wall grid, the wall BVH and the static index share.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "ricochet/vec2.hpp"

namespace ricochet::detail {

/// max(|p.x|, |p.y|).
inline double max_abs(Vec2 p) { return std::max(std::fabs(p.x), std::fabs(p.y)); }

/// Both components finite.
inline bool finite(Vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

/// Keeps the first occurrence of each value in out[base..], in order; sorts when there are many.
inline void dedupe_tail(std::vector<std::uint32_t>& out, std::size_t base) {
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
inline std::int64_t clamp_floor(double g, std::int64_t lo, std::int64_t hi) {
    if (!(g >= static_cast<double>(lo))) return lo;
    if (g >= static_cast<double>(hi)) return hi;
    // lo ≥ 0 here, so g ≥ 0 and truncation is ⌊g⌋ (no libm call on the hot path).
    return lo >= 0 ? static_cast<std::int64_t>(g) : static_cast<std::int64_t>(std::floor(g));
}

/// Side of a uniform grid with about `cells` cells over a width × height box: h² · cells ≈ area; a line
/// (width or height 0) has no area, so its length / cells; 1 when there is no extent at all.
inline double grid_cell_size(double width, double height, double cells) {
    const double h = width > 0.0 && height > 0.0 ? std::sqrt(width * height / cells) : std::max(width, height) / cells;
    return h > 0.0 && std::isfinite(h) ? h : 1.0;
}

/// h grown until 1/h is finite and the grid over width × height, with `border` extra cells along each
/// axis, has at most `cap` cells. A bigger cell only puts more items in a cell, so every grid here stays
/// conservative for any h it returns.
inline double grid_fit(double h, double width, double height, double border, double cap) {
    // A subnormal h (items a few subnormals apart) has no finite 1/h.
    while (!std::isfinite(1.0 / h)) h *= 2.0;
    while ((width / h + border) * (height / h + border) > cap) h *= 1.5;
    return h;
}

/// The cell budget of a grid that aims at `cells` cells: the √(area / cells) side alone lets a flat box
/// (width ≫ height) take about border·width/h cells, millions for a few walls, and building that table
/// dominated a small scene's run (seconds per fuzz input); 16× the aim, at least 64, bounds it.
inline double grid_budget(double cells, double max_cells) { return std::min(max_cells, std::max(64.0, 16.0 * cells)); }

}  // namespace ricochet::detail
