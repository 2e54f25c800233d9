// Internal: the walls a leg tries, shared by every kernel's frame loop: what the wall index says, or every wall;
// for a disc, the walls and bumpers that may come within its radius of the leg.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "ricochet/shapes.hpp"
#include "ricochet/vec2.hpp"
#include "ricochet/wall_index.hpp"

namespace ricochet::detail {

/// Walls to try for the segment a → b: every wall (all, filled once), or what the index says (into out).
std::span<const std::uint32_t> candidates(std::span<const Wall> walls, const WallIndex* index, Vec2 a, Vec2 b,
                                          std::vector<std::uint32_t>& out, std::vector<std::uint32_t>& all);

/// Walls to try for a disc of radius r sweeping a → b, in increasing index order: every wall (all, filled once),
/// or those the index says may come within r of the segment (into out, sorted).
std::span<const std::uint32_t> candidates_near(std::size_t count, const WallIndex* index, Vec2 a, Vec2 b, double r,
                                               std::vector<std::uint32_t>& out, std::vector<std::uint32_t>& all);

}  // namespace ricochet::detail
