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


}  // namespace ricochet::detail
