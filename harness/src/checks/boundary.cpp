// boundary: the kernel's answers at the boundary agree with each other: a point, a radius-0 circle and
// a zero-size rectangle are the same thing; a circle holds a point as the point's circle holds its
// centre; classify and the sweep's first tests read one sign; a ball on a wall's line never hits it;
// a leg ending on the wall's line hits it at t = 1, at Be itself. A disc (and a point ball among bumpers) that
// starts a frame touching an obstacle, its centre exactly R from a wall's segment or R + r from a bumper's
// centre (or within, the start-in-reach rule), and whose leg Bs → Be (Be = Bs + v as rounded, the leg the kernel
// sweeps) starts by moving closer, meets it at once: its first event is a hit or a bump at its start point.
// Touching is contact.
#include <fmt/format.h>

#include "checks/frame_check.hpp"
#include "ricochet/format.hpp"
#include "ricochet/truth.hpp"

namespace ricochet::checks {
namespace {

class Boundary final : public FrameCheck {
public:
    Boundary(const Scene& scene, KernelId kernel)
        : scene_(scene), kernel_(kernel), reach_(has_discs_or_bumpers(scene)) {}

    std::optional<CheckFailure> frame(const Frame& f) override {
        if (reach_)
            for (std::uint32_t i = 0; i < f.before.size(); ++i)
                if (auto bad = touching(f, i)) return bad;
        for (const Event& e : f.events) {
            if (e.kind != Event::Kind::state || is_disc(scene_.balls[e.ball])) continue;
            if (auto bad = at(f, e)) return bad;
        }
        return std::nullopt;
    }

private:
    /// Ball i starts the frame at p moving v: if it touches an obstacle (or is within its reach) and its leg p → p + v
    /// starts by moving closer, its first event in the frame is a contact at p.
    std::optional<CheckFailure> touching(const Frame& f, std::uint32_t i) const {
        const Vec2 p = f.before[i].pos, v = f.before[i].vel, be = p + v;
        const double R = scene_.balls[i].r > 0 ? scene_.balls[i].r : 0.0;
        std::string what;
        // A point ball's walls are the point rules' (at() below): a disc's only.
        for (std::size_t k = 0; k < scene_.walls.size() && what.empty() && R > 0; ++k) {
            const int reach = truth::wall_reach_side(p, scene_.walls[k], R);
            if (reach <= 0 && truth::wall_approach_sign(p, be, scene_.walls[k]) < 0)
                what = fmt::format("{} R = {} from wall {}", reach == 0 ? "exactly" : "less than", R, k);
        }
        for (std::size_t k = 0; k < scene_.bumpers.size() && what.empty(); ++k) {
            const Bumper& u = scene_.bumpers[k];
            const int reach = truth::circle_reach_side(p, u.c, R, u.r);
            if (reach <= 0 && truth::circle_approach_sign(p, be, u.c) < 0)
                what = fmt::format("{} R + r = {} + {} from bumper {}'s centre", reach == 0 ? "exactly" : "less than",
                                   R, u.r, k);
        }
        if (what.empty()) return std::nullopt;
        const Event* first = nullptr;
        for (const Event& e : f.events)
            if (e.ball == i && e.kind != Event::Kind::overlap) {
                first = &e;
                break;
            }
        if (first != nullptr && first->kind != Event::Kind::state && first->pos == p) return std::nullopt;
        return failure(Check::boundary, f.index, i,
                       fmt::format("the ball starts the frame at {} moving {}, its centre {} and moving closer, so it "
                                   "meets that at once; but its first event is {}",
                                   p, v, what, first ? fmt::format("'{}'", *first) : std::string("none")));
    }

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
    bool reach_;  ///< a disc or a bumper: the touching rule applies
};

}  // namespace

std::unique_ptr<FrameCheck> make_boundary(const Scene& scene, KernelId kernel, const WorldOptions&) {
    return std::make_unique<Boundary>(scene, kernel);
}

}  // namespace ricochet::checks
