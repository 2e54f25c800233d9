// The other kernels' discs: lecture-float and lecture-double (kernels/lecture/lecture_disc.hpp) agree with robust where
// a contact is well conditioned and fail on the degenerate cases they were written to fail on; exact
// (kernels/exact/exact_disc.cpp) takes robust's decisions, leg for leg, on the disc corpus and on random scenes, rounds
// its contact points to the nearest double unless that one is not clear (checked against a 1024-bit
// computation), and holds every disc check.
#include <gtest/gtest.h>

#include <gmpxx.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>
#include <string>
#include <variant>

#include <fmt/format.h>

#include "kernels/disc/contact.hpp"
#include "ricochet/checks.hpp"
#include "ricochet/kernel.hpp"
#include "ricochet/scene_log.hpp"
#include "ricochet/step_trace.hpp"
#include "ricochet/world.hpp"

namespace ricochet {
namespace {

const Check k_disc_checks[] = {Check::no_tunnel, Check::penetration, Check::speed, Check::no_escape,
                               Check::event_order, Check::deterministic, Check::ghost_bounce};

/// The first failure of scene under kernel k with every disc check, as "CHECK F", or "" if none.
std::string first_failure(const Scene& scene, KernelId k) {
    const CheckedRun run = run_checked(scene, k, scene.frames, k_disc_checks);
    if (run.error) return run.error->message();
    return run.failure ? fmt::format("{} {}", check_name(run.failure->check), run.failure->frame) : "";
}

/// One frame of ball under k among the scene's obstacles, traced.
struct Stepped {
    Ball ball;
    std::vector<HitEvent> hits;
    StepTrace trace;
    FrameStatus status = FrameStatus::ok;
};
Stepped step(KernelId k, Ball ball, const Scene& s) {
    Stepped out;
    BallMemory memory;
    StepScratch scratch;
    scratch.trace = &out.trace;
    out.status = step_ball(k, ball, memory, Obstacles{s.walls, s.bumpers, nullptr}, out.hits, scratch);
    out.ball = ball;
    return out;
}

/// |a − b|∞ relative to scale.
double off(Vec2 a, Vec2 b, double scale) { return std::fmax(std::fabs(a.x - b.x), std::fabs(a.y - b.y)) / scale; }

// --- lecture ----------------------------------------------------------------------------------------------------

TEST(DiscLecture, AgreesWithRobustWhereTheContactIsWellConditioned) {
    // A disc of radius 0.5…1.5 from 3…5 away meeting the middle of a long wall at a steep angle, or a bumper nearly
    // head on: one hit, the same wall or bumper as robust, B_i and v′ within float's or double's few ulps.
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0, 1);
    double worst_double = 0, worst_float = 0;
    for (int i = 0; i < 1000; ++i) {
        Scene s;
        s.frames = 1;
        const double a = 2 * std::numbers::pi * unit(rng);
        const Vec2 u{std::cos(a), std::sin(a)}, n{-u.y, u.x};  // along the wall, and towards the ball
        const Vec2 c{20 * (unit(rng) - 0.5), 20 * (unit(rng) - 0.5)};
        const double R = 0.5 + unit(rng), dist = 2 + unit(rng), along = 4 * (unit(rng) - 0.5);
        const double vn = 4 + 2 * unit(rng), vt = 2 * (unit(rng) - 0.5);
        const Vec2 start = c + (dist + R) * n + along * u;
        const Vec2 v = -vn * n + vt * u;
        if (i % 2 == 0) {
            s.walls = {{c - 10.0 * u, c + 10.0 * u}};
        } else {
            // A bumper of radius r in the way, 1 to 1.5 ahead, hit within a quarter of its reach of the centre line.
            const double r = 0.25 + unit(rng);
            s.bumpers = {{start + (R + r + 0.5 * dist) * (v * (1.0 / std::sqrt(dot(v, v)))) + (0.25 * (R + r) * (unit(rng) - 0.5)) * u, r}};
        }
        s.balls = {{start, v, R}};
        const Stepped robust = step(KernelId::robust, s.balls[0], s);
        ASSERT_EQ(robust.hits.size(), 1u) << i;
        for (const KernelId k : {KernelId::lecture_double, KernelId::lecture_float}) {
            const Stepped lecture = step(k, s.balls[0], s);
            ASSERT_EQ(lecture.hits.size(), 1u) << i << kernel_name(k);
            EXPECT_EQ(lecture.hits[0].wall, robust.hits[0].wall);
            EXPECT_EQ(lecture.hits[0].bumper, robust.hits[0].bumper);
            const double e = std::fmax(off(lecture.hits[0].point, robust.hits[0].point, 20),
                                       std::fmax(off(lecture.ball.pos, robust.ball.pos, 20),
                                                 off(lecture.ball.vel, robust.ball.vel, std::sqrt(dot(v, v)))));
            (k == KernelId::lecture_double ? worst_double : worst_float) =
                std::fmax(k == KernelId::lecture_double ? worst_double : worst_float, e);
        }
    }
    // Relative to the scene's size and the speed: double within 2^−40, float within 2^−14.
    EXPECT_LT(worst_double, 0x1p-40);
    EXPECT_LT(worst_float, 0x1p-14);
    EXPECT_GT(worst_float, 0.0);  // float does round: the comparison is not of one computation with itself
    fmt::print("lecture against robust, 1000 well-conditioned contacts: worst relative difference {:.3g} (double), "
               "{:.3g} (float)\n", worst_double, worst_float);
}

/// A degenerate case: a scene, the lecture kernel that fails on it and its first failure.
struct Degenerate {
    const char* what;
    Scene scene;
    KernelId kernel;
    const char* failure;
};

Scene scene(std::int64_t frames, std::vector<Wall> walls, std::vector<Ball> balls, std::vector<Bumper> bumpers = {}) {
    Scene s;
    s.frames = frames;
    s.walls = std::move(walls);
    s.balls = std::move(balls);
    s.bumpers = std::move(bumpers);
    return s;
}

TEST(DiscLecture, FailsOnTheDegenerateCases) {
    // The cases of replays/discs/lecture/, built here by hand: each lecture kernel breaks the named check at the
    // named frame, and robust and exact hold every disc check on the same scene.
    const Degenerate cases[] = {
        {"a cap's rounded root inside the cap", scene(1, {{{0, 14}, {0, 18}}}, {{{1, 9}, {0, 1}, 5}}),
         KernelId::lecture_double, "penetration 1"},
        {"a sloped face's rounded t_i beyond the shifted line", scene(1, {{{100, 3}, {0, 0}}}, {{{38, 0}, {-7, 0}, 1}}),
         KernelId::lecture_double, "penetration 1"},
        {"a bumper's rounded root inside R + r", scene(1, {}, {{{13, 18}, {1, -3}, 1}}, {{{14, 14}, 1}}),
         KernelId::lecture_double, "penetration 1"},
        {"a ghost bounce at a joint of a 3-4-5 chain", scene(3, {{{0, 10}, {3, 14}}, {{3, 14}, {6, 18}}}, {{{4, 7}, {0.75, 1}, 5}}),
         KernelId::lecture_double, "penetration 3"},
        {"out of an acute wedge in float",
         scene(5, {{{0, 0}, {100, 3}}, {{100, -3}, {0, 0}}, {{100, 3}, {100, -3}}}, {{{60, 0.1}, {-7.3, 0.01}, 1}}),
         KernelId::lecture_float, "no-tunnel 5"},
    };
    for (const Degenerate& c : cases) {
        SCOPED_TRACE(c.what);
        // The lecture's first failure, under its one check (as the log lists it).
        const Check only[] = {c.failure[0] == 'n' ? Check::no_tunnel : Check::penetration};
        const CheckedRun run = run_checked(c.scene, c.kernel, c.scene.frames, only);
        ASSERT_TRUE(run.failure.has_value());
        EXPECT_EQ(fmt::format("{} {}", check_name(run.failure->check), run.failure->frame), c.failure);
        EXPECT_EQ(first_failure(c.scene, KernelId::robust), "");
        EXPECT_EQ(first_failure(c.scene, KernelId::exact), "");
    }
    // The ghost bounce itself, along a straight chain at exactly R: robust never hits, lecture-double takes the
    // joint's tangent caps for hits, bouncing between the two walls at the joint until the bounce limit.
    const Scene chain = scene(1, {{{-10, 0}, {-7, 0}}, {{-7, 0}, {-6, 0}}}, {{{-9, 1}, {2.25, 0}, 1}});
    EXPECT_TRUE(step(KernelId::robust, chain.balls[0], chain).hits.empty());
    const Stepped ghost = step(KernelId::lecture_double, chain.balls[0], chain);
    EXPECT_EQ(ghost.status, FrameStatus::bounce_limit);
    EXPECT_EQ(ghost.ball.pos, (Vec2{-7, 1}));
}

// --- exact ------------------------------------------------------------------------------------------------------

/// Random scenes for exact against robust: a box (near the origin or far from it) with bumpers and a chain of
/// split walls inside, discs of radii from 10^−9 to 0.3 of the box and point balls.
std::vector<Scene> random_scenes(int count, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    std::vector<Scene> out;
    for (int i = 0; i < count; ++i) {
        Scene s;
        s.frames = 30;
        const double L = std::pow(10.0, -2 + 6 * unit(rng));
        const Vec2 o = i % 2 == 0 ? Vec2{} : Vec2{1e6 + 7 * unit(rng), -3e7};
        const auto at = [&](double x, double y) { return Vec2{o.x + L * x, o.y + L * y}; };
        s.walls = {{at(0, 0), at(0, 1)}, {at(0, 1), at(1, 1)}, {at(1, 1), at(1, 0)}, {at(1, 0), at(0, 0)}};
        // A bent chain across the middle, sharing end points.
        const double y0 = 0.3 + 0.4 * unit(rng), y1 = 0.3 + 0.4 * unit(rng);
        s.walls.push_back({at(0.2, y0), at(0.5, y0)});
        s.walls.push_back({at(0.5, y0), at(0.8, y1)});
        for (int k = 0; k < 4; ++k) s.bumpers.push_back({at(0.1 + 0.8 * unit(rng), 0.1 + 0.8 * unit(rng)), L * 0.08 * unit(rng)});
        for (int b = 0; b < 4; ++b) {
            const double r = b == 0 ? 0.0 : L * std::array{0.01, 0.05, 0.3, 1e-9}[rng() % 4];
            const double a = 7 * unit(rng), v = L * (0.05 + 0.5 * unit(rng));
            s.balls.push_back({at(0.3 + 0.4 * unit(rng), 0.1 + 0.1 * unit(rng)), {v * std::cos(a), v * std::sin(a)}, r});
        }
        out.push_back(std::move(s));
    }
    return out;
}

/// The disc corpus (replays/discs/*.scene, robust's logs).
std::vector<Scene> corpus() {
    std::vector<Scene> out;
    std::vector<std::filesystem::path> paths;
    for (const auto& e : std::filesystem::directory_iterator(RICOCHET_REPLAYS_DIR "/discs"))
        if (e.path().extension() == ".scene") paths.push_back(e.path());
    std::sort(paths.begin(), paths.end());
    for (const auto& p : paths) {
        auto r = read_scene_log(p);
        if (auto* s = std::get_if<Scene>(&r)) out.push_back(std::move(*s));
        else ADD_FAILURE() << p;
    }
    return out;
}

/// What exact and robust decided on the same frames: frames compared, frames with a hit, and first hit points
/// that the two rounded differently.
struct Agreement {
    int frames = 0, hits = 0, points_differ = 0;
};

/// Steps every ball of s along robust's path, and from each of its states one frame under both kernels: the
/// first leg's decisions (every wall, in order, hit or not), the wall it took, the first event's obstacle, and
/// the whole frame's decisions when both printed the same first point.
void compare_decisions(const Scene& s, Agreement& a) {
    for (std::size_t i = 0; i < s.balls.size(); ++i) {
        Ball state = s.balls[i];
        for (std::int64_t f = 1; f <= s.frames; ++f) {
            const Stepped r = step(KernelId::robust, state, s), e = step(KernelId::exact, state, s);
            ++a.frames;
            if (!r.trace.legs.empty() && !e.trace.legs.empty()) {
                const TracedLeg &lr = r.trace.legs[0], &le = e.trace.legs[0];
                EXPECT_EQ(lr.from, le.from);
                EXPECT_EQ(lr.to, le.to);
                EXPECT_EQ(lr.hit, le.hit) << f;
                ASSERT_EQ(lr.decision_count, le.decision_count);
                for (std::uint32_t d = 0; d < lr.decision_count; ++d) {
                    EXPECT_EQ(r.trace.decisions[lr.first_decision + d].wall, e.trace.decisions[le.first_decision + d].wall);
                    EXPECT_EQ(r.trace.decisions[lr.first_decision + d].miss, e.trace.decisions[le.first_decision + d].miss);
                }
            } else {
                EXPECT_EQ(r.trace.legs.size(), e.trace.legs.size());
            }
            ASSERT_EQ(r.hits.empty(), e.hits.empty()) << "frame " << f << " ball " << i;
            if (!r.hits.empty()) {
                ++a.hits;
                EXPECT_EQ(r.hits[0].wall, e.hits[0].wall);
                EXPECT_EQ(r.hits[0].bumper, e.hits[0].bumper);
                if (r.hits[0].point != e.hits[0].point) {
                    ++a.points_differ;
                } else if (r.ball.vel == e.ball.vel && r.hits.size() == e.hits.size()) {
                    // The same first point and bounce: every later leg starts alike and is decided alike.
                    for (std::size_t h = 0; h < r.hits.size(); ++h) {
                        EXPECT_EQ(r.hits[h].wall, e.hits[h].wall);
                        EXPECT_EQ(r.hits[h].bumper, e.hits[h].bumper);
                    }
                }
            }
            state = r.ball;
        }
    }
}

TEST(DiscExact, DecidesAsRobustOnTheCorpusAndOnRandomScenes) {
    Agreement a;
    const std::vector<Scene> logs = corpus();
    EXPECT_GE(logs.size(), 6u);
    for (const Scene& s : logs) compare_decisions(s, a);
    for (const Scene& s : random_scenes(16, 23)) compare_decisions(s, a);
    // The comparison has something to compare: many frames with hits.
    EXPECT_GT(a.frames, 2000);
    EXPECT_GT(a.hits, 300);
    fmt::print("exact against robust: {} frames, {} with a hit, {} first hit points rounded differently\n", a.frames,
               a.hits, a.points_differ);
}

TEST(DiscExact, HoldsEveryDiscCheckOnTheCorpusAndOnRandomScenes) {
    for (const Scene& s : corpus()) EXPECT_EQ(first_failure(s, KernelId::exact), "");
    for (const Scene& s : random_scenes(16, 29)) EXPECT_EQ(first_failure(s, KernelId::exact), "");
}

/// x is the double nearest to exact (ties either way): no neighbour of x is closer.
bool nearest(double x, const mpf_class& exact) {
    const mpf_class d0 = abs(mpf_class(x, 1100) - exact);
    for (const double n : {std::nextafter(x, -INFINITY), std::nextafter(x, INFINITY)})
        if (abs(mpf_class(n, 1100) - exact) < d0) return false;
    return true;
}
/// The double nearest to exact: mpf's truncation or a neighbour of it.
double nearest_to(const mpf_class& exact) {
    double x = exact.get_d();
    for (int k = 0; k < 2 && !nearest(x, exact); ++k) x = std::nextafter(x, mpf_class(x, 1100) < exact ? INFINITY : -INFINITY);
    return x;
}

TEST(DiscExact, ContactPointsAndBouncesAreTheNearestDoubles) {
    // One leg onto a long wall's face or onto a bumper, its exact contact point X* = q + t*·(b − q) computed in
    // 1024-bit floating point (t* from contact.hpp's formulas, √ the only rounding): exact prints the nearest
    // double to each coordinate unless the piece to that point is not clear (then it walked back, and that point
    // is not clear: checked); robust, which rounds t first, misses the nearest more often. And v′ is the nearest
    // double to the exact reflection about the normal at the printed point.
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> unit(0, 1);
    int cases = 0, exact_nearest = 0, robust_nearest = 0, walked = 0;
    for (int i = 0; i < 2000; ++i) {
        const double a = 2 * std::numbers::pi * unit(rng);
        const Vec2 u{std::cos(a), std::sin(a)}, n{-u.y, u.x};
        const Vec2 c{std::ldexp(unit(rng), static_cast<int>(rng() % 40)), std::ldexp(unit(rng) - 0.5, static_cast<int>(rng() % 40))};
        const double L = std::ldexp(1.0 + unit(rng), static_cast<int>(rng() % 20) - 10);
        const double R = L * (0.05 + 0.3 * unit(rng));
        const Vec2 q = c + (L * (1 + unit(rng)) + R) * n + (L * (unit(rng) - 0.5)) * u;
        const Vec2 v = (-L * (2 + unit(rng))) * n + (L * (unit(rng) - 0.5)) * u;
        Scene s;
        s.frames = 1;
        const bool face = i % 2 == 0;
        if (face) s.walls = {{c - (4 * L) * u, c + (4 * L) * u}};
        else s.bumpers = {{c, L * 0.5 * unit(rng)}};
        s.balls = {{q, v, R}};
        const Stepped e = step(KernelId::exact, s.balls[0], s), r = step(KernelId::robust, s.balls[0], s);
        if (e.hits.empty()) continue;
        // X* on the leg q → b (b = q + v as the frame computes it).
        const Vec2 b = q + 1.0 * v;
        const mpf_class qx(q.x, 1100), qy(q.y, 1100), dx = mpf_class(b.x, 1100) - qx, dy = mpf_class(b.y, 1100) - qy;
        mpf_class t(0, 1100);
        if (face) {
            // t_f = (s·n·w − R·|n|)/(−s·n·d), n = (e_y, −e_x), w = q − P0
            const Wall& w = s.walls[0];
            const mpf_class ex = mpf_class(w.p1.x, 1100) - w.p0.x, ey = mpf_class(w.p1.y, 1100) - w.p0.y;
            const mpf_class nx = ey, ny = -ex;
            const mpf_class nw = nx * (qx - w.p0.x) + ny * (qy - w.p0.y), nd = nx * dx + ny * dy;
            const int side = sgn(nw);
            const auto ct = disc::first_contact({q, b, R}, w);
            ASSERT_TRUE(ct.has_value());
            if (ct->part != disc::Part::face) continue;
            t = (side * nw - R * sqrt(nx * nx + ny * ny)) / (-side * nd);
        } else {
            // t_c = (−β − √Δ)/a
            const Bumper& bu = s.bumpers[0];
            const mpf_class px = qx - bu.c.x, py = qy - bu.c.y, rho = mpf_class(R, 1100) + bu.r;
            const mpf_class beta = dx * px + dy * py, aa = dx * dx + dy * dy, gamma = px * px + py * py - rho * rho;
            t = (-beta - sqrt(beta * beta - aa * gamma)) / aa;
        }
        const mpf_class X = qx + t * dx, Y = qy + t * dy;
        ++cases;
        const Vec2 x = e.hits[0].point;
        // The bounce: v′ = v − 2(v·N)N/(N·N) about the exact normal at the printed x (the wall's n, or x − C),
        // each coordinate the nearest double.
        mpf_class nx(0, 1100), ny(0, 1100);
        if (face) {
            nx = mpf_class(s.walls[0].p1.y, 1100) - s.walls[0].p0.y;
            ny = mpf_class(s.walls[0].p0.x, 1100) - s.walls[0].p1.x;
        } else {
            nx = mpf_class(x.x, 1100) - s.bumpers[0].c.x;
            ny = mpf_class(x.y, 1100) - s.bumpers[0].c.y;
        }
        const mpf_class k = 2 * (v.x * nx + v.y * ny) / (nx * nx + ny * ny);
        ASSERT_EQ(e.hits.size(), 1u);
        EXPECT_TRUE(nearest(e.ball.vel.x, v.x - k * nx) && nearest(e.ball.vel.y, v.y - k * ny)) << i;
        const bool exact_is_nearest = nearest(x.x, X) && nearest(x.y, Y);
        exact_nearest += exact_is_nearest;
        robust_nearest += nearest(r.hits[0].point.x, X) && nearest(r.hits[0].point.y, Y);
        if (!exact_is_nearest) {
            // Walked back: the nearest point's piece is not clear.
            ++walked;
            const Vec2 best{nearest_to(X), nearest_to(Y)};
            const disc::Obstacle o = face ? disc::Obstacle{&s.walls[0], {}, 0.0} : disc::Obstacle{nullptr, s.bumpers[0].c, s.bumpers[0].r};
            EXPECT_TRUE(nearest(best.x, X) && nearest(best.y, Y));
            EXPECT_FALSE(disc::piece_clear(q, best, R, o)) << i;
        }
    }
    EXPECT_GT(cases, 1500);
    EXPECT_GT(exact_nearest, robust_nearest);
    fmt::print("contact points: {} cases; exact the nearest doubles in {} ({} walked back), robust in {}\n", cases,
               exact_nearest, walked, robust_nearest);
}

}  // namespace
}  // namespace ricochet
