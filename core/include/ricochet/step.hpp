// One frame's step of one ball: the bounces it reports (HitEvent), how it ended (FrameStatus) and the
// scratch space the step reuses.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "ricochet/vec2.hpp"
#include "ricochet/wall_plan.hpp"

namespace ricochet {

/// A bounce during a frame: the wall (or bumper, or ball), the frame time t_i and the point B_i (the ball's centre).
struct HitEvent {
    std::uint32_t wall = 0;  ///< the wall, or the bumper when bumper is set, or the other ball when ball is set
    double t = 0.0;
    Vec2 point;
    bool bumper = false;     ///< the ball bounced off bumper `wall`, not a wall (a `bump` event)
    bool ball = false;       ///< the ball met ball `wall` (a `meet` event, meet.hpp)
    /// The velocity the ball leaves the contact with: set by the disc frame and for a meet; zero elsewhere.
    Vec2 out{};
};

/// How a frame ended for one ball.
enum class FrameStatus : std::uint8_t {
    ok,            ///< the ball finished its frame
    bounce_limit,  ///< k_max_bounces reached: the ball stays at its last safe point
    out_of_range,  ///< a position or velocity left the accepted range: the ball did not move
};

struct StepTrace;        // step_trace.hpp
struct MeetFrameScratch;  // kernels/meet/frame.cpp

/// Scratch space reused across calls to step_ball (keeps the hot loop free of allocation).
struct StepScratch {
    std::vector<std::uint32_t> candidates;
    std::vector<std::uint32_t> all_walls;  ///< 0, 1, …, n − 1: every wall, when there is no index
    std::vector<std::uint32_t> bumper_candidates;  ///< a disc's bumpers near a leg (kernel.hpp, Obstacles)
    std::vector<std::uint32_t> all_bumpers;        ///< 0, 1, …, n − 1: every bumper, when there is no index
    /// If set, step_ball fills it with the frame's legs, decisions and reflections (appending; the caller
    /// clears it). Unset, a step pays one null test per leg and per reflection.
    StepTrace* trace = nullptr;
    /// The plan of the walls last stepped among (wall_plan.hpp), made on the first step among them and again
    /// only when a step names other walls: a scene is looked at once per scratch, not once per frame.
    WallPlan plan;
    /// The frame time the step starts at: 0 for a whole frame; a ball stepped on after a meet at t starts at t, its
    /// first leg q → q + (1 − t)·v (the disc frame reads it; meet.hpp). Hit times are frame times either way.
    double start = 0.0;
    /// What the frame's meets keep between frames (meet.hpp's step_meets: its per-ball arrays and grid, reused so that
    /// a frame of a scene whose size was seen before allocates next to nothing); made on first use. Like the rest of
    /// the scratch it serves one thread: a copy shares it.
    std::shared_ptr<MeetFrameScratch> meets;
};

/// scratch.plan, made afresh first if it does not describe these walls.
inline const WallPlan& planned(StepScratch& scratch, std::span<const Wall> walls) {
    if (!scratch.plan.describes(walls)) scratch.plan = plan_walls(walls);
    return scratch.plan;
}

}  // namespace ricochet
