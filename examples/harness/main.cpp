// harness_consumer LOG: replays a scene log as `ricochet replay` does (its checks and expect lines), then runs it
// again with every check defined for its scene, and prints both verdicts. Exit 0 if the replay passed, 1 if not,
// 2 if the log cannot be read.
#include <algorithm>
#include <variant>
#include <vector>

#include <fmt/core.h>

#include "ricochet/checks.hpp"
#include "ricochet/replay.hpp"
#include "ricochet/scene_log.hpp"

int main(int argc, char** argv) {
    if (argc != 2) {
        fmt::print(stderr, "usage: harness_consumer LOG\n");
        return 2;
    }
    const ricochet::SceneOrDiagnostic read = ricochet::read_scene_log(argv[1]);
    if (const auto* bad = std::get_if<ricochet::Diagnostic>(&read)) {
        fmt::print(stderr, "{}\n", bad->str());
        return 2;
    }
    const auto& scene = std::get<ricochet::Scene>(read);

    // The log's own verdict: its checks, then its expect lines.
    const ricochet::ReplayResult replayed = ricochet::replay_scene(scene);
    fmt::print("replay: {}: {}\n", replayed.passed ? "passed" : "FAILED", replayed.message);

    // Every check, under the log's kernel.
    const std::vector<ricochet::Check> checks(ricochet::k_all_checks.begin(), ricochet::k_all_checks.end());
    try {
        const ricochet::CheckedRun run = ricochet::run_checked(scene, scene.kernel, scene.frames, checks);
        if (run.error)
            fmt::print("all checks: stopped: {}\n", run.error->message());
        else if (run.failure)
            fmt::print("all checks: {}\n", run.failure->str());
        else
            fmt::print("all checks: {} held over {} frames\n", checks.size(), run.frames_run);
    } catch (const ricochet::UnsupportedScene& refused) {  // the kernel cannot step this scene
        fmt::print("all checks: refused: {}\n", refused.what());
    }
    return replayed.passed ? 0 : 1;
}
