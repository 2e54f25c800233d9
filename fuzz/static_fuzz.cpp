// Fuzz target `static`: the four static tests (point/circle, circle/circle, point/rectangle,
// rectangle/rectangle) and the classification of a point against a wall.
// Oracle: every answer equals the exact kernel's (oracle); swapping the arguments or reversing the
// wall gives the same, or the opposite, answer (symmetry); a point, a radius-0 circle and a
// zero-size rectangle agree, and a point the kernel classifies On a wall is never "hit" by a sweep
// that starts there (boundary).
#include <cstdint>
#include <string>

#include <fmt/format.h>

#include "fuzz_common.hpp"

namespace ricochet::fuzz {
namespace {

/// The geometry a static input decodes to.
struct StaticCase {
    Wall wall;
    Circle a, b;
    Rect ra, rb;
    Vec2 p;
    Vec2 v;  ///< a motion starting at p, for the classification/sweep agreement
};

StaticCase decode(const std::uint8_t* data, std::size_t size) {
    ByteReader in(data, size);
    StaticCase c;
    c.wall = in.wall();
    c.a = in.circle();
    c.ra = in.rect();
    c.b = in.circle();
    c.rb = in.rect();
    c.p = in.point();
    c.v = in.velocity(c.p);
    return c;
}

/// The case as a scene: the wall, the circles and rectangles, and a ball at p moving v, for 0 frames
/// (static checks only).
Scene to_scene(const StaticCase& c) {
    Scene s;
    s.frames = 0;
    s.walls = {c.wall};
    s.balls = {Ball{c.p, c.v}};
    s.circles = {c.a, c.b};
    s.rects = {c.ra, c.rb};
    return s;
}

std::string show(Vec2 p) { return fmt::format("({}, {})", p.x, p.y); }
std::string show(const Circle& c) { return fmt::format("circle {} r {}", show(c.c), c.r); }
std::string show(const Rect& r) { return fmt::format("rect [{}, {}]×[{}, {}]", r.left, r.right, r.bottom, r.top); }

[[noreturn]] void failed(const StaticCase& c, Check check, std::string kind, std::string what) {
    fail("static", Failure{check, 0, std::move(kind), std::move(what)}, to_scene(c));
}

void expect_same(const StaticCase& c, Check check, const char* kind, bool got, bool want, const std::string& what) {
    if (got != want) failed(c, check, kind, fmt::format("{}: got {}, expected {}", what, got, want));
}

void check_oracle(KernelId k, const StaticCase& c) {
    const auto kn = kernel_name(k);
    const Side side = classify(k, c.p, c.wall);
    const Side exact_side = classify(KernelId::exact, c.p, c.wall);
    if (side != exact_side)
        failed(c, Check::oracle, "classify",
               fmt::format("{} against wall {}→{}: {} says {}, exact {}", show(c.p), show(c.wall.p0), show(c.wall.p1), kn,
                           sign_of(side), sign_of(exact_side)));
    expect_same(c, Check::oracle, "point-circle", point_in_circle(k, c.p, c.a), point_in_circle(KernelId::exact, c.p, c.a),
                fmt::format("{} in {} ({} vs exact)", show(c.p), show(c.a), kn));
    expect_same(c, Check::oracle, "circle-circle", circles_overlap(k, c.a, c.b), circles_overlap(KernelId::exact, c.a, c.b),
                fmt::format("{} overlaps {} ({} vs exact)", show(c.a), show(c.b), kn));
    expect_same(c, Check::oracle, "point-rect", point_in_rect(k, c.p, c.ra), point_in_rect(KernelId::exact, c.p, c.ra),
                fmt::format("{} in {} ({} vs exact)", show(c.p), show(c.ra), kn));
    expect_same(c, Check::oracle, "rect-rect", rects_overlap(k, c.ra, c.rb), rects_overlap(KernelId::exact, c.ra, c.rb),
                fmt::format("{} overlaps {} ({} vs exact)", show(c.ra), show(c.rb), kn));
}

void check_symmetry(KernelId k, const StaticCase& c) {
    expect_same(c, Check::symmetry, "circle-swap", circles_overlap(k, c.b, c.a), circles_overlap(k, c.a, c.b),
                fmt::format("{} overlaps {} with the arguments swapped", show(c.b), show(c.a)));
    expect_same(c, Check::symmetry, "rect-swap", rects_overlap(k, c.rb, c.ra), rects_overlap(k, c.ra, c.rb),
                fmt::format("{} overlaps {} with the arguments swapped", show(c.rb), show(c.ra)));
    // Reversing P0 → P1 flips n = (e_y, −e_x), so BC changes sign.
    const Side side = classify(k, c.p, c.wall);
    const Side back = classify(k, c.p, reversed(c.wall));
    if (back != opposite(side))
        failed(c, Check::symmetry, "reversed-wall",
               fmt::format("{}: side {} but {} against the reversed wall", show(c.p), sign_of(side), sign_of(back)));
}

void check_boundary(KernelId k, const StaticCase& c) {
    // A point, a radius-0 circle and a zero-size rectangle are the same thing.
    const Circle dot_circle{c.p, 0.0};
    const Rect dot_rect{c.p.x, c.p.y, c.p.x, c.p.y};
    expect_same(c, Check::boundary, "point-as-circle", circles_overlap(k, dot_circle, c.a), point_in_circle(k, c.p, c.a),
                fmt::format("radius-0 circle at {} against {} (vs the point test)", show(c.p), show(c.a)));
    expect_same(c, Check::boundary, "point-as-rect", rects_overlap(k, dot_rect, c.ra), point_in_rect(k, c.p, c.ra),
                fmt::format("zero-size rect at {} against {} (vs the point test)", show(c.p), show(c.ra)));
    expect_same(c, Check::boundary, "radius-0", point_in_circle(k, c.p, Circle{c.b.c, 0.0}), c.p == c.b.c,
                fmt::format("{} in the radius-0 circle at {}", show(c.p), show(c.b.c)));
    expect_same(c, Check::boundary, "circle-as-point", point_in_circle(k, c.a.c, Circle{c.p, c.a.r}),
                point_in_circle(k, c.p, c.a), fmt::format("{} in {} vs its mirror", show(c.p), show(c.a)));
    // A ball starting on the wall's line cannot hit it: it moves along it or leaves it.
    if (classify(k, c.p, c.wall) == Side::on) {
        const Sweep s = sweep(k, c.p, c.v, c.wall);
        if (s.hit())
            failed(c, Check::boundary, "on-line-sweep",
                   fmt::format("{} is On the wall {}→{}, yet a sweep from it moving {} hits it", show(c.p), show(c.wall.p0),
                               show(c.wall.p1), show(c.v)));
    }
}

}  // namespace
}  // namespace ricochet::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace ricochet::fuzz;
    const ricochet::KernelId k = kernel_under_test();
    const StaticCase c = decode(data, size);
    check_oracle(k, c);
    check_symmetry(k, c);
    check_boundary(k, c);
    return 0;
}
