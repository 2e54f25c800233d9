// The criterion of a reduction and its tries (trials.hpp).
#include "reduce/trials.hpp"

#include <algorithm>
#include <utility>

namespace ricochet::detail::reduce {

Culprit culprit_of(const Scene& scene, const CheckFailure& f) {
    // Degenerate: a static shape's failure (oracle at frame 0) names ball 0 of a scene that may have none.
    const bool disc = f.ball < scene.balls.size() && scene.balls[f.ball].r > 0.0;
    return {disc, f.against ? std::optional<bool>(f.against->bumper) : std::nullopt};
}

CheckedRun run_to_first_failure(const Scene& scene, KernelId kernel, std::span<const Check> checks,
                                const std::function<void(std::span<const Event>)>& on_frame) {
    CheckOptions options;
    options.keep_events = false;
    options.on_frame = on_frame;
    // The world's default options, as `ricochet replay` steps the reduced log: on a correct core the broad phase
    // changes no bits, but a bug in one of its paths shows only on that path, and the log must fail as replay
    // runs it (properties/harness.cpp judges the same way).
    // Nothing after the first failure can change the verdict.
    options.stop_after = [](const CheckedRun& run) { return run.failure.has_value(); };
    return run_checked(scene, kernel, scene.frames, checks, options);
}

std::optional<Failing> judge(const Scene& scene, KernelId kernel, const Target& target,
                             const std::function<void(std::span<const Event>)>& on_frame) {
    CheckedRun run = run_to_first_failure(scene, kernel, target.checks, on_frame);
    Failing out;
    if (target.check) {
        // Only C runs, so a failure is C's; a run that stops at an error before it fails otherwise.
        if (!run.failure || run.failure->check != *target.check) return std::nullopt;
        // The same check, failing for another kind of ball or obstacle, is another failure.
        if (target.culprit && culprit_of(scene, *run.failure) != *target.culprit) return std::nullopt;
        out.failure = std::move(run.failure);
    } else {
        if (run.failure || !run.error) return std::nullopt;
        out.error = std::move(run.error);
    }
    out.scene = scene;
    out.scene.frames = out.frame();
    return out;
}

Trials::Trials(KernelId kernel, Target target, Failing start, const ReduceOptions& options, std::uint64_t tries)
    : kernel_(kernel), target_(std::move(target)), current_(std::move(start)), options_(options), tries_(tries) {}

bool Trials::spent() {
    if (!ended_ && tries_ >= options_.max_tries) ended_ = ReduceEnd::budget;
    if (!ended_ && options_.stop && options_.stop()) ended_ = ReduceEnd::stopped;
    return ended_.has_value();
}

void Trials::counted(std::string_view pass) {
    ++tries_;
    if (options_.on_progress) options_.on_progress(ReduceProgress{tries_, SceneSize::of(current_.scene), pass});
}

bool Trials::attempt(Scene candidate, std::string_view pass) {
    if (spent()) return false;
    candidate.kernel = kernel_;
    candidate.checks = target_.checks;
    // Never past the frame that fails now: a later failure would be a larger case.
    candidate.frames = std::min(candidate.frames, current_.frame());
    // A smaller case outside the log's domain (a wall made shorter than its wall-length, say) is no case of it.
    std::optional<Failing> failing;
    if (!outside_domain(candidate, candidate.domain)) failing = judge(candidate, kernel_, target_);
    if (failing) {
        current_ = std::move(*failing);
        ++kept_;
    }
    counted(pass);
    return failing.has_value();
}

bool Trials::observe(const std::function<void(std::span<const Event>)>& on_frame, std::string_view pass) {
    if (spent()) return false;
    // The current scene fails the target (deterministically): the run is for its events only.
    judge(current_.scene, kernel_, target_, on_frame);
    counted(pass);
    return true;
}

}  // namespace ricochet::detail::reduce
