// Reducing a failing log (reduce.hpp): the target from the log's own run, rounds of passes to a fixed
// point or the end of the budget, and the reduced log written as a failure log.
#include "ricochet/reduce.hpp"

#include <fmt/format.h>

#include "reduce/passes.hpp"
#include "ricochet/format.hpp"
#include "ricochet/scene_log_format.hpp"

namespace ricochet {

SceneSize SceneSize::of(const Scene& scene) {
    return {scene.walls.size(), scene.balls.size(), scene.circles.size(), scene.rects.size(), scene.frames,
            scene.bumpers.size()};
}

std::variant<ReducedLog, ReduceRefusal> reduce_log(const Scene& log, const ReduceOptions& options) {
    using namespace detail::reduce;
    const KernelId kernel = options.kernel.value_or(log.kernel);
    // The log's own run names what must keep failing: its first failure, else its step error.
    const CheckedRun run = run_to_first_failure(log, kernel, log.checks);
    Target target;
    if (run.failure) {
        target = {run.failure->check, {run.failure->check}, culprit_of(log, *run.failure)};
    } else if (run.error) {
        target = {std::nullopt, log.checks, std::nullopt};
    } else if (log.checks.empty()) {
        return ReduceRefusal{fmt::format("the log names no check and its run under {} ends at frame {} without an "
                                         "error: nothing to reduce",
                                         kernel, run.frames_run)};
    } else {
        return ReduceRefusal{
            fmt::format("every check holds under {} through frame {}: nothing to reduce", kernel, run.frames_run)};
    }
    // The first try: the bare scene (no expect lines) with only the target's checks, cut to the failing frame.
    Scene bare;
    bare.kernel = kernel;
    bare.frames = run.failure ? run.failure->frame : run.error->frame;
    bare.walls = log.walls;
    bare.balls = log.balls;
    bare.masses = log.masses;                // one per ball, or none
    bare.balls_collide = log.balls_collide;  // kept: without it the balls pass through each other, another case
    bare.circles = log.circles;
    bare.rects = log.rects;
    bare.bumpers = log.bumpers;
    bare.checks = target.checks;
    bare.domain = log.domain;  // every smaller case stays in the log's domain, and the reduced log states it
    std::optional<Failing> start = judge(bare, kernel, target);
    // A guard: a check's verdict does not depend on the other checks listed, so C alone breaks where it broke
    // among them (checks.hpp; a trace that differs is the first tracing check's failure either way), and a
    // run is deterministic.
    if (!start)
        return ReduceRefusal{run.failure ? fmt::format("{} does not break with `check {}` alone: nothing to reduce",
                                                       run.failure->str(), run.failure->check)
                                         : fmt::format("{} does not happen again: nothing to reduce", run.error->message())};

    Trials trials(kernel, target, std::move(*start), options, 2);
    ReducedLog out;
    for (;;) {
        const std::uint64_t kept = trials.kept();
        cut_balls(trials);
        cut_front_frames(trials);
        cut_walls(trials);
        cut_statics(trials);
        simplify_numbers(trials);
        if (trials.ended()) {
            out.end = *trials.ended();
            break;
        }
        if (trials.kept() == kept) {
            out.end = ReduceEnd::fixed_point;
            break;
        }
    }

    const Failing& reduced = trials.current();
    std::vector<std::string> provenance = log.provenance;
    if (provenance.size() < k_max_provenance) provenance.push_back("reduce " + scene_content_id(log));
    if (reduced.failure) {
        out.log = make_failure_log(reduced.scene, kernel, "", *reduced.failure);
        // A documented failure stays documented, whatever the kernel.
        if (log.expect_failure) out.log.scene.expect_failure = ExpectFailure{reduced.failure->check, reduced.failure->frame};
    } else {
        out.log.scene = reduced.scene;
        out.log.note = reduced.error->message();
        out.error = reduced.error;
    }
    out.log.scene.provenance = std::move(provenance);
    out.before = SceneSize::of(log);
    out.after = SceneSize::of(out.log.scene);
    out.tries = trials.tries();
    return out;
}

}  // namespace ricochet
