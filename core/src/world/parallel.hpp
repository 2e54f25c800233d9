// Internal to World: many balls stepped one frame on a fixed number of threads, a static partition
// by ball index. Each part has its own scratch and hit buffer; hits are read back in ball order, so
// the thread count changes no result.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "ricochet/kernel.hpp"
#include "ricochet/wall_grid.hpp"
#include "ricochet/wall_plan.hpp"

namespace ricochet::detail {

/// Steps every ball one frame on threads() threads.
class ParallelStepper {
public:
    /// threads ≥ 1 (0 is taken as 1); 1 steps on the calling thread.
    explicit ParallelStepper(unsigned threads = 1);
    /// Threads used.
    unsigned threads() const { return threads_; }
    /// Steps ball i with memory i for every i among the obstacles (obstacles.index may be null: every wall
    /// is tried). prefetch, if given, is the grid behind the index: its cells are fetched a few balls ahead
    /// (results unchanged).
    void step(KernelId k, std::span<Ball> balls, std::span<BallMemory> memories, const Obstacles& obstacles,
              const WallGrid* prefetch);
    /// Hands every part the walls' plan (wall_plan.hpp), so that no part works it out again.
    void set_plan(const WallPlan& plan);
    /// Ball i's hits in the last step, in order.
    std::span<const HitEvent> hits(std::size_t i) const;
    /// Ball i's status in the last step.
    FrameStatus status(std::size_t i) const { return status_[i]; }

private:
    struct Part {
        std::size_t begin = 0, end = 0;
        StepScratch scratch;
        std::vector<HitEvent> hits;
    };
    /// Where a ball's hits are: parts_[part].hits[first .. last).
    struct BallHits {
        std::uint32_t part = 0, first = 0, last = 0;
    };
    void run_part(unsigned p, KernelId k, std::span<Ball> balls, std::span<BallMemory> memories,
                  const Obstacles& obstacles, const WallGrid* prefetch);
    unsigned threads_;
    std::vector<Part> parts_;
    // Per ball, reset every step, so that a ball no part stepped (a wrong partition) reads as a ball that
    // did not move, with no hits: the broad-phase check sees that, where offsets kept per part would be read
    // past their end.
    std::vector<FrameStatus> status_;
    std::vector<BallHits> ball_hits_;
};

}  // namespace ricochet::detail
