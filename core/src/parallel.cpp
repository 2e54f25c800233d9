// Many balls on N threads, and the World that skips what a scene does not need (parallel.hpp).
#include "ricochet/parallel.hpp"

#include "overlaps.hpp"

#include <algorithm>
#include <thread>

namespace ricochet {

ParallelStepper::ParallelStepper(unsigned threads) : threads_(std::max(1u, threads)), parts_(threads_) {}

void ParallelStepper::run_part(Part& part, KernelId k, std::span<Ball> balls, std::span<BallMemory> memories,
                               std::span<const Wall> walls, const WallIndex* index) {
    part.hits.clear();
    part.offset.clear();
    part.offset.push_back(0);
    // With a grid too big for the caches, fetch the cells of the balls a few steps ahead: each ball's
    // cell entry, wall list and walls are cache misses otherwise (measured, 10^6-wall maze: ~820 →
    // ~320 ns per ball-frame; below 8 MB the hints only cost, ~10%). Results are unaffected.
    const auto* grid = dynamic_cast<const WallGrid*>(index);
    if (grid != nullptr && grid->bytes() + walls.size_bytes() < (std::size_t{8} << 20)) grid = nullptr;
    constexpr std::size_t k_ahead = 8;
    for (std::size_t i = part.begin; i < part.end; ++i) {
        if (grid != nullptr) {
            if (i + 3 * k_ahead < part.end) grid->prefetch(balls[i + 3 * k_ahead].pos, 0, walls);
            if (i + 2 * k_ahead < part.end) grid->prefetch(balls[i + 2 * k_ahead].pos, 1, walls);
            if (i + k_ahead < part.end) grid->prefetch(balls[i + k_ahead].pos, 2, walls);
        }
        Ball& b = balls[i];
        // A ball at rest does no sweep. Only for robust is skipping step_ball bit-identical: it stops
        // at v = 0 before touching anything, whereas the lecture kernels round the position through
        // their own precision (and −0 + 0 = +0).
        if (k == KernelId::robust && b.vel.x == 0.0 && b.vel.y == 0.0 && in_range(b.pos.x) && in_range(b.pos.y)) {
            status_[i] = FrameStatus::ok;
        } else {
            status_[i] = step_ball(k, b, memories[i], walls, part.hits, part.scratch, index);
        }
        part.offset.push_back(static_cast<std::uint32_t>(part.hits.size()));
    }
}

void ParallelStepper::step(KernelId k, std::span<Ball> balls, std::span<BallMemory> memories,
                           std::span<const Wall> walls, const WallIndex* index) {
    const std::size_t n = balls.size();
    status_.resize(n);
    // Static partition: part p steps balls [p·n/T, (p + 1)·n/T).
    for (unsigned p = 0; p < threads_; ++p) {
        parts_[p].begin = n * p / threads_;
        parts_[p].end = n * (p + 1) / threads_;
    }
    if (threads_ == 1 || n < 2 * threads_) {
        // Too few balls to share: one thread does it all (same results, no thread start-up).
        for (unsigned p = 0; p < threads_; ++p) run_part(parts_[p], k, balls, memories, walls, index);
        return;
    }
    {
        std::vector<std::jthread> workers;
        workers.reserve(threads_ - 1);
        for (unsigned p = 1; p < threads_; ++p)
            workers.emplace_back([&, p] { run_part(parts_[p], k, balls, memories, walls, index); });
        run_part(parts_[0], k, balls, memories, walls, index);
    }  // jthreads join here
}

std::span<const HitEvent> ParallelStepper::hits(std::size_t i) const {
    // The part whose range holds i: the last one whose begin ≤ i.
    const auto it = std::upper_bound(parts_.begin(), parts_.end(), i,
                                     [](std::size_t v, const Part& p) { return v < p.begin; });
    const Part& part = *(it - 1);
    const std::size_t j = i - part.begin;
    return std::span<const HitEvent>(part.hits).subspan(part.offset[j], part.offset[j + 1] - part.offset[j]);
}

ScaledWorld::ScaledWorld(const Scene& scene, KernelId kernel, ScaleOptions options)
    : kernel_(kernel),
      options_(options),
      walls_(scene.walls),
      circles_(scene.circles),
      rects_(scene.rects),
      balls_(scene.balls),
      memories_(scene.balls.size()),
      stepper_(options.threads) {
    if (options.broad_phase) {
        // The exact kernel always tries every wall: a grid would be built for nothing.
        if (kernel != KernelId::exact && !walls_.empty()) grid_.emplace(walls_, options.grid);
        if (!circles_.empty() || !rects_.empty()) statics_.emplace(circles_, rects_);
    }
}

void ScaledWorld::append_overlaps(std::vector<Event>& out) const {
    // No circles and no rectangles: no static-test pass at all.
    if (circles_.empty() && rects_.empty()) return;
    for (std::size_t i = 0; i < balls_.size(); ++i) {
        const Vec2 p = balls_[i].pos;
        detail::ShapeIds ids;
        if (statics_) {
            // One cell lookup; its lists are in index order, as the brute-force loop visits them.
            const StaticIndex::Candidates c = statics_->query(p);
            ids = {c.circles, c.rects};
        }
        detail::append_ball_overlaps(out, kernel_, frame_, static_cast<std::uint32_t>(i), p, circles_, rects_, ids);
    }
}

void ScaledWorld::start(std::vector<Event>& out) const {
    for (std::size_t i = 0; i < balls_.size(); ++i)
        out.push_back({Event::Kind::state, 0, static_cast<std::uint32_t>(i), Event::Shape::none, 0, balls_[i].pos,
                       balls_[i].vel});
    append_overlaps(out);
}

std::optional<StepError> ScaledWorld::step(std::vector<Event>& out) {
    ++frame_;
    // Keep the states before the frame only to report an error: a ball that fails is unchanged.
    stepper_.step(kernel_, balls_, memories_, walls_, wall_index());
    std::optional<StepError> error;
    for (std::size_t i = 0; i < balls_.size(); ++i) {
        const auto ball = static_cast<std::uint32_t>(i);
        if (stepper_.status(i) == FrameStatus::out_of_range && !error)
            error = StepError{frame_, ball, FrameStatus::out_of_range, balls_[i]};  // step_ball left it unchanged
        for (const HitEvent& h : stepper_.hits(i))
            out.push_back({Event::Kind::hit, frame_, ball, Event::Shape::none, h.wall, h.point, {}});
        out.push_back({Event::Kind::state, frame_, ball, Event::Shape::none, 0, balls_[i].pos, balls_[i].vel});
    }
    append_overlaps(out);
    return error;
}

std::string ScaledWorld::skipped() const {
    std::string s;
    const auto add = [&](const char* clause) {
        if (!s.empty()) s += "; ";
        s += clause;
    };
    if (circles_.empty() && rects_.empty()) add("no static-test pass (no circles or rectangles)");
    else if (statics_) add("static tests: one cell lookup per ball");
    if (grid_) add("walls: uniform-grid broad phase");
    if (kernel_ == KernelId::robust) add("balls at rest: no sweep");
    add("exact fallback: kept (no filter-only proof)");
    return s;
}

std::vector<Event> run_scene_scaled(const Scene& scene, KernelId kernel, std::int64_t frames, ScaleOptions options) {
    ScaledWorld world(scene, kernel, options);
    std::vector<Event> events;
    world.start(events);
    for (std::int64_t f = 0; f < frames; ++f)
        if (auto error = world.step(events)) throw StepFailure(*error);
    return events;
}

}  // namespace ricochet
