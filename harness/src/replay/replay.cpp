// Replay: a log's run against its checks and expect lines (replay.hpp).
#include "ricochet/replay.hpp"

#include <algorithm>
#include <vector>

#include <fmt/format.h>

#include "ricochet/bits.hpp"
#include "ricochet/format.hpp"
#include "ricochet/hash.hpp"

namespace ricochet {

ReplayResult replay_scene(const Scene& scene, std::optional<KernelId> kernel, const ReplayStop& stop) {
    ReplayResult result;
    // Expect states by frame, so the run's states are compared as they stream past.
    std::vector<ExpectState> expects = scene.expect_states;
    std::stable_sort(expects.begin(), expects.end(),
                     [](const ExpectState& a, const ExpectState& b) { return a.frame < b.frame; });
    std::size_t next = 0;
    std::optional<std::string> diverged;
    std::int64_t last_matched_frame = -1;
    CheckOptions options;
    options.keep_events = false;
    options.on_frame = [&](std::span<const Event> events) {
        if (events.empty() || next >= expects.size()) return;
        std::int64_t f = -1;
        for (const Event& e : events)
            if (e.kind == Event::Kind::state) f = e.frame;
        while (next < expects.size() && expects[next].frame == f) {
            const ExpectState& x = expects[next++];
            for (const Event& e : events)
                if (e.kind == Event::Kind::state && e.ball == x.ball) {
                    const Ball got{e.pos, e.vel};
                    if (!same_bits(got, x.state) && !diverged)
                        diverged = fmt::format("first diverging frame {}: ball {} expected state {}, got {}", f,
                                               x.ball, x.state, got);
                    else if (!diverged)
                        last_matched_frame = f;
                }
        }
    };
    // Between two frames: the last frame ends the run anyway, so a stop asked then changes nothing.
    if (stop)
        options.stop_after = [&](const CheckedRun& so_far) {
            result.stopped = so_far.frames_run < scene.frames && stop();
            return result.stopped;
        };
    const KernelId k = kernel.value_or(scene.kernel);
    result.run = run_checked(scene, k, scene.frames, scene.checks, options);
    const CheckedRun& run = result.run;
    if (result.stopped) {
        result.message = fmt::format("stopped after frame {} of {}", run.frames_run, scene.frames);
        return result;
    }

    // A saved failure log (a `found` line, no `expect hash`): its expect states note how the saving run went before
    // the failure, so that a divergence is said; they are no verdict. A bug that acted a frame before a check saw it
    // changed those frames, and the log must still pass once the bug is fixed (docs/scene-log.md).
    const bool states_are_notes = scene.found && !scene.expect_hash;
    std::vector<std::string> problems;
    if (run.error) problems.push_back(run.error->message());
    if (diverged && !states_are_notes) problems.push_back(*diverged);
    if (scene.expect_failure) {
        const ExpectFailure& want = *scene.expect_failure;
        if (!run.failure)
            problems.push_back(fmt::format("expected {} to break first at frame {}, but every check held",
                                           want.check, want.frame));
        else if (run.failure->check != want.check || run.failure->frame != want.frame)
            problems.push_back(fmt::format("expected {} to break first at frame {}, got {}", want.check, want.frame,
                                           run.failure->str()));
    } else if (run.failure) {
        problems.push_back(fmt::format("invariant {}", run.failure->str()));
    }
    if (scene.expect_hash && *scene.expect_hash != run.hash && !run.error) {
        std::string where = diverged ? std::string()
                            : last_matched_frame >= 0
                                ? fmt::format(" (expect states match through frame {}: the divergence is after it, or "
                                              "in a hit or overlap)",
                                              last_matched_frame)
                                : std::string(" (no expect state to name the frame)");
        problems.push_back(fmt::format("hash expected {}, got {}{}", format_hash(*scene.expect_hash),
                                       format_hash(run.hash), where));
    }
    // A saved failure log records what its run showed (`found`): say when this run shows something else.
    // A record only: the verdict above stands.
    std::optional<std::string> drift;
    if (scene.found) {
        const Found& was = *scene.found;
        const std::string found = fmt::format("found {} at frame {} ball {}", was.check, was.frame, was.ball);
        if (!run.failure)
            drift = fmt::format("{} when saved, but every check holds now", found);
        else if (run.failure->check != was.check || run.failure->frame != was.frame || run.failure->ball != was.ball)
            drift = fmt::format("{} when saved, now {} at frame {} ball {}", found, run.failure->check,
                                run.failure->frame, run.failure->ball);
    }
    result.passed = problems.empty();
    if (result.passed) {
        result.message = fmt::format("{} frames, hash {}", run.frames_run, format_hash(run.hash));
        if (scene.expect_failure)
            result.message += fmt::format(", expected failure reproduced: {}", run.failure->str());
    } else {
        for (std::size_t i = 0; i < problems.size(); ++i) {
            if (i) result.message += "; ";
            result.message += problems[i];
        }
    }
    if (drift) result.message += "; " + *drift;
    if (diverged && states_are_notes) result.message += fmt::format("; a note: {} (before its failure)", *diverged);
    return result;
}

}  // namespace ricochet
