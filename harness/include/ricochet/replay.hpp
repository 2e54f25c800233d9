// Replay: a log's run against its checks and its expect lines, the verdict `ricochet replay` prints.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "ricochet/checks.hpp"
#include "ricochet/scene.hpp"

namespace ricochet {

/// Outcome of replaying one log against its checks and expect lines.
struct ReplayResult {
    bool passed = false;  ///< every check and expect line held (or the expected failure reproduced)
    std::string message;  ///< one line: why it failed, or what it checked
    CheckedRun run;       ///< the run itself (events not kept)
    bool stopped = false; ///< stop asked to end it after frame run.frames_run, before its last: no verdict
};

/// Asked between two frames of a replay: true stops it there (a SIGINT, a SIGTERM).
using ReplayStop = std::function<bool()>;

/// Replays scene (its kernel unless overridden, its frames): checks, then expect failure / hash / states.
/// A log with `expect failure C F` passes only if C fails first at frame F. When stop (if given) says so after
/// a frame, the run ends there: stopped is set, passed is false, and the message says where it stopped.
ReplayResult replay_scene(const Scene& scene, std::optional<KernelId> kernel = std::nullopt,
                          const ReplayStop& stop = {});

}  // namespace ricochet
