// Scenes that scale: many independent balls stepped on N threads, and a World that skips what a
// scene does not need (broad phase for walls and static shapes, no overlap pass without shapes, no
// sweep for a ball at rest). Both give the same events, bit for bit, as World without an index on
// one thread (scale_test checks it): balls are independent within a frame, each thread steps a
// contiguous range of balls with its own scratch and hit buffer, and the results are read back in
// ball order.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "ricochet/grid.hpp"
#include "ricochet/kernel.hpp"
#include "ricochet/scene.hpp"
#include "ricochet/world.hpp"

namespace ricochet {

/// Steps many balls one frame on a fixed number of threads (static partition by ball index).
class ParallelStepper {
public:
    /// threads ≥ 1 (0 is taken as 1); 1 steps on the calling thread.
    explicit ParallelStepper(unsigned threads = 1);
    /// Threads used.
    unsigned threads() const { return threads_; }
    /// Steps ball i with memory i for every i. index may be null (every wall is tried).
    void step(KernelId k, std::span<Ball> balls, std::span<BallMemory> memories, std::span<const Wall> walls,
              const WallIndex* index);
    /// Ball i's hits in the last step, in order.
    std::span<const HitEvent> hits(std::size_t i) const;
    /// Ball i's status in the last step.
    FrameStatus status(std::size_t i) const { return status_[i]; }

private:
    struct Part {
        std::size_t begin = 0, end = 0;
        StepScratch scratch;
        std::vector<HitEvent> hits;
        std::vector<std::uint32_t> offset;  // ball begin + j has hits[offset[j] .. offset[j + 1])
    };
    void run_part(Part& part, KernelId k, std::span<Ball> balls, std::span<BallMemory> memories,
                  std::span<const Wall> walls, const WallIndex* index);
    unsigned threads_;
    std::vector<Part> parts_;
    std::vector<FrameStatus> status_;
};

/// How a ScaledWorld steps.
struct ScaleOptions {
    bool broad_phase = true;  ///< a WallGrid for the walls and a StaticIndex for circles and rectangles
    unsigned threads = 1;     ///< threads stepping the balls
    GridOptions grid{};       ///< the wall grid's layout (lecture-float wants margin = k_float_margin)
};

/// World's events (world.hpp) from a broad phase and N threads: same order, same bits.
class ScaledWorld {
public:
    /// Copies the scene and builds the indices it needs.
    ScaledWorld(const Scene& scene, KernelId kernel, ScaleOptions options = {});
    /// Appends frame 0's events (as World::start).
    void start(std::vector<Event>& out) const;
    /// Steps one frame and appends its events (as World::step).
    std::optional<StepError> step(std::vector<Event>& out);
    /// Frames stepped so far.
    std::int64_t frame() const { return frame_; }
    /// The balls' current states.
    std::span<const Ball> balls() const { return balls_; }
    /// The wall index in use, or null.
    const WallIndex* wall_index() const { return grid_ ? &*grid_ : nullptr; }
    /// What this world skips for its scene, one clause each, for the run to print.
    std::string skipped() const;

private:
    void append_overlaps(std::vector<Event>& out) const;

    KernelId kernel_;
    ScaleOptions options_;
    std::vector<Wall> walls_;
    std::vector<Circle> circles_;
    std::vector<Rect> rects_;
    std::vector<Ball> balls_;
    std::vector<BallMemory> memories_;
    std::optional<WallGrid> grid_;
    std::optional<StaticIndex> statics_;
    ParallelStepper stepper_;
    std::int64_t frame_ = 0;
};

/// Every event of frames 0..frames, as run_scene, from a ScaledWorld. Throws StepFailure.
std::vector<Event> run_scene_scaled(const Scene& scene, KernelId kernel, std::int64_t frames,
                                    ScaleOptions options = {});

}  // namespace ricochet
