// World: stepping a scene frame by frame into events (order documented in world.hpp).
#include "ricochet/world.hpp"

#include "overlaps.hpp"

#include <fmt/format.h>

namespace ricochet {

std::string StepError::message() const {
    return fmt::format("frame {} ball {}: the ball at ({}, {}) moving ({}, {}) would leave the accepted range "
                       "(|coordinate| <= 2^256, finite); the run stops here",
                       frame, ball, state.pos.x, state.pos.y, state.vel.x, state.vel.y);
}

StepFailure::StepFailure(const StepError& error) : std::runtime_error(error.message()), error_(error) {}

World::World(const Scene& scene, KernelId kernel, const WallIndex* index)
    : kernel_(kernel),
      index_(index),
      walls_(scene.walls),
      circles_(scene.circles),
      rects_(scene.rects),
      balls_(scene.balls),
      memories_(scene.balls.size()) {}

namespace detail {

void append_ball_overlaps(std::vector<Event>& out, KernelId kernel, std::int64_t frame, std::uint32_t ball, Vec2 p,
                          std::span<const Circle> circles, std::span<const Rect> rects, const ShapeIds& ids) {
    // Visits ids if given, else 0..n−1: either way in ascending order.
    const auto each = [](std::optional<std::span<const std::uint32_t>> given, std::size_t n, auto&& visit) {
        if (given) {
            for (std::uint32_t k : *given) visit(k);
        } else {
            for (std::uint32_t k = 0; k < n; ++k) visit(k);
        }
    };
    each(ids.circles, circles.size(), [&](std::uint32_t k) {
        if (point_in_circle(kernel, p, circles[k]))
            out.push_back({Event::Kind::overlap, frame, ball, Event::Shape::circle, k, {}, {}});
    });
    each(ids.rects, rects.size(), [&](std::uint32_t k) {
        if (point_in_rect(kernel, p, rects[k]))
            out.push_back({Event::Kind::overlap, frame, ball, Event::Shape::rect, k, {}, {}});
    });
}

}  // namespace detail

void World::append_overlaps(std::vector<Event>& out) const {
    for (std::size_t i = 0; i < balls_.size(); ++i)
        detail::append_ball_overlaps(out, kernel_, frame_, static_cast<std::uint32_t>(i), balls_[i].pos, circles_,
                                     rects_);
}

void World::start(std::vector<Event>& out) const {
    for (std::size_t i = 0; i < balls_.size(); ++i)
        out.push_back({Event::Kind::state, 0, static_cast<std::uint32_t>(i), Event::Shape::none, 0, balls_[i].pos,
                       balls_[i].vel});
    append_overlaps(out);
}

std::optional<StepError> World::step(std::vector<Event>& out) {
    ++frame_;
    bounce_limited_ = 0;
    std::optional<StepError> error;
    for (std::size_t i = 0; i < balls_.size(); ++i) {
        hits_.clear();
        const Ball before = balls_[i];
        const FrameStatus status = step_ball(kernel_, balls_[i], memories_[i], walls_, hits_, scratch_, index_);
        if (status == FrameStatus::out_of_range && !error)
            error = StepError{frame_, static_cast<std::uint32_t>(i), status, before};
        if (status == FrameStatus::bounce_limit) ++bounce_limited_;
        for (const HitEvent& h : hits_)
            out.push_back({Event::Kind::hit, frame_, static_cast<std::uint32_t>(i), Event::Shape::none, h.wall,
                           h.point, {}});
        out.push_back({Event::Kind::state, frame_, static_cast<std::uint32_t>(i), Event::Shape::none, 0,
                       balls_[i].pos, balls_[i].vel});
    }
    append_overlaps(out);
    return error;
}

std::vector<Event> run_scene(const Scene& scene, KernelId kernel, std::int64_t frames) {
    World world(scene, kernel);
    std::vector<Event> events;
    world.start(events);
    for (std::int64_t f = 0; f < frames; ++f)
        if (auto error = world.step(events)) throw StepFailure(*error);
    return events;
}

std::string format_event(const Event& e) {
    std::string s;
    append_event_line(s, e);
    s.pop_back();
    return s;
}

void append_event_line(std::string& out, const Event& e) {
    auto it = std::back_inserter(out);
    switch (e.kind) {
        case Event::Kind::state:
            fmt::format_to(it, "state {} {} {} {} {} {}\n", e.frame, e.ball, e.pos.x, e.pos.y, e.vel.x, e.vel.y);
            break;
        case Event::Kind::hit:
            fmt::format_to(it, "hit {} {} {} {} {}\n", e.frame, e.ball, e.index, e.pos.x, e.pos.y);
            break;
        case Event::Kind::overlap:
            fmt::format_to(it, "overlap {} {} {} {}\n", e.frame, e.ball,
                           e.shape == Event::Shape::circle ? "circle" : "rect", e.index);
            break;
    }
}

}  // namespace ricochet
