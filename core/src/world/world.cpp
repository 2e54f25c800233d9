// World: stepping a scene frame by frame into events (order and options in world.hpp).
#include "ricochet/world.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "ricochet/format.hpp"
#include "ricochet/meet.hpp"
#include "ricochet/wall_plan.hpp"
#include "world/parallel.hpp"

namespace ricochet {

std::string StepError::message() const {
    return fmt::format("frame {} ball {}: the ball at {} moving {} would leave the accepted range "
                       "(|coordinate| <= 2^256, finite); the run stops here",
                       frame, ball, state.pos, state.vel);
}

StepFailure::StepFailure(const StepError& error) : std::runtime_error(error.message()), error_(error) {}

namespace {

/// Wall grid and static index past this many bytes (walls included) get cache hints: below it they
/// only cost, ~10%; above it they pay (measured, 10^6-wall maze: ~820 → ~320 ns per ball-frame).
constexpr std::size_t k_prefetch_bytes = std::size_t{8} << 20;

}  // namespace

World::World(const Scene& scene, KernelId kernel, WorldOptions options)
    : kernel_(kernel),
      walls_(scene.walls),
      circles_(scene.circles),
      rects_(scene.rects),
      bumpers_(scene.bumpers),
      balls_(scene.balls),
      memories_(scene.balls.size()),
      stepper_(std::make_unique<detail::ParallelStepper>(options.threads)),
      balls_meet_(scene.balls_collide) {
    if (auto why = unsupported_scene(kernel, balls_, bumpers_.size(), balls_meet_)) throw UnsupportedScene(*why);
    masses_.resize(balls_.size());
    for (std::size_t i = 0; i < balls_.size(); ++i) masses_[i] = mass_of(scene, i);
    // The scene is looked at once, here. Without a plan every decision takes the general path: a plan that
    // describes the walls and found none axis-aligned (the same bits, wall_plan.hpp).
    stepper_->set_plan(options.plan ? plan_walls(walls_) : WallPlan{walls_.data(), walls_.size(), 0});
    if (options.broad_phase == BroadPhase::none) return;
    // The exact kernel always tries every wall: a wall index would be built for nothing.
    if (kernel != KernelId::exact && !walls_.empty()) {
        GridOptions grid = options.grid;
        // lecture-float rounds at 2^-24, past the default margin (wall_grid.hpp).
        if (kernel == KernelId::lecture_float) grid.margin = std::max(grid.margin, k_float_margin);
        if (options.broad_phase == BroadPhase::grid) {
            grid_.emplace(walls_, grid);
            prefetch_ = grid_->bytes() + std::span<const Wall>(walls_).size_bytes() >= k_prefetch_bytes;
        } else {
            bvh_.emplace(walls_, grid.margin);
        }
    }
    // A disc's bumpers: a grid over their centres, asked for those within R + the largest radius of a leg.
    if (kernel != KernelId::exact && !bumpers_.empty()) {
        for (const Bumper& b : bumpers_) {
            bumper_centres_.push_back({b.c, b.c});
            bumper_reach_ = std::max(bumper_reach_, b.r);
        }
        GridOptions grid = options.grid;
        if (kernel == KernelId::lecture_float) grid.margin = std::max(grid.margin, k_float_margin);
        bumper_grid_.emplace(bumper_centres_, grid);
    }
    if (!circles_.empty() || !rects_.empty()) statics_.emplace(circles_, rects_);
}

World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

Obstacles World::obstacles() const {
    return {walls_, bumpers_, wall_index(), bumper_grid_ ? &*bumper_grid_ : nullptr, bumper_reach_, balls_meet_};
}

const WallIndex* World::wall_index() const {
    if (grid_) return &*grid_;
    if (bvh_) return &*bvh_;
    return nullptr;
}

void World::append_overlaps(std::vector<Event>& out) const {
    // No circles and no rectangles: no static-test pass at all.
    if (circles_.empty() && rects_.empty()) return;
    for (std::size_t i = 0; i < balls_.size(); ++i) {
        const auto ball = static_cast<std::uint32_t>(i);
        const Vec2 p = balls_[i].pos;
        const double R = balls_[i].r;
        if (is_disc(balls_[i])) {
            // A disc overlaps a circle when |p − c| ≤ R + r (circles_overlap), and a rectangle when the rectangle's
            // point nearest to p, clamp(p) (exact: each coordinate is p's or an edge's), is within R of p. Every
            // shape is tried: the static index answers for points.
            for (std::uint32_t k = 0; k < circles_.size(); ++k)
                if (circles_overlap(kernel_, Circle{p, R}, circles_[k]))
                    out.push_back({Event::Kind::overlap, frame_, ball, Event::Shape::circle, k, {}, {}});
            for (std::uint32_t k = 0; k < rects_.size(); ++k) {
                const Rect& r = rects_[k];
                const Vec2 near{std::clamp(p.x, r.left, r.right), std::clamp(p.y, r.bottom, r.top)};
                if (point_in_circle(kernel_, near, Circle{p, R}))
                    out.push_back({Event::Kind::overlap, frame_, ball, Event::Shape::rect, k, {}, {}});
            }
            continue;
        }
        const auto circle = [&](std::uint32_t k) {
            if (point_in_circle(kernel_, p, circles_[k]))
                out.push_back({Event::Kind::overlap, frame_, ball, Event::Shape::circle, k, {}, {}});
        };
        const auto rect = [&](std::uint32_t k) {
            if (point_in_rect(kernel_, p, rects_[k]))
                out.push_back({Event::Kind::overlap, frame_, ball, Event::Shape::rect, k, {}, {}});
        };
        // Circles before rects, each in ascending index order: the index's candidate lists are sorted,
        // so one cell lookup gives the events the loop over every shape gives.
        if (statics_) {
            const StaticIndex::Candidates c = statics_->query(p);
            for (std::uint32_t k : c.circles) circle(k);
            for (std::uint32_t k : c.rects) rect(k);
        } else {
            for (std::uint32_t k = 0; k < circles_.size(); ++k) circle(k);
            for (std::uint32_t k = 0; k < rects_.size(); ++k) rect(k);
        }
    }
}

void World::start(std::vector<Event>& out) const {
    for (std::size_t i = 0; i < balls_.size(); ++i)
        out.push_back({Event::Kind::state, 0, static_cast<std::uint32_t>(i), Event::Shape::none, 0, balls_[i].pos,
                       balls_[i].vel});
    append_overlaps(out);
}

std::optional<StepError> World::step(std::vector<Event>& out) {
    ++frame_;
    if (balls_meet_) return step_meeting(out);
    stepper_->step(kernel_, balls_, memories_, obstacles(), prefetch_ ? &*grid_ : nullptr);
    std::optional<StepError> error;
    for (std::size_t i = 0; i < balls_.size(); ++i) {
        const auto ball = static_cast<std::uint32_t>(i);
        const FrameStatus status = stepper_->status(i);
        // step_ball leaves a ball that would leave the range unchanged: its state is the one before.
        if (status == FrameStatus::out_of_range && !error) error = StepError{frame_, ball, status, balls_[i]};
        for (const HitEvent& h : stepper_->hits(i))
            out.push_back({h.bumper ? Event::Kind::bump : Event::Kind::hit, frame_, ball, Event::Shape::none, h.wall,
                           h.point, {}});
        out.push_back({Event::Kind::state, frame_, ball, Event::Shape::none, 0, balls_[i].pos, balls_[i].vel});
    }
    append_overlaps(out);
    return error;
}

std::optional<StepError> World::step_meeting(std::vector<Event>& out) {
    // Each ball alone through the frame (in parallel), then the frame's meets among them (meet.hpp), which re-step
    // the balls that meet from their meets on.
    if (frames_.size() != balls_.size()) {
        // The first frame; each later one finds its balls' states and memories here, written as the last one ended.
        frames_.resize(balls_.size());
        for (std::size_t i = 0; i < balls_.size(); ++i) {
            frames_[i].before = balls_[i];
            frames_[i].memory = memories_[i];
        }
    }
    stepper_->step(kernel_, balls_, memories_, obstacles(), prefetch_ ? &*grid_ : nullptr);
    for (std::size_t i = 0; i < balls_.size(); ++i) {
        BallFrame& f = frames_[i];
        f.state = balls_[i];
        f.status = stepper_->status(i);
        const auto hits = stepper_->hits(i);
        if (hits.empty()) f.events.clear();  // (most balls: no call)
        else f.events.assign(hits.begin(), hits.end());
    }
    meets_.clear();
    step_meets(kernel_, obstacles(), masses_, frames_, meets_, meet_scratch_);
    std::optional<StepError> error;
    for (std::size_t i = 0; i < balls_.size(); ++i) {
        const auto ball = static_cast<std::uint32_t>(i);
        BallFrame& f = frames_[i];
        // A step that would leave the range left its ball where that step began.
        if (f.status == FrameStatus::out_of_range && !error) error = StepError{frame_, ball, f.status, f.state};
        balls_[i] = f.state;
        // (the next frame's start, while its frame is at hand)
        f.before = f.state;
        f.memory = memories_[i];
        for (const HitEvent& h : f.events) {
            if (h.ball)
                out.push_back({Event::Kind::meet, frame_, ball, Event::Shape::none, h.wall, h.point, h.out});
            else
                out.push_back({h.bumper ? Event::Kind::bump : Event::Kind::hit, frame_, ball, Event::Shape::none,
                               h.wall, h.point, {}});
        }
        out.push_back({Event::Kind::state, frame_, ball, Event::Shape::none, 0, balls_[i].pos, balls_[i].vel});
    }
    append_overlaps(out);
    return error;
}

std::span<const PathPoint> World::path(std::size_t i) const {
    if (i >= frames_.size()) return {};
    return frames_[i].path;
}

std::string World::skipped() const {
    std::string s;
    const auto add = [&](const char* clause) {
        if (!s.empty()) s += "; ";
        s += clause;
    };
    if (circles_.empty() && rects_.empty()) add("no static-test pass (no circles or rectangles)");
    else if (statics_) add("static tests: one cell lookup per ball");
    if (grid_) add("walls: uniform-grid broad phase");
    if (bvh_) add("walls: BVH broad phase");
    if (bumper_grid_) add("bumpers: a grid over their centres");
    add("exact fallback: kept (no filter-only proof)");
    return s;
}

std::vector<Event> run_scene(const Scene& scene, KernelId kernel, std::int64_t frames, WorldOptions options) {
    World world(scene, kernel, options);
    std::vector<Event> events;
    world.start(events);
    for (std::int64_t f = 0; f < frames; ++f)
        if (auto error = world.step(events)) throw StepFailure(*error);
    return events;
}

}  // namespace ricochet
