// Many balls on N threads, a static partition by ball index (parallel.hpp).
#include "world/parallel.hpp"

#include <algorithm>
#include <thread>

// wasm32 as node runs `ricochet` (emscripten without -pthread) has no threads, and its libc++ (13) no
// std::jthread: there every part runs on the calling thread, in order. The parts are independent (each
// ball's step reads only the walls), so the results are the same bits.
#if defined(__EMSCRIPTEN__) && !defined(__EMSCRIPTEN_PTHREADS__)
#define RICOCHET_NO_THREADS 1
#endif

namespace ricochet::detail {

#if defined(RICOCHET_NO_THREADS)
constexpr bool k_have_threads = false;
#else
constexpr bool k_have_threads = true;
#endif

ParallelStepper::ParallelStepper(unsigned threads) : threads_(std::max(1u, threads)), parts_(threads_) {}

void ParallelStepper::run_part(unsigned p, KernelId k, std::span<Ball> balls, std::span<BallMemory> memories,
                               const Obstacles& obstacles, const WallGrid* prefetch) {
    const std::span<const Wall> walls = obstacles.walls;
    Part& part = parts_[p];
    part.hits.clear();
    // Fetch the cells of the balls a few steps ahead, in three stages (the cell's entry, its wall list,
    // its walls): each is a cache miss otherwise.
    constexpr std::size_t k_ahead = 8;
    for (std::size_t i = part.begin; i < part.end; ++i) {
        if (prefetch != nullptr) {
            if (i + 3 * k_ahead < part.end) prefetch->prefetch(balls[i + 3 * k_ahead].pos, 0, walls);
            if (i + 2 * k_ahead < part.end) prefetch->prefetch(balls[i + 2 * k_ahead].pos, 1, walls);
            if (i + k_ahead < part.end) prefetch->prefetch(balls[i + k_ahead].pos, 2, walls);
        }
        const auto first = static_cast<std::uint32_t>(part.hits.size());
        status_[i] = step_ball(k, balls[i], memories[i], obstacles, part.hits, part.scratch);
        ball_hits_[i] = {p, first, static_cast<std::uint32_t>(part.hits.size())};
    }
}

void ParallelStepper::step(KernelId k, std::span<Ball> balls, std::span<BallMemory> memories,
                           const Obstacles& obstacles, const WallGrid* prefetch) {
    const std::size_t n = balls.size();
    status_.assign(n, FrameStatus::ok);
    ball_hits_.assign(n, BallHits{});
    // Static partition: part p steps balls [p·n/T, (p + 1)·n/T).
    for (unsigned p = 0; p < threads_; ++p) {
        parts_[p].begin = n * p / threads_;
        parts_[p].end = n * (p + 1) / threads_;
    }
    if (!k_have_threads || threads_ == 1 || n < 2 * threads_) {
        // Too few balls to share, or no threads: one thread does it all (same results, no thread start-up).
        for (unsigned p = 0; p < threads_; ++p) run_part(p, k, balls, memories, obstacles, prefetch);
        return;
    }
#if !defined(RICOCHET_NO_THREADS)
    {
        std::vector<std::jthread> workers;
        workers.reserve(threads_ - 1);
        for (unsigned p = 1; p < threads_; ++p)
            workers.emplace_back([&, p] { run_part(p, k, balls, memories, obstacles, prefetch); });
        run_part(0, k, balls, memories, obstacles, prefetch);
    }  // jthreads join here
#endif
}

void ParallelStepper::set_plan(const WallPlan& plan) {
    for (Part& part : parts_) part.scratch.plan = plan;
}

std::span<const HitEvent> ParallelStepper::hits(std::size_t i) const {
    const BallHits& h = ball_hits_[i];
    return std::span<const HitEvent>(parts_[h.part].hits).subspan(h.first, h.last - h.first);
}

}  // namespace ricochet::detail
