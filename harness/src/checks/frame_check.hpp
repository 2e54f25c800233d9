// Internal: one check as the checker runs it, frame after frame (the definitions are in checks.hpp).
#pragma once

#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "ricochet/checks.hpp"
#include "ricochet/meet.hpp"
#include "ricochet/step_trace.hpp"

namespace ricochet::checks {

/// What a check sees of one frame of the run.
struct Frame {
    std::int64_t index = 0;                     ///< 0: the initial states and overlaps
    std::span<const Event> events;              ///< the frame's events, in order
    std::span<const Ball> before;               ///< each ball before the frame (empty at frame 0)
    std::span<const BallMemory> memory_before;  ///< each ball's memory before the frame (empty at frame 0)
    std::span<const StepTrace> traces;          ///< each ball's frame as its kernel stepped it, if asked for
    /// The frame's meets in the order the World took them (World::meets(); empty unless the balls collide).
    std::span<const MeetRecord> meets{};
    /// Each ball's path in the frame, its printed points with their frame times (World::path); empty where the World
    /// gives none.
    std::span<const std::span<const PathPoint>> paths{};
};

/// One check with its state between frames.
class FrameCheck {
public:
    virtual ~FrameCheck() = default;
    /// The first failure of this check in the frame (the lowest ball), or nothing. Called once per frame,
    /// frame 0 first; a check with worlds of its own steps them here.
    virtual std::optional<CheckFailure> frame(const Frame& f) = 0;
    /// True if the check reads Frame::traces.
    virtual bool needs_traces() const { return false; }
};

/// The check c for scene under kernel; its own worlds (if any) step with world.
std::unique_ptr<FrameCheck> make_check(Check c, const Scene& scene, KernelId kernel, const WorldOptions& world);

std::unique_ptr<FrameCheck> make_no_tunnel(const Scene& scene, KernelId kernel, const WorldOptions& world);
std::unique_ptr<FrameCheck> make_symmetry(const Scene& scene, KernelId kernel, const WorldOptions& world);
std::unique_ptr<FrameCheck> make_boundary(const Scene& scene, KernelId kernel, const WorldOptions& world);
std::unique_ptr<FrameCheck> make_speed(const Scene& scene, KernelId kernel, const WorldOptions& world);
std::unique_ptr<FrameCheck> make_deterministic(const Scene& scene, KernelId kernel, const WorldOptions& world);
std::unique_ptr<FrameCheck> make_oracle(const Scene& scene, KernelId kernel, const WorldOptions& world);
std::unique_ptr<FrameCheck> make_swap(const Scene& scene, KernelId kernel, const WorldOptions& world);
std::unique_ptr<FrameCheck> make_translation(const Scene& scene, KernelId kernel, const WorldOptions& world);
std::unique_ptr<FrameCheck> make_broad_phase(const Scene& scene, KernelId kernel, const WorldOptions& world);
std::unique_ptr<FrameCheck> make_round_trip(const Scene& scene, KernelId kernel, const WorldOptions& world);
std::unique_ptr<FrameCheck> make_no_escape(const Scene& scene, KernelId kernel, const WorldOptions& world);
std::unique_ptr<FrameCheck> make_bounce_side(const Scene& scene, KernelId kernel, const WorldOptions& world);
std::unique_ptr<FrameCheck> make_accuracy(const Scene& scene, KernelId kernel, const WorldOptions& world);
std::unique_ptr<FrameCheck> make_event_order(const Scene& scene, KernelId kernel, const WorldOptions& world);
std::unique_ptr<FrameCheck> make_penetration(const Scene& scene, KernelId kernel, const WorldOptions& world);
std::unique_ptr<FrameCheck> make_ghost_bounce(const Scene& scene, KernelId kernel, const WorldOptions& world);
std::unique_ptr<FrameCheck> make_plan(const Scene& scene, KernelId kernel, const WorldOptions& world);
std::unique_ptr<FrameCheck> make_ball_overlap(const Scene& scene, KernelId kernel, const WorldOptions& world);
std::unique_ptr<FrameCheck> make_pass_through(const Scene& scene, KernelId kernel, const WorldOptions& world);
std::unique_ptr<FrameCheck> make_jump_through(const Scene& scene, KernelId kernel, const WorldOptions& world);
std::unique_ptr<FrameCheck> make_momentum(const Scene& scene, KernelId kernel, const WorldOptions& world);
std::unique_ptr<FrameCheck> make_relabel(const Scene& scene, KernelId kernel, const WorldOptions& world);

/// A failure of check c at frame f for ball.
inline CheckFailure failure(Check c, std::int64_t f, std::uint32_t ball, std::string message) {
    return CheckFailure{c, f, ball, std::move(message), std::nullopt, std::nullopt};
}

/// The leg's ends are finite: a leg with an infinite or NaN end is not a segment, and no exact decision exists to
/// compare the kernel's with (lecture-float's arithmetic overflows to one). The oracle fails such a leg.
inline bool finite_leg(const TracedLeg& leg) {
    return std::isfinite(leg.from.x) && std::isfinite(leg.from.y) && std::isfinite(leg.to.x) && std::isfinite(leg.to.y);
}

/// A disc, or any ball among bumpers or among balls that collide: the disc frame steps it (kernel.hpp, step_ball with
/// obstacles), and the checks that read its legs read them by the disc rules.
inline bool stepped_as_disc(const Scene& scene, std::uint32_t ball) {
    return is_disc(scene.balls[ball]) || !scene.bumpers.empty() || scene.balls_collide;
}

/// The balls that met another in frame f (a `meet` of their own), or every ball where the frame's meets reached the
/// limit (16·N, meet.hpp: there every ball stops where its path is at the last meet). Such a ball's frame is not the
/// one it makes alone: the checks that step a ball again alone (run_checked's trace; speed, oracle and accuracy,
/// which read it) leave it to ball-overlap, pass-through and momentum.
inline std::vector<bool> met_in_frame(const Frame& f, std::size_t balls) {
    const bool limit = !f.meets.empty() && f.meets.size() >= static_cast<std::size_t>(k_max_meets_per_ball) * balls;
    std::vector<bool> met(balls, limit);
    for (const Event& e : f.events)
        if (e.kind == Event::Kind::meet && e.ball < balls) met[e.ball] = true;
    return met;
}

/// The event printed the contact the leg took: a hit on its wall, or a bump on its bumper.
inline bool printed_as(const Event& e, const TracedLeg& leg) {
    if (leg.hit) return e.kind == Event::Kind::hit && e.index == *leg.hit;
    return leg.bumped && e.kind == Event::Kind::bump && e.index == *leg.bumped;
}

/// The velocity the ball left its last contact of frame f with, where no leg follows it: the frame's end state's.
inline Vec2 end_velocity(const Frame& f, std::uint32_t ball) {
    for (const Event& e : f.events)
        if (e.kind == Event::Kind::state && e.ball == ball) return e.vel;
    return {};  // not reached: every ball prints a state every frame (world.hpp)
}

/// The velocity the ball left leg l's contact with: the next leg's, else the frame's end state's.
inline Vec2 velocity_after(const Frame& f, std::uint32_t ball, std::size_t l) {
    const StepTrace& trace = f.traces[ball];
    return l + 1 < trace.legs.size() ? trace.legs[l + 1].vel : end_velocity(f, ball);
}

/// Compares two frames' events: bit for bit (bits) or by value. Describes the first difference as `who`
/// giving something else, as a failure of c; nothing if they agree.
std::optional<CheckFailure> compare_events(Check c, std::int64_t f, std::span<const Event> expected,
                                           std::span<const Event> actual, bool bits, std::string_view who);

}  // namespace ricochet::checks
