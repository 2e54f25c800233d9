// Recording: a log's expect lines filled from its run (record.hpp).
#include "ricochet/record.hpp"

#include <algorithm>
#include <set>
#include <vector>

namespace ricochet {

CheckedRun record_expectations(Scene& scene) {
    const std::size_t nb = scene.balls.size();
    const std::int64_t frames = scene.frames;
    // Which frames get `expect state` lines: every frame for small runs, else 8 spread frames and the last.
    std::set<std::int64_t> chosen;
    if (static_cast<double>(frames + 1) * static_cast<double>(nb) <= 64.0) {
        for (std::int64_t f = 0; f <= frames; ++f) chosen.insert(f);
    } else {
        for (std::int64_t k = 1; k <= 8; ++k) chosen.insert(frames * k / 8);
        chosen.insert(frames);
    }
    const std::uint32_t balls_recorded = static_cast<std::uint32_t>(std::min<std::size_t>(nb, 8));
    std::vector<ExpectState> states;
    CheckOptions options;
    options.keep_events = false;
    options.on_frame = [&](std::span<const Event> events) {
        for (const Event& e : events)
            if (e.kind == Event::Kind::state && e.ball < balls_recorded && chosen.count(e.frame))
                states.push_back({e.frame, e.ball, Ball{e.pos, e.vel}});
    };
    CheckedRun run = run_checked(scene, scene.kernel, frames, scene.checks, options);
    if (run.error) return run;
    scene.expect_hash = run.hash;
    scene.expect_failure.reset();
    if (run.failure) scene.expect_failure = ExpectFailure{run.failure->check, run.failure->frame};
    scene.expect_states = std::move(states);
    return run;
}

}  // namespace ricochet
