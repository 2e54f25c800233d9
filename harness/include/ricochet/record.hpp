// Recording: a log's expect lines filled from its own run, what `ricochet record` writes back.
#pragma once

#include <functional>
#include <span>

#include "ricochet/checks.hpp"
#include "ricochet/scene.hpp"

namespace ricochet {

/// Fills scene's expect lines from a run: expect hash, expect failure (if a check failed), expect state
/// for every ball at a spread of frames (all frames if frames+1 times balls ≤ 64, else 8 spread frames and
/// the last). Returns the run (its error set if it could not finish; then nothing is filled). on_frame, if
/// set, is called with each frame's events as they come (a caller's progress line), changing nothing.
CheckedRun record_expectations(Scene& scene, const std::function<void(std::span<const Event>)>& on_frame = {});

}  // namespace ricochet
