// translation: moving the whole scene by an offset that rounds nothing changes no decision (for a disc: its
// first contact in frames 0 and 1, the one its exact decisions reach before any rounded construction; not a meet,
// which is decided on paths of rounded contact points).
#include <fmt/format.h>

#include <array>

#include "checks/frame_check.hpp"
#include "ricochet/format.hpp"
#include "ricochet/truth.hpp"

namespace ricochet::checks {
namespace {

/// True if p + t is exact in both coordinates.
bool moves_exactly(Vec2 p, Vec2 t) { return truth::sum_exact(p.x, t.x) && truth::sum_exact(p.y, t.y); }

/// True if t moves every coordinate of the scene and every ball's Bs and Be = Bs + v without rounding, and
/// the moved Bs + v is the moved Be.
bool applies(const Scene& s, Vec2 t) {
    for (const Wall& w : s.walls)
        if (!moves_exactly(w.p0, t) || !moves_exactly(w.p1, t)) return false;
    for (const Ball& b : s.balls) {
        const Vec2 be = b.pos + b.vel;
        if (!moves_exactly(b.pos, t) || !moves_exactly(be, t) || !((b.pos + t) + b.vel == be + t)) return false;
    }
    for (const Circle& c : s.circles)
        if (!moves_exactly(c.c, t)) return false;
    for (const Bumper& u : s.bumpers)
        if (!moves_exactly(u.c, t)) return false;
    for (const Rect& r : s.rects)
        if (!moves_exactly({r.left, r.bottom}, t) || !moves_exactly({r.right, r.top}, t)) return false;
    return true;
}

Scene moved(const Scene& s, Vec2 t) {
    Scene out = s;
    for (Wall& w : out.walls) w = {w.p0 + t, w.p1 + t};
    for (Ball& b : out.balls) b.pos = b.pos + t;
    for (Circle& c : out.circles) c.c = c.c + t;
    for (Bumper& u : out.bumpers) u.c = u.c + t;
    for (Rect& r : out.rects) r = {r.left + t.x, r.bottom + t.y, r.right + t.x, r.top + t.y};
    return out;
}

/// What each ball did in a frame, for the decisions below: whether it met anything (a hit, a bump or a meet), and
/// whether its first contact was a meet.
struct Contacts {
    std::vector<bool> met, meet_first;
    Contacts(std::span<const Event> events, std::size_t balls) : met(balls, false), meet_first(balls, false) {
        for (const Event& e : events) {
            if (e.kind != Event::Kind::hit && e.kind != Event::Kind::bump && e.kind != Event::Kind::meet) continue;
            if (!met[e.ball]) meet_first[e.ball] = e.kind == Event::Kind::meet;
            met[e.ball] = true;
        }
    }
    /// Both runs' together: a ball counts as having met something, or met a ball first, if it did in either.
    void add(const Contacts& o) {
        for (std::size_t i = 0; i < met.size(); ++i) {
            met[i] = met[i] || o.met[i];
            meet_first[i] = meet_first[i] || o.meet_first[i];
        }
    }
};

/// The frame's decisions that an exact translation keeps: the overlaps of every ball that met nothing in the frame
/// (its state is Bs + v, which the offset moves exactly; after a contact the state is a rounded construction, which
/// an offset may round differently), and each ball's contacts, hit walls and bumped bumpers (the first only, or all
/// for the exact kernel, whose hit points are not rounded before the next decision). A ball whose first contact is
/// a meet, in either run, has none compared: a meet is decided on the balls' paths, whose contact points are
/// rounded constructions; its first hit or bump alone is decided from Bs and Be exactly.
std::vector<std::string> decisions(std::span<const Event> events, bool all_hits, const Contacts& both) {
    std::vector<std::string> out;
    std::vector<int> seen(both.met.size(), 0);
    for (const Event& e : events) {
        if (e.kind == Event::Kind::overlap && both.met[e.ball]) continue;
        if (e.kind == Event::Kind::overlap)
            out.push_back(fmt::format("overlap ball {} {} {}", e.ball, e.shape == Event::Shape::circle ? "circle" : "rect",
                                      e.index));
        if ((e.kind != Event::Kind::hit && e.kind != Event::Kind::bump) || both.meet_first[e.ball]) continue;
        if (e.kind == Event::Kind::hit && (all_hits || seen[e.ball]++ == 0))
            out.push_back(fmt::format("hit ball {} wall {}", e.ball, e.index));
        else if (e.kind == Event::Kind::bump && (all_hits || seen[e.ball]++ == 0))
            out.push_back(fmt::format("bump ball {} bumper {}", e.ball, e.index));
    }
    return out;
}

class Translation final : public FrameCheck {
public:
    Translation(const Scene& scene, KernelId kernel, const WorldOptions& world)
        : scene_(scene), kernel_(kernel),
          // The exact kernel rounds no point ball's hit point; a disc's contact points it rounds to the nearest
          // doubles, which an offset may move differently: for a disc (and any ball among bumpers or among balls
          // that collide, stepped as one), its first contact alone.
          all_hits_(kernel == KernelId::exact && !has_discs_or_bumpers(scene) && !scene.balls_collide) {
        for (Vec2 t : k_offsets) {
            if (!applies(scene, t)) continue;
            offsets_.push_back(t);
            moved_.push_back(moved(scene, t));
        }
        for (const Scene& m : moved_) worlds_.emplace_back(m, kernel, world);
    }

    std::optional<CheckFailure> frame(const Frame& f) override {
        // The run-level comparison holds where the states are still the same up to t: frames 0 and 1.
        if (f.index <= 1) {
            const Contacts ours(f.events, scene_.balls.size());
            for (std::size_t j = 0; j < worlds_.size(); ++j) {
                other_.clear();
                if (f.index == 0) worlds_[j].start(other_);
                else (void)worlds_[j].step(other_);
                Contacts both(other_, scene_.balls.size());
                both.add(ours);
                if (decisions(other_, all_hits_, both) != decisions(f.events, all_hits_, both))
                    return failure(Check::translation, f.index, 0,
                                   fmt::format("moving the scene by {} (exactly) changes a hit, a bump or an overlap",
                                               offsets_[j]));
            }
        }
        // A point ball's decisions from its printed states (a disc's are its first contact, compared above).
        for (const Event& e : f.events)
            if (e.kind == Event::Kind::state && !is_disc(scene_.balls[e.ball]))
                if (auto bad = at(f.index, e)) return bad;
        return std::nullopt;
    }

private:
    /// Every decision from the printed state e, against the scene moved by each offset that moves e exactly.
    std::optional<CheckFailure> at(std::int64_t f, const Event& e) const {
        const KernelId k = kernel_;
        const Vec2 p = e.pos, v = e.vel, be = p + v;
        for (std::size_t j = 0; j < offsets_.size(); ++j) {
            const Vec2 t = offsets_[j];
            if (!moves_exactly(p, t) || !moves_exactly(be, t) || !((p + t) + v == be + t)) continue;
            const Scene& m = moved_[j];
            const auto fail = [&](std::string what) {
                return failure(Check::translation, f, e.ball, fmt::format("moving by {}: {}", t, what));
            };
            for (std::size_t i = 0; i < scene_.walls.size(); ++i) {
                if (classify(k, p + t, m.walls[i]) != classify(k, p, scene_.walls[i]))
                    return fail(fmt::format("the side of {} against wall {} changes", p, i));
                if (v == Vec2{}) continue;
                if (sweep(k, p + t, v, m.walls[i]).miss != sweep(k, p, v, scene_.walls[i]).miss)
                    return fail(fmt::format("the sweep from {} moving {} against wall {} changes", p, v, i));
            }
            for (std::size_t c = 0; c < scene_.circles.size(); ++c)
                if (point_in_circle(k, p + t, m.circles[c]) != point_in_circle(k, p, scene_.circles[c]))
                    return fail(fmt::format("point_in_circle({}, circle {}) changes", p, c));
            for (std::size_t r = 0; r < scene_.rects.size(); ++r)
                if (point_in_rect(k, p + t, m.rects[r]) != point_in_rect(k, p, scene_.rects[r]))
                    return fail(fmt::format("point_in_rect({}, rect {}) changes", p, r));
        }
        return std::nullopt;
    }

    static constexpr std::array<Vec2, 5> k_offsets = {
        {{1, -2}, {1024, 4096}, {-0x1p30 * 3, 0x1p31}, {0x1p40, -0x1p40 * 5}, {0.5, 0.25}}};

    const Scene& scene_;
    KernelId kernel_;
    bool all_hits_;
    std::vector<Vec2> offsets_;
    std::vector<Scene> moved_;
    std::vector<World> worlds_;
    std::vector<Event> other_;
};

}  // namespace

std::unique_ptr<FrameCheck> make_translation(const Scene& scene, KernelId kernel, const WorldOptions& world) {
    return std::make_unique<Translation>(scene, kernel, world);
}

}  // namespace ricochet::checks
