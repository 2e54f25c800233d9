// Static-shape generators for the properties: circles, rectangles and points at rest, each free or derived
// from the one before it (circles touching exactly via Pythagorean triples scaled by powers of two,
// rectangles sharing an edge or a corner, points exactly on a circle or on a rectangle's edge or corner).
#pragma once

#include <rapidcheck.h>

#include <array>
#include <cmath>
#include <vector>

#include "generators_numbers.hpp"
#include "oracle.hpp"
#include "ricochet/scene.hpp"

namespace ricochet::props::gen {

namespace rcg = rc::gen;

/// Pythagorean triples (a, b, c), a² + b² = c²: exact points on circles and exactly touching circles.
inline constexpr std::array<std::array<int, 3>, 7> k_triples = {
    {{0, 1, 1}, {3, 4, 5}, {5, 12, 13}, {8, 15, 17}, {7, 24, 25}, {20, 21, 29}, {119, 120, 169}}};
/// Where a derived radius splits a distance c between two touching circles: rA = c·q, rB = c − rA.
inline constexpr std::array<double, 5> k_splits = {0.5, 0.0, 1.0, 0.25, 0.375};

/// How to build one static shape, or a point, relative to the previous one.
struct ShapeSpec {
    int mode = 0;          ///< 0 derived from the previous shape (touching / on it), 1 free
    int triple = 1;        ///< index into k_triples
    int sx = 1, sy = 1;    ///< signs of the triple's legs
    bool swap = false;     ///< swap the legs
    int scale_exp = 0;     ///< triple ×2^scale_exp
    int split = 0;         ///< index into k_splits
    int ur = 0;            ///< ulps by which the derived radius or point is moved
    int corner = 0;        ///< rect: which edge or corner is shared or touched (0..8)
    Vec2 c;                ///< free: centre or corner
    double r = 1;          ///< free: radius or size
    double h = 1;          ///< free: rect height
};

inline rc::Gen<ShapeSpec> shape_spec() {
    return rcg::build<ShapeSpec>(
        rcg::set(&ShapeSpec::mode, upto(1)), rcg::set(&ShapeSpec::triple, upto(int(k_triples.size()) - 1)),
        rcg::set(&ShapeSpec::sx, rcg::element(1, -1)), rcg::set(&ShapeSpec::sy, rcg::element(1, -1)),
        rcg::set(&ShapeSpec::swap, rcg::arbitrary<bool>()), rcg::set(&ShapeSpec::scale_exp, signed_upto(40)),
        rcg::set(&ShapeSpec::split, upto(int(k_splits.size()) - 1)),
        rcg::set(&ShapeSpec::ur, rcg::weightedOneOf<int>({{3, rcg::just(0)}, {2, signed_upto(2)}})),
        rcg::set(&ShapeSpec::corner, upto(8)), rcg::set(&ShapeSpec::c, vec()),
        rcg::set(&ShapeSpec::r, rcg::weightedOneOf<double>({{1, rcg::just(0.0)}, {4, coordinate()}})),
        rcg::set(&ShapeSpec::h, rcg::weightedOneOf<double>({{1, rcg::just(0.0)}, {4, coordinate()}})));
}

/// (x, y) of the spec's triple, signed, swapped and scaled, and its hypotenuse c: x² + y² = c² exactly.
inline std::array<double, 3> scaled_triple(const ShapeSpec& s) {
    const auto& t = k_triples[std::size_t(s.triple)];
    double a = s.sx * std::ldexp(double(t[0]), s.scale_exp), b = s.sy * std::ldexp(double(t[1]), s.scale_exp);
    if (s.swap) std::swap(a, b);
    return {a, b, std::ldexp(double(t[2]), s.scale_exp)};
}

/// A point on (or a few ulps off) the rectangle's boundary: corner or edge midpoint k of 0..8 (8: centre).
inline Vec2 rect_point(const Rect& r, int k, int ulps) {
    const double xs[3] = {r.left, 0.5 * r.left + 0.5 * r.right, r.right};
    const double ys[3] = {r.bottom, 0.5 * r.bottom + 0.5 * r.top, r.top};
    const Vec2 p{xs[k % 3], ys[(k / 3) % 3]};
    return nudge(p, ulps, -ulps);
}

/// Static scenes: 1..4 circles, 1..4 rectangles and 1..4 points (balls at rest), each either free or
/// derived from the one before it: circles touching exactly (or a few ulps apart or overlapping),
/// rectangles sharing an edge or a corner, points exactly on a circle or on a rectangle's edge or corner.
inline rc::Gen<Scene> static_scene() {
    const auto specs = [](int lo, int hi) {
        return rcg::mapcat(rcg::inRange(lo, hi + 1),
                           [](int n) { return rcg::container<std::vector<ShapeSpec>>(std::size_t(n), shape_spec()); });
    };
    return rcg::apply(
        [](const std::vector<ShapeSpec>& cs, const std::vector<ShapeSpec>& rs, const std::vector<ShapeSpec>& ps,
           Vec2 off) {
            Scene s;
            for (const ShapeSpec& c : cs) {
                if (c.mode == 1 || s.circles.empty()) {
                    s.circles.push_back({c.c + off, std::fabs(c.r)});
                    continue;
                }
                // Touching the previous circle: |cA − cB| = c = rA + rB exactly.
                // If rB = c − rA is not exact, the previous radius becomes c·q (q dyadic: c − c·q is exact).
                Circle& prev = s.circles.back();
                const auto [x, y, h] = scaled_triple(c);
                if (!(h - prev.r >= 0) || !sum_exact(h, -prev.r)) prev.r = h * k_splits[std::size_t(c.split)];
                const double rb = nudge(h - prev.r, c.ur);
                s.circles.push_back({prev.c + Vec2{x, y}, std::fabs(rb)});
            }
            for (const ShapeSpec& r : rs) {
                const double w = std::fabs(r.r), hh = std::fabs(r.h);
                if (r.mode == 1 || s.rects.empty()) {
                    const Vec2 p = r.c + off;
                    s.rects.push_back({p.x, p.y, p.x + w, p.y + hh});
                    continue;
                }
                // Sharing an edge or a corner with the previous rectangle (moved by a few ulps if ur ≠ 0).
                const Rect& q = s.rects.back();
                const Vec2 k = rect_point(q, r.corner, r.ur);
                const double left = r.corner % 3 == 0 ? k.x - w : k.x;
                const double bottom = (r.corner / 3) % 3 == 0 ? k.y - hh : k.y;
                s.rects.push_back({left, bottom, left + w, bottom + hh});
            }
            for (const ShapeSpec& p : ps) {
                Vec2 at;
                if (p.mode == 1) {
                    at = p.c + off;
                } else if (p.corner % 2 == 0 && !s.circles.empty()) {
                    // Exactly on circle k: c + (x, y) with x² + y² = r² when r is the triple's c.
                    // On circle k: c + (x, y)·r/h with x² + y² = h²; exact when r/h and the sums are, else
                    // c + (r, 0); StaticBoundary's tags count how many points are exactly on a circle.
                    const Circle& c = s.circles[std::size_t(p.triple) % s.circles.size()];
                    const auto [x, y, h] = scaled_triple(p);
                    const double scale = c.r / h;
                    at = c.c + Vec2{x * scale, y * scale};
                    if (circle_side_oracle(at, c) != 0) at = c.c + Vec2{p.sx * c.r, 0.0};
                    at = nudge(at, p.ur, 0);
                } else {
                    at = rect_point(s.rects[std::size_t(p.triple) % s.rects.size()], p.corner, p.ur);
                }
                s.balls.push_back({at, {}});
            }
            return s;
        },
        specs(1, 4), specs(1, 4), specs(1, 4), offset());
}

}  // namespace ricochet::props::gen
