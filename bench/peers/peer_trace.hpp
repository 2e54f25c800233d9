// Internal: what the two peer kernels share: the walls a leg tries, the trace of a leg and its per-wall
// decisions (step_trace.hpp), and how a peer's bare "no hit" is written in the Miss vocabulary.
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

/// The Miss recorded for a peer's "no hit" on the leg a → b against w. A peer answers hit or no hit and gives
/// no reason, while `oracle` (checks.hpp) compares each per-wall Miss with the exact one. So that it judges
/// only what the peer decided: where the leg misses w exactly, the exact reason (truth::leg_miss); where it
/// hits exactly, the peer's claim that the leg stays on the side it starts on (a leg that hits starts strictly
/// off the line): both-outside or both-inside by that side. A leg with a non-finite end: degenerate.
Miss no_hit_miss(Vec2 a, Vec2 b, const Wall& w);

/// Starts the trace of the leg a → b, moving vel, if the step is traced (else nullptr); skipped is the wall
/// the peer's loop leaves out (the one just bounced off: the ray starts on it).
TracedLeg* begin_leg(StepScratch& scratch, Vec2 a, Vec2 b, Vec2 vel, std::optional<std::uint32_t> skipped);

/// Records one per-wall decision of a traced leg: a hit (Miss::none) or no_hit_miss of the leg.
void decide(StepScratch& scratch, TracedLeg* leg, std::uint32_t wall, const Wall& w, bool hit);

}  // namespace ricochet::peers
