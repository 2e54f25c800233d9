// run_checked: a World stepped frame by frame with the scene's checks asserted on every frame
// (checks.hpp); the first failure is the earliest frame, then the first check in the scene's order,
// then the lowest ball.
#include <algorithm>
#include <utility>

#include <fmt/format.h>

#include "checks/frame_check.hpp"
#include "ricochet/bits.hpp"
#include "ricochet/format.hpp"
#include "ricochet/hash.hpp"

namespace ricochet {

std::string CheckFailure::str() const {
    return fmt::format("{} broke at frame {} ball {}: {}", check, frame, ball, message);
}

Scene mirror_x(const Scene& scene) {
    Scene m = scene;
    // x ↦ −x is exact for every double; walls keep their direction (so the mirrored wall's normal is the
    // mirror of the normal, and every cross product is exactly negated).
    for (Wall& w : m.walls) {
        w.p0.x = -w.p0.x;
        w.p1.x = -w.p1.x;
    }
    for (Ball& b : m.balls) {
        b.pos.x = -b.pos.x;
        b.vel.x = -b.vel.x;
    }
    for (Circle& c : m.circles) c.c.x = -c.c.x;
    for (Bumper& c : m.bumpers) c.c.x = -c.c.x;
    for (Rect& r : m.rects) r = {-r.right, r.bottom, -r.left, r.top};
    return m;
}

namespace checks {

std::unique_ptr<FrameCheck> make_check(Check c, const Scene& scene, KernelId kernel, const WorldOptions& world) {
    // Unreachable default: every Check has a case; only a value outside the enumeration falls through.
    switch (c) {
        case Check::no_tunnel: return make_no_tunnel(scene, kernel, world);
        case Check::symmetry: return make_symmetry(scene, kernel, world);
        case Check::boundary: return make_boundary(scene, kernel, world);
        case Check::speed: return make_speed(scene, kernel, world);
        case Check::deterministic: return make_deterministic(scene, kernel, world);
        case Check::oracle: return make_oracle(scene, kernel, world);
        case Check::swap: return make_swap(scene, kernel, world);
        case Check::translation: return make_translation(scene, kernel, world);
        case Check::broad_phase: return make_broad_phase(scene, kernel, world);
        case Check::round_trip: return make_round_trip(scene, kernel, world);
        case Check::no_escape: return make_no_escape(scene, kernel, world);
        case Check::bounce_side: return make_bounce_side(scene, kernel, world);
        case Check::accuracy: return make_accuracy(scene, kernel, world);
        case Check::event_order: return make_event_order(scene, kernel, world);
        case Check::penetration: return make_penetration(scene, kernel, world);
        case Check::ghost_bounce: return make_ghost_bounce(scene, kernel, world);
        case Check::plan: return make_plan(scene, kernel, world);
        case Check::ball_overlap: return make_ball_overlap(scene, kernel, world);
        case Check::pass_through: return make_pass_through(scene, kernel, world);
        case Check::momentum: return make_momentum(scene, kernel, world);
        case Check::relabel: return make_relabel(scene, kernel, world);
        case Check::jump_through: return make_jump_through(scene, kernel, world);
    }
    return nullptr;
}

std::optional<CheckFailure> compare_events(Check c, std::int64_t f, std::span<const Event> expected,
                                           std::span<const Event> actual, bool bits, std::string_view who) {
    const std::size_t n = std::min(expected.size(), actual.size());
    for (std::size_t j = 0; j < n; ++j) {
        const bool same = bits ? same_bits(expected[j], actual[j]) : expected[j] == actual[j];
        if (!same)
            return failure(c, f, expected[j].ball,
                           fmt::format("{} gives '{}', expected '{}'", who, actual[j], expected[j]));
    }
    if (expected.size() != actual.size()) {
        const std::uint32_t ball = n < expected.size() ? expected[n].ball : actual[n].ball;
        return failure(c, f, ball,
                       fmt::format("{} has {} events in this frame, expected {}", who, actual.size(), expected.size()));
    }
    return std::nullopt;
}

namespace {

/// The scene's checks, run on every frame, with the traces they read.
class Checker {
public:
    Checker(const Scene& scene, KernelId kernel, std::span<const Check> checks, const WorldOptions& world)
        : kernel_(kernel), balls_collide_(scene.balls_collide) {
        for (Check c : checks) {
            checks_.push_back(make_check(c, scene, kernel, world));
            if (checks_.back()->needs_traces() && !tracer_) tracer_ = c;
        }
        traces_.resize(scene.balls.size());
    }

    std::optional<CheckFailure> run(const World& world, Frame f) {
        // Balls that meet: the frame's meets and each ball's path, as the World took them.
        f.meets = world.meets();
        if (balls_collide_) {
            paths_.clear();
            for (std::size_t i = 0; i < world.balls().size(); ++i) paths_.push_back(world.path(i));
            f.paths = paths_;
        }
        if (tracer_ && f.index > 0) {
            if (auto bad = trace(world, f)) return failure(*tracer_, f.index, bad->first, std::move(bad->second));
            f.traces = traces_;
        }
        std::optional<CheckFailure> first;
        for (auto& c : checks_) {
            // Every check keeps its state up to date, but the first in the scene's order is reported.
            auto r = c->frame(f);
            if (r && !first) first = std::move(r);
        }
        return first;
    }

private:
    /// Steps each ball again from its state before the frame, with a trace; the step is deterministic,
    /// so it must end where the run's did (else the ball and why). A ball that met another in the frame is not
    /// stepped alone (its trace stays empty, and the checks that read traces do not judge it: met_in_frame).
    std::optional<std::pair<std::uint32_t, std::string>> trace(const World& world, const Frame& f) {
        const std::vector<bool> met = met_in_frame(f, f.before.size());
        for (std::size_t i = 0; i < f.before.size(); ++i) {
            traces_[i].clear();
            if (met[i]) continue;
            Ball ball = f.before[i];
            BallMemory memory = f.memory_before[i];
            hits_.clear();
            scratch_.trace = &traces_[i];
            traces_[i].stopped_at_limit =
                step_ball(kernel_, ball, memory, world.obstacles(), hits_, scratch_) == FrameStatus::bounce_limit;
            scratch_.trace = nullptr;
            const Ball now = world.balls()[i];
            if (!same_bits(ball, now))
                return std::pair{static_cast<std::uint32_t>(i),
                                 fmt::format("stepping the ball again from {} with a trace gives {}, the run gave {}",
                                             f.before[i], ball, now)};
        }
        return std::nullopt;
    }

    KernelId kernel_;
    bool balls_collide_;
    std::vector<std::span<const PathPoint>> paths_;  ///< the frame's paths, one per ball (balls that collide)
    std::vector<std::unique_ptr<FrameCheck>> checks_;
    std::optional<Check> tracer_;  ///< the first check that reads traces: a bad trace is its failure
    std::vector<StepTrace> traces_;
    std::vector<HitEvent> hits_;
    StepScratch scratch_;
};

}  // namespace
}  // namespace checks

std::optional<std::string> refusal(const Scene& scene, KernelId kernel) {
    return unsupported_scene(kernel, scene.balls, scene.bumpers.size());
}

CheckedRun run_checked(const Scene& scene, KernelId kernel, std::int64_t frames, std::span<const Check> checks,
                       const CheckOptions& options) {
    CheckedRun run;
    // A scene the kernel cannot step is refused before anything runs.
    if (auto why = refusal(scene, kernel)) throw UnsupportedScene(*why);
    World world(scene, kernel, options.world);
    // The checks the scene's domain waives (domain.hpp: `waive touching`) are not run.
    std::vector<Check> kept;
    const std::span<const Check> waived = waived_checks(scene.domain);
    for (Check c : checks)
        if (std::find(waived.begin(), waived.end(), c) == waived.end()) kept.push_back(c);
    checks = kept;
    std::optional<checks::Checker> checker;
    if (!checks.empty()) checker.emplace(scene, kernel, checks, options.world);
    RunHasher hasher;
    std::vector<Event> events;
    std::vector<Ball> before;
    std::vector<BallMemory> memory_before;
    const auto finish_frame = [&](std::span<const Event> e) {
        hasher.add(e);
        if (options.on_frame) options.on_frame(e);
        if (options.keep_events) run.events.insert(run.events.end(), e.begin(), e.end());
    };
    world.start(events);
    finish_frame(events);
    if (checker) run.failure = checker->run(world, {0, events, {}, {}, {}});
    if (run.failure) checker.reset();
    const auto stop = [&] { return options.stop_after && options.stop_after(run); };
    const bool stop_at_0 = stop();
    for (std::int64_t f = 1; f <= frames && !stop_at_0; ++f) {
        const bool checking = checker.has_value();
        if (checking) {
            before.assign(world.balls().begin(), world.balls().end());
            memory_before.assign(world.memories().begin(), world.memories().end());
        }
        events.clear();
        const auto error = world.step(events);
        finish_frame(events);
        run.frames_run = f;
        if (error) {
            run.error = error;
            break;
        }
        if (checking) run.failure = checker->run(world, {f, events, before, memory_before, {}});
        // Nothing left to check: drop the checks' own worlds and their work.
        if (run.failure) checker.reset();
        if (stop()) break;
    }
    run.hash = hasher.digest();
    return run;
}

}  // namespace ricochet
