// boundary: the kernel's answers at the boundary agree with each other: a point, a radius-0 circle and
// a zero-size rectangle are the same thing; a circle holds a point as the point's circle holds its
// centre; classify and the sweep's first tests read one sign; a ball on a wall's line never hits it;
// a leg ending on the wall's line hits it at t = 1, at Be itself.
#include <fmt/format.h>

#include "checks/frame_check.hpp"
#include "ricochet/format.hpp"

namespace ricochet::checks {
namespace {

class Boundary final : public FrameCheck {
public:
    Boundary(const Scene& scene, KernelId kernel) : scene_(scene), kernel_(kernel) {}

    std::optional<CheckFailure> frame(const Frame& f) override {
        for (const Event& e : f.events) {
            if (e.kind != Event::Kind::state) continue;
            if (auto bad = at(f, e)) return bad;
        }
        return std::nullopt;
    }

private:
    std::optional<CheckFailure> at(const Frame& f, const Event& e) const {
        const KernelId k = kernel_;
        const Vec2 p = e.pos, v = e.vel;
        const auto fail = [&](std::string m) { return failure(Check::boundary, f.index, e.ball, std::move(m)); };
        const Circle dot{p, 0.0};
        const Rect box{p.x, p.y, p.x, p.y};
        // The degenerate shapes at p hold exactly p among the frame's printed positions.
        for (const Event& o : f.events) {
            if (o.kind != Event::Kind::state) continue;
            const bool same = o.pos == p;
            if (point_in_circle(k, o.pos, dot) != same)
                return fail(fmt::format("the radius-0 circle at {} says {} holds {}", p,
                                        same ? "it no longer" : "it", o.pos));
            if (point_in_rect(k, o.pos, box) != same)
                return fail(fmt::format("the zero-size rect at {} says {} holds {}", p, same ? "it no longer" : "it",
                                        o.pos));
        }
        for (std::size_t c = 0; c < scene_.circles.size(); ++c) {
            const Circle& C = scene_.circles[c];
            const bool in = point_in_circle(k, p, C);
            if (circles_overlap(k, dot, C) != in)
                return fail(fmt::format("point/circle says {} but circle/circle with radius 0 says {} for circle {}",
                                        in ? "inside" : "outside", in ? "apart" : "overlap", c));
            // |p − c| ≤ r is |c − p| ≤ r: the centre lies in the circle of the same radius about p.
            if (point_in_circle(k, C.c, Circle{p, C.r}) != in)
                return fail(fmt::format("{} is {} circle {} but its centre is {} the circle of radius {} about it", p,
                                        in ? "in" : "not in", c, in ? "not in" : "in", C.r));
        }
        for (std::size_t r = 0; r < scene_.rects.size(); ++r) {
            const bool in = point_in_rect(k, p, scene_.rects[r]);
            if (rects_overlap(k, box, scene_.rects[r]) != in)
                return fail(fmt::format("point/rect says {} but rect/rect with a zero-size rect says {} for rect {}",
                                        in ? "inside" : "outside", in ? "apart" : "overlap", r));
        }
        if (v == Vec2{}) return std::nullopt;
        const Vec2 be = p + v;
        for (std::size_t i = 0; i < scene_.walls.size(); ++i) {
            const Wall& w = scene_.walls[i];
            const Side s = classify(k, p, w);
            const Sweep got = sweep(k, p, v, w);
            const Miss m = got.miss;
            // Test 1 and 2 read the sign of BC(Bs) that classify gives.
            const bool bad = (s == Side::on && (m == Miss::both_inside || m == Miss::both_outside)) ||
                             (s == Side::inside && m == Miss::both_outside) ||
                             (s == Side::outside && m == Miss::both_inside);
            if (bad) return fail(fmt::format("classify says {} is {} wall {} but the sweep from it says {}", p, s, i, m));
            if (s == Side::on && got.hit())
                return fail(fmt::format("{} is on wall {}'s line, yet the sweep from it moving {} hits it", p, i, v));
            if (got.hit() && classify(k, be, w) == Side::on && (got.t != 1.0 || !(got.point == be)))
                return fail(fmt::format("from {} moving {} the leg ends on wall {}'s line at {}, but the hit is at t {} "
                                        "point {}",
                                        p, v, i, be, got.t, got.point));
        }
        return std::nullopt;
    }

    const Scene& scene_;
    KernelId kernel_;
};

}  // namespace

std::unique_ptr<FrameCheck> make_boundary(const Scene& scene, KernelId kernel, const WorldOptions&) {
    return std::make_unique<Boundary>(scene, kernel);
}

}  // namespace ricochet::checks
