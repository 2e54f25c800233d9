// Internal: what the two peer kernels share: the walls a leg tries, and the trace of a leg and its per-wall
// decisions (step_trace.hpp). A peer answers hit or no hit and gives no reason: its "no hit" is
// Miss::no_reason (sweep.hpp), which the oracle judges as a miss, right whenever the leg misses exactly.
#pragma once

#include <cstdint>
#include <optional>
#include <span>

#include "ricochet/kernel.hpp"
#include "ricochet/step_trace.hpp"

namespace ricochet::peers {

/// The walls to try for the leg a → b: what the index says (into scratch.candidates), else every wall.
std::span<const std::uint32_t> candidates(std::span<const Wall> walls, const WallIndex* index, Vec2 a, Vec2 b,
                                          StepScratch& scratch);

/// Starts the trace of the leg a → b, moving vel, if the step is traced (else nullptr); skipped is the wall
/// the peer's loop leaves out (the one just bounced off: the ray starts on it).
TracedLeg* begin_leg(StepScratch& scratch, Vec2 a, Vec2 b, Vec2 vel, std::optional<std::uint32_t> skipped);

/// Records one per-wall decision of a traced leg: a hit (Miss::none) or a miss without a reason (Miss::no_reason).
void decide(StepScratch& scratch, TracedLeg* leg, std::uint32_t wall, bool hit);

}  // namespace ricochet::peers
