// World: a scene's balls stepped frame by frame by one kernel into events, in the order of
// docs/scene-log.md: per frame, per ball its hits and bumps in order then its state; then the overlaps of
// every ball (ball-major, circles before rects, each in index order) after all balls have moved.
// Frame 0 is the initial states followed by the initial overlaps.
//
// The options change how fast, never what: every broad phase and every thread count gives the same
// events bit for bit (scale_test and the BroadPhaseSameBits property check it against
// BroadPhase::none on one thread). Balls are independent within a frame, so each thread steps a
// contiguous range of balls with its own scratch and hit buffer, and the results are read back in
// ball order.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "ricochet/bvh.hpp"
#include "ricochet/kernel.hpp"
#include "ricochet/meet.hpp"
#include "ricochet/scene.hpp"
#include "ricochet/static_index.hpp"
#include "ricochet/wall_grid.hpp"

namespace ricochet {

/// A ball that could not be stepped: its position or velocity left the accepted range (kernel.hpp).
struct StepError {
    std::int64_t frame = 0;      ///< the frame being stepped
    std::uint32_t ball = 0;      ///< the ball
    FrameStatus status = FrameStatus::out_of_range;
    Ball state;                  ///< the ball's state before the frame (unchanged)
    /// "frame F ball I: ... left the accepted range ..." for people.
    std::string message() const;
};

/// The one exception type run_scene throws: the run hit a StepError.
class StepFailure : public std::runtime_error {
public:
    /// Wraps error.
    explicit StepFailure(const StepError& error);
    /// What went wrong.
    const StepError& error() const { return error_; }

private:
    StepError error_;
};

/// How a World finds the walls a leg may hit and the shapes a ball may lie in.
enum class BroadPhase : std::uint8_t {
    none,  ///< every wall tried, every shape tested: the plain reference
    grid,  ///< a WallGrid over the walls, one over the bumpers' centres and a StaticIndex over the circles and
           ///< rectangles
    bvh,   ///< a WallBvh over the walls, the bumpers' WallGrid and a StaticIndex (the grid's alternative, for
           ///< measuring)
};

/// How a World steps: none of it changes an event's bits.
struct WorldOptions {
    BroadPhase broad_phase = BroadPhase::grid;  ///< on by default
    unsigned threads = 1;                       ///< threads stepping the balls (0 is taken as 1)
    GridOptions grid{};                         ///< the wall grid's layout (the World raises the margin
                                                ///< to k_float_margin for lecture-float)
    /// Look at the walls once and let each decision take the cheapest exact path they allow (wall_plan.hpp);
    /// false takes the general path everywhere (the `plan` check compares the two).
    bool plan = true;
};

namespace detail {
class ParallelStepper;
}  // namespace detail

/// A scene's state under one kernel, stepped a frame at a time.
class World {
public:
    /// Copies the scene's entities and initial balls and builds the indices options and kernel call for.
    /// Throws UnsupportedScene (kernel.hpp) if the kernel cannot step the scene's discs or bumpers.
    World(const Scene& scene, KernelId kernel, WorldOptions options = {});
    /// Frees the stepper.
    ~World();
    World(World&&) noexcept;             ///< moves the state and indices
    World& operator=(World&&) noexcept;  ///< moves the state and indices

    /// Appends frame 0's events: every ball's initial state, then the initial overlaps.
    void start(std::vector<Event>& out) const;
    /// Steps frame frame() + 1 and appends its events. A ball that would leave the accepted range keeps
    /// its state (it is still printed) and the first such ball is returned as the error.
    std::optional<StepError> step(std::vector<Event>& out);

    /// Frames stepped so far (0 before the first step).
    std::int64_t frame() const { return frame_; }
    /// The kernel stepping this world.
    KernelId kernel() const { return kernel_; }
    /// The balls' current states.
    std::span<const Ball> balls() const { return balls_; }
    /// What the kernel remembers of each ball.
    std::span<const BallMemory> memories() const { return memories_; }
    /// The scene's walls.
    std::span<const Wall> walls() const { return walls_; }
    /// The scene's bumpers.
    std::span<const Bumper> bumpers() const { return bumpers_; }
    /// The wall index in use, or null (BroadPhase::none, no walls, or the exact kernel).
    const WallIndex* wall_index() const;
    /// What a ball is stepped among: the walls, the bumpers and their indices (kernel.hpp).
    Obstacles obstacles() const;
    /// What this world skips for its scene, one clause each, for a run to print.
    std::string skipped() const;
    /// True if the scene's balls meet (`balls collide`).
    bool balls_meet() const { return balls_meet_; }
    /// The balls' masses, one per ball.
    std::span<const double> masses() const { return masses_; }
    /// The last frame's meets in the order they were taken (empty unless balls_meet()).
    std::span<const MeetRecord> meets() const { return meets_; }
    /// Ball i's path in the last frame: its printed points with their frame times, from the state before the frame
    /// (t = 0) to its state (t = 1) (empty unless balls_meet()).
    std::span<const PathPoint> path(std::size_t i) const;

private:
    void append_overlaps(std::vector<Event>& out) const;
    /// step() for a scene whose balls meet.
    std::optional<StepError> step_meeting(std::vector<Event>& out);

    KernelId kernel_;
    std::vector<Wall> walls_;
    std::vector<Circle> circles_;
    std::vector<Rect> rects_;
    std::vector<Bumper> bumpers_;
    std::vector<Ball> balls_;
    std::vector<BallMemory> memories_;
    std::optional<WallGrid> grid_;
    std::optional<WallBvh> bvh_;
    std::vector<Wall> bumper_centres_;       // bumper i as the zero-length wall at its centre, for bumper_grid_
    std::optional<WallGrid> bumper_grid_;    // over bumper_centres_, with the broad phase, unless the kernel is exact
    double bumper_reach_ = 0.0;              // the largest bumper radius
    std::optional<StaticIndex> statics_;
    bool prefetch_ = false;  // the grid is past the size where cache hints pay (world.cpp)
    std::unique_ptr<detail::ParallelStepper> stepper_;
    std::int64_t frame_ = 0;
    bool balls_meet_ = false;
    std::vector<double> masses_;
    std::vector<MeetRecord> meets_;
    std::vector<BallFrame> frames_;  // the frame's balls as step_meets works them; between frames, their paths the
                                     // last frame's, their `before` and `memory` the next one's
    StepScratch meet_scratch_;
};

/// Every event of frames 0..frames under kernel. Throws StepFailure if a ball leaves the accepted range, and
/// UnsupportedScene as World does.
std::vector<Event> run_scene(const Scene& scene, KernelId kernel, std::int64_t frames, WorldOptions options = {});

}  // namespace ricochet
