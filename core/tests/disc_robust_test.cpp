// The robust kernel's discs among walls (kernels/robust/robust_disc.cpp), held to their promises: no ghost bounce at
// a chain's joints, the corner rule, the bounce's numbers worked by hand, overlaps of sensors, and on scenes
// built for it (closed convex and concave polygons, chains, wedges, far from the origin, tiny and huge radii)
// no-tunnel, penetration with δ = 0, speed and no-escape, every frame. (The penetration and ghost-bounce checks
// themselves, on paths fed by hand, are harness/tests/disc_checks_test.cpp's.)
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include <fmt/format.h>
#include <gmpxx.h>

#include "kernels/disc/contact.hpp"
#include "ricochet/checks.hpp"
#include "ricochet/format.hpp"
#include "ricochet/world.hpp"

namespace ricochet {
namespace {

const Check k_disc_checks[] = {Check::no_tunnel, Check::penetration, Check::speed, Check::no_escape,
                               Check::event_order, Check::deterministic, Check::ghost_bounce};

/// The run of scene under robust with every check defined for discs; the failure, if any, as text.
std::string checked(const Scene& scene) {
    const CheckedRun run = run_checked(scene, KernelId::robust, scene.frames, k_disc_checks);
    if (run.error) return run.error->message();
    return run.failure ? run.failure->str() : "";
}

TEST(DiscRobust, NoGhostBounceAlongAChain) {
    // A chain of collinear walls sharing end points, in both directions, and a disc sliding along it at
    // exactly R: no hit, and the velocity never changes, frame after frame.
    for (const bool reversed : {false, true}) {
        Scene s;
        s.frames = 40;
        double x = -50;
        std::mt19937 rng(3);
        while (x < 200) {
            const double next = x + 1 + static_cast<double>(rng() % 7);
            s.walls.push_back(reversed ? Wall{{next, 0}, {x, 0}} : Wall{{x, 0}, {next, 0}});
            x = next;
        }
        s.balls = {{{-40, 0.5}, {3.25, 0}, 0.5}, {{-40, -2}, {4, 0}, 2}, {{150, 0.125}, {-2.5, 0}, 0.125}};
        const std::vector<Event> events = run_scene(s, KernelId::robust, s.frames);
        for (const Event& e : events) {
            EXPECT_NE(e.kind, Event::Kind::hit) << format_event(e);
            if (e.kind == Event::Kind::state) EXPECT_EQ(e.vel, s.balls[e.ball].vel) << format_event(e);
        }
        EXPECT_EQ(checked(s), "");
    }
    // Along a 3-4-5 slope: walls (3k, 4k) → (3k + 3, 4k + 4), the centre 5 away at offset (4, −3), moving
    // (1.5, 2) per frame: every position is exact, so the disc stays at exactly R.
    Scene slope;
    slope.frames = 30;
    for (int k = 0; k < 30; ++k) slope.walls.push_back({{3.0 * k, 4.0 * k}, {3.0 * k + 3, 4.0 * k + 4}});
    slope.balls = {{{4, -3}, {1.5, 2}, 5}};
    for (const Event& e : run_scene(slope, KernelId::robust, slope.frames)) EXPECT_NE(e.kind, Event::Kind::hit);
    EXPECT_EQ(checked(slope), "");
}

TEST(DiscRobust, AJointIsAWallWhenTheChainBends) {
    // The same joint with the second wall turned up by 1/8: the disc now meets it.
    Scene s;
    s.frames = 4;
    s.walls = {{{-10, 0}, {0, 0}}, {{0, 0}, {8, 1}}};
    s.balls = {{{-8, 1}, {3, 0}, 1}};
    bool hit = false;
    for (const Event& e : run_scene(s, KernelId::robust, s.frames)) hit = hit || e.kind == Event::Kind::hit;
    EXPECT_TRUE(hit);
    EXPECT_EQ(checked(s), "");
}

TEST(DiscRobust, BouncesWorkedByHand) {
    // Face: a disc of radius 1 from (2, 3) moving (4, −4) meets the floor's face at t = 0.5, B_i = (4, 1), and
    // leaves with (4, 4) for the rest of the frame: (4, 1) + 0.5·(4, 4) = (6, 3).
    Scene face;
    face.frames = 1;
    face.walls = {{{0, 0}, {10, 0}}};
    face.balls = {{{2, 3}, {4, -4}, 1}};
    const std::vector<Event> f = run_scene(face, KernelId::robust, 1);
    ASSERT_EQ(f.size(), 3u);
    EXPECT_EQ(format_event(f[1]), "hit 1 0 0 4 1");
    EXPECT_EQ(format_event(f[2]), "state 1 0 6 3 4 4");
    // Cap, 3-4-5: R = 5 from (−8, 4) moving (10, 0) meets P0's cap at (−3, 4), t = 0.5; the normal (−3, 4)/5
    // turns (10, 0) into (10, 0) − 2·(−6)·(−0.6, 0.8) = (2.8, 9.6); the rest of the frame adds half of it.
    Scene cap;
    cap.frames = 1;
    cap.walls = {{{0, 0}, {10, 0}}};
    cap.balls = {{{-8, 4}, {10, 0}, 5}};
    const std::vector<Event> c = run_scene(cap, KernelId::robust, 1);
    ASSERT_EQ(c.size(), 3u);
    EXPECT_EQ(c[1].kind, Event::Kind::hit);
    EXPECT_EQ(c[1].pos, (Vec2{-3, 4}));
    EXPECT_NEAR(c[2].vel.x, 2.8, 1e-14);
    EXPECT_NEAR(c[2].vel.y, 9.6, 1e-14);
    EXPECT_NEAR(c[2].pos.x, -1.6, 1e-14);
    EXPECT_NEAR(c[2].pos.y, 8.8, 1e-14);
    EXPECT_EQ(checked(cap), "");
}

TEST(DiscRobust, CornerRule) {
    // Into the corner of a box, at 45°: both walls' contacts come at once (t = 0.5, the centre at (1, 1)); the
    // rule reflects about the lower wall, then about the other: straight back, exactly.
    Scene s;
    s.frames = 1;
    s.walls = {{{0, 0}, {0, 10}}, {{10, 0}, {0, 0}}};
    s.balls = {{{3, 3}, {-4, -4}, 1}};
    const std::vector<Event> e = run_scene(s, KernelId::robust, 1);
    ASSERT_EQ(e.size(), 3u);
    EXPECT_EQ(format_event(e[1]), "hit 1 0 0 1 1");
    EXPECT_EQ(format_event(e[2]), "state 1 0 3 3 4 4");
    // An acute wedge: the disc wedges in, bounces and comes out, held to every check for many frames.
    Scene wedge;
    wedge.frames = 200;
    wedge.walls = {{{0, 0}, {100, 3}}, {{100, -3}, {0, 0}}, {{100, 3}, {100, -3}}};
    wedge.balls = {{{60, 0.1}, {-7.3, 0.01}, 1}, {{90, 0}, {-13, 0}, 1.5}};
    EXPECT_EQ(checked(wedge), "");
}

TEST(DiscRobust, SensorsSeeTheDiscAtItsSize) {
    // A circle sensor 3 away and a rectangle 2 away from a disc of radius 2: touching counts, so both overlap;
    // a point ball there overlaps neither.
    Scene s;
    s.circles = {{{3, 0}, 1}, {{3.5, 0}, 1}};
    s.rects = {{2, -1, 4, 1}, {2.5, -1, 4, 1}};
    s.balls = {{{0, 0}, {0, 0}, 2}, {{0, 0}, {0, 0}, 0}};
    std::vector<std::string> overlaps;
    for (const Event& e : run_scene(s, KernelId::robust, 0))
        if (e.kind == Event::Kind::overlap) overlaps.push_back(format_event(e));
    EXPECT_EQ(overlaps, (std::vector<std::string>{"overlap 0 0 circle 0", "overlap 0 0 rect 0"}));
}

/// A regular n-gon of walls (counter-clockwise), radius `size` around c, rotated by `turn`, each side split
/// into `split` collinear walls.
std::vector<Wall> polygon(int n, double size, Vec2 c, double turn, int split) {
    std::vector<Wall> walls;
    for (int k = 0; k < n; ++k) {
        const double a0 = turn + 2 * std::numbers::pi * k / n, a1 = turn + 2 * std::numbers::pi * (k + 1) / n;
        const Vec2 p{c.x + size * std::cos(a0), c.y + size * std::sin(a0)};
        const Vec2 q{c.x + size * std::cos(a1), c.y + size * std::sin(a1)};
        Vec2 from = p;
        for (int j = 1; j <= split; ++j) {
            // The split points as (1 − f)·p + f·q: not exactly collinear, the joints the ghost rule must still face.
            const double f = static_cast<double>(j) / split;
            const Vec2 to = j == split ? q : Vec2{(1 - f) * p.x + f * q.x, (1 - f) * p.y + f * q.y};
            walls.push_back({from, to});
            from = to;
        }
    }
    return walls;
}

TEST(DiscRobust, ClosedPolygonsHoldEveryCheck) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0, 1);
    int frames_run = 0;
    for (int i = 0; i < 60; ++i) {
        Scene s;
        s.frames = 40;
        const double size = std::pow(10.0, -3 + 8 * unit(rng));
        const Vec2 c = i % 3 == 0 ? Vec2{} : Vec2{std::pow(10.0, 12 * unit(rng)), -std::pow(10.0, 9 * unit(rng))};
        s.walls = polygon(3 + static_cast<int>(rng() % 6), size, c, 6 * unit(rng), 1 + static_cast<int>(rng() % 3));
        // Concave: a notch pushed in from one side (two walls from a side's ends to a point inside).
        if (i % 2 == 1) {
            const Wall side = s.walls.back();
            s.walls.pop_back();
            const Vec2 in{0.5 * (side.p0.x + side.p1.x) * 0.6 + 0.4 * c.x, 0.5 * (side.p0.y + side.p1.y) * 0.6 + 0.4 * c.y};
            s.walls.push_back({side.p0, in});
            s.walls.push_back({in, side.p1});
        }
        for (int b = 0; b < 3; ++b) {
            const double r = size * std::array{0.2, 0.05, 1e-9, 1e-14, 0.3}[rng() % 5];
            const double angle = 7 * unit(rng), speed = size * std::pow(10.0, -2 + 3 * unit(rng));
            const Vec2 p{c.x + 0.2 * size * (unit(rng) - 0.5), c.y + 0.2 * size * (unit(rng) - 0.5)};
            s.balls.push_back({p, {speed * std::cos(angle), speed * std::sin(angle)}, r});
        }
        EXPECT_EQ(checked(s), "") << i << "\n" << fmt::format("{}", s.walls.size());
        frames_run += static_cast<int>(s.frames);
    }
    EXPECT_EQ(frames_run, 60 * 40);
}

/// The exact contact point of a leg entering a wall's face, q + t*·d, t* = (σR − h)/(n̂·d) with h = n̂·(q − P0) and
/// σ = sign(h), in 512-bit floating point (independent of the kernels' code), and its distance in ∞-norm to x.
double face_contact_error(Vec2 q, Vec2 b, double R, const Wall& w, Vec2 x) {
    mpf_set_default_prec(512);
    using F = mpf_class;
    const F qx(q.x), qy(q.y), dx = F(b.x) - qx, dy = F(b.y) - qy;
    const F ex = F(w.p1.x) - F(w.p0.x), ey = F(w.p1.y) - F(w.p0.y);
    const F len = sqrt(ex * ex + ey * ey);
    const F nx = ey / len, ny = -ex / len;
    const F h = nx * (qx - F(w.p0.x)) + ny * (qy - F(w.p0.y));
    const F t = (sgn(h) * F(R) - h) / (nx * dx + ny * dy);
    const F ex_err = abs(qx + t * dx - F(x.x)), ey_err = abs(qy + t * dy - F(x.y));
    return std::fmax(ex_err.get_d(), ey_err.get_d());
}

TEST(DiscRobust, GrazingLegsPrintTheirContactNearTheExactOne) {
    // A leg that approaches a wall's face by ulps over its length: the wall along a Pythagorean direction (a, b, c)
    // on a grid of 2^−7, a disc of radius R = k·c/2^7 (so R·n̂ is on the grid) starting at a point of the wall plus
    // R·n̂ with its y moved by one or two ulps away from the wall, moving along the wall with its velocity one or two
    // ulps from parallel. From doubles t_f = (s·n·w − R·|n|)/(−s·n·d) is a rounding error over a rounding error
    // (robust once printed t = 0 where the exact entry was at 0.2 or 1, and bounced at its start 16 times). The
    // printed first hit must lie within 2^−40·|d|∞ (robust's tolerance on t) and a few ulps of the exact contact
    // point: neither a rounded t nor a walk back along a leg that gains no distance from the wall may move it
    // (measured: within 5.7e−15·|d|∞ on all of them). Later hits in the frame follow the rules (a reflected leg may
    // graze the face again), but a frame never runs into the bounce limit.
    const int dirs[][3] = {{3, 4, 5}, {5, 12, 13}, {8, 15, 17}, {7, 24, 25}, {20, 21, 29}};
    int hits = 0;
    for (const auto& abc : dirs)
        for (int flip = 0; flip < 8; ++flip) {
            double a = abc[0], b = abc[1];
            if (flip & 1) std::swap(a, b);
            if (flip & 2) a = -a;
            if (flip & 4) b = -b;
            const Vec2 p0{0.75390625, -0.1875};
            const Wall w{p0, {p0.x + a / 8, p0.y + b / 8}};
            for (int k = 1; k <= 3; ++k) {
                const double R = k * abc[2] / 128.0;
                // n̂ = (b, −a)/c; the start at a quarter of the wall plus R·n̂ on either side.
                for (const int side : {-1, 1}) {
                    const Vec2 on{p0.x + a / 32, p0.y + b / 32};
                    const Vec2 exact_start{on.x + side * k * b / 128, on.y - side * k * a / 128};
                    for (const int away : {1, 2})
                        for (const int skew : {-2, -1, 1, 2}) {
                            // Away from the wall's line by `away` ulps of y (the side n̂'s y points to).
                            Vec2 q = exact_start;
                            const double up = -side * a > 0 ? 1.0 : -1.0;
                            for (int u = 0; u < away; ++u) q.y = std::nextafter(q.y, up * 1e300);
                            Vec2 v{a / 16, b / 16};
                            for (int u = 0; u < std::abs(skew); ++u) v.y = std::nextafter(v.y, skew * 1e300);
                            Scene s;
                            s.frames = 1;
                            s.walls = {w};
                            s.balls = {{q, v, R}};
                            int frame_hits = 0;
                            for (const Event& e : run_scene(s, KernelId::robust, 1)) {
                                if (e.kind != Event::Kind::hit || ++frame_hits > 1) continue;
                                ++hits;
                                const double err = face_contact_error(q, q + v, R, w, e.pos);
                                const double d_inf = std::fmax(std::fabs(v.x), std::fabs(v.y));
                                EXPECT_LE(err, 0x1p-40 * d_inf + 0x1p-50)
                                    << fmt::format("wall {} {} ball {} v {} R {}", w.p0, w.p1, q, v, R);
                            }
                            EXPECT_LT(frame_hits, 16) << fmt::format("wall {} {} ball {} v {} R {}", w.p0, w.p1, q, v, R);
                            EXPECT_EQ(checked(s), "");
                        }
                }
            }
        }
    EXPECT_GT(hits, 900);
    // Random walls (the bench's third kind of grazing leg): B_s and B_e rounded from points of the wall plus R·n̂, so
    // within ulps of tangent in any direction; |n| is irrational and t_f's cancellation deeper than double-double
    // can round, where robust once walked a point it had placed two ulps off the contact back to the leg's start.
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> unit(-1, 1);
    int faces = 0;
    for (int i = 0; i < 3000; ++i) {
        const Wall w{{unit(rng), unit(rng)}, {unit(rng), unit(rng)}};
        const double R = 0.05 + 0.1 * std::fabs(unit(rng));
        const double ex = w.p1.x - w.p0.x, ey = w.p1.y - w.p0.y, len = std::hypot(ex, ey);
        const double nx = ey / len * R, ny = -ex / len * R;
        const double u0 = 0.1 + 0.3 * std::fabs(unit(rng)), u1 = u0 + 0.2 + 0.3 * std::fabs(unit(rng));
        const Vec2 q{w.p0.x + u0 * ex + nx, w.p0.y + u0 * ey + ny};
        const Vec2 b{w.p0.x + u1 * ex + nx, w.p0.y + u1 * ey + ny};
        const Vec2 v = b - q;
        const auto c = disc::first_contact(disc::Leg{q, q + v, R}, w);
        if (!c || c->at_start || c->part != disc::Part::face) continue;
        ++faces;
        Scene s;
        s.frames = 1;
        s.walls = {w};
        s.balls = {{q, v, R}};
        for (const Event& e : run_scene(s, KernelId::robust, 1)) {
            if (e.kind != Event::Kind::hit) continue;
            const double d_inf = std::fmax(std::fabs(v.x), std::fabs(v.y));
            EXPECT_LE(face_contact_error(q, q + v, R, w, e.pos), 0x1p-40 * d_inf + 0x1p-50)
                << fmt::format("wall {} {} ball {} v {} R {}", w.p0, w.p1, q, v, R);
            break;
        }
    }
    EXPECT_GT(faces, 300);
}

TEST(DiscRobust, AGrazingLegThatEndsAtItsRadiusHitsThere) {
    // The bench's disc-grazing case that ran into the bounce limit: the wall along 8-15-17, the disc 2^−55 farther
    // than R from its line, v exactly parallel to it; the leg ends at fl(B + v) = (1.37109375, 0.6875), exactly R
    // from the line, approaching: the exact entry is at t = 1. Robust printed t = 0 sixteen times; now the leg's end,
    // once. (ghost-bounce is left out: it judges the path B + t·v, parallel to the wall, not the leg to fl(B + v)
    // that the kernels step, and fails this hit under exact and robust alike.)
    Scene s;
    s.frames = 1;
    s.walls = {{{1.37890625, 0.984375}, {0.75390625, -0.1875}}};
    s.balls = {{{0.93359375, -0.13281250000000003}, {0.4375, 0.8203125}, 0.1328125}};
    std::vector<std::string> hits;
    for (const Event& e : run_scene(s, KernelId::robust, 1))
        if (e.kind == Event::Kind::hit) hits.push_back(format_event(e));
    EXPECT_EQ(hits, (std::vector<std::string>{"hit 1 0 0 1.37109375 0.6875"}));
    const Check checks[] = {Check::no_tunnel, Check::penetration, Check::speed, Check::no_escape, Check::event_order,
                            Check::deterministic};
    const CheckedRun run = run_checked(s, KernelId::robust, 4, checks);
    EXPECT_FALSE(run.error);
    EXPECT_FALSE(run.failure);
}

TEST(DiscRobust, BumpersWorkedByHand) {
    // A disc of radius 1 from (5, 5) moving (0, −2) onto a bumper of radius 0.5 at (5, 1): frame 2 starts at
    // y = 3, |B − C| = 1.5 at y = 2.5, t = 0.25; the normal (0, 1) sends it back up with the rest, 0.75·2: (5, 4).
    Scene s;
    s.frames = 2;
    s.walls = {{{0, 0}, {10, 0}}};
    s.bumpers = {{{5, 1}, 0.5}};
    s.balls = {{{5, 5}, {0, -2}, 1}, {{5, 5}, {0, -2}, 0}};
    std::vector<std::string> lines;
    for (const Event& e : run_scene(s, KernelId::robust, 2))
        if (e.frame == 2) lines.push_back(format_event(e));
    // The point ball meets it at y = 1.5 (t = 0.75) and goes back up 0.25·2: (5, 2).
    EXPECT_EQ(lines, (std::vector<std::string>{"bump 2 0 0 5 2.5", "state 2 0 5 4 0 2", "bump 2 1 0 5 1.5",
                                               "state 2 1 5 2 0 2"}));
    EXPECT_EQ(checked(s), "");
    // 3-4-5 off centre: R = 2, r = 3, from (−4, 4) moving (8, 0): |X − C|² = 25 at x = −3, t = 1/8, normal
    // (−3, 4)/5: (8, 0) − 2·(−24/5)·(−3, 4)/5 = (8 − 144/25, 192/25) = (2.24, 7.68).
    Scene slant;
    slant.frames = 1;
    slant.bumpers = {{{0, 0}, 3}};
    slant.balls = {{{-4, 4}, {8, 0}, 2}};
    const std::vector<Event> e = run_scene(slant, KernelId::robust, 1);
    ASSERT_EQ(e.size(), 3u);
    EXPECT_EQ(format_event(e[1]), "bump 1 0 0 -3 4");
    EXPECT_NEAR(e[2].vel.x, 2.24, 1e-14);
    EXPECT_NEAR(e[2].vel.y, 7.68, 1e-14);
    EXPECT_EQ(checked(slant), "");
}

TEST(DiscRobust, BumpersInABoxHoldEveryCheck) {
    // Discs and point balls among bumpers (some touching each other or a wall) in a closed box, far from the
    // origin and near it: no tunnel, no penetration, the speed bound and no escape, every frame.
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(0, 1);
    int bumps = 0, point_hits = 0;
    for (int i = 0; i < 12; ++i) {
        Scene s;
        s.frames = 60;
        const double L = std::pow(10.0, -2 + 6 * unit(rng));
        const Vec2 o = i % 2 == 0 ? Vec2{} : Vec2{1e6 + 7 * unit(rng), -3e7};
        const auto at = [&](double x, double y) { return Vec2{o.x + L * x, o.y + L * y}; };
        s.walls = {{at(0, 0), at(0, 1)}, {at(0, 1), at(1, 1)}, {at(1, 1), at(1, 0)}, {at(1, 0), at(0, 0)}};
        for (int k = 0; k < 6; ++k) s.bumpers.push_back({at(0.1 + 0.8 * unit(rng), 0.1 + 0.8 * unit(rng)), L * 0.08 * unit(rng)});
        s.bumpers.push_back({at(0.5, 0), L * 0.1});  // half inside the floor
        for (int b = 0; b < 4; ++b) {
            const double r = b == 0 ? 0.0 : L * std::array{0.01, 0.05, 1e-9}[rng() % 3];
            const double a = 7 * unit(rng), v = L * (0.05 + 0.5 * unit(rng));
            s.balls.push_back({at(0.3 + 0.4 * unit(rng), 0.3 + 0.4 * unit(rng)), {v * std::cos(a), v * std::sin(a)}, r});
        }
        EXPECT_EQ(checked(s), "") << i;
        for (const Event& e : run_scene(s, KernelId::robust, s.frames)) {
            bumps += e.kind == Event::Kind::bump;
            point_hits += e.kind == Event::Kind::hit && e.ball == 0;
        }
    }
    // The scenes do what they are for: many bumps, and the point balls hit walls too.
    EXPECT_GT(bumps, 100);
    EXPECT_GT(point_hits, 20);
}

TEST(DiscRobust, GridScenesFullOfTiesHoldEveryCheck) {
    // Everything on a grid of halves, so that exact ties are everywhere: chains of walls sharing end points
    // (straight, diagonal, 3-4-5), bumpers on grid points (radius 0 too), balls starting at exactly their radius
    // from a wall or inside reach, moving along walls or into corners; point balls among bumpers too.
    std::mt19937 rng(11);
    const auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
    const Vec2 dirs[] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}, {2, 1}, {3, 4}};
    const Vec2 vels[] = {{1, 0}, {0, 1}, {1, 1}, {-1, 0}, {0, -1}, {-1, -1}, {2, 1}, {-3, 4}, {0.5, 0}, {0.75, 1}};
    const double radii[] = {0, 0.5, 1, 0.25, 0.125};
    int hits = 0, bumps = 0;
    for (int i = 0; i < 150; ++i) {
        Scene s;
        s.frames = 20;
        s.walls = {{{0, 0}, {0, 8}}, {{0, 8}, {8, 8}}, {{8, 8}, {8, 0}}, {{8, 0}, {0, 0}}};
        for (int k = pick(11); k > 0; --k) {
            const Vec2 at{static_cast<double>(pick(9)), static_cast<double>(pick(9))}, d = dirs[pick(6)];
            for (int j = pick(3); j >= 0; --j) s.walls.push_back({at + j * d, at + (j + 1) * d});
        }
        for (int k = pick(5); k > 0; --k)
            s.bumpers.push_back({{static_cast<double>(pick(9)), static_cast<double>(pick(9))}, 0.5 * pick(4)});
        for (int k = 1 + pick(4); k > 0; --k)
            s.balls.push_back({{0.5 * pick(17), 0.5 * pick(17)}, std::array{1.0, 2.0, 0.5, 3.0}[pick(4)] * vels[pick(10)],
                               radii[pick(5)]});
        EXPECT_EQ(checked(s), "") << i;
        for (const Event& e : run_scene(s, KernelId::robust, s.frames)) {
            hits += e.kind == Event::Kind::hit;
            bumps += e.kind == Event::Kind::bump;
        }
    }
    EXPECT_GT(hits, 1000);
    EXPECT_GT(bumps, 100);
}

TEST(DiscRobust, HugeAndTinyRadii) {
    // A radius near the accepted limit in a box of that size, and one of 2^−1000 in a box of size 1.
    Scene huge;
    huge.frames = 20;
    const double L = 0x1p250;
    huge.walls = {{{0, 0}, {0, L}}, {{0, L}, {L, L}}, {{L, L}, {L, 0}}, {{L, 0}, {0, 0}}};
    huge.balls = {{{L / 2, L / 2}, {L / 3, L / 7}, L / 5}};
    EXPECT_EQ(checked(huge), "");
    Scene tiny;
    tiny.frames = 20;
    tiny.walls = {{{0, 0}, {0, 1}}, {{0, 1}, {1, 1}}, {{1, 1}, {1, 0}}, {{1, 0}, {0, 0}}};
    tiny.balls = {{{0.5, 0.5}, {0.37, 0.21}, 0x1p-1000}, {{0.25, 0.75}, {-0.3, 0.9}, 0x1p-1074}};
    EXPECT_EQ(checked(tiny), "");
}

TEST(DiscRobust, AStartOverlappingAWallGetsOut) {
    // The disc starts 0.5 deep in the floor's reach, moving further in: it bounces at once, then keeps clear.
    Scene s;
    s.frames = 10;
    s.walls = {{{0, 0}, {10, 0}}, {{0, 5}, {10, 5}}};
    s.balls = {{{5, 0.5}, {0.1, -1}, 1}};
    const std::vector<Event> e = run_scene(s, KernelId::robust, 1);
    ASSERT_GE(e.size(), 3u);
    EXPECT_EQ(format_event(e[1]), "hit 1 0 0 5 0.5");
    EXPECT_EQ(checked(s), "");
}

TEST(DiscRobust, SlidesAlongAChainAtItsRadiusHoldingEveryCheck) {
    // A 3-4-5 chain through (0, 10): the disc of radius 5 moves along (0.75, 1), exactly 5 from the line. Robust
    // makes no hit (harness/tests/disc_checks_test.cpp shows ghost-bounce failing a hit here), and the whole run
    // holds every check.
    Scene s;
    s.frames = 4;
    s.walls = {{{0, 10}, {3, 14}}, {{3, 14}, {6, 18}}};
    s.balls = {{{4, 7}, {0.75, 1}, 5}};
    EXPECT_EQ(checked(s), "");
}

}  // namespace
}  // namespace ricochet
