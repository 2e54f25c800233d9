// World: a scene's balls stepped frame by frame by one kernel into events, in the order of
// scene-log.md: per frame, per ball its hits in order then its state; then the overlaps of every
// ball (ball-major, circles before rects, each in index order) after all balls have moved.
// Frame 0 is the initial states followed by the initial overlaps.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "ricochet/kernel.hpp"
#include "ricochet/scene.hpp"

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

/// A scene's state under one kernel, stepped a frame at a time.
class World {
public:
    /// Copies the scene's entities and initial balls; index (optional) must outlive the World and
    /// index the scene's walls.
    World(const Scene& scene, KernelId kernel, const WallIndex* index = nullptr);

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
    /// Balls that stopped at k_max_bounces in the last frame (a documented outcome, not an error).
    std::uint64_t bounce_limited() const { return bounce_limited_; }
    /// The scene's walls.
    std::span<const Wall> walls() const { return walls_; }

private:
    void append_overlaps(std::vector<Event>& out) const;

    KernelId kernel_;
    const WallIndex* index_;
    std::vector<Wall> walls_;
    std::vector<Circle> circles_;
    std::vector<Rect> rects_;
    std::vector<Ball> balls_;
    std::vector<BallMemory> memories_;
    StepScratch scratch_;
    std::vector<HitEvent> hits_;
    std::int64_t frame_ = 0;
    std::uint64_t bounce_limited_ = 0;
};

/// Every event of frames 0..frames under kernel. Throws StepFailure if a ball leaves the accepted range.
std::vector<Event> run_scene(const Scene& scene, KernelId kernel, std::int64_t frames);

/// One event as `ricochet run` prints it (no newline): `state F I X Y VX VY`, `hit F I W X Y`,
/// `overlap F I circle|rect K`, numbers in shortest round-trip form.
std::string format_event(const Event& event);
/// Appends format_event(event) and a newline to out (no temporary string).
void append_event_line(std::string& out, const Event& event);

}  // namespace ricochet
