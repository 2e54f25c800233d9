// What the robust kernel learns by looking once at a scene's walls, and the exact path it picks from it.
//
// A wall with P0.y = P1.y or P0.x = P1.x (tile maps, editor grids, boxes) has its side of a point decided by
// comparisons alone, exact for every double and the same sign as the filtered orientation (orient_filter.hpp
// derives it); a scene with no such wall skips even the two comparisons that look for one. Either path gives
// the exact sign, so a plan changes the time a step takes, never its bits: a stale or absent plan is only
// slower. The check `plan` (docs/scene-log.md) holds a run to the general path's bits; the property
// PlanChangesNoBits, replays/tile-grid.scene and core/tests/wall_plan_test.cpp ask it.
#pragma once

#include <cstddef>
#include <span>

#include "ricochet/shapes.hpp"

namespace ricochet {

/// The walls a plan describes (by address and count, as a span names them) and what it found in them.
struct WallPlan {
    const Wall* walls = nullptr;
    std::size_t count = 0;
    /// Walls with P0.y = P1.y or P0.x = P1.x (a zero-length wall counts): their sides are comparisons.
    std::size_t axis_aligned = 0;

    /// True if this plan was made for exactly these walls (the same array, the same count).
    bool describes(std::span<const Wall> w) const { return w.data() == walls && w.size() == count; }
};

/// Looks at every wall once: O(walls).
WallPlan plan_walls(std::span<const Wall> walls);

}  // namespace ricochet
