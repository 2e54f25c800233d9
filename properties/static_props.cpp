// Static tests: symmetry and consistent boundary cases (circles, rectangles, points). Each statement
// is a list of checks (checks.hpp); the generator reaches the boundary cases.
#include <cmath>

#include "generators.hpp"
#include "harness.hpp"
#include "ricochet/truth.hpp"

namespace ricochet::props {
namespace {

/// Tags what the generator reached: exact touching, points exactly on boundaries, degenerate shapes.
void classify_static(const Scene& s) {
    for (const Ball& b : s.balls) {
        for (const Circle& c : s.circles) classify(truth::circle_side(b.pos, c) == 0, "point exactly on a circle");
        for (const Rect& r : s.rects) {
            const bool in = truth::point_in_rect(b.pos, r);
            const bool on_x = b.pos.x == r.left || b.pos.x == r.right, on_y = b.pos.y == r.bottom || b.pos.y == r.top;
            classify(in && on_x && on_y, "point on a rect corner");
            classify(in && (on_x != on_y), "point on a rect edge");
        }
    }
    for (std::size_t i = 0; i + 1 < s.circles.size(); ++i) {
        const Circle &a = s.circles[i], &c = s.circles[i + 1];
        const bool touch = truth::circles_overlap(a, c) &&
                           !truth::circles_overlap({a.c, a.r}, {c.c, std::nextafter(c.r, 0.0)});
        classify(touch, "circles touching exactly");
        classify(a.r == 0 || c.r == 0, "radius-0 circle");
    }
    for (std::size_t i = 0; i + 1 < s.rects.size(); ++i) {
        const Rect &a = s.rects[i], &r = s.rects[i + 1];
        const bool share_x = a.right == r.left || r.right == a.left, share_y = a.top == r.bottom || r.top == a.bottom;
        classify(truth::rects_overlap(a, r) && (share_x || share_y), "rects sharing an edge or corner");
        classify(r.left == r.right || r.bottom == r.top, "zero-width or zero-height rect");
    }
}

RICOCHET_PROPERTY_SUITE(Static);

/// Swapping the arguments of circle/circle and rect/rect changes nothing; mirroring the scene across
/// x = 0 or turning it by 90° changes no static answer.
TEST_P(Static, StaticSymmetry) {
    run_property({"StaticSymmetry", Check::swap, gen::static_scene(), checked({Check::swap, Check::symmetry},
                                                                                classify_static),
                  6000},
                 GetParam());
}

/// Touching is a collision (every static answer is the exact one), and a point, a radius-0 circle and a
/// zero-size rectangle at that point give the same answers.
TEST_P(Static, StaticBoundary) {
    run_property({"StaticBoundary", Check::boundary, gen::static_scene(),
                  checked({Check::boundary, Check::oracle}, classify_static), 6000},
                 GetParam());
}

}  // namespace
}  // namespace ricochet::props
