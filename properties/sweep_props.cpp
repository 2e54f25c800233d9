// Kernel-level properties of one leg against one wall: symmetry, consistent boundary cases, decisions
// equal to the exact ones, and the bounce's speed.
#include <fmt/format.h>

#include "generators.hpp"
#include "harness.hpp"
#include "oracle.hpp"
#include "ricochet/checks.hpp"
#include "ricochet/world.hpp"
#include "sweep_oracle.hpp"

namespace ricochet::props {
namespace {

/// Miss with Inside and Outside exchanged: what mirroring does to a classification.
Miss mirrored(Miss m) {
    if (m == Miss::both_inside) return Miss::both_outside;
    if (m == Miss::both_outside) return Miss::both_inside;
    return m;
}

bool bits_equal(double a, double b) { return a == b; }

/// Symmetry of one leg: reversing the wall flips the classification but not whether the ball hits;
/// mirroring across x = 0 flips sides and mirrors t_i, B_i; a quarter turn changes nothing but B_i's turn.
std::optional<Failure> sweep_symmetry(KernelId k, const Scene& s) {
    classify_legs(s);
    for (const Ball& b : s.balls) {
        const Vec2 bs = b.pos, v = b.vel, be = b.pos + b.vel;
        for (const Wall& w : s.walls) {
            const Sweep base = sweep(k, bs, v, w);
            const Wall rev{w.p1, w.p0};
            for (Vec2 p : {bs, be})
                if (classify(k, p, rev) != opposite(classify(k, p, w)))
                    return fail(Check::symmetry, fmt::format("reversing {} does not flip the side of {}", str(w), str(p)));
            const Sweep r = sweep(k, bs, v, rev);
            if (r.hit() != base.hit())
                return fail(Check::symmetry, fmt::format("ball {} moving {} against {}: {}, but {} when the wall is "
                                                         "reversed",
                                                         str(bs), str(v), str(w), miss_name(base.miss), miss_name(r.miss)));
            struct Map {
                const char* name;
                Vec2 (*f)(Vec2);
                bool flips;
            };
            for (const Map& m : {Map{"mirroring across x = 0", mirror, true}, Map{"a quarter turn", rotate90, false}}) {
                const Wall mw{m.f(w.p0), m.f(w.p1)};
                const Sweep t = sweep(k, m.f(bs), m.f(v), mw);
                const Miss want = m.flips ? mirrored(base.miss) : base.miss;
                const Side side = m.flips ? opposite(classify(k, bs, w)) : classify(k, bs, w);
                if (classify(k, m.f(bs), mw) != side)
                    return fail(Check::symmetry, fmt::format("{} changes the side of {} against {}", m.name, str(bs), str(w)));
                if (t.miss != want)
                    return fail(Check::symmetry, fmt::format("ball {} moving {} against {}: {}, but {} after {}", str(bs),
                                                             str(v), str(w), miss_name(base.miss), miss_name(t.miss),
                                                             m.name));
                if (base.hit() && (!bits_equal(t.t, base.t) || !same_value(t.point, m.f(base.point))))
                    return fail(Check::symmetry, fmt::format("ball {} moving {} against {}: hit at t {} point {}, but "
                                                             "after {} at t {} point {} (expected {})",
                                                             str(bs), str(v), str(w), base.t, str(base.point), m.name,
                                                             t.t, str(t.point), str(m.f(base.point))));
            }
        }
    }
    return std::nullopt;
}

/// Consistent boundary of one leg: the classification of Bs and Be is the exact side; the animated test's
/// decision is the exact one (touching is a collision, leaving is not); a leg ending exactly on the wall's
/// closed segment hits it at t = 1, at Be itself.
std::optional<Failure> sweep_boundary(KernelId k, const Scene& s) {
    classify_legs(s);
    for (const Ball& b : s.balls) {
        const Vec2 bs = b.pos, v = b.vel, be = b.pos + b.vel;
        for (const Wall& w : s.walls) {
            for (Vec2 p : {bs, be}) {
                const Side want = side_from_sign(side_oracle(p, w));
                if (classify(k, p, w) != want)
                    return fail(Check::boundary, fmt::format("classify({}, {}) = {}, exactly {}", str(p), str(w),
                                                             sign_of(classify(k, p, w)), sign_of(want)));
            }
            const Sweep got = sweep(k, bs, v, w);
            const Miss want = expected_miss(bs, be, w);
            if (got.miss != want)
                return fail(Check::boundary, fmt::format("ball {} moving {} (Be {}) against {}: {}, exactly {}",
                                                         str(bs), str(v), str(be), str(w), miss_name(got.miss),
                                                         miss_name(want)));
            if (got.hit() && side_oracle(be, w) == 0 && (got.t != 1.0 || !same_value(got.point, be)))
                return fail(Check::boundary, fmt::format("ball {} moving {} ends on {} at {} but the hit is at t {} "
                                                         "point {}",
                                                         str(bs), str(v), str(w), str(be), got.t, str(got.point)));
        }
    }
    return std::nullopt;
}

/// Every decision equals the exact one: static tests, sides and legs (against the exact kernel, and the
/// exact kernel against the independent oracle).
std::optional<Failure> decisions_exact(KernelId k, const Scene& s) {
    classify_legs(s);
    const KernelId ref = KernelId::exact;
    for (const Ball& b : s.balls) {
        const Vec2 bs = b.pos, v = b.vel, be = b.pos + b.vel;
        for (const Wall& w : s.walls) {
            for (Vec2 p : {bs, be}) {
                const Side got = classify(k, p, w), want = classify(ref, p, w);
                const Side truth = side_from_sign(side_oracle(p, w));
                if (got != want || want != truth)
                    return fail(Check::oracle, fmt::format("classify({}, {}): {} {}, exact kernel {}, oracle {}", str(p),
                                                           str(w), kernel_name(k), sign_of(got), sign_of(want),
                                                           sign_of(truth)));
            }
            const Miss got = sweep(k, bs, v, w).miss, want = sweep(ref, bs, v, w).miss;
            const Miss truth = expected_miss(bs, be, w);
            if (got != want || want != truth)
                return fail(Check::oracle, fmt::format("ball {} moving {} against {}: {} says {}, exact kernel {}, "
                                                       "oracle {}",
                                                       str(bs), str(v), str(w), kernel_name(k), miss_name(got),
                                                       miss_name(want), miss_name(truth)));
        }
        for (const Circle& c : s.circles)
            if (point_in_circle(k, bs, c) != point_in_circle(ref, bs, c) ||
                point_in_circle(ref, bs, c) != point_in_circle_oracle(bs, c))
                return fail(Check::oracle, fmt::format("point_in_circle({}, circle {} r {}) differs from the exact "
                                                       "answer",
                                                       str(bs), str(c.c), c.r));
        for (const Rect& r : s.rects)
            if (point_in_rect(k, bs, r) != point_in_rect_oracle(bs, r))
                return fail(Check::oracle, fmt::format("point_in_rect({}, ...) differs from the exact answer", str(bs)));
    }
    for (const Circle& a : s.circles)
        for (const Circle& c : s.circles)
            if (circles_overlap(k, a, c) != circles_overlap(ref, a, c) ||
                circles_overlap(ref, a, c) != circles_overlap_oracle(a, c))
                return fail(Check::oracle, fmt::format("circles_overlap(circle {} r {}, circle {} r {}) differs from "
                                                       "the exact answer",
                                                       str(a.c), a.r, str(c.c), c.r));
    for (const Rect& a : s.rects)
        for (const Rect& r : s.rects)
            if (rects_overlap(k, a, r) != rects_overlap_oracle(a, r))
                return fail(Check::oracle, "rects_overlap differs from the exact answer");
    return std::nullopt;
}

/// The bounce keeps the speed: for every velocity and wall, | |v'| − |v| | ≤ k_speed_rel_bound·|v| +
/// k_speed_abs_bound (kernel.hpp; decided exactly); and over a run, a frame with n hits changes |v| by at most (1 + b)^(4n + 1) − 1 relative (each
/// hit reflects about at most the 4 walls BallMemory holds; a leg blocked by a contact at the frame's start
/// adds one more reflection).
std::optional<Failure> bounce_speed(KernelId k, const Scene& s) {
    classify_legs(s);
    const double bound = speed_rel_bound(k);
    // kernel.hpp: robust and exact also allow k_speed_abs_bound per bounce for subnormal rounding.
    const double abs_bound = k == KernelId::robust || k == KernelId::exact ? k_speed_abs_bound : 0.0;
    for (const Ball& b : s.balls)
        for (const Wall& w : s.walls) {
            if (w.p0 == w.p1) continue;  // a zero-length wall has no normal: never hit, never reflects
            const Vec2 r = reflect(k, b.vel, w);
            classify(std::fabs(b.vel.x) < 0x1p-1000 && std::fabs(b.vel.y) < 0x1p-1000 && b.vel != Vec2{},
                        "tiny velocity (|v| < 2^-1000)");
            if (!speed_within(b.vel, r, 1, bound, abs_bound))
                return fail(Check::speed, fmt::format("reflect({}, {}) = {}: |v'| differs from |v| by more than "
                                                      "{} |v|",
                                                      str(b.vel), str(w), str(r), bound));
        }
    World world(s, k);
    std::vector<Event> events;
    world.start(events);
    for (std::int64_t f = 1; f <= s.frames; ++f) {
        const std::vector<Ball> before(world.balls().begin(), world.balls().end());
        events.clear();
        if (world.step(events)) return std::nullopt;  // out of range: not this property's business
        std::vector<int> hits(before.size(), 0);
        for (const Event& e : events)
            if (e.kind == Event::Kind::hit) ++hits[e.ball];
        for (std::size_t i = 0; i < before.size(); ++i) {
            const Vec2 v0 = before[i].vel, v1 = world.balls()[i].vel;
            if (!speed_within(v0, v1, 4 * hits[i] + 1, bound, abs_bound))
                return fail(Check::speed, fmt::format("frame {} ball {}: {} hits change the velocity {} to {}", f, i,
                                                      hits[i], str(v0), str(v1)));
        }
    }
    return std::nullopt;
}

RICOCHET_PROPERTY_SUITE(Sweep);

TEST_P(Sweep, SweepSymmetry) {
    run_property({"SweepSymmetry", Check::symmetry, gen::wall_scene(3, 1), sweep_symmetry, 8000}, GetParam());
}

TEST_P(Sweep, SweepBoundary) {
    run_property({"SweepBoundary", Check::boundary, gen::wall_scene(3, 1), sweep_boundary, 8000}, GetParam());
}

TEST_P(Sweep, DecisionsEqualExact) {
    const auto g = rc::gen::weightedOneOf<Scene>({{3, gen::wall_scene(3, 1)}, {1, gen::static_scene()}});
    run_property({"DecisionsEqualExact", Check::oracle, g, decisions_exact, 8000}, GetParam());
}

TEST_P(Sweep, BounceSpeed) {
    run_property({"BounceSpeed", Check::speed, gen::wall_scene(3, 4), bounce_speed, 3000}, GetParam());
}

}  // namespace
}  // namespace ricochet::props
