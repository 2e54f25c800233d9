// A scene's image stepped beside the run (mapped_run.hpp).
#include "checks/mapped_run.hpp"

#include <algorithm>
#include <span>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "ricochet/format.hpp"

namespace ricochet::checks {

Scene apply(const SceneMap& m, const Scene& s) {
    const auto f = [&](Vec2 p) { return m.point ? m.point(p) : p; };
    Scene out = s;
    for (Wall& w : out.walls) w = m.reverse_walls ? Wall{f(w.p1), f(w.p0)} : Wall{f(w.p0), f(w.p1)};
    for (Ball& b : out.balls) b = {f(b.pos), f(b.vel), b.r};
    if (m.reverse_balls) {
        std::reverse(out.balls.begin(), out.balls.end());
        std::reverse(out.masses.begin(), out.masses.end());
    }
    for (Bumper& u : out.bumpers) u.c = f(u.c);
    for (Circle& c : out.circles) c.c = f(c.c);
    for (Rect& r : out.rects) {
        const Vec2 a = f({r.left, r.bottom}), b = f({r.right, r.top});
        r = {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
    }
    return out;
}

MappedRun::MappedRun(const Scene& scene, const SceneMap& map, KernelId kernel, const WorldOptions& world)
    : map_(map), image_(apply(map, scene)), world_(image_, kernel, world), want_(scene.balls.size()),
      got_(scene.balls.size()) {}

std::uint32_t MappedRun::image_of(std::uint32_t ball) const {
    return map_.reverse_balls ? static_cast<std::uint32_t>(image_.balls.size() - 1 - ball) : ball;
}

Event MappedRun::mapped(Event e) const {
    // Hits and bumps keep their wall or bumper (walls are reversed in place), overlaps their shape; a meet names the
    // other ball's image.
    e.ball = image_of(e.ball);
    if (e.kind == Event::Kind::meet) e.index = image_of(e.index);
    if (map_.point) {
        e.pos = map_.point(e.pos);
        e.vel = map_.point(e.vel);
    }
    return e;
}

namespace {

/// A meet was taken while another sharing a ball was due at the same exact time (MeetRecord::tied): the tie rule's
/// order depends on the balls' numbers.
bool shared_time(std::span<const MeetRecord> meets) {
    return std::any_of(meets.begin(), meets.end(), [](const MeetRecord& m) { return m.tied; });
}

}  // namespace

bool MappedRun::parts(const Frame& f) {
    if (!map_.reverse_balls || !image_.balls_collide) return false;
    parted_ = parted_ || shared_time(f.meets) || shared_time(world_.meets());
    return parted_;
}

std::optional<CheckFailure> MappedRun::frame(Check c, const Frame& f) {
    if ((map_.first_contacts && f.index > 1) || parted_) return std::nullopt;
    events_.clear();
    if (f.index == 0) world_.start(events_);
    else (void)world_.step(events_);
    if (parts(f)) return std::nullopt;
    for (auto& v : want_) v.clear();
    for (auto& v : got_) v.clear();
    // First contacts: a ball's first hit, bump or meet, its kind and obstacle (the point is a rounded construction).
    const auto keep = [&](std::vector<Event>& v, Event e) {
        if (!map_.first_contacts) return v.push_back(e);
        const bool contact = e.kind == Event::Kind::hit || e.kind == Event::Kind::bump || e.kind == Event::Kind::meet;
        if (!contact || !v.empty()) return;
        e.pos = e.vel = {};
        v.push_back(e);
    };
    for (const Event& e : f.events) keep(want_[image_of(e.ball)], mapped(e));
    for (const Event& e : events_) keep(got_[e.ball], e);
    for (std::uint32_t ball = 0; ball < want_.size(); ++ball) {
        const auto& want = want_[image_of(ball)];
        const auto& got = got_[image_of(ball)];
        // A first meet, in either run, is decided on paths of rounded contact points: the ball is not compared.
        const auto meet_first = [](const std::vector<Event>& v) { return !v.empty() && v[0].kind == Event::Kind::meet; };
        if (map_.first_contacts && (meet_first(want) || meet_first(got))) continue;
        for (std::size_t j = 0; j < std::max(want.size(), got.size()); ++j) {
            // By value: x − x is +0 in both runs, so −0 against +0 is no asymmetry.
            if (j < want.size() && j < got.size() && want[j] == got[j]) continue;
            const auto say = [&](const std::vector<Event>& v) {
                if (j >= v.size()) return std::string("nothing");
                if (!map_.first_contacts) return fmt::format("'{}'", v[j]);
                return fmt::format("{} {}", v[j].kind == Event::Kind::hit ? "wall" : "bumper", v[j].index);
            };
            if (map_.first_contacts)
                return failure(c, f.index, ball,
                               fmt::format("{} meets {} first in this frame, the run {}", map_.name, say(got), say(want)));
            return failure(c, f.index, ball,
                           fmt::format("{} gives {} as ball {}'s event {} in this frame, expected {}", map_.name,
                                       say(got), ball, j, say(want)));
        }
    }
    return std::nullopt;
}

}  // namespace ricochet::checks
