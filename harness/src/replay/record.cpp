// Recording: a log's expect lines filled from its run (record.hpp).
#include "ricochet/record.hpp"

#include "replay/state_sampler.hpp"

namespace ricochet {

CheckedRun record_expectations(Scene& scene, const std::function<void(std::span<const Event>)>& on_frame) {
    const std::int64_t frames = scene.frames;
    // Every frame for small runs, else 8 spread frames, the last among them (state_sampler.hpp).
    detail::StateSampler sampler(frames, scene.balls.size());
    CheckOptions options;
    options.keep_events = false;
    options.on_frame = [&](std::span<const Event> events) {
        sampler.add(events);
        if (on_frame) on_frame(events);
    };
    CheckedRun run = run_checked(scene, scene.kernel, frames, scene.checks, options);
    if (run.error) return run;
    scene.expect_hash = run.hash;
    scene.expect_failure.reset();
    if (run.failure) scene.expect_failure = ExpectFailure{run.failure->check, run.failure->frame};
    scene.expect_states = sampler.take();
    return run;
}

}  // namespace ricochet
