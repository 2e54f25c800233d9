// Reducing a failing log: the smallest scene found that still fails the same way, by delta debugging over
// its balls, walls, circles and rects, frames cut from both ends, and simpler numbers (docs/scene-log.md,
// "Reduced logs").
//
// "Fails the same way" is decided by the shared checker alone (run_checked, checks.hpp), on the log's
// kernel (or options.kernel):
//   - The log's failure is the first failure of its run with its own `check` lines: check C at frame F for
//     ball B. A candidate fails the same way if run_checked with `check C` alone breaks C at any frame and
//     for any ball (removing entities renumbers the rest and moves the frame). That is the run replay makes of
//     the reduced log, which lists only `check C`, as every failure log does.
//   - A log whose run stops at a StepError (a ball leaving the accepted range, checks.hpp) before any check
//     breaks: a candidate fails the same way if its run with the log's checks stops at a StepError, at any
//     frame and for any ball, with every check holding before it.
//   - Anything else (every check holds, or the log names none, and the run ends): nothing to reduce.
// The log's expect lines and `found` play no part: a log that fails replay only by its `expect hash` or
// `expect state` lines, or by an `expect failure` that does not reproduce, has nothing a check sees.
//
// Every decision is a count of tries, never a clock: the same log and options give the same reduced log,
// byte for byte.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "ricochet/failure_log.hpp"
#include "ricochet/scene.hpp"
#include "ricochet/world.hpp"

namespace ricochet {

/// How many tries reduce_log makes at most by default. A 10^4-wall chain that a ball tunnels out of reduces in
/// about 100; one whose every wall is needed (no-escape of the closed chain) spends them all, about 40 s.
inline constexpr std::uint64_t k_reduce_default_tries = 20'000;

/// A scene's size as a reduction reports it.
struct SceneSize {
    std::size_t walls = 0;    ///< walls
    std::size_t balls = 0;    ///< balls
    std::size_t circles = 0;  ///< static circles
    std::size_t rects = 0;    ///< static rectangles
    std::int64_t frames = 0;  ///< frames stepped
    std::size_t bumpers = 0;  ///< bumpers
    /// walls + balls + circles + rects + bumpers.
    std::size_t entities() const { return walls + balls + circles + rects + bumpers; }
    /// The sizes of scene.
    static SceneSize of(const Scene& scene);
    friend bool operator==(const SceneSize&, const SceneSize&) = default;
};

/// Where a reduction stands, after each try.
struct ReduceProgress {
    std::uint64_t tries = 0;  ///< candidate scenes run so far (every run_checked counts)
    SceneSize size;           ///< the smallest failing scene so far
    std::string_view pass;    ///< the pass under way: "balls", "frames", "walls", "circles", "rects", "bumpers",
                              ///< "numbers"
};

/// Options for reduce_log.
struct ReduceOptions {
    std::optional<KernelId> kernel;  ///< run under this kernel instead of the log's (the reduced log names it)
    /// Stop once this many tries are made (the log's own run and the first cut, 2, are always made).
    std::uint64_t max_tries = k_reduce_default_tries;
    std::function<void(const ReduceProgress&)> on_progress;  ///< called after each try
    std::function<bool()> stop;  ///< asked before each try: true ends the reduction with what it has
};

/// Why a reduction ended.
enum class ReduceEnd : std::uint8_t {
    fixed_point,  ///< a whole round of passes found nothing smaller
    budget,       ///< max_tries were made
    stopped,      ///< options.stop asked to stop
};

/// A reduced log, ready to write.
struct ReducedLog {
    /// The reduced log. For a check failure, the failure log make_failure_log makes for the reduced scene
    /// (kernel, frames cut to the failure, `check C`, `found C F B`, the message as its note, `expect state`
    /// lines, `expect failure C F` if the kernel documents its failures or the input had `expect failure`),
    /// its `from` lines the input's and `reduce ID` (ID: the input's scene_content_id). For a step error,
    /// the reduced scene with the input's checks, frames cut to the error's frame, no found and no expect lines.
    FailureLog log;
    std::optional<StepError> error;  ///< a step-error reduction: where the reduced log's run stops
    SceneSize before;                ///< the input's size
    SceneSize after;                 ///< the reduced log's
    std::uint64_t tries = 0;         ///< candidate scenes run
    ReduceEnd end = ReduceEnd::fixed_point;
};

/// Why a log cannot be reduced: what its run shows instead of a failure.
struct ReduceRefusal {
    std::string message;  ///< one line: "every check holds under robust through frame 10: nothing to reduce"
};

/// Reduces log (its scene, kernel, frames and checks) to the smallest failing scene its passes find, in
/// this order, each pass repeated in rounds until a round finds nothing smaller or the budget is spent:
/// frames cut to the failing frame; balls (the failing ball alone first, then delta debugging: chunks
/// from all of them halving down to one); frames cut from the front (every ball started from its state
/// at a later frame); walls (for no-tunnel the wall the path went through alone, then with the walls the
/// balls hit, then delta debugging); circles; rects; bumpers; then each number in turn replaced by a simpler one
/// (0, an integer, fewer significant digits, a dyadic fraction k/2^j, without its sign: fewer characters
/// in the log). Never throws on a valid scene.
std::variant<ReducedLog, ReduceRefusal> reduce_log(const Scene& log, const ReduceOptions& options = {});

}  // namespace ricochet
