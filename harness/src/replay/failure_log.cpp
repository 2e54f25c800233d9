// Failure logs: the scene log a harness saves for a failing run (failure_log.hpp).
#include "ricochet/failure_log.hpp"

#include <algorithm>
#include <fmt/format.h>

#include "replay/state_sampler.hpp"
#include "ricochet/format.hpp"
#include "ricochet/scene_log_format.hpp"

namespace ricochet {

bool documents_weakness(KernelId kernel) { return kernel_ops(kernel).failures_documented; }

bool FailureLog::reproduces() const {
    return replayed && scene.found && replayed->check == scene.found->check && replayed->frame == scene.found->frame &&
           replayed->ball == scene.found->ball;
}

std::string FailureLog::text() const {
    std::string out = write_scene_log(scene);
    if (!scene.found || note.empty()) return out;
    const std::string line = fmt::format("found {} {} {}\n", scene.found->check, scene.found->frame, scene.found->ball);
    const std::size_t at = out.find(line);
    // A guard: write_scene_log writes a found as this very line, so it is always there.
    if (at == std::string::npos) return out;
    // One comment line: a newline in the message would end the comment and start a directive.
    std::string comment = "# ";
    for (char c : note) comment += (c == '\n' || c == '\r') ? ' ' : c;
    out.insert(at + line.size(), comment + "\n");
    return out;
}

FailureLog make_failure_log(const Scene& scene, KernelId kernel, std::string_view provenance,
                            const CheckFailure& failure) {
    FailureLog log;
    Scene& s = log.scene;
    s = scene;
    s.kernel = kernel;
    s.frames = failure.frame;
    s.checks = {failure.check};
    s.provenance = {std::string(provenance)};
    s.found = Found{failure.check, failure.frame, failure.ball};
    s.expect_hash.reset();
    s.expect_states.clear();
    s.expect_failure.reset();
    log.note = failure.message;

    // `expect state` lines at the frames before F, as `ricochet record` picks them for a run through F − 1.
    detail::StateSampler sampler(failure.frame - 1, s.balls.size());
    CheckOptions options;
    options.keep_events = false;
    options.on_frame = [&](std::span<const Event> events) { sampler.add(events); };
    // The log's own run, as replay will run it.
    const CheckedRun run = run_checked(s, kernel, s.frames, s.checks, options);
    s.expect_states = sampler.take();
    log.replayed = run.failure;
    if (documents_weakness(kernel)) s.expect_failure = ExpectFailure{failure.check, failure.frame};
    return log;
}

Scene plugin_case_log(const Scene& scene, KernelId kernel, std::string_view provenance) {
    Scene s = scene;
    s.kernel = kernel;
    s.provenance = {std::string(provenance)};
    // Replay steps what the checks step: every check, so that it reaches the call that crashed.
    if (s.checks.empty()) s.checks.assign(k_all_checks.begin(), k_all_checks.end());
    // Those its domain waives are not run, and a log may not name them (docs/scene-log.md, "Domain").
    const std::span<const Check> waived = waived_checks(s.domain);
    std::erase_if(s.checks, [&](Check c) { return std::find(waived.begin(), waived.end(), c) != waived.end(); });
    s.found.reset();
    s.expect_hash.reset();
    s.expect_states.clear();
    s.expect_failure.reset();
    return s;
}

}  // namespace ricochet
