// Generators for balls that meet (`balls collide`, docs/scene-log.md "Balls that meet"; meet_props.cpp): 2–8 balls
// with radii and masses on collision courses (each aimed at where another ball will be, head-on or off centre, some
// fast enough to cross it within one frame), in the open or in a closed box; head-on pairs along an axis; a Newton's
// cradle; a break shot (a triangle rack and a cue ball in a box); balls converging on one point at one time; fast
// pairs crossing within a frame; two paths that only touch (a tangent, no meet). Everything is laid out in integer
// units and placed by Placement's exact map
// (generators_discs.hpp), so "touching", "head-on" and "at the same time" hold bit for bit.
#pragma once

#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "generators_discs.hpp"
#include "generators_numbers.hpp"
#include "ricochet/scene.hpp"

namespace ricochet::props::gen {

namespace rcg = rc::gen;

/// A ball's mass: mostly 1, else unequal ones over six orders of magnitude.
inline rc::Gen<double> mass() {
    return rcg::weightedOneOf<double>(
        {{4, rcg::just(1.0)}, {2, rcg::element(2.0, 0.5, 3.0)}, {1, rcg::element(1e-3, 1e3)}});
}

/// The four walls of the box [lo, hi] in units, placed.
inline std::vector<Wall> box_walls(const Placement& at, Vec2 lo, Vec2 hi) {
    const Vec2 c[4] = {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
    std::vector<Wall> walls;
    for (int i = 0; i < 4; ++i) walls.push_back({at.place(c[i]), at.place(c[(i + 1) % 4])});
    return walls;
}

/// Ball i of a meeting scene: in cell (i mod 3, i div 3) of a lattice of 6 units, a radius, a mass and how it moves.
struct MeetBallSpec {
    int jx = 0, jy = 0;  ///< where in its cell, in quarter units (0..12)
    int rm = 32;         ///< radius rm/64 units (0: a point ball, which meets discs only)
    int mode = 2;        ///< 0 at rest, 1 free, 2 aimed at another ball
    int vx = 0, vy = 0;  ///< free: quarter units a frame
    int target = 0;      ///< aimed: which other ball (mod n − 1, itself skipped)
    int tau = 2;         ///< aimed: it would reach the target's centre after 2^(tau − 2) frames (1/4 .. 4)
    int ox = 0, oy = 0;  ///< aimed: off centre by (ox, oy)/8 units (0: head-on)
    double mass = 1.0;
};

inline rc::Gen<MeetBallSpec> meet_ball_spec() {
    return rcg::build<MeetBallSpec>(
        rcg::set(&MeetBallSpec::jx, upto(12)), rcg::set(&MeetBallSpec::jy, upto(12)),
        rcg::set(&MeetBallSpec::rm, rcg::weightedOneOf<int>({{8, rcg::inRange(1, 65)}, {1, rcg::just(0)}})),
        rcg::set(&MeetBallSpec::mode,
                 rcg::weightedOneOf<int>({{1, rcg::just(0)}, {1, rcg::just(1)}, {4, rcg::just(2)}})),
        rcg::set(&MeetBallSpec::vx, signed_upto(16)), rcg::set(&MeetBallSpec::vy, signed_upto(16)),
        rcg::set(&MeetBallSpec::target, upto(7)), rcg::set(&MeetBallSpec::tau, upto(4)),
        rcg::set(&MeetBallSpec::ox, rcg::weightedOneOf<int>({{2, rcg::just(0)}, {1, signed_upto(8)}})),
        rcg::set(&MeetBallSpec::oy, rcg::weightedOneOf<int>({{2, rcg::just(0)}, {1, signed_upto(8)}})),
        rcg::set(&MeetBallSpec::mass, mass()));
}

/// A Placement whose offset stays near the origin (no far offsets): for scenes the float lecture kernel must see
/// as the doubles do.
inline rc::Gen<Placement> near_placement() {
    return rcg::map(placement(), [](Placement p) {
        p.off_exp = 0;
        p.off_x %= 1024;
        p.off_y %= 1024;
        return p;
    });
}

/// 2..max_balls balls on collision courses, every one starting at least 3 units from the others (radii ≤ 1 unit):
/// an aimed ball moves so as to reach the centre its target will have after τ = 2^(tau − 2) frames, moved off centre
/// by (ox, oy)/8 units; masses equal (every 1, or all one drawn mass) or each its own. With box, a closed box of
/// walls 6 units clear of the lattice holds them. 1..max_frames frames.
inline rc::Gen<Scene> meeting_scene(int max_balls, int max_frames, bool box) {
    return rcg::apply(
        [box](const Placement& at, const std::vector<MeetBallSpec>& bs, int masses, int frames) {
            const std::size_t n = bs.size();
            std::vector<Vec2> p(n), v(n);
            for (std::size_t i = 0; i < n; ++i) {
                p[i] = Vec2{6.0 * double(i % 3), 6.0 * double(i / 3)} + Vec2{bs[i].jx / 4.0, bs[i].jy / 4.0};
                v[i] = bs[i].mode == 1 ? Vec2{bs[i].vx / 4.0, bs[i].vy / 4.0} : Vec2{};
            }
            // Aimed: (p_t + v_t·τ + o − p_i)/τ, τ a power of two, so every velocity is exact in units.
            for (std::size_t i = 0; i < n; ++i) {
                if (bs[i].mode != 2) continue;
                std::size_t t = std::size_t(bs[i].target) % (n - 1);
                if (t >= i) ++t;
                const double tau = std::ldexp(1.0, bs[i].tau - 2);
                const Vec2 aim = p[t] + tau * (bs[t].mode == 1 ? v[t] : Vec2{}) + Vec2{bs[i].ox / 8.0, bs[i].oy / 8.0};
                v[i] = (1.0 / tau) * (aim - p[i]);
            }
            Scene s;
            s.balls_collide = true;
            const double unit = std::ldexp(1.0, at.scale_exp);
            for (std::size_t i = 0; i < n; ++i)
                s.balls.push_back({at.place(p[i]), at.vector(v[i]), unit * (bs[i].rm / 64.0)});
            // 0: no masses (every ball 1); 1: every ball the first ball's mass; 2: each its own.
            if (masses > 0)
                for (std::size_t i = 0; i < n; ++i) s.masses.push_back(masses == 1 ? bs[0].mass : bs[i].mass);
            if (box) s.walls = box_walls(at, {-6, -6}, {18, 6.0 * double((n + 2) / 3) + 6});
            s.frames = frames;
            return s;
        },
        placement(),
        rcg::mapcat(rcg::inRange(2, max_balls + 1),
                    [](int n) { return rcg::container<std::vector<MeetBallSpec>>(std::size_t(n), meet_ball_spec()); }),
        upto(2), rcg::inRange(1, max_frames + 1));
}

/// Any meeting scene: in the open or boxed.
inline rc::Gen<Scene> meeting_scene(int max_balls, int max_frames) {
    return rcg::weightedOneOf<Scene>(
        {{1, meeting_scene(max_balls, max_frames, false)}, {1, meeting_scene(max_balls, max_frames, true)}});
}

/// Two balls on one axis line, head-on or chasing, of equal masses, in the open or in a corridor whose walls are
/// along the axes (so every bounce keeps them on the line).
struct HeadOnSpec {
    int xa = -16, xb = 32;  ///< starts: a at xa/4 units (−8..0), b at 4 + xb/4 units (4..12)
    int va = 8, vb = -8;    ///< velocities along the line, quarter units a frame
    int ra = 32, rb = 32;   ///< radii ra/64, rb/64 units
    bool corridor = false;
    int frames = 4;
    double mass = 1.0;
};

inline rc::Gen<Scene> head_on_scene(int max_frames) {
    const auto spec = rcg::build<HeadOnSpec>(
        rcg::set(&HeadOnSpec::xa, rcg::inRange(-32, 1)), rcg::set(&HeadOnSpec::xb, upto(32)),
        rcg::set(&HeadOnSpec::va, rcg::inRange(-8, 65)), rcg::set(&HeadOnSpec::vb, rcg::inRange(-64, 9)),
        rcg::set(&HeadOnSpec::ra, rcg::inRange(1, 65)), rcg::set(&HeadOnSpec::rb, upto(64)),
        rcg::set(&HeadOnSpec::corridor, rcg::arbitrary<bool>()),
        rcg::set(&HeadOnSpec::frames, rcg::inRange(1, max_frames + 1)), rcg::set(&HeadOnSpec::mass, mass()));
    return rcg::apply(
        [](const Placement& at, const HeadOnSpec& h) {
            Scene s;
            s.balls_collide = true;
            const double unit = std::ldexp(1.0, at.scale_exp);
            s.balls = {{at.place({h.xa / 4.0, 0}), at.vector({h.va / 4.0, 0}), unit * (h.ra / 64.0)},
                       {at.place({4 + h.xb / 4.0, 0}), at.vector({h.vb / 4.0, 0}), unit * (h.rb / 64.0)}};
            s.masses = {h.mass, h.mass};
            if (h.corridor) s.walls = box_walls(at, {-16, -4}, {24, 4});
            s.frames = h.frames;
            return s;
        },
        placement(), spec);
}

/// A Newton's cradle: n − 1 balls of radius R = 2^−k units at rest, touching in a row along an axis, and ball 0
/// arriving along it at speed s after a whole number of quarter frames, all of one mass: every number exact.
struct CradleSpec {
    int n = 5;         ///< balls, the arriving one included (2..8)
    int k = 0;         ///< R = 2^−k units (0..6)
    int speed = 4;     ///< quarter units a frame (1..32)
    int quarters = 4;  ///< the gap is speed·quarters/4: it arrives after quarters/4 frames (0..16)
    int extra = 1;     ///< frames after the arrival's (0..3)
    double mass = 1.0;
};

inline rc::Gen<Scene> cradle_scene() {
    const auto spec = rcg::build<CradleSpec>(
        rcg::set(&CradleSpec::n, rcg::inRange(2, 9)), rcg::set(&CradleSpec::k, upto(6)),
        rcg::set(&CradleSpec::speed, rcg::inRange(1, 33)), rcg::set(&CradleSpec::quarters, upto(16)),
        rcg::set(&CradleSpec::extra, upto(3)), rcg::set(&CradleSpec::mass, mass()));
    return rcg::apply(
        [](const Placement& at, const CradleSpec& c) {
            Scene s;
            s.balls_collide = true;
            const double R = std::ldexp(1.0, -c.k), v = c.speed / 4.0, gap = v * c.quarters / 4.0;
            const double unit = std::ldexp(1.0, at.scale_exp);
            s.balls.push_back({at.place({-2 * R - gap, 0}), at.vector({v, 0}), unit * R});
            for (int i = 1; i < c.n; ++i) s.balls.push_back({at.place({2 * R * (i - 1), 0}), {0, 0}, unit * R});
            s.masses.assign(std::size_t(c.n), c.mass);
            // It arrives after quarters/4 frames: the row moves on by the end of frame ⌊quarters/4⌋ + 1 (one arriving
            // at a frame's very end passes its momentum on at the next one's start).
            s.frames = c.quarters / 4 + 1 + c.extra;
            return s;
        },
        placement(), spec);
}

/// A break shot: a triangle rack of `rows` columns (1 + 2 + … balls) of radius R = 2^−k units, columns 7R/4 apart
/// and balls in a column 2R + gap apart (touching where gap = 0; neighbours in adjacent columns at least
/// √(49/16 + 1)·R > 2R apart), a cue ball d units before it moving along x at speed·R/4 a frame, off the rack's axis by
/// off·R/8; in a box of walls 4R clear of everything.
struct BreakSpec {
    int rows = 3;   ///< 2..4
    int k = 0;      ///< R = 2^−k units (0..2)
    int gap = 0;    ///< 0: touching in a column; 1: R/8 apart; 2: R/2
    int d = 8;      ///< the cue ball starts d·R before the rack (4..16)
    int off = 0;    ///< −4..4
    int speed = 8;  ///< quarter radii a frame (1..64: up to 16R, across the rack in one frame)
    double cue_mass = 1.0;
    int frames = 6;
};

inline rc::Gen<Scene> break_shot_scene(int max_frames) {
    const auto spec = rcg::build<BreakSpec>(
        rcg::set(&BreakSpec::rows, rcg::inRange(2, 5)), rcg::set(&BreakSpec::k, upto(2)),
        rcg::set(&BreakSpec::gap, upto(2)), rcg::set(&BreakSpec::d, rcg::inRange(4, 17)),
        rcg::set(&BreakSpec::off, signed_upto(4)), rcg::set(&BreakSpec::speed, rcg::inRange(1, 65)),
        rcg::set(&BreakSpec::cue_mass, rcg::weightedOneOf<double>({{3, rcg::just(1.0)}, {1, mass()}})),
        rcg::set(&BreakSpec::frames, rcg::inRange(1, max_frames + 1)));
    return rcg::apply(
        [](const Placement& at, const BreakSpec& b) {
            Scene s;
            s.balls_collide = true;
            const double R = std::ldexp(1.0, -b.k), unit = std::ldexp(1.0, at.scale_exp);
            const double dx = 1.75 * R, dy = 2 * R + (b.gap == 0 ? 0.0 : b.gap == 1 ? R / 8 : R / 2);
            s.balls.push_back({at.place({-b.d * R, b.off * R / 8}), at.vector({b.speed * R / 4, 0}), unit * R});
            for (int r = 0; r < b.rows; ++r)
                for (int i = 0; i <= r; ++i)
                    s.balls.push_back({at.place({r * dx, (i - r / 2.0) * dy}), {0, 0}, unit * R});
            s.masses.assign(s.balls.size(), 1.0);
            s.masses[0] = b.cue_mass;
            const double half = b.rows * dy / 2 + 4 * R;
            s.walls = box_walls(at, {-b.d * R - 4 * R, -half}, {b.rows * dx + 4 * R, half});
            s.frames = b.frames;
            return s;
        },
        placement(), spec);
}

/// 3..8 balls converging on one point, each from one of the eight directions (±1, 0), (0, ±1), (±1, ±1) at dist
/// units along it (dist·√2 on a diagonal), all arriving at its centre after τ = 2^(tau − 2) frames: by symmetry the
/// pairs at one angle meet at the same exact time, several sharing a ball. Radii all one (r/64 units), masses equal
/// or drawn.
struct ConvergeSpec {
    std::vector<bool> from;  ///< which of the eight directions hold a ball (at least 3 are forced)
    int dist = 8;            ///< 4..16
    int r = 32;              ///< 8..64
    int tau = 2;             ///< 0..4
    bool own_masses = false;
    std::vector<double> masses;
    int frames = 4;
};

inline rc::Gen<Scene> converging_scene(int max_frames) {
    const auto spec = rcg::build<ConvergeSpec>(
        rcg::set(&ConvergeSpec::from, rcg::container<std::vector<bool>>(8, rcg::arbitrary<bool>())),
        rcg::set(&ConvergeSpec::dist, rcg::inRange(4, 17)), rcg::set(&ConvergeSpec::r, rcg::inRange(8, 65)),
        rcg::set(&ConvergeSpec::tau, upto(4)), rcg::set(&ConvergeSpec::own_masses, rcg::arbitrary<bool>()),
        rcg::set(&ConvergeSpec::masses, rcg::container<std::vector<double>>(8, mass())),
        rcg::set(&ConvergeSpec::frames, rcg::inRange(1, max_frames + 1)));
    return rcg::apply(
        [](const Placement& at, ConvergeSpec c) {
            // At least three: the first three directions (two opposite, one across) where fewer are drawn.
            if (std::count(c.from.begin(), c.from.end(), true) < 3) c.from[0] = c.from[1] = c.from[2] = true;
            Scene s;
            s.balls_collide = true;
            const double tau = std::ldexp(1.0, c.tau - 2), unit = std::ldexp(1.0, at.scale_exp);
            constexpr Vec2 dirs[8] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {-1, -1}, {1, -1}, {-1, 1}};
            for (int i = 0; i < 8; ++i) {
                if (!c.from[std::size_t(i)]) continue;
                const Vec2 p = double(c.dist) * dirs[i];
                s.balls.push_back({at.place(p), at.vector((-1.0 / tau) * p), unit * (c.r / 64.0)});
                s.masses.push_back(c.own_masses ? c.masses[std::size_t(i)] : c.masses[0]);
            }
            s.frames = c.frames;
            return s;
        },
        placement(), spec);
}

/// Two balls crossing each other within frame 1: a from c − w to c + w, b from c + w + o to c − w + o, |w|∞ ≥ 2 units
/// (so they are more than R_a + R_b ≤ 2 units apart at both ends of the frame) and |o| < (R_a + R_b)/√2 (so their
/// paths come within R_a + R_b of each other half-way), near the origin.
struct CrossSpec {
    int cx = 0, cy = 0;    ///< c in units, −8..8
    int wx = 4, wy = 0;    ///< w in units: |wx| 2..16, wy −16..16
    int ra = 32, rb = 32;  ///< radii /64 units, 1..64
    int ox = 0, oy = 0;    ///< o = (ox, oy)·(R_a + R_b)/16, −8..8
};

inline rc::Gen<Scene> crossing_scene() {
    const auto spec = rcg::build<CrossSpec>(
        rcg::set(&CrossSpec::cx, signed_upto(8)), rcg::set(&CrossSpec::cy, signed_upto(8)),
        rcg::set(&CrossSpec::wx,
                 rcg::apply([](int m, bool neg) { return neg ? -m : m; }, rcg::inRange(2, 17), rcg::arbitrary<bool>())),
        rcg::set(&CrossSpec::wy, signed_upto(16)), rcg::set(&CrossSpec::ra, rcg::inRange(1, 65)),
        rcg::set(&CrossSpec::rb, rcg::inRange(1, 65)), rcg::set(&CrossSpec::ox, signed_upto(8)),
        rcg::set(&CrossSpec::oy, signed_upto(8)));
    return rcg::apply(
        [](const Placement& at, const CrossSpec& x) {
            Scene s;
            s.balls_collide = true;
            s.frames = 1;
            const double unit = std::ldexp(1.0, at.scale_exp), S = (x.ra + x.rb) / 64.0;
            const Vec2 c{double(x.cx), double(x.cy)}, w{double(x.wx), double(x.wy)}, o{x.ox * S / 16, x.oy * S / 16};
            s.balls = {{at.place(c - w), at.vector(2.0 * w), unit * (x.ra / 64.0)},
                       {at.place(c + w + o), at.vector(-2.0 * w), unit * (x.rb / 64.0)}};
            return s;
        },
        near_placement(), spec);
}

/// Two balls whose paths only touch: ball 0 from c moving v, ball 1 from c + (−d, S) moving v + (w, 0), S = R_0 + R_1,
/// so that their distance √((w·u − d)² + S²) reaches S at the one instant u = d/w (a double root: no meet, docs/
/// scene-log.md "Balls that meet", 2), within frame 1 or, with over, just past it. The hand-made tangent `ball 0 0 0 0
/// 0.5`, `ball -3 1 4 0 0.5` is one of them (c = 0, v = 0, d = 3, w = 4). Radii in 64ths and everything else in quarter
/// units, placed by Placement's exact map, so the tangent is exact in doubles at every scale and offset.
struct TangentSpec {
    int cx = 0, cy = 0;    ///< c, quarter units, −32..32
    int vx = 0, vy = 0;    ///< v, quarter units a frame, −16..16 (0 half the time: ball 0 at rest)
    int ra = 32, rb = 32;  ///< radii /64 units, 1..64 and 0..64 (0: a point ball passing a disc)
    int w = 16;            ///< quarter units a frame, 1..64
    int k = 6;             ///< d = w·k/8 quarter units: the tangent at u = k/8, 1..8 (over: k + 8)
    bool over = false;     ///< the tangent after the frame's end
};

inline rc::Gen<Scene> tangent_scene() {
    const auto spec = rcg::build<TangentSpec>(
        rcg::set(&TangentSpec::cx, signed_upto(32)), rcg::set(&TangentSpec::cy, signed_upto(32)),
        rcg::set(&TangentSpec::vx, rcg::weightedOneOf<int>({{1, rcg::just(0)}, {1, signed_upto(16)}})),
        rcg::set(&TangentSpec::vy, rcg::weightedOneOf<int>({{1, rcg::just(0)}, {1, signed_upto(16)}})),
        rcg::set(&TangentSpec::ra, rcg::inRange(1, 65)), rcg::set(&TangentSpec::rb, upto(64)),
        rcg::set(&TangentSpec::w, rcg::inRange(1, 65)), rcg::set(&TangentSpec::k, rcg::inRange(1, 9)),
        rcg::set(&TangentSpec::over, rcg::weightedOneOf<bool>({{4, rcg::just(false)}, {1, rcg::just(true)}})));
    return rcg::apply(
        [](const Placement& at, const TangentSpec& x) {
            Scene s;
            s.balls_collide = true;
            s.frames = 1;
            const double unit = std::ldexp(1.0, at.scale_exp), S = (x.ra + x.rb) / 64.0;
            const Vec2 c{x.cx / 4.0, x.cy / 4.0}, v{x.vx / 4.0, x.vy / 4.0};
            const double d = x.w * (x.k + (x.over ? 8 : 0)) / 32.0;
            s.balls = {{at.place(c), at.vector(v), unit * (x.ra / 64.0)},
                       {at.place(c + Vec2{-d, S}), at.vector(v + Vec2{x.w / 4.0, 0}), unit * (x.rb / 64.0)}};
            return s;
        },
        placement(), spec);
}

/// Two balls touching exactly at the frame's start and moving nearly square to their line of centres, so that whether
/// they approach (B = D·W < 0: a meet at t = 0) rests on the last bits of the velocities: D = (3m, 4m)/64 units and
/// S = 5m/64 (exact in doubles, |D| = S exactly), ball 1 moving j·(4, −3)/4 units a frame plus a tilt a and b times
/// 2^−e, e in 40..80, either way or none, at every scale, turned and mirrored, near the origin (a far offset would
/// round the printed ends to a grain coarser than the tilt). The products of D and W round there, but seldom by more
/// than B: mutant 48 (the moving-apart filter without its error bound) passes this generator's cases, which
/// MeetRootStages.MovingApartIsDecidedAsTheRationalsDecideIt, a unit test, catches.
struct GrazeSpec {
    int m = 1;            ///< 1..12
    int ra = 1;           ///< ball 0's radius in 64ths, 0..5m (ball 1's is the rest of 5m)
    int j = 4;            ///< −16..16, not 0
    int a = 0, b = 0;     ///< the tilt's numerators, −2^20..2^20
    int e = 60;           ///< the tilt's exponent, 40..80
    int vx = 0, vy = 0;   ///< both balls' common velocity in quarter units a frame, −8..8
};

inline rc::Gen<Scene> grazing_scene() {
    const auto spec = rcg::mapcat(rcg::inRange(1, 13), [](int m) {
        return rcg::build<GrazeSpec>(
            rcg::set(&GrazeSpec::m, rcg::just(m)), rcg::set(&GrazeSpec::ra, upto(5 * m)),
            rcg::set(&GrazeSpec::j, rcg::suchThat(signed_upto(16), [](int j) { return j != 0; })),
            rcg::set(&GrazeSpec::a, signed_upto(1 << 20)), rcg::set(&GrazeSpec::b, signed_upto(1 << 20)),
            rcg::set(&GrazeSpec::e, rcg::inRange(40, 81)),
            rcg::set(&GrazeSpec::vx, rcg::weightedOneOf<int>({{2, rcg::just(0)}, {1, signed_upto(8)}})),
            rcg::set(&GrazeSpec::vy, rcg::weightedOneOf<int>({{2, rcg::just(0)}, {1, signed_upto(8)}})));
    });
    return rcg::apply(
        [](Placement at, const GrazeSpec& x) {
            at.off_x = at.off_y = 0;
            Scene s;
            s.balls_collide = true;
            s.frames = 1;
            const double unit = std::ldexp(1.0, at.scale_exp);
            const Vec2 v{x.vx / 4.0, x.vy / 4.0};
            const Vec2 tilt = std::ldexp(1.0, -x.e) * Vec2{double(x.a), double(x.b)};
            const Vec2 w = Vec2{x.j * 1.0, x.j * -0.75} + tilt;
            s.balls = {{at.place({0, 0}), at.vector(v), unit * (x.ra / 64.0)},
                       {at.place({3.0 * x.m / 64, 4.0 * x.m / 64}), at.vector(v + w), unit * ((5 * x.m - x.ra) / 64.0)}};
            return s;
        },
        placement(), spec);
}

}  // namespace ricochet::props::gen
