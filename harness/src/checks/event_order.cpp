// event-order: a frame's events come in the order docs/scene-log.md gives ("Events, frames and the run
// hash"), each naming its frame and an entity that exists (checks.hpp); every meet prints under both its balls.
#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <tuple>
#include <utility>

#include "checks/frame_check.hpp"
#include "ricochet/format.hpp"

namespace ricochet::checks {
namespace {

class EventOrder final : public FrameCheck {
public:
    explicit EventOrder(const Scene& scene) : scene_(scene) {}

    std::optional<CheckFailure> frame(const Frame& f) override {
        const auto balls = static_cast<std::uint32_t>(scene_.balls.size());
        const auto fail = [&](std::size_t j, std::uint32_t ball, std::string_view why) {
            return failure(Check::event_order, f.index, ball,
                           fmt::format("event {} of the frame, '{}': {}", j, f.events[j], why));
        };
        std::size_t j = 0;
        const auto at = [&](Event::Kind k) { return j < f.events.size() && f.events[j].kind == k; };
        // Each meet of ball I with ball J, counted under I: (I, J) as often as (J, I).
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> meets;
        // Per ball in index order: its hits, bumps and meets in the order they happened (none at frame 0), then
        // its state.
        for (std::uint32_t b = 0; b < balls; ++b) {
            for (; at(Event::Kind::hit) || at(Event::Kind::bump) || at(Event::Kind::meet); ++j) {
                const Event& e = f.events[j];
                const bool hit = e.kind == Event::Kind::hit, bump = e.kind == Event::Kind::bump;
                if (f.index == 0)
                    return fail(j, e.ball, hit ? "frame 0 has no hits" : bump ? "frame 0 has no bumps" : "frame 0 has no meets");
                if (e.ball != b) return fail(j, e.ball, fmt::format("ball {}'s events come next", b));
                if (hit && (e.index >= scene_.walls.size() || e.shape != Event::Shape::none))
                    return fail(j, e.ball, "a hit names a wall of the scene and no shape");
                if (bump && (e.index >= scene_.bumpers.size() || e.shape != Event::Shape::none))
                    return fail(j, e.ball, "a bump names a bumper of the scene and no shape");
                if (!hit && !bump) {
                    if (!scene_.balls_collide) return fail(j, e.ball, "a meet in a scene whose balls do not collide");
                    if (e.index >= balls || e.index == e.ball || e.shape != Event::Shape::none)
                        return fail(j, e.ball, "a meet names another ball of the scene and no shape");
                    // S = R_i + R_j > 0: two point balls never meet.
                    if (!(scene_.balls[e.ball].r > 0) && !(scene_.balls[e.index].r > 0))
                        return fail(j, e.ball, "two point balls never meet");
                    ++meets[{e.ball, e.index}];
                }
                if (e.frame != f.index) return fail(j, e.ball, "not this frame's number");
            }
            if (!at(Event::Kind::state))
                return j < f.events.size() ? fail(j, b, fmt::format("ball {}'s state comes next", b))
                                           : failure(Check::event_order, f.index, b,
                                                     fmt::format("the frame ends before ball {}'s state", b));
            const Event& e = f.events[j];
            if (e.ball != b || e.frame != f.index || e.index != 0 || e.shape != Event::Shape::none)
                return fail(j, e.ball, fmt::format("ball {}'s state at this frame comes next", b));
            ++j;
        }
        // Every meet prints twice, once under each ball: the lowest ball of a pair whose counts differ fails.
        std::optional<std::pair<std::uint32_t, std::uint32_t>> unpaired;
        for (const auto& [pair, n] : meets) {
            const auto back = meets.find({pair.second, pair.first});
            if (back != meets.end() && back->second == n) continue;
            const std::pair<std::uint32_t, std::uint32_t> low{std::min(pair.first, pair.second),
                                                               std::max(pair.first, pair.second)};
            if (!unpaired || low < *unpaired) unpaired = low;
        }
        if (unpaired) {
            const auto count = [&](std::uint32_t a, std::uint32_t b) {
                const auto it = meets.find({a, b});
                return it == meets.end() ? std::size_t{0} : it->second;
            };
            const auto [lo, hi] = *unpaired;
            return failure(Check::event_order, f.index, lo,
                           fmt::format("ball {} prints {} meet(s) with ball {}, ball {} prints {} with ball {}: every "
                                       "meet prints under both its balls",
                                       lo, count(lo, hi), hi, hi, count(hi, lo), lo));
        }
        // Then every overlap: ball-major, circles before rects, each by index, each once.
        std::optional<std::tuple<std::uint32_t, Event::Shape, std::uint32_t>> last;
        for (; j < f.events.size(); ++j) {
            const Event& e = f.events[j];
            if (e.kind != Event::Kind::overlap) return fail(j, e.ball, "after the states come only overlaps");
            const std::size_t shapes = e.shape == Event::Shape::circle ? scene_.circles.size()
                                       : e.shape == Event::Shape::rect ? scene_.rects.size()
                                                                       : 0;
            if (e.ball >= balls || e.index >= shapes || e.frame != f.index)
                return fail(j, e.ball, "an overlap names a ball and a circle or rect of the scene, at this frame");
            const auto key = std::tuple{e.ball, e.shape, e.index};
            if (last && !(*last < key)) return fail(j, e.ball, "overlaps go by ball, circles before rects, then index");
            last = key;
        }
        return std::nullopt;
    }

private:
    const Scene& scene_;
};

}  // namespace

std::unique_ptr<FrameCheck> make_event_order(const Scene& scene, KernelId, const WorldOptions&) {
    return std::make_unique<EventOrder>(scene);
}

}  // namespace ricochet::checks
