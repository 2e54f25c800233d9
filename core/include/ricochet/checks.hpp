// The `check` invariants of scene logs, asserted frame by frame while a scene runs.
//
//   no-tunnel      TunnelChecker (tunnel.hpp, exact) on every ball's printed path.
//   symmetry       the scene mirrored across x = 0 (x ↦ −x is exact) gives the mirrored events bit for bit.
//   boundary       at every printed ball position p: p is in the radius-0 circle and the zero-size rect at
//                  p; point_in_circle(p, C) == circles_overlap({p, 0}, C) and point_in_rect(p, R) ==
//                  rects_overlap({p, p}, R) for every circle and rect; and classify(p, w) agrees with
//                  sweep(p, v, w) for every wall (On never gives tests 1/2, Inside never "both outside",
//                  Outside never "both inside").
//   speed          per ball per frame with n bounces: | |v_end| − |v_start| | ≤ ((1+b)^n − 1)·|v_start|
//                  + 4·2^−53·|v_start|, b = speed_rel_bound(kernel) (the last term covers computing |v|).
//   deterministic  a second World run in lockstep gives the same events, frame by frame (so the same hash).
//   oracle         per frame per ball, the first wall the kernel hits (or none) equals the one the exact
//                  kernel hits from the same double state and memory.
// The first failure is the earliest frame; within a frame the first check in the scene's order, then the
// lowest ball.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "ricochet/check.hpp"
#include "ricochet/scene.hpp"
#include "ricochet/world.hpp"

namespace ricochet {

/// The bound b on the relative change of |v| per bounce that `speed` allows: k_speed_rel_bound for robust
/// and exact; 1e-6 for lecture-double and 1e-3 for lecture-float (they state none; these are loose bounds
/// chosen so that only real blunders fail).
double speed_rel_bound(KernelId kernel);

/// The first broken invariant of a run.
struct CheckFailure {
    Check check = Check::no_tunnel;  ///< the invariant that broke
    std::int64_t frame = 0;          ///< the first frame it broke in
    std::uint32_t ball = 0;          ///< the ball it broke for
    std::string message;  ///< expected against actual, for people
    /// "CHECK at frame F ball I: MESSAGE".
    std::string str() const;
};

/// What running a scene with its checks produced.
struct CheckedRun {
    std::vector<Event> events;              ///< every event (empty if not kept)
    std::uint64_t hash = 0;                 ///< run hash (hash.hpp) of every event stepped
    std::int64_t frames_run = 0;            ///< frames stepped (< frames only after an error)
    std::optional<CheckFailure> failure;    ///< the first broken invariant
    std::optional<StepError> error;         ///< the run stopped: a ball left the accepted range
};

/// Options for run_checked.
struct CheckOptions {
    bool keep_events = true;                                   ///< store events in CheckedRun::events
    std::function<void(std::span<const Event>)> on_frame;      ///< called with each frame's events, in order
};

/// Runs frames 0..frames of scene under kernel, asserting checks on every frame. After the first failure
/// the remaining checks are skipped but the run goes on (the hash covers the whole run). Every World here
/// (the run's, the mirrored one and the twin) steps with the default WorldOptions, as `ricochet run` does.
CheckedRun run_checked(const Scene& scene, KernelId kernel, std::int64_t frames, std::span<const Check> checks,
                       const CheckOptions& options = {});

/// The scene mirrored across x = 0: every x coordinate and x velocity negated (walls keep their direction).
Scene mirror_x(const Scene& scene);

}  // namespace ricochet
