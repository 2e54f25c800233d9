// Failure logs: the scene log a harness saves when a run breaks a check (docs/scene-log.md, "Saved
// failure logs"). On the code that produced it, `ricochet replay` fails the log with the same check at
// the same frame (a lecture kernel's log expects that failure, so replay passes while it reproduces).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "ricochet/checks.hpp"
#include "ricochet/scene.hpp"

namespace ricochet {

/// Most `expect state` lines' balls in a failure log (balls 0..7), as `ricochet record` writes.
inline constexpr std::uint32_t k_failure_log_balls = 8;
/// A failure log has `expect state` lines at every frame before the failure while frames × balls stays
/// at most this; past it, at 8 spread frames (the `ricochet record` rule, applied to frames 0..F−1).
inline constexpr double k_failure_log_all_frames = 64.0;

/// True for the kernels whose failures are documented weaknesses, not bugs (KernelOps::failures_documented:
/// lecture-float, lecture-double and the peers; not a plug-in, the user's own code): their failure logs carry
/// `expect failure`, so replay passes while they reproduce.
bool documents_weakness(KernelId kernel);

/// A failure log, ready to save.
struct FailureLog {
    Scene scene;       ///< the log: kernel, frames cut to F, the one check, found, expect lines, provenance
    std::string note;  ///< the failure's message for people, one line: a `#` comment after `found`
    std::optional<CheckFailure> replayed;  ///< what the log's own run shows (check C only); nothing if it holds
    /// True if the log's own run breaks the same check at the same frame for the same ball as found.
    bool reproduces() const;
    /// The canonical text of scene with `# note` on the line after `found`.
    std::string text() const;
};

/// Makes the log to save for a run of scene under kernel whose first failure is failure, with the
/// provenance words (`property NAME seed S`, `fuzz TARGET SHA1`): kernel K; frames F (the failing
/// frame); `check C` only; `found C F BALL`; `expect state` lines for balls 0..7 at the frames before F
/// (all of them while F × balls ≤ 64, else 8 spread ones); `expect failure C F` for a lecture kernel;
/// no `expect hash` (the run at and after F changes once the bug is fixed). Runs the log once to fill
/// the states and `replayed`.
FailureLog make_failure_log(const Scene& scene, KernelId kernel, std::string_view provenance,
                            const CheckFailure& failure);

/// A case a harness is about to step under a plug-in kernel, as the log its guard keeps should the plug-in
/// crash or hang on it (plugin_guard.hpp, PluginStage): scene under kernel, `from PROVENANCE` in place of its
/// own, its frames, every check if it lists none, no `found` or `expect` lines (nothing failed yet). Keep it
/// as PREFIX-ID.scene (scene_content_id), as saved failures are named.
Scene plugin_case_log(const Scene& scene, KernelId kernel, std::string_view provenance);

}  // namespace ricochet
