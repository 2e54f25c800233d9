// Failure logs: the scene log a harness saves for a failing run (failure_log.hpp).
#include "ricochet/failure_log.hpp"

#include <algorithm>
#include <set>
#include <vector>

#include <fmt/format.h>

#include "ricochet/format.hpp"
#include "ricochet/scene_log_format.hpp"

namespace ricochet {

bool documents_weakness(KernelId kernel) {
    return kernel == KernelId::lecture_float || kernel == KernelId::lecture_double;
}

bool FailureLog::reproduces() const {
    return replayed && scene.found && replayed->check == scene.found->check && replayed->frame == scene.found->frame &&
           replayed->ball == scene.found->ball;
}

std::string FailureLog::text() const {
    std::string out = write_scene_log(scene);
    if (!scene.found || note.empty()) return out;
    const std::string line = fmt::format("found {} {} {}\n", scene.found->check, scene.found->frame, scene.found->ball);
    const std::size_t at = out.find(line);
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

    // The frames before F that get `expect state` lines: all of 0..F−1 for small runs, else the 8 frames
    // (F−1)·k/8, k = 1..8 (record.cpp's rule with F−1 as the last frame).
    const std::int64_t last = failure.frame - 1;
    const std::size_t nb = s.balls.size();
    std::set<std::int64_t> chosen;
    if (last >= 0) {
        if (static_cast<double>(last + 1) * static_cast<double>(nb) <= k_failure_log_all_frames) {
            for (std::int64_t f = 0; f <= last; ++f) chosen.insert(f);
        } else {
            for (std::int64_t k = 1; k <= 8; ++k) chosen.insert(last * k / 8);
        }
    }
    const auto balls = static_cast<std::uint32_t>(std::min<std::size_t>(nb, k_failure_log_balls));
    std::vector<ExpectState> states;
    CheckOptions options;
    options.keep_events = false;
    options.on_frame = [&](std::span<const Event> events) {
        for (const Event& e : events)
            if (e.kind == Event::Kind::state && e.ball < balls && chosen.count(e.frame))
                states.push_back({e.frame, e.ball, Ball{e.pos, e.vel}});
    };
    // The log's own run, as replay will run it.
    const CheckedRun run = run_checked(s, kernel, s.frames, s.checks, options);
    s.expect_states = std::move(states);
    log.replayed = run.failure;
    if (documents_weakness(kernel)) s.expect_failure = ExpectFailure{failure.check, failure.frame};
    return log;
}

}  // namespace ricochet
