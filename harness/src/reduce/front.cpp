// Cutting frames from the front of a failing scene: every ball starts where the run had it at a later
// frame (passes.hpp). What a kernel remembers of a ball (BallMemory: lecture's wall just bounced off) is
// not in a log, so the shorter run may differ; the check decides, as for every candidate.
#include <map>

#include "reduce/passes.hpp"

namespace ricochet::detail::reduce {

void cut_front_frames(Trials& trials) {
    const std::int64_t f = trials.current().frame();
    const std::size_t balls = trials.current().scene.balls.size();
    // Degenerate: nothing to cut at frame 0, and no ball to move.
    if (f < 1 || balls == 0) return;
    // Start at frame F − L with L = 0, 1, 2, 4, … < F frames left, the shortest first.
    std::map<std::int64_t, std::vector<Ball>> starts;
    for (std::int64_t left = 0; left < f; left = left == 0 ? 1 : 2 * left) starts[f - left];
    const bool ran = trials.observe(
        [&](std::span<const Event> events) {
            for (const Event& e : events) {
                const auto at = starts.find(e.frame);
                // A frame's states come ball by ball in index order (docs/scene-log.md).
                // A state has no radius: each ball keeps its own.
                if (e.kind == Event::Kind::state && at != starts.end() && at->second.size() < balls)
                    at->second.push_back(Ball{e.pos, e.vel, trials.current().scene.balls[at->second.size()].r});
            }
        },
        "frames");
    if (!ran) return;
    for (auto it = starts.rbegin(); it != starts.rend(); ++it) {
        const auto& [start, states] = *it;
        // A guard: the run stops at F, so every frame up to it printed every ball.
        if (states.size() != balls) continue;
        Scene candidate = trials.current().scene;
        candidate.balls = states;
        candidate.frames = f - start;
        if (trials.attempt(std::move(candidate), "frames")) return;
        if (trials.spent()) return;
    }
}

}  // namespace ricochet::detail::reduce
