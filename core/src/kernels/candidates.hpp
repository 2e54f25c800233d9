// Internal: the walls a leg tries, shared by every kernel's frame loop: what the wall index says, or every wall.
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

}  // namespace ricochet::detail
