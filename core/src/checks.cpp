// The `check` invariants, run frame by frame alongside a World (definitions in checks.hpp).
#include "ricochet/checks.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "ricochet/bits.hpp"
#include "ricochet/format.hpp"
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
    for (Rect& r : m.rects) r = {-r.right, r.bottom, -r.left, r.top};
    return m;
}

namespace {

Event mirrored(Event e) {
    e.pos.x = -e.pos.x;
    e.vel.x = -e.vel.x;
    return e;
}

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
                                     fmt::format("the path piece {} -> {} goes through wall {} ({}); "
                                                 "expected no piece to cross a wall",
                                                 q, e.pos, *w, wall)};
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
            if (!mirror && same) same = same_bits(expected, actual);
            if (!same)
                return CheckFailure{c, f, events[j].ball,
                                    fmt::format("{} gives '{}', expected '{}'",
                                                mirror ? "the run mirrored across x = 0" : "a second run",
                                                actual, expected)};
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
                return fail(fmt::format("{} is not in the radius-0 circle at itself; expected inside", p));
            if (!point_in_rect(kernel_, p, Rect{p.x, p.y, p.x, p.y}))
                return fail(fmt::format("{} is not in the zero-size rect at itself; expected inside", p));
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
                const int sign = sign_of(s);  // +1 outside, −1 inside, 0 on
                const Miss m = sweep(kernel_, p, e.vel, scene_.walls[w]).miss;
                const bool bad = (sign == 0 && (m == Miss::both_inside || m == Miss::both_outside)) ||
                                 (sign < 0 && m == Miss::both_outside) || (sign > 0 && m == Miss::both_inside);
                if (bad)
                    return fail(fmt::format("classify says {} is {} wall {} but the sweep from it says {}", p, s, w,
                                            m));
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
                                    fmt::format("from {} moving {} the kernel hits {} first, the exact kernel hits {}",
                                                before[i].pos, before[i].vel, name(first[i]), name(want))};
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

}  // namespace ricochet
