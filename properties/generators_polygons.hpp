// Closed-polygon generators for the properties: polygons of walls (convex and concave, 2^−40 to 2^40 in
// size, far from the origin) with balls strictly inside or strictly outside.
#pragma once

#include <rapidcheck.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "generators_numbers.hpp"
#include "generators_walls.hpp"
#include "oracle.hpp"
#include "ricochet/line.hpp"
#include "ricochet/scene.hpp"

namespace ricochet::props::gen {

namespace rcg = rc::gen;

/// How to build a closed polygon of walls over [0, W] × [0, H] in integer units before scaling.
/// Mountain: bottom edge, then straight tops between integer heights (convex or concave, any slope).
/// Histogram: flat tops and vertical steps (orthogonal, concave; equal neighbours give zero-length walls).
struct PolySpec {
    int kind = 0;                 ///< 0 mountain, 1 histogram
    std::vector<int> heights;     ///< n + 1 heights in 1..8 (histogram uses the first n)
    std::vector<int> widths;      ///< n column widths in 1..4
    int scale_exp = 0;            ///< everything ×2^scale_exp (−40..40)
    int off_x = 0, off_y = 0;     ///< offset in units of 2^(scale_exp + off_exp)
    int off_exp = 0;              ///< 0..24
    int turn = 0;                 ///< quarter turns
    bool mirrored = false;        ///< mirror across x = 0
    bool clockwise = false;       ///< walk the boundary clockwise
    std::vector<bool> flips;      ///< reverse each wall's direction
};

inline rc::Gen<PolySpec> poly_spec() {
    return rcg::mapcat(rcg::inRange(1, 7), [](int n) {
        return rcg::build<PolySpec>(
            rcg::set(&PolySpec::kind, upto(1)),
            rcg::set(&PolySpec::heights, rcg::container<std::vector<int>>(std::size_t(n + 1), rcg::inRange(1, 9))),
            rcg::set(&PolySpec::widths, rcg::container<std::vector<int>>(std::size_t(n), rcg::inRange(1, 5))),
            rcg::set(&PolySpec::scale_exp, signed_upto(40)), rcg::set(&PolySpec::off_x, signed_upto(1 << 20)),
            rcg::set(&PolySpec::off_y, signed_upto(1 << 20)),
            rcg::set(&PolySpec::off_exp, rcg::weightedOneOf<int>({{3, rcg::just(0)}, {1, upto(24)}})),
            rcg::set(&PolySpec::turn, upto(3)), rcg::set(&PolySpec::mirrored, rcg::arbitrary<bool>()),
            rcg::set(&PolySpec::clockwise, rcg::arbitrary<bool>()),
            rcg::set(&PolySpec::flips, rcg::container<std::vector<bool>>(std::size_t(2 * n + 3),
                                                                         rcg::arbitrary<bool>())));
    });
}

/// A polygon in integer units with its map to the plane.
struct Polygon {
    std::vector<Vec2> vertices;  ///< integer units, counter-clockwise
    PolySpec spec;
    /// Integer units to the plane: turn, mirror, ×2^scale_exp, + offset (exact for these magnitudes).
    Vec2 place(Vec2 p) const {
        for (int i = 0; i < spec.turn; ++i) p = rotate90(p);
        if (spec.mirrored) p = mirror(p);
        // Keep offsets within about 2^50 whatever the scale.
        const int e = std::min(spec.scale_exp + spec.off_exp, 30);
        return std::ldexp(1.0, spec.scale_exp) * p + std::ldexp(1.0, e) * Vec2{double(spec.off_x), double(spec.off_y)};
    }
    /// Height of the region over column c's interior.
    double column_height(std::size_t c) const {
        const auto& h = spec.heights;
        return spec.kind == 0 ? std::min(h[c], h[c + 1]) : h[c];
    }
    /// Left edge of column c.
    double column_x(std::size_t c) const {
        double x = 0;
        for (std::size_t i = 0; i < c; ++i) x += spec.widths[i];
        return x;
    }
    /// A point strictly inside: column c at fractions u/256 across and v/256 up (u, v in 1..255).
    Vec2 interior(int c, int u, int v) const {
        const std::size_t col = std::size_t(c) % spec.widths.size();
        const double x = column_x(col) + spec.widths[col] * (u / 256.0);
        return place({x, column_height(col) * (v / 256.0)});
    }
};

inline Polygon make_polygon(const PolySpec& s) {
    Polygon poly{{}, s};
    const std::size_t n = s.widths.size();
    std::vector<double> xs{0};
    for (int w : s.widths) xs.push_back(xs.back() + w);
    auto& v = poly.vertices;
    v.push_back({0, 0});
    v.push_back({xs[n], 0});
    if (s.kind == 0) {
        for (std::size_t i = n + 1; i-- > 0;) v.push_back({xs[i], double(s.heights[i])});
    } else {
        for (std::size_t i = n; i-- > 0;) {
            v.push_back({xs[i + 1], double(s.heights[i])});
            v.push_back({xs[i], double(s.heights[i])});
        }
    }
    return poly;
}

/// The polygon's walls in the plane: one per edge, in boundary order, each possibly reversed.
inline std::vector<Wall> polygon_walls(const Polygon& poly) {
    std::vector<Vec2> pts;
    for (Vec2 p : poly.vertices) pts.push_back(poly.place(p));
    if (poly.spec.clockwise) std::reverse(pts.begin(), pts.end());
    std::vector<Wall> walls;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        Wall w{pts[i], pts[(i + 1) % pts.size()]};
        if (i < poly.spec.flips.size() && poly.spec.flips[i]) std::swap(w.p0, w.p1);
        walls.push_back(w);
    }
    return walls;
}

/// How to place a ball for a polygon, and how it moves.
struct PolyBallSpec {
    int where = 0;          ///< 0 deep inside (or far outside), 1 a hair from the boundary
    int column = 0, u = 128, v = 128;  ///< the interior point (column, u/256, v/256)
    int vertex = 0;         ///< boundary point: a vertex (even) or an edge midpoint (odd)
    int hair = 1;           ///< distance 2^−hair of the way from the boundary point toward the interior point
    int vmode = 0;          ///< 0 any, 1 at a vertex, 2 parallel to an edge, 3 along x, 4 at rest, 5 fast
    Vec2 vel;               ///< modes 0, 3 and 5, in units of 2^scale_exp
    int factor = 0;         ///< index into k_factors
    int ux = 0, uy = 0;     ///< ulps by which the velocity is moved
};

inline rc::Gen<PolyBallSpec> poly_ball_spec() {
    return rcg::build<PolyBallSpec>(
        rcg::set(&PolyBallSpec::where, upto(1)), rcg::set(&PolyBallSpec::column, upto(5)),
        rcg::set(&PolyBallSpec::u, rcg::inRange(1, 256)), rcg::set(&PolyBallSpec::v, rcg::inRange(1, 256)),
        rcg::set(&PolyBallSpec::vertex, upto(31)), rcg::set(&PolyBallSpec::hair, rcg::inRange(1, 61)),
        rcg::set(&PolyBallSpec::vmode, upto(5)), rcg::set(&PolyBallSpec::vel, vec()),
        rcg::set(&PolyBallSpec::factor, upto(int(k_factors.size()) - 1)),
        rcg::set(&PolyBallSpec::ux, signed_upto(2)), rcg::set(&PolyBallSpec::uy, signed_upto(2)));
}

/// The ball a spec describes: strictly inside the walls' region if inside, else strictly outside.
inline Ball make_poly_ball(const PolyBallSpec& s, const Polygon& poly, const std::vector<Wall>& walls, bool inside) {
    const double unit = std::ldexp(1.0, poly.spec.scale_exp);
    const Vec2 deep = poly.interior(s.column, s.u, s.v);
    // A boundary point: a vertex, or the midpoint of an edge (exact: integer units halved).
    const std::size_t nv = poly.vertices.size();
    const std::size_t k = std::size_t(s.vertex / 2) % nv;
    const Vec2 a = poly.vertices[k], b = poly.vertices[(k + 1) % nv];
    const Vec2 on = poly.place(s.vertex % 2 == 0 ? a : 0.5 * (a + b));
    Vec2 pos;
    if (inside) {
        pos = s.where == 0 ? deep : on + std::ldexp(1.0, -s.hair) * (deep - on);
        if (locate(pos, walls) != 1) pos = deep;  // rounding landed it on or outside the boundary
    } else {
        // Left of everything (x < 0 in integer units, before the map), or a hair outside the boundary.
        const Vec2 far = poly.place({-1.0 - s.u / 64.0, s.v / 16.0 - 4.0});
        pos = s.where == 0 ? far : on - std::ldexp(1.0, -s.hair) * (deep - on);
        if (locate(pos, walls) != -1) pos = far;
        if (locate(pos, walls) != -1) pos = poly.place({-64.0, -64.0});
    }
    const double f = k_factors[std::size_t(s.factor)];
    Vec2 vel;
    switch (s.vmode) {
        case 0: vel = unit * s.vel; break;
        case 1: vel = f * (poly.place(poly.vertices[std::size_t(s.vertex) % nv]) - pos); break;
        case 2: {
            const Wall& w = walls[std::size_t(s.vertex) % walls.size()];
            vel = f * edge(w);
            break;
        }
        case 3: vel = {unit * s.vel.x, 0.0}; break;
        case 4: vel = {}; break;
        default: vel = (64.0 * unit) * s.vel; break;  // many bounces a frame
    }
    return {pos, nudge(vel, s.ux, s.uy)};
}

/// A closed polygon of walls with 1..3 balls strictly inside (inside = true) or outside, 1..max_frames frames.
inline rc::Gen<Scene> polygon_scene(bool inside, int max_frames) {
    return rcg::apply(
        [inside](const PolySpec& ps, const std::vector<PolyBallSpec>& bs, int frames) {
            const Polygon poly = make_polygon(ps);
            Scene s;
            s.walls = polygon_walls(poly);
            for (const PolyBallSpec& b : bs) s.balls.push_back(make_poly_ball(b, poly, s.walls, inside));
            s.frames = frames;
            return s;
        },
        poly_spec(),
        rcg::mapcat(rcg::inRange(1, 4),
                    [](int n) { return rcg::container<std::vector<PolyBallSpec>>(std::size_t(n), poly_ball_spec()); }),
        rcg::inRange(1, max_frames + 1));
}

}  // namespace ricochet::props::gen
