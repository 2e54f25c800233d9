// Static tests: symmetry and consistent boundary cases (circles, rectangles, points).
#include <fmt/format.h>

#include <vector>

#include "generators.hpp"
#include "harness.hpp"
#include "oracle.hpp"

namespace ricochet::props {
namespace {

/// Every static answer of a scene under kernel k, in a fixed order: point/circle, point/rect,
/// circle/circle and rect/rect for every pair (both orders).
std::vector<bool> static_answers(KernelId k, const Scene& s) {
    std::vector<bool> out;
    for (const Ball& b : s.balls) {
        for (const Circle& c : s.circles) out.push_back(point_in_circle(k, b.pos, c));
        for (const Rect& r : s.rects) out.push_back(point_in_rect(k, b.pos, r));
    }
    for (const Circle& a : s.circles)
        for (const Circle& c : s.circles) out.push_back(circles_overlap(k, a, c));
    for (const Rect& a : s.rects)
        for (const Rect& r : s.rects) out.push_back(rects_overlap(k, a, r));
    return out;
}

using props::str;
std::string str(const Circle& c) { return fmt::format("circle {} r {}", props::str(c.c), c.r); }
std::string str(const Rect& r) { return fmt::format("rect [{}, {}] x [{}, {}]", r.left, r.right, r.bottom, r.top); }

/// Tags what the generator reached: exact touching, points exactly on boundaries, degenerate shapes.
void classify_static(const Scene& s) {
    for (const Ball& b : s.balls) {
        for (const Circle& c : s.circles) classify(circle_side_oracle(b.pos, c) == 0, "point exactly on a circle");
        for (const Rect& r : s.rects) {
            const bool in = point_in_rect_oracle(b.pos, r);
            const bool on_x = b.pos.x == r.left || b.pos.x == r.right, on_y = b.pos.y == r.bottom || b.pos.y == r.top;
            classify(in && on_x && on_y, "point on a rect corner");
            classify(in && (on_x != on_y), "point on a rect edge");
        }
    }
    for (std::size_t i = 0; i + 1 < s.circles.size(); ++i) {
        const Circle &a = s.circles[i], &c = s.circles[i + 1];
        const bool touch = circles_overlap_oracle(a, c) &&
                           !circles_overlap_oracle({a.c, a.r}, {c.c, std::nextafter(c.r, 0.0)});
        classify(touch, "circles touching exactly");
        classify(a.r == 0 || c.r == 0, "radius-0 circle");
    }
    for (std::size_t i = 0; i + 1 < s.rects.size(); ++i) {
        const Rect &a = s.rects[i], &r = s.rects[i + 1];
        const bool share_x = a.right == r.left || r.right == a.left, share_y = a.top == r.bottom || r.top == a.bottom;
        classify(rects_overlap_oracle(a, r) && (share_x || share_y), "rects sharing an edge or corner");
        classify(r.left == r.right || r.bottom == r.top, "zero-width or zero-height rect");
    }
}

/// Symmetry: swapping the arguments of circle/circle and rect/rect changes nothing; mirroring the scene
/// across x = 0 or turning it by 90° (both exact) changes no static answer.
std::optional<Failure> static_symmetry(KernelId k, const Scene& s) {
    classify_static(s);
    for (const Circle& a : s.circles)
        for (const Circle& c : s.circles)
            if (circles_overlap(k, a, c) != circles_overlap(k, c, a))
                return fail(Check::symmetry, fmt::format("circles_overlap({}, {}) = {} but swapped = {}", str(a), str(c),
                                                         circles_overlap(k, a, c), circles_overlap(k, c, a)));
    for (const Rect& a : s.rects)
        for (const Rect& r : s.rects)
            if (rects_overlap(k, a, r) != rects_overlap(k, r, a))
                return fail(Check::symmetry, fmt::format("rects_overlap({}, {}) = {} but swapped = {}", str(a), str(r),
                                                         rects_overlap(k, a, r), rects_overlap(k, r, a)));
    const std::vector<bool> base = static_answers(k, s);
    if (static_answers(k, transform(s, mirror)) != base)
        return fail(Check::symmetry, "mirroring the scene across x = 0 changes a static answer");
    if (static_answers(k, transform(s, rotate90)) != base)
        return fail(Check::symmetry, "turning the scene by 90 degrees changes a static answer");
    return std::nullopt;
}

/// Consistent boundary: every static test counts touching as a collision (equals the exact answer), and a
/// point, a radius-0 circle and a zero-size rectangle at that point give the same answers.
std::optional<Failure> static_boundary(KernelId k, const Scene& s) {
    classify_static(s);
    for (const Ball& b : s.balls) {
        const Vec2 p = b.pos;
        const Circle dot{p, 0.0};
        const Rect box{p.x, p.y, p.x, p.y};
        for (const Circle& c : s.circles) {
            const bool want = point_in_circle_oracle(p, c);
            if (point_in_circle(k, p, c) != want)
                return fail(Check::boundary, fmt::format("point_in_circle({}, {}) = {}, exactly {}", str(p), str(c),
                                                         !want, want));
            if (circles_overlap(k, dot, c) != want)
                return fail(Check::boundary, fmt::format("circles_overlap(radius-0 circle at {}, {}) = {} but the "
                                                         "point is {} the circle (exactly)",
                                                         str(p), str(c), !want, want ? "in" : "not in"));
        }
        for (const Rect& r : s.rects) {
            const bool want = point_in_rect_oracle(p, r);
            if (point_in_rect(k, p, r) != want)
                return fail(Check::boundary,
                            fmt::format("point_in_rect({}, {}) = {}, exactly {}", str(p), str(r), !want, want));
            if (rects_overlap(k, box, r) != want)
                return fail(Check::boundary, fmt::format("rects_overlap(zero-size rect at {}, {}) = {} but the point "
                                                         "is {} the rect",
                                                         str(p), str(r), !want, want ? "in" : "not in"));
        }
        // The degenerate shapes themselves contain exactly their own point.
        for (const Ball& o : s.balls) {
            const bool same = same_value(o.pos, p);
            if (point_in_circle(k, o.pos, dot) != same || point_in_rect(k, o.pos, box) != same)
                return fail(Check::boundary, fmt::format("the radius-0 circle / zero-size rect at {} disagree about "
                                                         "the point {}",
                                                         str(p), str(o.pos)));
        }
    }
    for (const Circle& a : s.circles)
        for (const Circle& c : s.circles)
            if (circles_overlap(k, a, c) != circles_overlap_oracle(a, c))
                return fail(Check::boundary, fmt::format("circles_overlap({}, {}) = {}, exactly {}", str(a), str(c),
                                                         circles_overlap(k, a, c), circles_overlap_oracle(a, c)));
    for (const Rect& a : s.rects)
        for (const Rect& r : s.rects)
            if (rects_overlap(k, a, r) != rects_overlap_oracle(a, r))
                return fail(Check::boundary, fmt::format("rects_overlap({}, {}) = {}, exactly {}", str(a), str(r),
                                                         rects_overlap(k, a, r), rects_overlap_oracle(a, r)));
    return std::nullopt;
}

RICOCHET_PROPERTY_SUITE(Static);

TEST_P(Static, StaticSymmetry) {
    run_property({"StaticSymmetry", Check::symmetry, gen::static_scene(), static_symmetry, 6000}, GetParam());
}

TEST_P(Static, StaticBoundary) {
    run_property({"StaticBoundary", Check::boundary, gen::static_scene(), static_boundary, 6000}, GetParam());
}

}  // namespace
}  // namespace ricochet::props
