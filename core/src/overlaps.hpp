// Internal: the overlap events of one ball, shared by World (every shape) and ScaledWorld (the static
// index's candidates), so both emit the same events in the same order.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "ricochet/kernel.hpp"
#include "ricochet/scene.hpp"

namespace ricochet::detail {

/// Candidate shapes for one ball, in ascending index order; nothing means every shape.
struct ShapeIds {
    std::optional<std::span<const std::uint32_t>> circles;
    std::optional<std::span<const std::uint32_t>> rects;
};

/// Appends `overlap F I circle|rect K` for every candidate circle, then rect, holding p (scene-log order).
void append_ball_overlaps(std::vector<Event>& out, KernelId kernel, std::int64_t frame, std::uint32_t ball, Vec2 p,
                          std::span<const Circle> circles, std::span<const Rect> rects, const ShapeIds& ids = {});

}  // namespace ricochet::detail
