// Batched robust sweep decisions: many balls against one wall, or one ball against many walls, with
// the inputs laid out as a structure of arrays so that the floating-point filter runs in SIMD lanes.
// Every decision equals sweep(KernelId::robust, …).miss exactly: the lanes compute bit-for-bit the
// filter of exact::orient, then for the signs it declines the exact path's second stage (a double-double
// estimate against a proven bound), and a lane neither certifies is decided by the exact predicates.
#pragma once

#include <cstddef>
#include <span>

#include "ricochet/kernel.hpp"

namespace ricochet {

/// Balls as a structure of arrays: ball i is at (x[i], y[i]) moving (vx[i], vy[i]) per frame.
struct BallsSoA {
    std::span<const double> x, y, vx, vy;
};

/// Walls as a structure of arrays: wall i is the segment (x0[i], y0[i]) → (x1[i], y1[i]).
struct WallsSoA {
    std::span<const double> x0, y0, x1, y1;
};

/// Robust decisions for every ball of balls against w: out[i] = sweep(robust, Bs_i, v_i, w).miss.
/// out must hold balls.x.size() entries. Returns how many lanes were left to the exact predicates.
std::size_t sweep_decisions(const BallsSoA& balls, const Wall& w, std::span<Miss> out);

/// Robust decisions for one ball (bs, v) against every wall of walls: out[i] = sweep(robust, bs, v, wall i).miss.
/// out must hold walls.x0.size() entries. Returns how many lanes were left to the exact predicates.
std::size_t sweep_decisions(Vec2 bs, Vec2 v, const WallsSoA& walls, std::span<Miss> out);

}  // namespace ricochet
