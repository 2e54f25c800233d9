// Near-degenerate generators for the properties: scenes whose decisions the predicates' filters cannot make, so
// that the exact stages behind them decide (core/src/predicates/: filter, ordered products, bounded tail, complete
// sum, GMP). Every point is built exactly on doubles, so its exact value is known by construction (collinear, a
// tie, or k ulps off one); the checks judge every decision in GMP rationals all the same (truth.hpp).
//
// Why two kinds of line. With exact differences the rounded products l = fl(A·B), r = fl(C·D) are ordered as
// the exact ones (rounding is monotone), so fl(l − r) never has the wrong sign, whatever the filter's bound;
// only differences that round can make it lie. Points λ·d on a line through the origin with λ of very different
// magnitudes (2^-1000 to 2^254 mixed) give such differences, and collinear ones have an exact determinant 0
// that the rounded one misses by up to a few ε of the products: the filter's error bound alone stands between
// them and a wrong sign. Points o + λ·d on a lattice far from the origin have exact differences (stage 1).
#pragma once

#include <rapidcheck.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "generators_numbers.hpp"
#include "ricochet/scene.hpp"

namespace ricochet::props::gen {

namespace rcg = rc::gen;

/// A scale λ = ±(1 + m)·2^e (m < 2^20, so λ·d is exact for |d| ≤ 16); on a lattice line λ = ±m·2^s instead.
struct NearScale {
    int m = 0;
    int e = 0;
    bool neg = false;
};

/// Exponents from three bands, so that two points are often within 2^60 of each other (their differences round)
/// and sometimes 2^1000 apart (the smaller lost entirely): tiny (2^-1000, below the expansions' range, where
/// GMP decides), near 1, huge (up to 2^254 for a point, 2^255 for a ball's start f·Be: inside the accepted range
/// 2^256).
inline rc::Gen<NearScale> near_scale() {
    const auto band = rcg::weightedOneOf<int>(
        {{4, rcg::inRange(-60, 61)}, {1, rcg::inRange(-1000, -940)}, {1, rcg::inRange(170, 230)}});
    return rcg::build<NearScale>(rcg::set(&NearScale::m, upto((1 << 20) - 1)), rcg::set(&NearScale::e, band),
                                 rcg::set(&NearScale::neg, rcg::arbitrary<bool>()));
}

/// A small direction with both components non-zero (an axis-aligned line would let the plan's comparison decide).
inline rc::Gen<Vec2> near_direction() {
    const auto c = rcg::apply([](int m, bool neg) { return neg ? -double(1 + m) : double(1 + m); }, upto(15),
                              rcg::arbitrary<bool>());
    return rcg::apply([](double x, double y) { return Vec2{x, y}; }, c, c);
}

/// How to build one near-collinear wall and ball.
struct NearSpec {
    int kind = 0;         ///< 0: Be on the wall's line; 1: the leg's line through the wall's end P0; 2: Bs on it
    bool lattice = false; ///< the line o + λ·d far from the origin (exact differences) instead of λ·d
    Vec2 d, d2;           ///< the line's direction; kind 1: the direction of the line P1 lies on
    std::array<NearScale, 4> lam;
    int off_exp = 0;      ///< lattice: o = 2^off_exp·(ox, oy) and λ = ±m·2^(off_exp − 40)
    int ox = 1, oy = 0;
    int which = 0;        ///< which point is nudged (kind 0: Be, P0 or P1; kind 1: P0, Bs, Be; kind 2: Bs, P0, P1)
    int ulps = 0;         ///< by how many ulps, in one coordinate
    bool nudge_y = false;
    int fx = 0, fy = 1;   ///< the ball's other end: each coordinate times k_near_factors[f] of the end on the line
    bool reverse = false; ///< swap the wall's ends
};

/// Factors f with f·x and x − f·x exact and fl(f·x + (x − f·x)) = x for every double x in the ranges drawn here:
/// a leg from f·x to x whose velocity x − f·x is exact and ends exactly at x.
inline constexpr std::array<double, 4> k_near_factors = {0.0, 0.5, 2.0, 1.0};

inline rc::Gen<NearSpec> near_spec() {
    return rcg::build<NearSpec>(
        rcg::set(&NearSpec::kind, upto(2)), rcg::set(&NearSpec::lattice, rcg::weightedOneOf<bool>(
                                                                             {{3, rcg::just(false)}, {1, rcg::just(true)}})),
        rcg::set(&NearSpec::d, near_direction()), rcg::set(&NearSpec::d2, near_direction()),
        rcg::set(&NearSpec::lam, rcg::apply([](NearScale a, NearScale b, NearScale c, NearScale e) {
                     return std::array<NearScale, 4>{a, b, c, e};
                 }, near_scale(), near_scale(), near_scale(), near_scale())),
        rcg::set(&NearSpec::off_exp, rcg::inRange(-20, 241)), rcg::set(&NearSpec::ox, signed_upto(7)),
        rcg::set(&NearSpec::oy, signed_upto(7)), rcg::set(&NearSpec::which, upto(2)),
        rcg::set(&NearSpec::ulps, rcg::weightedOneOf<int>({{2, rcg::just(0)}, {3, signed_upto(3)}})),
        rcg::set(&NearSpec::nudge_y, rcg::arbitrary<bool>()), rcg::set(&NearSpec::fx, upto(3)),
        rcg::set(&NearSpec::fy, upto(3)), rcg::set(&NearSpec::reverse, rcg::arbitrary<bool>()));
}

/// The point of s's line (direction dir) at scale l: λ·dir exactly (|λ| has at most 21 bits, |dir| at most 5), or
/// on a lattice o + m·2^(off_exp − 40)·dir: every such point below 2^(off_exp + 13) is a multiple of 2^(off_exp − 40)
/// (53 bits), so the sum is exact and differences between lattice points are too.
inline Vec2 near_point(const NearSpec& s, const NearScale& l, Vec2 dir) {
    const double sign = l.neg ? -1.0 : 1.0;
    if (!s.lattice) return std::ldexp(sign * (1.0 + l.m), l.e) * dir;
    const Vec2 o = std::ldexp(1.0, s.off_exp) * Vec2{double(s.ox), double(s.oy)};
    return o + std::ldexp(sign * l.m, s.off_exp - 40) * dir;
}

/// p moved k ulps in one coordinate.
inline Vec2 nudge_one(Vec2 p, int k, bool y) { return y ? Vec2{p.x, nudge(p.y, k)} : Vec2{nudge(p.x, k), p.y}; }

/// Appends the wall and ball a spec describes: three points on one line (exactly, or one nudged k ulps).
inline void add_near(Scene& scene, const NearSpec& s) {
    const auto pt = [&](int i) { return near_point(s, s.lam[std::size_t(i)], s.d); };
    const auto nudged = [&](int slot, Vec2 p) { return s.which == slot ? nudge_one(p, s.ulps, s.nudge_y) : p; };
    // The ball's end off the line: each coordinate scaled by a factor; equal factors would keep a ray's point on it.
    const auto off = [&](Vec2 p) {
        const int fy = s.fy == s.fx ? (s.fx + 1) % 4 : s.fy;
        return Vec2{k_near_factors[std::size_t(s.fx)] * p.x, k_near_factors[std::size_t(fy)] * p.y};
    };
    Wall w;
    Ball b;
    switch (s.kind) {
        case 0: {
            // Be on the wall's line P0 P1 (a side test and the leg's hit at t = 1): Bs off it, v = Be − Bs exact.
            w = {nudged(1, pt(0)), nudged(2, pt(1))};
            const Vec2 be = nudged(0, pt(2));
            b = {off(be), be - off(be)};
            break;
        }
        case 1: {
            // The leg's line through P0 (the end tests orient(Bs, Be, P0)); P1 on another line, so the wall crosses.
            const Vec2 be = nudged(2, pt(2));
            // On a ray through the origin f·Be is on the line too; on a lattice another lattice point is.
            const Vec2 bs = nudged(1, s.lattice ? pt(3) : k_near_factors[std::size_t(s.fx % 3)] * pt(2));
            w = {nudged(0, pt(0)), near_point(s, s.lam[1], s.d2)};
            b = {bs, be - bs};
            break;
        }
        default: {
            // Bs on the wall's line (leaving it, or starting on it): Be off it, v = Be − Bs exact.
            w = {nudged(1, pt(0)), nudged(2, pt(1))};
            const Vec2 bs = nudged(0, pt(2));
            b = {bs, off(bs) - bs};
            break;
        }
    }
    if (s.reverse) std::swap(w.p0, w.p1);
    scene.walls.push_back(w);
    scene.balls.push_back(b);
}

/// Scenes of 1–2 near-collinear walls and balls (each ball meets every wall), one frame.
inline rc::Gen<Scene> near_collinear_scene() {
    return rcg::apply(
        [](const std::vector<NearSpec>& specs) {
            Scene s;
            for (const NearSpec& n : specs) add_near(s, n);
            s.frames = 1;
            return s;
        },
        rcg::mapcat(rcg::inRange(1, 3),
                    [](int n) { return rcg::container<std::vector<NearSpec>>(std::size_t(n), near_spec()); }));
}

/// One wall crossing a lattice leg (crossings_scene).
struct CrossWall {
    std::int64_t j = 0;   ///< crosses the leg at Bs + j·d, a parameter j/2^q (wall 0's; the others' are offsets)
    int k = 0;            ///< walls after the first: j = j_0 + k, a few units (ulps at 2^52) apart, or a tie
    Vec2 w;               ///< the wall's direction, small integers
    int a = 1, b = 1;     ///< its ends X − a·w and X + b·w; a = 0: the wall ends exactly on the leg
    int len_exp = 0;      ///< a and b times 2^len_exp: short walls (the filter cannot order) to long ones
    int tilt = 0;         ///< 1, 2: X − a·w moved one unit in x or y, so the crossing is off the lattice and rounds
    bool reverse = false;
};

/// How to build a leg and 2–3 walls crossing it at parameters equal or a few units apart.
struct LatticeCrossing {
    int q = 48;                 ///< the leg Bs → Bs + 2^q·d
    Vec2 d;
    int r = 0, ox = 0, oy = 0;  ///< Bs = 2^r·(ox, oy)
    int e = 0;                  ///< the whole scene times 2^e
    std::vector<CrossWall> walls;
};

inline rc::Gen<CrossWall> cross_wall() {
    const auto dir = rcg::apply([](int x, int y) { return Vec2{double(x), double(y)}; }, signed_upto(4), signed_upto(4));
    return rcg::build<CrossWall>(
        rcg::set(&CrossWall::j, rcg::inRange<std::int64_t>(1, std::int64_t{1} << 50)),
        rcg::set(&CrossWall::k, rcg::weightedOneOf<int>({{1, rcg::just(0)}, {3, signed_upto(3)}})),
        rcg::set(&CrossWall::w, dir), rcg::set(&CrossWall::a, rcg::weightedOneOf<int>({{1, rcg::just(0)}, {3, rcg::inRange(1, 17)}})),
        rcg::set(&CrossWall::b, rcg::inRange(1, 17)),
        rcg::set(&CrossWall::len_exp, rcg::weightedOneOf<int>({{2, rcg::just(0)}, {1, rcg::inRange(1, 44)}})),
        rcg::set(&CrossWall::tilt, rcg::weightedOneOf<int>({{3, rcg::just(0)}, {1, rcg::inRange(1, 3)}})),
        rcg::set(&CrossWall::reverse, rcg::arbitrary<bool>()));
}

/// The scene a LatticeCrossing describes. Every coordinate is an integer below 2^53 before the scale 2^e: |Bs| ≤ 7·2^48,
/// 2^q·|d| ≤ 3·2^50, a·2^len_exp·|w| ≤ 2^50, so each point is exact and each crossing parameter j/2^q exact.
inline Scene make_crossings(const LatticeCrossing& c) {
    Scene s;
    const double scale = std::ldexp(1.0, c.e);
    const double n = std::ldexp(1.0, c.q);
    const Vec2 bs = std::ldexp(1.0, c.r) * Vec2{double(c.ox), double(c.oy)};
    const std::int64_t j0 = c.walls.front().j % (std::int64_t{1} << c.q);
    for (std::size_t i = 0; i < c.walls.size(); ++i) {
        const CrossWall& cw = c.walls[i];
        const std::int64_t j = std::clamp<std::int64_t>(i == 0 ? j0 : j0 + cw.k, 0, std::int64_t{1} << c.q);
        const Vec2 x = bs + double(j) * c.d;
        // A direction along the leg would make no crossing: turn it a quarter.
        const Vec2 w = cw.w.x * c.d.y == cw.w.y * c.d.x ? Vec2{-c.d.y, c.d.x} : cw.w;
        const double l = std::ldexp(1.0, cw.len_exp);
        Vec2 p0 = x - (cw.a * l) * w;
        if (cw.tilt == 1) p0.x += 1.0;
        if (cw.tilt == 2) p0.y += 1.0;
        Wall wall{scale * p0, scale * (x + (cw.b * l) * w)};
        if (cw.reverse) std::swap(wall.p0, wall.p1);
        s.walls.push_back(wall);
    }
    s.balls.push_back({scale * bs, scale * (n * c.d)});
    s.frames = 1;
    return s;
}

/// One leg and 2–3 walls crossing it at lattice parameters equal or a few units apart (a few ulps of the
/// coordinates near 2^52), some ending exactly on the leg, some tilted so that their crossing rounds: the order of
/// crossings compare_crossings decides (the filter, then GMP), ties to the lowest index, a rounded hit point next to
/// another wall's end point (the piece to it through that end, path.cpp's piece_allowed).
inline rc::Gen<Scene> crossings_scene() {
    const auto d = rcg::apply([](int x, int y) { return Vec2{double(1 + x), double(y)}; }, upto(2), signed_upto(3));
    return rcg::apply(
        [](int q, Vec2 dir, int r, int ox, int oy, int e, const std::vector<CrossWall>& walls) {
            return make_crossings({q, dir, r, ox, oy, e, walls});
        },
        rcg::inRange(30, 51), d, rcg::inRange(0, 49), signed_upto(7), signed_upto(7), signed_upto(100),
        rcg::mapcat(rcg::inRange(2, 4),
                    [](int n) { return rcg::container<std::vector<CrossWall>>(std::size_t(n), cross_wall()); }));
}

}  // namespace ricochet::props::gen
