// Wall index: the interface a broad phase offers the kernels, "which walls may touch this segment?".
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
};

}  // namespace ricochet
