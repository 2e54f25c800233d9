// symmetry: the scene mirrored across x = 0 runs as the mirror of the run; every static answer and
// every sweep from a printed state is unchanged by the mirror and by a quarter turn (both exact maps). A scene
// with a disc or a bumper also runs as its image mirrored across y = 0 and with its balls in reverse order,
// compared ball by ball (mapped_run.hpp).
#include <fmt/format.h>

#include "checks/frame_check.hpp"
#include "checks/mapped_run.hpp"
#include "ricochet/format.hpp"

namespace ricochet::checks {
namespace {

Event mirrored(Event e) {
    e.pos.x = -e.pos.x;
    e.vel.x = -e.vel.x;
    return e;
}

/// Miss with the two sides exchanged: what a mirror does to a decision.
Miss flip(Miss m) {
    if (m == Miss::both_inside) return Miss::both_outside;
    if (m == Miss::both_outside) return Miss::both_inside;
    return m;
}

/// An exact map of the plane, and whether it reverses orientation (sides flip).
struct Map {
    const char* name;
    Vec2 (*f)(Vec2);
    bool flips;
};
constexpr Map k_maps[] = {
    {"the mirror across x = 0", [](Vec2 p) { return Vec2{-p.x, p.y}; }, true},
    {"the quarter turn", [](Vec2 p) { return Vec2{-p.y, p.x}; }, false},
};

Wall map(const Map& m, const Wall& w) { return {m.f(w.p0), m.f(w.p1)}; }
Circle map(const Map& m, const Circle& c) { return {m.f(c.c), c.r}; }
Rect map(const Map& m, const Rect& r) {
    const Vec2 a = m.f({r.left, r.bottom}), b = m.f({r.right, r.top});
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
}

class Symmetry final : public FrameCheck {
public:
    Symmetry(const Scene& scene, KernelId kernel, const WorldOptions& world)
        : scene_(scene),
          kernel_(kernel),
          discs_(has_discs_or_bumpers(scene)) {
        if (discs_) {
            for (const SceneMap& m : k_disc_maps) images_.emplace_back(scene, m, kernel, world);
            return;
        }
        mirror_scene_ = mirror_x(scene);
        turned_scene_ = turned(scene);
        mirror_.emplace(mirror_scene_, kernel, world);
        turn_.emplace(turned_scene_, kernel, world);
    }

    std::optional<CheckFailure> frame(const Frame& f) override {
        for (MappedRun& image : images_)
            if (auto bad = image.frame(Check::symmetry, f)) return bad;
        for (int which = 0; which < 2 && !discs_; ++which) {
            World& world = which == 0 ? *mirror_ : *turn_;
            other_.clear();
            if (f.index == 0) world.start(other_);
            else (void)world.step(other_);
            expected_.clear();
            for (const Event& e : f.events) expected_.push_back(which == 0 ? mirrored(e) : turned(e));
            // By value: x − x is +0 in both runs, so −0 against +0 is no asymmetry.
            if (auto bad = compare_events(Check::symmetry, f.index, expected_, other_, false,
                                          which == 0 ? "the run mirrored across x = 0" : "the run turned by 90 degrees"))
                return bad;
        }
        if (f.index == 0)
            if (auto bad = statics(f.index)) return bad;
        // A point ball's decisions from its printed states (a disc's are its run's, compared above).
        for (const Event& e : f.events)
            if (e.kind == Event::Kind::state && !is_disc(scene_.balls[e.ball]))
                if (auto bad = decisions(f.index, e)) return bad;
        return std::nullopt;
    }

private:
    std::optional<CheckFailure> statics(std::int64_t f) const {
        const KernelId k = kernel_;
        for (const Map& m : k_maps) {
            for (const Circle& a : scene_.circles)
                for (const Circle& c : scene_.circles)
                    if (circles_overlap(k, map(m, a), map(m, c)) != circles_overlap(k, a, c))
                        return failure(Check::symmetry, f, 0,
                                       fmt::format("circles_overlap({}, {}) changes under {}", a, c, m.name));
            for (const Rect& a : scene_.rects)
                for (const Rect& r : scene_.rects)
                    if (rects_overlap(k, map(m, a), map(m, r)) != rects_overlap(k, a, r))
                        return failure(Check::symmetry, f, 0,
                                       fmt::format("rects_overlap({}, {}) changes under {}", a, r, m.name));
        }
        return std::nullopt;
    }

    std::optional<CheckFailure> decisions(std::int64_t f, const Event& e) const {
        const KernelId k = kernel_;
        const Vec2 p = e.pos, v = e.vel;
        const auto fail = [&](std::string what) { return failure(Check::symmetry, f, e.ball, std::move(what)); };
        for (const Map& m : k_maps) {
            for (const Circle& c : scene_.circles)
                if (point_in_circle(k, m.f(p), map(m, c)) != point_in_circle(k, p, c))
                    return fail(fmt::format("point_in_circle({}, {}) changes under {}", p, c, m.name));
            for (const Rect& r : scene_.rects)
                if (point_in_rect(k, m.f(p), map(m, r)) != point_in_rect(k, p, r))
                    return fail(fmt::format("point_in_rect({}, {}) changes under {}", p, r, m.name));
            for (std::size_t i = 0; i < scene_.walls.size(); ++i) {
                const Wall& w = scene_.walls[i];
                const Wall mw = map(m, w);
                const Side side = classify(k, p, w);
                if (classify(k, m.f(p), mw) != (m.flips ? opposite(side) : side))
                    return fail(fmt::format("the side of {} against wall {} changes under {}", p, i, m.name));
                if (v == Vec2{}) continue;
                const Sweep base = sweep(k, p, v, w), t = sweep(k, m.f(p), m.f(v), mw);
                const Miss want = m.flips ? flip(base.miss) : base.miss;
                if (t.miss != want)
                    return fail(fmt::format("from {} moving {} against wall {}: {}, but {} under {}", p, v, i,
                                            base.miss, t.miss, m.name));
                if (base.hit() && (t.t != base.t || !(t.point == m.f(base.point))))
                    return fail(fmt::format("from {} moving {} against wall {}: hit at t {} point {}, under {} at t {} "
                                            "point {}",
                                            p, v, i, base.t, base.point, m.name, t.t, t.point));
            }
        }
        return std::nullopt;
    }

    static Event turned(Event e) {
        e.pos = k_maps[1].f(e.pos);
        e.vel = k_maps[1].f(e.vel);
        return e;
    }
    static Scene turned(const Scene& s) {
        Scene out = s;
        for (Wall& w : out.walls) w = map(k_maps[1], w);
        for (Ball& b : out.balls) b = {k_maps[1].f(b.pos), k_maps[1].f(b.vel), b.r};
        for (Circle& c : out.circles) c = map(k_maps[1], c);
        for (Rect& r : out.rects) r = map(k_maps[1], r);
        return out;
    }

    /// The images a scene with a disc or a bumper is held to: both mirrors, the quarter turn, the balls reversed.
    static constexpr SceneMap k_disc_maps[] = {
        {"the run mirrored across x = 0", [](Vec2 p) { return Vec2{-p.x, p.y}; }, false, false},
        {"the run mirrored across y = 0", [](Vec2 p) { return Vec2{p.x, -p.y}; }, false, false},
        {"the run turned by 90 degrees", [](Vec2 p) { return Vec2{-p.y, p.x}; }, false, false},
        {"the run with its balls in reverse order", nullptr, false, true},
    };

    const Scene& scene_;
    KernelId kernel_;
    bool discs_;
    Scene mirror_scene_, turned_scene_;
    std::optional<World> mirror_, turn_;
    std::vector<MappedRun> images_;
    std::vector<Event> other_, expected_;
};

}  // namespace

std::unique_ptr<FrameCheck> make_symmetry(const Scene& scene, KernelId kernel, const WorldOptions& world) {
    return std::make_unique<Symmetry>(scene, kernel, world);
}

}  // namespace ricochet::checks
