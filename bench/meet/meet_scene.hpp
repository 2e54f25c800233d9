// The scene of `ricochet bench meet`: N discs of one radius in a closed square box of four walls, every ball's mass
// 1, restitution 1, no friction, no gravity, dt = 1 per frame; the same initial state for every engine.
#pragma once

#include <cstdint>
#include <vector>

#include "ricochet/scene.hpp"

namespace ricochet::meet_bench {

/// One scene: the box [0, side]², its discs and how long to step them.
struct MeetScene {
    double side = 0.0;         ///< the box's side
    double r = 0.0;            ///< every disc's radius
    double v_max = 0.0;        ///< speeds are drawn uniform in [0, v_max] (per frame)
    std::int64_t frames = 0;   ///< frames to step
    std::vector<Ball> balls;   ///< the initial states, each at least k_start_gap clear of the others and the walls
};

/// The clearance between any two discs, and between a disc and a wall, at the start: enough that rounding a
/// position to float (Box2D) cannot make two discs overlap that did not.
inline constexpr double k_start_gap = 0.05;

/// The area the discs cover over the box's area: moderate, a dilute gas in which every ball meets others often.
inline constexpr double k_area_fraction = 0.1;

/// n discs of radius r, speeds up to v_max, in a box sized for k_area_fraction; one disc per cell of a square grid,
/// jittered within its cell, directions uniform; drawn from seed. Every coordinate and velocity component is a
/// multiple of 2^-14 and below 2^9 (so that Box2D's floats, after scaling by a power of two, hold them exactly).
MeetScene make_scene(int n, double r, double v_max, std::int64_t frames, std::uint64_t seed);

/// The scene as ricochet steps it: the four walls, the balls, `balls collide`.
Scene to_scene(const MeetScene& s);

}  // namespace ricochet::meet_bench
