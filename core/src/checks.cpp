// The `check` invariants, run frame by frame alongside a World (definitions in checks.hpp), replay
// against expect lines, and recording of expect lines.
#include "ricochet/checks.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include "ricochet/hash.hpp"
#include "ricochet/tunnel.hpp"

namespace ricochet {

double speed_rel_bound(KernelId kernel) {
    switch (kernel) {
        case KernelId::lecture_float: return 1e-3;
        case KernelId::lecture_double: return 1e-6;
        case KernelId::robust:
        case KernelId::exact: return k_speed_rel_bound;
    }
    return k_speed_rel_bound;
}

std::string CheckFailure::str() const {
    return fmt::format("{} broke at frame {} ball {}: {}", check_name(check), frame, ball, message);
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
    for (Rect& r : m.rects) r = {-r.right, r.bottom, -r.left, r.top};
    return m;
}

namespace {

Event mirrored(Event e) {
    e.pos.x = -e.pos.x;
    e.vel.x = -e.vel.x;
    return e;
}

std::string sides(int s) { return s > 0 ? "outside" : s < 0 ? "inside" : "on"; }

/// Runs the checks of one frame; holds the per-check state between frames.
class Checker {
public:
    Checker(const Scene& scene, KernelId kernel, std::span<const Check> checks)
        : scene_(scene), kernel_(kernel), checks_(checks.begin(), checks.end()), last_(scene.balls.size()) {
        for (Check c : checks_) {
            if (c == Check::no_tunnel) tunnel_.emplace(scene.walls, scene.balls);
            if (c == Check::symmetry) {
                mirror_scene_ = mirror_x(scene);
                mirror_.emplace(mirror_scene_, kernel);
            }
            if (c == Check::deterministic) twin_.emplace(scene, kernel);
        }
        for (std::size_t i = 0; i < scene.balls.size(); ++i) last_[i] = scene.balls[i].pos;
    }

    /// Frame 0: the initial states and overlaps.
    std::optional<CheckFailure> start(std::span<const Event> events) {
        other_.clear();
        if (mirror_) mirror_->start(other_);
        mirror_events_ = other_;
        other_.clear();
        if (twin_) twin_->start(other_);
        return check_frame(0, events, {}, {});
    }

    /// Frame f, given the balls and memories before it and its events.
    std::optional<CheckFailure> step(std::int64_t f, std::span<const Event> events, std::span<const Ball> before,
                                     std::span<const BallMemory> memory_before) {
        other_.clear();
        if (mirror_) (void)mirror_->step(other_);
        mirror_events_ = other_;
        other_.clear();
        if (twin_) (void)twin_->step(other_);
        return check_frame(f, events, before, memory_before);
    }

private:
    std::optional<CheckFailure> check_frame(std::int64_t f, std::span<const Event> events, std::span<const Ball> before,
                                            std::span<const BallMemory> memory_before) {
        std::optional<CheckFailure> first;
        for (Check c : checks_) {
            std::optional<CheckFailure> r;
            switch (c) {
                case Check::no_tunnel: r = no_tunnel(f, events); break;
                case Check::symmetry: r = compare(Check::symmetry, f, events, mirror_events_, true); break;
                case Check::boundary: r = boundary(f, events); break;
                case Check::speed: r = speed(f, events, before); break;
                case Check::deterministic: r = compare(Check::deterministic, f, events, other_, false); break;
                case Check::oracle: r = oracle(f, events, before, memory_before); break;
            }
            // Every check keeps its state up to date, but the first in the scene's order is reported.
            if (r && !first) first = r;
        }
        return first;
    }

    std::optional<CheckFailure> no_tunnel(std::int64_t f, std::span<const Event> events) {
        std::optional<CheckFailure> found;
        for (const Event& e : events) {
            if (e.kind == Event::Kind::overlap || (e.kind == Event::Kind::state && f == 0)) continue;
            const Vec2 q = last_[e.ball];
            last_[e.ball] = e.pos;
            const auto w = tunnel_->advance(e.ball, e.pos);
            if (w && !found) {
                const Wall& wall = scene_.walls[*w];
                found = CheckFailure{Check::no_tunnel, f, e.ball,
                                     fmt::format("the path piece ({}, {}) -> ({}, {}) goes through wall {} ({} {} {} {}); "
                                                 "expected no piece to cross a wall",
                                                 q.x, q.y, e.pos.x, e.pos.y, *w, wall.p0.x, wall.p0.y, wall.p1.x,
                                                 wall.p1.y)};
            }
        }
        return found;
    }

    static std::optional<CheckFailure> compare(Check c, std::int64_t f, std::span<const Event> events,
                                               std::span<const Event> other, bool mirror) {
        const std::size_t n = std::min(events.size(), other.size());
        for (std::size_t j = 0; j < n; ++j) {
            const Event expected = mirror ? mirrored(events[j]) : events[j];
            const Event& actual = other[j];
            // Symmetry compares values (−0 == +0: x − x is +0 in both runs); determinism compares bits
            // through the hash record.
            bool same = expected == actual;
            if (!mirror && same) {
                unsigned char a[k_event_record_size], b[k_event_record_size];
                encode_event(expected, a);
                encode_event(actual, b);
                same = std::equal(a, a + k_event_record_size, b);
            }
            if (!same)
                return CheckFailure{c, f, events[j].ball,
                                    fmt::format("{} gives '{}', expected '{}'",
                                                mirror ? "the run mirrored across x = 0" : "a second run",
                                                format_event(actual), format_event(expected))};
        }
        if (events.size() != other.size()) {
            const std::uint32_t ball = n < events.size() ? events[n].ball : other[n].ball;
            return CheckFailure{c, f, ball,
                                fmt::format("{} has {} events in this frame, expected {}",
                                            mirror ? "the mirrored run" : "a second run", other.size(), events.size())};
        }
        return std::nullopt;
    }

    std::optional<CheckFailure> boundary(std::int64_t f, std::span<const Event> events) const {
        for (const Event& e : events) {
            if (e.kind != Event::Kind::state) continue;
            const Vec2 p = e.pos;
            const auto fail = [&](std::string m) { return CheckFailure{Check::boundary, f, e.ball, std::move(m)}; };
            // A radius-0 circle and a zero-size rect are the point itself: touching counts.
            if (!point_in_circle(kernel_, p, Circle{p, 0.0}))
                return fail(fmt::format("({}, {}) is not in the radius-0 circle at itself; expected inside", p.x, p.y));
            if (!point_in_rect(kernel_, p, Rect{p.x, p.y, p.x, p.y}))
                return fail(fmt::format("({}, {}) is not in the zero-size rect at itself; expected inside", p.x, p.y));
            for (std::size_t c = 0; c < scene_.circles.size(); ++c) {
                const bool a = point_in_circle(kernel_, p, scene_.circles[c]);
                const bool b = circles_overlap(kernel_, Circle{p, 0.0}, scene_.circles[c]);
                if (a != b)
                    return fail(fmt::format("point/circle says {} but circle/circle with radius 0 says {} for circle {}",
                                            a ? "inside" : "outside", b ? "overlap" : "apart", c));
            }
            for (std::size_t r = 0; r < scene_.rects.size(); ++r) {
                const bool a = point_in_rect(kernel_, p, scene_.rects[r]);
                const bool b = rects_overlap(kernel_, Rect{p.x, p.y, p.x, p.y}, scene_.rects[r]);
                if (a != b)
                    return fail(fmt::format("point/rect says {} but rect/rect with a zero-size rect says {} for rect {}",
                                            a ? "inside" : "outside", b ? "overlap" : "apart", r));
            }
            // The classification of Bs and the sweep's first two tests read the same sign of BC(Bs).
            if (e.vel == Vec2{}) continue;
            for (std::size_t w = 0; w < scene_.walls.size(); ++w) {
                const Side s = classify(kernel_, p, scene_.walls[w]);
                const Miss m = sweep(kernel_, p, e.vel, scene_.walls[w]).miss;
                const bool bad = (s == Side::on && (m == Miss::both_inside || m == Miss::both_outside)) ||
                                 (s == Side::inside && m == Miss::both_outside) ||
                                 (s == Side::outside && m == Miss::both_inside);
                if (bad)
                    return fail(fmt::format("classify says ({}, {}) is {} wall {} but the sweep from it says {}",
                                            p.x, p.y, sides(sign_of(s)), w, miss_name(m)));
            }
        }
        return std::nullopt;
    }

    std::optional<CheckFailure> speed(std::int64_t f, std::span<const Event> events, std::span<const Ball> before) const {
        if (f == 0) return std::nullopt;
        const double b = speed_rel_bound(kernel_);
        int bounces = 0;
        for (const Event& e : events) {
            if (e.kind == Event::Kind::hit) ++bounces;
            if (e.kind != Event::Kind::state) continue;
            const double v0 = std::hypot(before[e.ball].vel.x, before[e.ball].vel.y);
            const double v1 = std::hypot(e.vel.x, e.vel.y);
            // | |v1| − |v0| | ≤ ((1+b)^n − 1)·|v0| + n·a + 4·2^−53·|v0| + 2^−1073 (hypot's own rounding on
            // both sides, relative and, for subnormal speeds, absolute); a = k_speed_abs_bound.
            const double allowed = (std::pow(1.0 + b, bounces) - 1.0) * v0 + bounces * k_speed_abs_bound +
                                   0x1p-51 * v0 + 0x1p-1073;
            if (std::fabs(v1 - v0) > allowed)
                return CheckFailure{Check::speed, f, e.ball,
                                    fmt::format("|v| went from {} to {} over {} bounce(s): relative change {:.3g}, "
                                                "allowed {:.3g}",
                                                v0, v1, bounces, std::fabs(v1 - v0) / v0, allowed / v0)};
            bounces = 0;
        }
        return std::nullopt;
    }

    std::optional<CheckFailure> oracle(std::int64_t f, std::span<const Event> events, std::span<const Ball> before,
                                       std::span<const BallMemory> memory_before) {
        if (f == 0 || kernel_ == KernelId::exact) return std::nullopt;
        std::vector<std::optional<std::uint32_t>> first(before.size());
        std::vector<bool> seen(before.size(), false);
        for (const Event& e : events)
            if (e.kind == Event::Kind::hit && !seen[e.ball]) {
                seen[e.ball] = true;
                first[e.ball] = e.index;
            }
        for (std::size_t i = 0; i < before.size(); ++i) {
            Ball ball = before[i];
            BallMemory memory = memory_before[i];
            hits_.clear();
            (void)step_ball(KernelId::exact, ball, memory, scene_.walls, hits_, scratch_);
            const std::optional<std::uint32_t> want =
                hits_.empty() ? std::nullopt : std::optional<std::uint32_t>(hits_.front().wall);
            if (want != first[i]) {
                const auto name = [](std::optional<std::uint32_t> w) {
                    return w ? fmt::format("wall {}", *w) : std::string("no wall");
                };
                return CheckFailure{Check::oracle, f, static_cast<std::uint32_t>(i),
                                    fmt::format("from ({}, {}) moving ({}, {}) the kernel hits {} first, the exact "
                                                "kernel hits {}",
                                                before[i].pos.x, before[i].pos.y, before[i].vel.x, before[i].vel.y,
                                                name(first[i]), name(want))};
            }
        }
        return std::nullopt;
    }

    const Scene& scene_;
    KernelId kernel_;
    std::vector<Check> checks_;
    std::optional<TunnelChecker> tunnel_;
    Scene mirror_scene_;
    std::optional<World> mirror_;
    std::optional<World> twin_;
    std::vector<Event> other_;
    std::vector<Event> mirror_events_;
    std::vector<Vec2> last_;
    std::vector<HitEvent> hits_;
    StepScratch scratch_;
};

}  // namespace

CheckedRun run_checked(const Scene& scene, KernelId kernel, std::int64_t frames, std::span<const Check> checks,
                       const CheckOptions& options) {
    CheckedRun run;
    World world(scene, kernel);
    std::optional<Checker> checker;
    if (!checks.empty()) checker.emplace(scene, kernel, checks);
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
    if (checker) run.failure = checker->start(events);
    for (std::int64_t f = 1; f <= frames; ++f) {
        const bool checking = checker && !run.failure;
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
        if (checking) run.failure = checker->step(f, events, before, memory_before);
        // Nothing left to check: drop the mirrored and twin worlds' work.
        if (run.failure) checker.reset();
    }
    run.hash = hasher.digest();
    return run;
}

namespace {

std::string state_text(const Ball& b) { return fmt::format("{} {} {} {}", b.pos.x, b.pos.y, b.vel.x, b.vel.y); }

bool same_ball_bits(const Ball& a, const Ball& b) {
    const auto bits = [](double x) { return std::bit_cast<std::uint64_t>(x); };
    return bits(a.pos.x) == bits(b.pos.x) && bits(a.pos.y) == bits(b.pos.y) && bits(a.vel.x) == bits(b.vel.x) &&
           bits(a.vel.y) == bits(b.vel.y);
}

}  // namespace

ReplayResult replay_scene(const Scene& scene, std::optional<KernelId> kernel) {
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
                    if (!same_ball_bits(got, x.state) && !diverged)
                        diverged = fmt::format("first diverging frame {}: ball {} expected state {}, got {}", f,
                                               x.ball, state_text(x.state), state_text(got));
                    else if (!diverged)
                        last_matched_frame = f;
                }
        }
    };
    const KernelId k = kernel.value_or(scene.kernel);
    result.run = run_checked(scene, k, scene.frames, scene.checks, options);
    const CheckedRun& run = result.run;

    std::vector<std::string> problems;
    if (run.error) problems.push_back(run.error->message());
    if (diverged) problems.push_back(*diverged);
    if (scene.expect_failure) {
        const ExpectFailure& want = *scene.expect_failure;
        if (!run.failure)
            problems.push_back(fmt::format("expected {} to break first at frame {}, but every check held",
                                           check_name(want.check), want.frame));
        else if (run.failure->check != want.check || run.failure->frame != want.frame)
            problems.push_back(fmt::format("expected {} to break first at frame {}, got {}", check_name(want.check),
                                           want.frame, run.failure->str()));
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
    return result;
}

CheckedRun record_expectations(Scene& scene) {
    const std::size_t nb = scene.balls.size();
    const std::int64_t frames = scene.frames;
    // Which frames get `expect state` lines: every frame for small runs, else 8 spread frames and the last.
    std::set<std::int64_t> chosen;
    if (static_cast<double>(frames + 1) * static_cast<double>(nb) <= 64.0) {
        for (std::int64_t f = 0; f <= frames; ++f) chosen.insert(f);
    } else {
        for (std::int64_t k = 1; k <= 8; ++k) chosen.insert(frames * k / 8);
        chosen.insert(frames);
    }
    const std::uint32_t balls_recorded = static_cast<std::uint32_t>(std::min<std::size_t>(nb, 8));
    std::vector<ExpectState> states;
    CheckOptions options;
    options.keep_events = false;
    options.on_frame = [&](std::span<const Event> events) {
        for (const Event& e : events)
            if (e.kind == Event::Kind::state && e.ball < balls_recorded && chosen.count(e.frame))
                states.push_back({e.frame, e.ball, Ball{e.pos, e.vel}});
    };
    CheckedRun run = run_checked(scene, scene.kernel, frames, scene.checks, options);
    if (run.error) return run;
    scene.expect_hash = run.hash;
    scene.expect_failure.reset();
    if (run.failure) scene.expect_failure = ExpectFailure{run.failure->check, run.failure->frame};
    scene.expect_states = std::move(states);
    return run;
}

}  // namespace ricochet
