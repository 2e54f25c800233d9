// Geometry generators for the properties: values you compose (RapidCheck's map, apply, oneOf, build) so
// that each regime is reached on purpose and every value shrinks toward a simple one.
//
// Numbers: small integers (and −0), dyadic fractions m/2^k, values near zero down to subnormals,
// magnitudes up to about ±1e15, far-from-origin offsets, and anything in between (random mantissa).
// Geometry: points exactly on a circle (Pythagorean triples scaled by powers of two), on a rectangle's
// edge or corner, on a wall's line (axis-aligned and small-integer-slope walls, P0 + t·e with dyadic t)
// and at its end points; end positions a few ulps either side of a wall; velocities parallel or nearly
// parallel to a wall; zero-length walls; zero velocities; closed polygons of walls (convex and concave,
// 2^−40 to 2^40 in size, far from the origin), with balls strictly inside or strictly outside.
// Every generator builds a whole Scene, so a failure is saved as the scene log it came from.
#pragma once

#include <rapidcheck.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "oracle.hpp"
#include "ricochet/line.hpp"
#include "ricochet/scene.hpp"

namespace ricochet::props::gen {

namespace rcg = rc::gen;

// ---- numbers -------------------------------------------------------------------------------------

/// An integer in [0, max], shrinking toward 0.
inline rc::Gen<int> upto(int max) { return rcg::inRange(0, max + 1); }
/// An integer in [−max, max], shrinking toward 0 and then toward positive.
inline rc::Gen<int> signed_upto(int max) {
    return rcg::apply([](int m, bool neg) { return neg ? -m : m; }, upto(max), rcg::arbitrary<bool>());
}
/// x moved by |ulps| representable doubles up (ulps > 0) or down (ulps < 0).
inline double nudge(double x, int ulps) {
    for (; ulps > 0; --ulps) x = std::nextafter(x, INFINITY);
    for (; ulps < 0; ++ulps) x = std::nextafter(x, -INFINITY);
    return x;
}
/// p with each coordinate moved by a few ulps.
inline Vec2 nudge(Vec2 p, int ux, int uy) { return {nudge(p.x, ux), nudge(p.y, uy)}; }

/// Small integers −16..16, including −0.
inline rc::Gen<double> small_integer() {
    return rcg::apply([](int m, bool neg) { return neg ? -double(m) : double(m); }, upto(16),
                      rcg::arbitrary<bool>());
}
/// Dyadic fractions ±m/2^k, m ≤ 256, k ≤ 12: exact, and sums of a few of them stay exact.
inline rc::Gen<double> dyadic() {
    return rcg::apply([](int m, int k) { return std::ldexp(double(m), -k); }, signed_upto(256), upto(12));
}
/// Values near zero: ±(1 + m)·2^−e with e in [30, 1074], reaching the subnormals.
inline rc::Gen<double> near_zero() {
    return rcg::apply([](int m, int e, bool neg) { return (neg ? -1.0 : 1.0) * std::ldexp(1.0 + m, -e); },
                      upto(1 << 20), rcg::inRange(30, 1075), rcg::arbitrary<bool>());
}
/// Large magnitudes: ±(1 + m)·2^e up to about 5.6e14, and ±1e15 itself.
inline rc::Gen<double> large() {
    return rcg::oneOf(
        rcg::apply([](int m, int e, bool neg) { return (neg ? -1.0 : 1.0) * std::ldexp(1.0 + m, e); },
                   upto(1 << 20), upto(29), rcg::arbitrary<bool>()),
        rcg::element(1e15, -1e15));
}
/// Any double with magnitude in [2^−64, 2^50): a random 52-bit mantissa.
inline rc::Gen<double> any_bits() {
    return rcg::apply(
        [](std::int64_t f, int e, bool neg) {
            return (neg ? -1.0 : 1.0) * std::ldexp(1.0 + std::ldexp(double(f), -52), e);
        },
        rcg::inRange<std::int64_t>(0, std::int64_t{1} << 52), signed_upto(49), rcg::arbitrary<bool>());
}
/// A coordinate or velocity component from every regime; simple ones first (what shrinking aims at).
inline rc::Gen<double> coordinate() {
    return rcg::weightedOneOf<double>({{6, small_integer()}, {4, dyadic()}, {3, any_bits()}, {1, near_zero()},
                                       {1, large()}});
}
/// A point or vector from coordinate().
inline rc::Gen<Vec2> vec() {
    return rcg::apply([](double x, double y) { return Vec2{x, y}; }, coordinate(), coordinate());
}
/// A far-from-origin offset: mostly none; else ±(1 + m)·2^e with e in [10, 39] (up to about 5.6e14).
inline rc::Gen<Vec2> offset() {
    const auto far = rcg::apply([](int m, int e, bool neg) { return (neg ? -1.0 : 1.0) * std::ldexp(1.0 + m, e); },
                                upto(1 << 10), rcg::inRange(10, 40), rcg::arbitrary<bool>());
    return rcg::weightedOneOf<Vec2>(
        {{3, rcg::just(Vec2{})},
         {2, rcg::apply([](double x, double y) { return Vec2{x, y}; }, far, far)},
         {1, rcg::apply([](double x) { return Vec2{x, 0.0}; }, far)}});
}

// ---- walls and balls ----------------------------------------------------------------------------

/// How to build one wall.
struct WallSpec {
    int kind = 0;          ///< 0 horizontal, 1 vertical, 2 small-integer slope, 3 any, 4 zero length
    Vec2 p0;               ///< the first end point
    Vec2 p1;               ///< kind 3: the second end point
    int len = 1;           ///< kinds 0–2: length factor 1..16
    int len_exp = 0;       ///< kinds 0–2: ×2^len_exp
    int dx = 1, dy = 0;    ///< kind 2: direction
    bool reverse = false;  ///< swap the end points
};

inline rc::Gen<WallSpec> wall_spec() {
    return rcg::build<WallSpec>(rcg::set(&WallSpec::kind, upto(4)), rcg::set(&WallSpec::p0, vec()),
                                rcg::set(&WallSpec::p1, vec()), rcg::set(&WallSpec::len, rcg::inRange(1, 17)),
                                rcg::set(&WallSpec::len_exp, signed_upto(24)),
                                rcg::set(&WallSpec::dx, signed_upto(4)), rcg::set(&WallSpec::dy, signed_upto(4)),
                                rcg::set(&WallSpec::reverse, rcg::arbitrary<bool>()));
}

/// The wall a spec describes, moved by offset.
inline Wall make_wall(const WallSpec& s, Vec2 offset) {
    const double l = std::ldexp(double(s.len), s.len_exp);
    Vec2 p1;
    switch (s.kind) {
        case 0: p1 = {s.p0.x + l, s.p0.y}; break;
        case 1: p1 = {s.p0.x, s.p0.y + l}; break;
        case 2: {
            const int dx = (s.dx == 0 && s.dy == 0) ? 1 : s.dx;
            p1 = s.p0 + l * Vec2{double(dx), double(s.dy)};
            break;
        }
        case 3: p1 = s.p1; break;
        default: p1 = s.p0; break;  // zero length
    }
    Wall w{s.p0 + offset, p1 + offset};
    if (s.reverse) std::swap(w.p0, w.p1);
    return w;
}

/// Where along a wall a ball aims or starts: t in P0 + t·e (end points, inside, just beyond the ends).
inline constexpr std::array<double, 8> k_along = {0.0, 1.0, 0.5, 0.25, 0.75, -0.25, 1.25, 1.0 / 3.0};
/// Velocity scale factors: end at the target, cross it half-way, stop short, overshoot by a hair, far beyond.
inline constexpr std::array<double, 6> k_factors = {1.0, 2.0, 0.5, 3.0, 1.0 + 0x1p-30, 1024.0};

/// How to build one ball against one of the scene's walls.
struct BallSpec {
    int mode = 0;              ///< 0 aim at a point of the wall, 1 anywhere near it, 2 start on it,
                               ///< 3 parallel to it, 4 at rest
    int wall = 0;              ///< which wall (modulo their number)
    int along = 0;             ///< index into k_along
    double dist = 1;           ///< distance from the wall's line, in units of its normal n = (e_y, −e_x)
    double tang = 0;           ///< offset along the wall, in units of e
    int ux = 0, uy = 0;        ///< ulps by which the target (or start) is moved
    int factor = 0;            ///< index into k_factors
    bool other_side = false;   ///< start on the inside (−n) rather than the outside (+n)
    Vec2 pos, vel;             ///< mode 1's offset and velocity; mode 2's velocity
};

inline rc::Gen<BallSpec> ball_spec() {
    return rcg::build<BallSpec>(
        rcg::set(&BallSpec::mode, upto(4)), rcg::set(&BallSpec::wall, upto(7)),
        rcg::set(&BallSpec::along, upto(int(k_along.size()) - 1)),
        rcg::set(&BallSpec::dist, rcg::weightedOneOf<double>({{4, dyadic()}, {1, near_zero()}, {1, coordinate()}})),
        rcg::set(&BallSpec::tang, rcg::weightedOneOf<double>({{3, rcg::just(0.0)}, {2, dyadic()}})),
        rcg::set(&BallSpec::ux, signed_upto(3)), rcg::set(&BallSpec::uy, signed_upto(3)),
        rcg::set(&BallSpec::factor, upto(int(k_factors.size()) - 1)),
        rcg::set(&BallSpec::other_side, rcg::arbitrary<bool>()), rcg::set(&BallSpec::pos, vec()),
        rcg::set(&BallSpec::vel, vec()));
}

/// The ball a spec describes among walls (walls must not be empty).
inline Ball make_ball(const BallSpec& s, const std::vector<Wall>& walls) {
    const Wall& w = walls[std::size_t(s.wall) % walls.size()];
    const Vec2 e = edge(w), n = normal(w);
    const Vec2 p = w.p0 + k_along[std::size_t(s.along)] * e;  // on the line when exact
    const double side = s.other_side ? -1.0 : 1.0;
    const double f = k_factors[std::size_t(s.factor)];
    switch (s.mode) {
        case 0: {
            // Aim at p moved by a few ulps: Be lands on, or just either side of, the wall.
            const Vec2 bs = p + (side * s.dist) * n + s.tang * e;
            const Vec2 target = nudge(p, s.ux, s.uy);
            return {bs, f * (target - bs)};
        }
        case 1: return {p + s.pos, s.vel};
        case 2: {
            // Start on the wall (exactly, or a few ulps off) and move anywhere, or straight off it.
            const Vec2 v = s.vel == Vec2{} ? side * n : s.vel;
            return {nudge(p, s.ux, s.uy), v};
        }
        case 3: {
            // Move parallel to the wall (exactly when f·e is exact), or nearly: a few ulps off.
            return {p + (side * s.dist) * n, nudge(f * e, s.ux, s.uy)};
        }
        default: return {p + (side * s.dist) * n, {}};
    }
}

/// A scene of 1..max_walls walls (sharing one far offset) and 1..3 balls aimed at them, 1..max_frames frames.
inline rc::Gen<Scene> wall_scene(int max_walls, int max_frames) {
    return rcg::apply(
        [](const std::vector<WallSpec>& ws, const std::vector<BallSpec>& bs, Vec2 off, int frames) {
            Scene s;
            for (const WallSpec& w : ws) s.walls.push_back(make_wall(w, off));
            for (const BallSpec& b : bs) s.balls.push_back(make_ball(b, s.walls));
            s.frames = frames;
            return s;
        },
        rcg::mapcat(rcg::inRange(1, max_walls + 1),
                    [](int n) { return rcg::container<std::vector<WallSpec>>(std::size_t(n), wall_spec()); }),
        rcg::mapcat(rcg::inRange(1, 4),
                    [](int n) { return rcg::container<std::vector<BallSpec>>(std::size_t(n), ball_spec()); }),
        offset(), rcg::inRange(1, max_frames + 1));
}

// ---- closed polygons -----------------------------------------------------------------------------

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

/// Any scene with walls and moving balls: single walls, wall soups and closed polygons.
inline rc::Gen<Scene> moving_scene(int max_frames) {
    return rcg::weightedOneOf<Scene>({{3, wall_scene(1, max_frames)},
                                      {2, wall_scene(5, max_frames)},
                                      {2, polygon_scene(true, max_frames)},
                                      {1, polygon_scene(false, max_frames)}});
}

// ---- static shapes --------------------------------------------------------------------------------

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
