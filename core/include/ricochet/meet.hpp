// Balls that meet (`balls collide`, docs/scene-log.md "Balls that meet"): what a frame's meets were, for the
// checks, the renderer and anyone who wants more than the printed `meet` lines; and the frame's paths they were
// searched on.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "ricochet/ball_memory.hpp"
#include "ricochet/kernel.hpp"
#include "ricochet/step.hpp"
#include "ricochet/vec2.hpp"

namespace ricochet {

/// A frame's meets at most, per ball of the scene (16·N for N balls): at the limit every ball stops where its
/// path is at the last meet's time (the safe stop of docs/scene-log.md, "Balls that meet", 7).
inline constexpr int k_max_meets_per_ball = 16;

/// One meet of two balls during a frame, as the World took it.
struct MeetRecord {
    std::uint32_t a = 0, b = 0;  ///< the two balls, a < b
    double t = 0.0;              ///< the frame time of the meet (rounded; the lecture kernels: 1)
    Vec2 pos_a, pos_b;           ///< their printed centres there
    Vec2 vel_a, vel_b;           ///< their velocities arriving
    Vec2 out_a, out_b;           ///< the velocities they leave with (printed in the `meet` lines)
    bool responded = false;      ///< false where the centres did not approach and the velocities stayed
    /// Another meet sharing a ball was due at the same exact time when this one was taken, or this one's centres
    /// did not stand the same against the balls its group's earlier meets moved as before those meets: the order the
    /// tie rule chose (the lowest pair first) decides the outcome, which depends on the balls' numbers
    /// (docs/scene-log.md, "Balls that meet", 3).
    bool tied = false;
    friend bool operator==(const MeetRecord&, const MeetRecord&) = default;
};

/// A printed point of a ball's path in a frame and its frame time: the path moves uniformly between consecutive
/// ones (docs/scene-log.md, "Balls that meet", 1).
struct PathPoint {
    double t = 0.0;
    Vec2 p;
    friend bool operator==(const PathPoint&, const PathPoint&) = default;
};

/// One ball's frame as the World hands it to step_meets and takes it back.
struct BallFrame {
    Ball before;                   ///< its state before the frame
    BallMemory memory;             ///< its memory before the frame (kept: the disc frame remembers nothing)
    Ball state;                    ///< in: stepped alone through the frame; out: its state at the frame's end
    FrameStatus status = FrameStatus::ok;  ///< in: that step's; out: the frame's last step's
    std::vector<HitEvent> events;  ///< in: that step's hits; out: its hits, bumps and meets in the order they happened
    std::vector<PathPoint> path;   ///< out: its path, from `before` at t = 0 to `state` at t = 1
};

/// The meets of one frame among balls each already stepped alone through it (balls[i].state, .status, .events),
/// by kernel k's MeetRule (docs/scene-log.md, "Balls that meet"): rewrites each ball's state, status and events,
/// fills its path, and appends the frame's meets, in the order taken, to meets. masses: one per ball.
void step_meets(KernelId k, const Obstacles& obstacles, std::span<const double> masses, std::span<BallFrame> balls,
                std::vector<MeetRecord>& meets, StepScratch& scratch);

}  // namespace ricochet
