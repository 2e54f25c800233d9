// Internal to reduce_log: the criterion a reduction keeps (reduce.hpp) and the smallest scene known to
// fail it. Each candidate scene is one try: a run_checked that stops at the first failure.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "ricochet/checks.hpp"
#include "ricochet/reduce.hpp"

namespace ricochet::detail::reduce {

/// What made a check's failure, which every smaller scene must keep: the failing ball a disc (R > 0) or a
/// point, and for `penetration` whether the piece reached into a bumper or a wall. A disc failure that a
/// point ball would also show is still a disc failure: the reduced log keeps the disc.
struct Culprit {
    bool disc = false;            ///< the failing ball has a radius
    std::optional<bool> bumper;   ///< penetration: into a bumper (true) or a wall (false)
    friend bool operator==(const Culprit&, const Culprit&) = default;
};

/// The culprit of failure f in scene.
Culprit culprit_of(const Scene& scene, const CheckFailure& f);

/// The failure a reduction keeps: check C (run alone) with its culprit, or a step error with every check of
/// the log held.
struct Target {
    std::optional<Check> check;  ///< the check that must break; nothing: a step error must stop the run
    std::vector<Check> checks;   ///< the checks each try runs: {C}, or the log's for a step error
    std::optional<Culprit> culprit;  ///< with check: what made C's failure
};

/// A scene that fails the target, and what its run showed.
struct Failing {
    Scene scene;  ///< kernel, frames cut to the failure, the entities, target.checks, the domain; nothing else
    std::optional<CheckFailure> failure;  ///< a check target: the failure its run shows
    std::optional<StepError> error;       ///< a step-error target: where its run stops
    /// The frame of the failure or the error.
    std::int64_t frame() const { return failure ? failure->frame : error ? error->frame : 0; }
};

/// Runs scene's frames under kernel with checks until the first failure (CheckOptions::stop_after), events
/// not kept; on_frame (if set) sees each frame's events.
CheckedRun run_to_first_failure(const Scene& scene, KernelId kernel, std::span<const Check> checks,
                                const std::function<void(std::span<const Event>)>& on_frame = {});

/// Runs scene once under kernel with target's checks, stopping at its first failure; on_frame (if set)
/// sees each frame's events. The failing scene (frames cut to the failure) if it fails the target.
std::optional<Failing> judge(const Scene& scene, KernelId kernel, const Target& target,
                             const std::function<void(std::span<const Event>)>& on_frame = {});

/// The tries of one reduction: the smallest failing scene so far, the budget, progress and stop.
class Trials {
public:
    /// start fails target (judge said so), found in tries runs; options give the budget, progress and stop.
    Trials(KernelId kernel, Target target, Failing start, const ReduceOptions& options, std::uint64_t tries);

    /// Tries candidate (its kernel, frames and checks are set here): true if it fails the target, and
    /// then it is the current failing scene. False without a run once spent().
    bool attempt(Scene candidate, std::string_view pass);
    /// Runs the current failing scene once more (a try) for what it shows: on_frame sees its events.
    /// False without a run once spent().
    bool observe(const std::function<void(std::span<const Event>)>& on_frame, std::string_view pass);
    /// True once the budget is used or a stop was asked: no more tries.
    bool spent();
    /// The smallest failing scene so far.
    const Failing& current() const { return current_; }
    /// Tries made.
    std::uint64_t tries() const { return tries_; }
    /// Tries that failed the target, each a new current scene.
    std::uint64_t kept() const { return kept_; }
    /// How it ended, if it did (budget or stop).
    std::optional<ReduceEnd> ended() const { return ended_; }
    /// The kernel every try runs under.
    KernelId kernel() const { return kernel_; }

private:
    void counted(std::string_view pass);

    KernelId kernel_;
    Target target_;
    Failing current_;
    const ReduceOptions& options_;
    std::uint64_t tries_ = 0;
    std::uint64_t kept_ = 0;
    std::optional<ReduceEnd> ended_;
};

}  // namespace ricochet::detail::reduce
