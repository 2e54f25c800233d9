// Disc and bumper generators for the properties: radii from every regime (zero of both signs, tiny down to
// subnormal, a fraction of the scene's size, larger than the scene), bumpers, closed polygons holding discs,
// chains of walls sharing end points with discs aimed at their joints or sliding along them at exactly their
// radius, and discs aimed at bumpers. Every placement is exact on doubles (integer units × 2^e plus an offset
// that keeps within 53 bits), so "at exactly R" and "head-on" hold bit for bit.
#pragma once

#include <rapidcheck.h>

#include <cmath>
#include <vector>

#include "generators_numbers.hpp"
#include "generators_polygons.hpp"
#include "generators_walls.hpp"
#include "ricochet/scene.hpp"

namespace ricochet::props::gen {

namespace rcg = rc::gen;

/// How to size one radius, relative to a scene's unit length (2^scale_exp).
struct RadiusSpec {
    int kind = 0;     ///< 0 zero, 1 m/64 units, 2 tiny (2^−e units), 3 subnormal, 4 huge (2^e units), 5 −0
    int m = 1;        ///< kind 1: 1..64
    int e = 1;        ///< kinds 2 and 4: the exponent (1..60)
};

inline rc::Gen<RadiusSpec> radius_spec() {
    return rcg::build<RadiusSpec>(
        rcg::set(&RadiusSpec::kind, rcg::weightedOneOf<int>({{1, rcg::just(0)}, {6, rcg::just(1)}, {2, rcg::just(2)},
                                                             {1, rcg::just(3)}, {1, rcg::just(4)}, {1, rcg::just(5)}})),
        rcg::set(&RadiusSpec::m, rcg::inRange(1, 65)), rcg::set(&RadiusSpec::e, rcg::inRange(1, 61)));
}

/// The radius a spec describes for a scene whose unit is unit (a power of two).
inline double make_radius(const RadiusSpec& s, double unit) {
    switch (s.kind) {
        case 0: return 0.0;
        case 1: return unit * (s.m / 64.0);
        case 2: return unit * std::ldexp(1.0, -s.e);
        case 3: return std::ldexp(double(s.m), -1074);  // subnormal: far below any unit
        case 4: return unit * std::ldexp(1.0, s.e % 41);
        default: return -0.0;
    }
}

/// How to place one bumper inside a polygon: an interior point and a radius in units.
struct BumperSpec {
    int column = 0, u = 128, v = 128;  ///< the interior point (Polygon::interior)
    int m = 8;                         ///< radius m/64 units (0: a bumper of radius 0, never hit)
};

inline rc::Gen<BumperSpec> bumper_spec() {
    return rcg::build<BumperSpec>(rcg::set(&BumperSpec::column, upto(5)), rcg::set(&BumperSpec::u, rcg::inRange(1, 256)),
                                  rcg::set(&BumperSpec::v, rcg::inRange(1, 256)), rcg::set(&BumperSpec::m, upto(64)));
}

/// A closed polygon (polygon_scene's) whose balls have radii, with 0..2 bumpers inside if bumpers is set.
inline rc::Gen<Scene> disc_polygon_scene(bool inside, int max_frames, bool bumpers) {
    return rcg::apply(
        [inside, bumpers](const PolySpec& ps, const std::vector<PolyBallSpec>& bs, const std::vector<RadiusSpec>& rs,
                          const std::vector<BumperSpec>& us, int frames) {
            const Polygon poly = make_polygon(ps);
            Scene s;
            s.walls = polygon_walls(poly);
            for (const PolyBallSpec& b : bs) s.balls.push_back(make_poly_ball(b, poly, s.walls, inside));
            const double unit = std::ldexp(1.0, ps.scale_exp);
            for (std::size_t i = 0; i < s.balls.size(); ++i) s.balls[i].r = make_radius(rs[i % rs.size()], unit);
            if (bumpers)
                for (const BumperSpec& u : us) s.bumpers.push_back({poly.interior(u.column, u.u, u.v), unit * (u.m / 64.0)});
            s.frames = frames;
            return s;
        },
        poly_spec(),
        rcg::mapcat(rcg::inRange(1, 4),
                    [](int n) { return rcg::container<std::vector<PolyBallSpec>>(std::size_t(n), poly_ball_spec()); }),
        rcg::container<std::vector<RadiusSpec>>(3, radius_spec()),
        rcg::mapcat(rcg::inRange(0, 3), [](int n) { return rcg::container<std::vector<BumperSpec>>(std::size_t(n), bumper_spec()); }),
        rcg::inRange(1, max_frames + 1));
}

/// The exact map from integer units to the plane shared by chains and bumper scenes: quarter turns, a mirror,
/// ×2^scale_exp and an offset of off·2^(scale_exp + off_exp). Magnitudes stay within 53 bits for the units these
/// generators use (|x| < 2^12 before scaling, offsets < 2^21 units shifted ≤ 2^20, fractions ≤ 2^−8 of a unit).
struct Placement {
    int turn = 0;
    bool mirrored = false;
    int scale_exp = 0;   ///< −30..30
    int off_x = 0, off_y = 0;
    int off_exp = 0;     ///< 0..20
    /// A point in units to the plane.
    Vec2 place(Vec2 p) const {
        return std::ldexp(1.0, scale_exp) * linear(p) + std::ldexp(1.0, scale_exp + off_exp) * Vec2{double(off_x), double(off_y)};
    }
    /// A vector in units to the plane (no offset).
    Vec2 vector(Vec2 v) const { return std::ldexp(1.0, scale_exp) * linear(v); }
    /// The turn and mirror alone.
    Vec2 linear(Vec2 p) const {
        for (int i = 0; i < turn; ++i) p = {-p.y, p.x};
        if (mirrored) p = {-p.x, p.y};
        return p;
    }
};

inline rc::Gen<Placement> placement() {
    return rcg::build<Placement>(
        rcg::set(&Placement::turn, upto(3)), rcg::set(&Placement::mirrored, rcg::arbitrary<bool>()),
        rcg::set(&Placement::scale_exp, signed_upto(30)), rcg::set(&Placement::off_x, signed_upto(1 << 20)),
        rcg::set(&Placement::off_y, signed_upto(1 << 20)),
        rcg::set(&Placement::off_exp, rcg::weightedOneOf<int>({{3, rcg::just(0)}, {1, upto(20)}})));
}

/// How to build a chain of walls sharing end points, in units: joints at x_0 = 0 < x_1 < … with heights h_i
/// (all 0: collinear), each wall possibly reversed.
struct ChainSpec {
    std::vector<int> widths;   ///< 1..8 units each
    std::vector<int> heights;  ///< one more than widths; −2..2 (ignored for a straight chain)
    bool straight = true;      ///< every joint on y = 0
    std::vector<bool> flips;   ///< reverse each wall's direction
};

inline rc::Gen<ChainSpec> chain_spec() {
    return rcg::mapcat(rcg::inRange(2, 7), [](int n) {
        return rcg::build<ChainSpec>(
            rcg::set(&ChainSpec::widths, rcg::container<std::vector<int>>(std::size_t(n), rcg::inRange(1, 9))),
            rcg::set(&ChainSpec::heights, rcg::container<std::vector<int>>(std::size_t(n + 1), signed_upto(2))),
            rcg::set(&ChainSpec::straight, rcg::arbitrary<bool>()),
            rcg::set(&ChainSpec::flips, rcg::container<std::vector<bool>>(std::size_t(n), rcg::arbitrary<bool>())));
    });
}

/// The chain's joints in units.
inline std::vector<Vec2> chain_joints(const ChainSpec& c) {
    std::vector<Vec2> j{{0.0, c.straight ? 0.0 : double(c.heights[0])}};
    for (std::size_t i = 0; i < c.widths.size(); ++i)
        j.push_back({j.back().x + c.widths[i], c.straight ? 0.0 : double(c.heights[i + 1])});
    return j;
}

/// The chain's walls in the plane.
inline std::vector<Wall> chain_walls(const ChainSpec& c, const Placement& at) {
    const std::vector<Vec2> j = chain_joints(c);
    std::vector<Wall> walls;
    for (std::size_t i = 0; i + 1 < j.size(); ++i) {
        Wall w{at.place(j[i]), at.place(j[i + 1])};
        if (c.flips[i]) std::swap(w.p0, w.p1);
        walls.push_back(w);
    }
    return walls;
}

/// A disc aimed at a chain: at a joint (or between two), from above or below, radius m/2^k units.
struct ChainBallSpec {
    int joint = 0;         ///< which joint (modulo their number)
    int half = 0;          ///< 0 the joint, 1 half-way to the next one
    int dx = 0, dy = 4;    ///< start offset from the target, in units/4 (dy ≠ 0 is forced)
    int rm = 16, rk = 6;   ///< radius rm/2^rk units, rk 5..12 (at most 2 units; rm 0: a point ball)
    int factor = 0;        ///< index into k_factors: end at the target, cross it, stop short, overshoot, far beyond
    int ux = 0, uy = 0;    ///< ulps by which the velocity is moved
};

inline rc::Gen<ChainBallSpec> chain_ball_spec() {
    return rcg::build<ChainBallSpec>(
        rcg::set(&ChainBallSpec::joint, upto(7)), rcg::set(&ChainBallSpec::half, upto(1)),
        rcg::set(&ChainBallSpec::dx, signed_upto(16)), rcg::set(&ChainBallSpec::dy, signed_upto(16)),
        rcg::set(&ChainBallSpec::rm, upto(64)), rcg::set(&ChainBallSpec::rk, rcg::inRange(5, 13)),
        rcg::set(&ChainBallSpec::factor, upto(int(k_factors.size()) - 1)), rcg::set(&ChainBallSpec::ux, signed_upto(2)),
        rcg::set(&ChainBallSpec::uy, signed_upto(2)));
}

/// A chain of walls (straight or bent) with 1..3 discs aimed at its joints from either side, 1..max_frames frames.
inline rc::Gen<Scene> chain_scene(int max_frames) {
    return rcg::apply(
        [](const ChainSpec& c, const Placement& at, const std::vector<ChainBallSpec>& bs, int frames) {
            Scene s;
            s.walls = chain_walls(c, at);
            const std::vector<Vec2> j = chain_joints(c);
            for (const ChainBallSpec& b : bs) {
                const std::size_t k = std::size_t(b.joint) % (j.size() - 1);
                const Vec2 target = b.half ? 0.5 * (j[k] + j[k + 1]) : j[k];
                const Vec2 start = target + Vec2{b.dx / 4.0, (b.dy == 0 ? 4 : b.dy) / 4.0};
                const Vec2 bs_ = at.place(start);
                const Vec2 v = k_factors[std::size_t(b.factor)] * (at.place(target) - bs_);
                s.balls.push_back({bs_, nudge(v, b.ux, b.uy), std::ldexp(1.0, at.scale_exp) * std::ldexp(double(b.rm), -b.rk)});
            }
            s.frames = frames;
            return s;
        },
        chain_spec(), placement(),
        rcg::mapcat(rcg::inRange(1, 4),
                    [](int n) { return rcg::container<std::vector<ChainBallSpec>>(std::size_t(n), chain_ball_spec()); }),
        rcg::inRange(1, max_frames + 1));
}

/// A disc sliding along a straight chain at exactly its radius: start at x0 units (before the chain, on it or
/// past it), y = ±R, moving along x by speed units a frame.
struct SlideSpec {
    int x0 = 0;          ///< start x in units/4, −8..60
    bool below = false;  ///< slide under the chain (y = −R)
    int rm = 16, rk = 6; ///< R = rm/2^rk units, rm ≥ 1
    int speed = 4;       ///< units/4 a frame, ±1..32
};

inline rc::Gen<SlideSpec> slide_spec() {
    return rcg::build<SlideSpec>(rcg::set(&SlideSpec::x0, rcg::inRange(-8, 61)), rcg::set(&SlideSpec::below, rcg::arbitrary<bool>()),
                                 rcg::set(&SlideSpec::rm, rcg::inRange(1, 65)), rcg::set(&SlideSpec::rk, upto(8)),
                                 rcg::set(&SlideSpec::speed, rcg::apply([](int m, bool neg) { return neg ? -m : m; },
                                                                         rcg::inRange(1, 33), rcg::arbitrary<bool>())));
}

/// A straight chain of collinear walls sharing end points with 1..3 discs sliding along it at exactly their radius,
/// placed by an exact map (so the chain is axis-aligned and every distance stays exact), 1..max_frames frames.
inline rc::Gen<Scene> sliding_chain_scene(int max_frames) {
    return rcg::apply(
        [](ChainSpec c, const Placement& at, const std::vector<SlideSpec>& ss, int frames) {
            c.straight = true;
            Scene s;
            s.walls = chain_walls(c, at);
            for (const SlideSpec& d : ss) {
                const double r = std::ldexp(double(d.rm), -d.rk);
                const Vec2 start{d.x0 / 4.0, d.below ? -r : r};
                s.balls.push_back({at.place(start), at.vector({d.speed / 4.0, 0.0}), std::ldexp(1.0, at.scale_exp) * r});
            }
            s.frames = frames;
            return s;
        },
        chain_spec(), placement(),
        rcg::mapcat(rcg::inRange(1, 4), [](int n) { return rcg::container<std::vector<SlideSpec>>(std::size_t(n), slide_spec()); }),
        rcg::inRange(1, max_frames + 1));
}

/// A disc aimed at a bumper: from a direction (axis or diagonal, or off-centre by a lateral offset), at a distance.
struct BumpSpec {
    int dir = 0;          ///< 0..7: the eight directions of (±1, 0), (0, ±1), (±1, ±1)
    int lateral = 0;      ///< offset across the line of approach, in units/16 (0: head-on)
    int dist = 8;         ///< distance to the bumper's centre in units/4 (beyond R + r when large)
    int rm = 16, cm = 32; ///< disc radius rm/64 units, bumper radius cm/64 units
    int factor = 0;       ///< index into k_factors
};

inline rc::Gen<BumpSpec> bump_spec() {
    return rcg::build<BumpSpec>(rcg::set(&BumpSpec::dir, upto(7)),
                                rcg::set(&BumpSpec::lateral, rcg::weightedOneOf<int>({{2, rcg::just(0)}, {1, signed_upto(32)}})),
                                rcg::set(&BumpSpec::dist, rcg::inRange(1, 65)), rcg::set(&BumpSpec::rm, upto(64)),
                                rcg::set(&BumpSpec::cm, upto(64)), rcg::set(&BumpSpec::factor, upto(int(k_factors.size()) - 1)));
}

/// The unit direction of BumpSpec::dir, unnormalized for diagonals (so that it stays exact).
inline Vec2 bump_direction(int dir) {
    constexpr Vec2 d[8] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}, {1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
    return d[dir % 8];
}

/// 1..max_pairs bumpers at integer points with as many discs aimed at them (head-on or off-centre), placed by an exact map;
/// with walls, the bumpers stand inside a box of walls.
inline rc::Gen<Scene> bumper_scene(int max_frames, bool box, int max_pairs = 3) {
    return rcg::apply(
        [box](const Placement& at, const std::vector<BumpSpec>& bs, int frames) {
            Scene s;
            for (std::size_t i = 0; i < bs.size(); ++i) {
                const BumpSpec& b = bs[i];
                const Vec2 c{double(8 * i), 0.0};
                s.bumpers.push_back({at.place(c), std::ldexp(1.0, at.scale_exp) * (b.cm / 64.0)});
                const Vec2 u = bump_direction(b.dir);
                const Vec2 across{-u.y, u.x};
                const Vec2 start = c + (b.dist / 4.0) * u + (b.lateral / 16.0) * across;
                const Vec2 target = c + (b.lateral / 16.0) * across;
                const Vec2 bs_ = at.place(start);
                s.balls.push_back({bs_, k_factors[std::size_t(b.factor)] * (at.place(target) - bs_),
                                   std::ldexp(1.0, at.scale_exp) * (b.rm / 64.0)});
            }
            if (box) {
                const Vec2 c[4] = {{-24, -24}, {8.0 * double(bs.size()) + 16, -24}, {8.0 * double(bs.size()) + 16, 24}, {-24, 24}};
                for (int i = 0; i < 4; ++i) s.walls.push_back({at.place(c[i]), at.place(c[(i + 1) % 4])});
            }
            s.frames = frames;
            return s;
        },
        placement(),
        rcg::mapcat(rcg::inRange(1, max_pairs + 1),
                    [](int n) { return rcg::container<std::vector<BumpSpec>>(std::size_t(n), bump_spec()); }),
        rcg::inRange(1, max_frames + 1));
}

/// How to place one disc touching an obstacle, in units: on a wall's face, at a cap, or at a bumper's rim.
struct TouchSpec {
    int kind = 0;            ///< 0 face, 1 cap (beyond an end, along the wall's line), 2 a bumper
    int len = 4;             ///< the wall's length, 1..8 units
    int along = 0;           ///< face: where the centre's foot lies, 0..8·len eighths of a unit (both ends included)
    bool far_end = false;    ///< cap: beyond P1 rather than P0; face: on the wall's other side
    bool reversed = false;   ///< the wall walked the other way
    int rm = 16, cm = 16;    ///< disc radius rm/64 units (1..64), bumper radius cm/64 units (0..64)
    int vx = 0, vy = -1;     ///< the velocity in quarter units (toward, along or away from the obstacle)
};

inline rc::Gen<TouchSpec> touch_spec() {
    return rcg::build<TouchSpec>(
        rcg::set(&TouchSpec::kind, upto(2)), rcg::set(&TouchSpec::len, rcg::inRange(1, 9)),
        rcg::set(&TouchSpec::along, upto(64)), rcg::set(&TouchSpec::far_end, rcg::arbitrary<bool>()),
        rcg::set(&TouchSpec::reversed, rcg::arbitrary<bool>()), rcg::set(&TouchSpec::rm, rcg::inRange(1, 65)),
        rcg::set(&TouchSpec::cm, upto(64)), rcg::set(&TouchSpec::vx, signed_upto(8)),
        rcg::set(&TouchSpec::vy, signed_upto(8)));
}

/// One disc per spec (1..3), each starting exactly touching its own obstacle (R from a wall's face or end, R + r
/// from a bumper's centre) and moving toward it, along it or away, the obstacles 16 units apart; placed by an
/// exact map, so "exactly touching" holds bit for bit.
inline rc::Gen<Scene> touching_scene(int max_frames) {
    return rcg::apply(
        [](const Placement& at, const std::vector<TouchSpec>& ts, int frames) {
            Scene s;
            const double unit = std::ldexp(1.0, at.scale_exp);
            for (std::size_t i = 0; i < ts.size(); ++i) {
                const TouchSpec& t = ts[i];
                const Vec2 o{16.0 * double(i), 0.0};
                const double R = t.rm / 64.0, len = double(t.len);
                Vec2 centre;
                if (t.kind == 2) {
                    // |B − C| = R + r along the first axis the spec's side picks.
                    s.bumpers.push_back({at.place(o), unit * (t.cm / 64.0)});
                    centre = o + Vec2{0.0, (t.far_end ? -1.0 : 1.0) * (R + t.cm / 64.0)};
                } else {
                    const Vec2 p0 = o, p1 = o + Vec2{len, 0.0};
                    s.walls.push_back(t.reversed ? Wall{at.place(p1), at.place(p0)} : Wall{at.place(p0), at.place(p1)});
                    if (t.kind == 0)
                        centre = o + Vec2{std::fmin(t.along / 8.0, len), (t.far_end ? -1.0 : 1.0) * R};
                    else
                        centre = t.far_end ? p1 + Vec2{R, 0.0} : p0 - Vec2{R, 0.0};
                }
                s.balls.push_back({at.place(centre), at.vector(Vec2{t.vx / 4.0, t.vy / 4.0}), unit * R});
            }
            s.frames = frames;
            return s;
        },
        placement(),
        rcg::mapcat(rcg::inRange(1, 4), [](int n) { return rcg::container<std::vector<TouchSpec>>(std::size_t(n), touch_spec()); }),
        rcg::inRange(1, max_frames + 1));
}

/// Any disc scene: polygons (inside and outside), chains, sliding chains and bumpers (bumpers only if asked).
inline rc::Gen<Scene> disc_scene(int max_frames, bool bumpers) {
    if (!bumpers)
        return rcg::weightedOneOf<Scene>({{3, disc_polygon_scene(true, max_frames, false)},
                                          {1, disc_polygon_scene(false, max_frames, false)},
                                          {2, chain_scene(max_frames)},
                                          {1, sliding_chain_scene(max_frames)}});
    return rcg::weightedOneOf<Scene>({{3, disc_polygon_scene(true, max_frames, true)},
                                      {1, disc_polygon_scene(false, max_frames, false)},
                                      {2, chain_scene(max_frames)},
                                      {1, sliding_chain_scene(max_frames)},
                                      {2, bumper_scene(max_frames, false)},
                                      {1, bumper_scene(max_frames, true)}});
}

}  // namespace ricochet::props::gen
