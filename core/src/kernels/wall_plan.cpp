// The walls' plan (wall_plan.hpp): one look at a scene's walls.
#include "ricochet/wall_plan.hpp"

namespace ricochet {

WallPlan plan_walls(std::span<const Wall> walls) {
    WallPlan plan{walls.data(), walls.size(), 0};
    for (const Wall& w : walls) plan.axis_aligned += w.p0.y == w.p1.y || w.p0.x == w.p1.x;
    return plan;
}

}  // namespace ricochet
