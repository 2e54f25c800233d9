// Wall-scene generators for the properties: walls, the balls aimed at them, and scenes of both.
// Walls are axis-aligned, of small-integer slope, arbitrary or zero-length, far from the origin or not;
// balls start on a wall's line, at its end points or a few ulps either side, and move along, across or
// parallel to it.
#pragma once

#include <rapidcheck.h>

#include <array>
#include <cmath>
#include <vector>

#include "generators_numbers.hpp"
#include "ricochet/line.hpp"
#include "ricochet/scene.hpp"

namespace ricochet::props::gen {

namespace rcg = rc::gen;

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

}  // namespace ricochet::props::gen
