// Wall index: the interface a broad phase offers the kernels, "which walls may touch this segment?", and for a
// disc, "which walls may come within its radius of this segment?".
#pragma once

#include <cstdint>
#include <vector>

#include "ricochet/vec2.hpp"

namespace ricochet {

/// Answers "which walls may touch the segment a → b?" faster than trying them all.
class WallIndex {
public:
    virtual ~WallIndex() = default;
    /// Appends to out every wall whose closed segment may meet the closed segment a → b (a superset
    /// is fine, each wall at most once, any order).
    virtual void query(Vec2 a, Vec2 b, std::vector<std::uint32_t>& out) const = 0;
    /// Appends to out every wall whose closed segment may come within distance r ≥ 0 of the closed segment
    /// a → b (a superset is fine, each wall at most once, any order): the walls a disc of radius r sweeping
    /// a → b may touch. r = 0 asks what query does.
    virtual void query_near(Vec2 a, Vec2 b, double r, std::vector<std::uint32_t>& out) const = 0;
};

}  // namespace ricochet
