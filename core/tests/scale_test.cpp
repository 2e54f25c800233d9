// The broad phase and the threads change nothing: World with BroadPhase::none on one thread and World
// with the wall grid (or the BVH) on N threads give the same events and run hash, for lecture-double
// and robust (and lecture-float and exact with the rules World picks for them), on random
// mazes, closed boxes, random segment soups and far-from-origin copies, with balls aimed at wall end
// points and corners. And the index contract itself: every wall that meets a segment is returned.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "ricochet/bvh.hpp"
#include "ricochet/hash.hpp"
#include "ricochet/predicates.hpp"
#include "ricochet/static_index.hpp"
#include "ricochet/wall_grid.hpp"
#include "ricochet/world.hpp"

namespace ricochet {
namespace {

using Rng = std::mt19937_64;

double uniform(Rng& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

/// A maze on an n×n lattice of pitch 1 with a closed border; each inner lattice edge a wall with
/// probability 0.5; balls at random points and aimed through lattice vertices (wall end points,
/// corners), some ending exactly on one.
Scene maze(Rng& rng, int n, int balls, double offset) {
    Scene s;
    const auto at = [&](int x, int y) { return Vec2{offset + x, offset + y}; };
    for (int i = 0; i < n; ++i) {
        s.walls.push_back({at(i, 0), at(i + 1, 0)});
        s.walls.push_back({at(n, i), at(n, i + 1)});
        s.walls.push_back({at(i + 1, n), at(i, n)});
        s.walls.push_back({at(0, i + 1), at(0, i)});
    }
    std::bernoulli_distribution coin(0.5);
    for (int x = 0; x < n; ++x)
        for (int y = 1; y < n; ++y) {
            if (coin(rng)) s.walls.push_back({at(x, y), at(x + 1, y)});
            if (coin(rng)) s.walls.push_back({at(y, x), at(y, x + 1)});
        }
    std::uniform_int_distribution<int> vertex(1, n - 1);
    for (int b = 0; b < balls; ++b) {
        Ball ball;
        switch (b % 3) {
            case 0:  // anywhere, any direction, up to 1.5 cells a frame
                ball.pos = {offset + uniform(rng, 0.01, n - 0.01), offset + uniform(rng, 0.01, n - 0.01)};
                ball.vel = {uniform(rng, -1.5, 1.5), uniform(rng, -1.5, 1.5)};
                break;
            case 1: {  // ends its first frame exactly on a lattice vertex (dyadic offsets: exact sums)
                const Vec2 v = at(vertex(rng), vertex(rng));
                const Vec2 d{std::ldexp(std::floor(uniform(rng, -64, 64)), -7), std::ldexp(std::floor(uniform(rng, -64, 64)), -7)};
                ball.pos = v + d;
                ball.vel = -d;
                break;
            }
            default: {  // passes through a lattice vertex mid-frame
                const Vec2 v = at(vertex(rng), vertex(rng));
                const Vec2 d{std::ldexp(std::floor(uniform(rng, -64, 64)), -7), std::ldexp(std::floor(uniform(rng, -64, 64)), -7)};
                ball.pos = v + d;
                ball.vel = -2.0 * d;
                break;
            }
        }
        s.balls.push_back(ball);
    }
    return s;
}

/// A closed convex polygon (k sides, random rotation) around the origin with balls inside, some
/// aimed at its corners, some at rest.
Scene closed_box(Rng& rng, int sides, int balls, double scale) {
    Scene s;
    const double phase = uniform(rng, 0, 6.283185307179586);
    std::vector<Vec2> corner;
    for (int i = 0; i < sides; ++i) {
        const double a = phase + 6.283185307179586 * i / sides;
        corner.push_back({scale * std::cos(a), scale * std::sin(a)});
    }
    // Counter-clockwise corners: p_i → p_{i+1} has its normal (e_y, −e_x) pointing outward.
    for (int i = 0; i < sides; ++i) s.walls.push_back({corner[i], corner[(i + 1) % sides]});
    for (int b = 0; b < balls; ++b) {
        Ball ball;
        ball.pos = {uniform(rng, -0.5, 0.5) * scale, uniform(rng, -0.5, 0.5) * scale};
        if (b % 4 == 1) {
            ball.vel = 0.7 * (corner[b % sides] - ball.pos);  // through a corner in two frames
        } else if (b % 4 == 2) {
            ball.vel = corner[b % sides] - ball.pos;  // to a corner, rounded
        } else if (b % 8 == 3) {
            ball.vel = {};  // at rest
        } else {
            ball.vel = {uniform(rng, -0.8, 0.8) * scale, uniform(rng, -0.8, 0.8) * scale};
        }
        s.balls.push_back(ball);
    }
    return s;
}

/// Random segments of all lengths and directions in a square, with circles and rectangles.
Scene soup(Rng& rng, int walls, int balls) {
    Scene s;
    for (int i = 0; i < walls; ++i) {
        const Vec2 p{uniform(rng, 0, 100), uniform(rng, 0, 100)};
        const double len = std::exp(uniform(rng, std::log(0.1), std::log(60.0)));
        const double a = uniform(rng, 0, 6.283185307179586);
        s.walls.push_back({p, p + Vec2{len * std::cos(a), len * std::sin(a)}});
    }
    for (int i = 0; i < walls / 8; ++i) s.circles.push_back({{uniform(rng, 0, 100), uniform(rng, 0, 100)}, uniform(rng, 0, 6)});
    for (int i = 0; i < walls / 8; ++i) {
        const double x = uniform(rng, 0, 100), y = uniform(rng, 0, 100);
        s.rects.push_back({x, y, x + uniform(rng, 0, 9), y + uniform(rng, 0, 9)});
    }
    std::uniform_int_distribution<int> pick(0, walls - 1);
    for (int b = 0; b < balls; ++b) {
        Ball ball{{uniform(rng, 0, 100), uniform(rng, 0, 100)}, {uniform(rng, -4, 4), uniform(rng, -4, 4)}};
        if (b % 3 == 1) ball.vel = s.walls[pick(rng)].p0 - ball.pos;  // ends on a wall's end point
        if (b % 3 == 2) ball.vel = 1.5 * (s.walls[pick(rng)].p1 - ball.pos);  // through one
        s.balls.push_back(ball);
    }
    return s;
}

std::vector<Event> run_world(const Scene& scene, KernelId k, std::int64_t frames, WorldOptions options) {
    World world(scene, k, options);
    std::vector<Event> events;
    world.start(events);
    for (std::int64_t f = 0; f < frames; ++f) world.step(events);
    return events;
}

/// The reference: every wall tried, every shape tested, one thread.
constexpr WorldOptions k_plain{.broad_phase = BroadPhase::none, .threads = 1};

/// World with broad phase b on t threads.
constexpr WorldOptions with(BroadPhase b, unsigned t) { return {.broad_phase = b, .threads = t}; }

/// The first event where a and b differ, for the failure message.
std::string first_difference(const std::vector<Event>& a, const std::vector<Event>& b) {
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
        if (!(a[i] == b[i])) return fmt::format("event {}: {} vs {}", i, format_event(a[i]), format_event(b[i]));
    return fmt::format("lengths {} vs {}", a.size(), b.size());
}

/// Brute force on one thread, the grid on 1 and 3 threads, the BVH, and brute force on 3 threads agree.
void expect_same_runs(const Scene& scene, KernelId k, std::int64_t frames) {
    const std::vector<Event> brute = run_world(scene, k, frames, k_plain);
    std::size_t hits = 0;
    for (const Event& e : brute) hits += e.kind == Event::Kind::hit;
    const auto with_grid = run_world(scene, k, frames, with(BroadPhase::grid, 1));
    const auto with_bvh = run_world(scene, k, frames, with(BroadPhase::bvh, 1));
    const auto scaled1 = run_world(scene, k, frames, {});  // the defaults: the grid, one thread
    const auto scaled3 = run_world(scene, k, frames, with(BroadPhase::grid, 3));
    const auto brute3 = run_world(scene, k, frames, with(BroadPhase::none, 3));
    ASSERT_GT(hits, 0u) << "the scene must bounce for the comparison to mean something";
    const std::uint64_t h = hash_events(brute);
    EXPECT_EQ(hash_events(with_grid), h) << first_difference(brute, with_grid);
    EXPECT_EQ(hash_events(with_bvh), h) << first_difference(brute, with_bvh);
    EXPECT_EQ(hash_events(scaled1), h) << first_difference(brute, scaled1);
    EXPECT_EQ(hash_events(scaled3), h) << first_difference(brute, scaled3);
    EXPECT_EQ(hash_events(brute3), h) << first_difference(brute, brute3);
    EXPECT_EQ(brute, scaled3);
}

class ScaleKernels : public ::testing::TestWithParam<KernelId> {};

TEST_P(ScaleKernels, MazesSameBitsWithAndWithoutBroadPhase) {
    Rng rng(7);
    for (int round = 0; round < 3; ++round) expect_same_runs(maze(rng, 12 + 6 * round, 300, 0.0), GetParam(), 60);
}

TEST_P(ScaleKernels, MazesFarFromOriginSameBits) {
    Rng rng(8);
    expect_same_runs(maze(rng, 10, 200, 0x1p30), GetParam(), 40);
    expect_same_runs(maze(rng, 10, 200, -1e9), GetParam(), 40);
}

TEST_P(ScaleKernels, ClosedBoxesSameBits) {
    Rng rng(9);
    for (int sides : {3, 4, 7, 32}) expect_same_runs(closed_box(rng, sides, 200, 10.0), GetParam(), 80);
    expect_same_runs(closed_box(rng, 5, 100, 1e-6), GetParam(), 80);
    expect_same_runs(closed_box(rng, 6, 100, 1e12), GetParam(), 80);
}

TEST_P(ScaleKernels, SegmentSoupWithShapesSameBits) {
    Rng rng(10);
    expect_same_runs(soup(rng, 400, 300), GetParam(), 40);
}

INSTANTIATE_TEST_SUITE_P(Kernels, ScaleKernels, ::testing::Values(KernelId::lecture_double, KernelId::robust),
                         [](const ::testing::TestParamInfo<KernelId>& p) {
                             return std::string(p.param == KernelId::robust ? "robust" : "lecture_double");
                         });

/// scene's balls as discs of radius r (a few at rest, a few as points), with k bumpers at random points of the
/// scene's box, radii up to 2r.
Scene as_discs(Rng& rng, Scene s, double r, int bumpers) {
    double lo = s.walls[0].p0.x, hi = lo;
    for (const Wall& w : s.walls)
        for (double c : {w.p0.x, w.p0.y, w.p1.x, w.p1.y}) {
            lo = std::min(lo, c);
            hi = std::max(hi, c);
        }
    for (std::size_t i = 0; i < s.balls.size(); ++i) s.balls[i].r = i % 7 == 3 ? 0.0 : r;
    for (int k = 0; k < bumpers; ++k)
        s.bumpers.push_back({{uniform(rng, lo, hi), uniform(rng, lo, hi)}, uniform(rng, 0.0, 2.0 * r)});
    return s;
}

TEST_P(ScaleKernels, DiscsAndBumpersSameBitsWithAndWithoutBroadPhase) {
    // A disc tries the walls and bumpers the indices say may come within its radius (query_near): the same events
    // as trying them all, with discs of a tenth and of a third of a cell, and far from the origin.
    Rng rng(17);
    expect_same_runs(as_discs(rng, maze(rng, 10, 120, 0.0), 0.1, 0), GetParam(), 30);
    expect_same_runs(as_discs(rng, maze(rng, 10, 120, 0.0), 0.3, 12), GetParam(), 30);
    expect_same_runs(as_discs(rng, maze(rng, 8, 80, 0x1p30), 0.25, 6), GetParam(), 20);
    expect_same_runs(as_discs(rng, closed_box(rng, 7, 60, 10.0), 0.5, 5), GetParam(), 40);
}

TEST(Scale, LectureFloatWithFloatMargin) {
    // lecture-float rounds to 2^-24: World gives its grid k_float_margin, and the grid still returns
    // every wall it can hit.
    Rng rng(11);
    const Scene s = maze(rng, 12, 200, 0.0);
    const auto brute = run_world(s, KernelId::lecture_float, 40, k_plain);
    EXPECT_EQ(hash_events(run_world(s, KernelId::lecture_float, 40, {})), hash_events(brute));
    EXPECT_EQ(hash_events(run_world(s, KernelId::lecture_float, 40, with(BroadPhase::grid, 2))), hash_events(brute));
}

TEST(Scale, ExactKernelWithBroadPhaseAndThreads) {
    Rng rng(12);
    const Scene s = closed_box(rng, 5, 30, 10.0);
    EXPECT_EQ(World(s, KernelId::exact).wall_index(), nullptr);  // exact tries every wall: no grid built
    EXPECT_EQ(hash_events(run_world(s, KernelId::exact, 10, with(BroadPhase::grid, 2))),
              hash_events(run_world(s, KernelId::exact, 10, k_plain)));
}

TEST(Scale, ThreadCountsAllGiveTheSameHash) {
    Rng rng(13);
    const Scene s = maze(rng, 30, 2000, 0.0);
    const std::uint64_t one = hash_events(run_world(s, KernelId::robust, 30, with(BroadPhase::grid, 1)));
    for (unsigned t : {2u, 3u, 4u, 7u, 16u})
        EXPECT_EQ(hash_events(run_world(s, KernelId::robust, 30, with(BroadPhase::grid, t))), one) << t << " threads";
}

TEST(Scale, BigGridWithCacheHintsSameBits) {
    // A 176 000-wall maze: the grid is past the size where World issues cache hints.
    Rng rng(16);
    const Scene s = maze(rng, 420, 3000, 0.0);
    const WallGrid grid(s.walls);
    ASSERT_GT(grid.bytes() + s.walls.size() * sizeof(Wall), std::size_t{8} << 20);
    // The reference without cache hints: the BVH (brute force would take minutes here).
    const auto plain = run_world(s, KernelId::robust, 8, with(BroadPhase::bvh, 1));
    EXPECT_EQ(hash_events(run_world(s, KernelId::robust, 8, with(BroadPhase::grid, 1))), hash_events(plain));
    EXPECT_EQ(hash_events(run_world(s, KernelId::robust, 8, with(BroadPhase::grid, 2))), hash_events(plain));
}

/// Closed segments ab and pq meet (exactly).
bool segments_meet(Vec2 a, Vec2 b, Vec2 p, Vec2 q) {
    const int o1 = exact::orient(a, b, p), o2 = exact::orient(a, b, q);
    const int o3 = exact::orient(p, q, a), o4 = exact::orient(p, q, b);
    const auto within = [](Vec2 u, Vec2 v, Vec2 x) {
        return std::min(u.x, v.x) <= x.x && x.x <= std::max(u.x, v.x) && std::min(u.y, v.y) <= x.y &&
               x.y <= std::max(u.y, v.y);
    };
    if (o1 * o2 < 0 && o3 * o4 < 0) return true;
    return (o1 == 0 && within(a, b, p)) || (o2 == 0 && within(a, b, q)) || (o3 == 0 && within(p, q, a)) ||
           (o4 == 0 && within(p, q, b));
}

TEST(Scale, IndexReturnsEveryWallTheSegmentMeetsEachOnce) {
    Rng rng(14);
    for (double scale : {1e-3, 1.0, 1e6}) {
        const Scene s = soup(rng, 600, 0);
        std::vector<Wall> walls;
        for (const Wall& w : s.walls) walls.push_back({scale * w.p0, scale * w.p1});
        const WallGrid grid(walls);
        const WallBvh bvh(walls);
        std::uniform_int_distribution<std::size_t> pick(0, walls.size() - 1);
        std::vector<std::uint32_t> got;
        std::size_t meets = 0;
        for (int i = 0; i < 3000; ++i) {
            Vec2 a{uniform(rng, -5, 105) * scale, uniform(rng, -5, 105) * scale};
            Vec2 b = a + Vec2{uniform(rng, -8, 8) * scale, uniform(rng, -8, 8) * scale};
            const Wall& w = walls[pick(rng)];
            // Touching cases: ending on an end point, on a point of the wall, starting on one.
            if (i % 4 == 1) b = w.p0;
            if (i % 4 == 2) b = w.p0 + 0.37 * (w.p1 - w.p0);
            if (i % 4 == 3) a = w.p1;
            for (const WallIndex* index : {static_cast<const WallIndex*>(&grid), static_cast<const WallIndex*>(&bvh)}) {
                got.clear();
                index->query(a, b, got);
                std::vector<std::uint32_t> sorted = got;
                std::sort(sorted.begin(), sorted.end());
                ASSERT_TRUE(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()) << "a wall twice";
                for (std::uint32_t k = 0; k < walls.size(); ++k) {
                    if (!segments_meet(a, b, walls[k].p0, walls[k].p1)) continue;
                    if (index == &grid) ++meets;
                    ASSERT_TRUE(std::binary_search(sorted.begin(), sorted.end(), k))
                        << "wall " << k << " meets the segment but was not returned (scale " << scale << ")";
                }
            }
        }
        EXPECT_GT(meets, 3000u);  // the touching cases alone give one each
    }
}

/// The distance between the closed segments ab and pq, in doubles (for a test that keeps clear of its rounding).
double segment_distance(Vec2 a, Vec2 b, Vec2 p, Vec2 q) {
    if (segments_meet(a, b, p, q)) return 0.0;
    const auto to_segment = [](Vec2 x, Vec2 u, Vec2 v) {
        const Vec2 d = v - u;
        const double dd = dot(d, d);
        const double t = dd > 0.0 ? std::clamp(dot(x - u, d) / dd, 0.0, 1.0) : 0.0;
        return length(x - (u + t * d));
    };
    return std::min({to_segment(a, p, q), to_segment(b, p, q), to_segment(p, a, b), to_segment(q, a, b)});
}

TEST(Scale, IndexNearReturnsEveryWallWithinTheRadius) {
    // query_near(a, b, r) returns every wall whose segment comes within r of the segment a → b: clearly within
    // (the doubles' distance below r by a margin), and exactly at r (walls a dyadic r away along an axis, from
    // the segment's side and from its end). r = 0 asks what query does.
    Rng rng(18);
    for (double scale : {1e-3, 1.0, 1e6}) {
        const Scene s = soup(rng, 500, 0);
        std::vector<Wall> walls;
        for (const Wall& w : s.walls) walls.push_back({scale * w.p0, scale * w.p1});
        const WallGrid grid(walls);
        const WallBvh bvh(walls);
        std::vector<std::uint32_t> got, plain;
        std::size_t within = 0;
        for (int i = 0; i < 1500; ++i) {
            const Vec2 a{uniform(rng, -5, 105) * scale, uniform(rng, -5, 105) * scale};
            const Vec2 b = a + Vec2{uniform(rng, -8, 8) * scale, uniform(rng, -8, 8) * scale};
            const double r = std::ldexp(std::floor(uniform(rng, 0, 64)), -4) * scale;  // 0 to 4 cells or so
            for (const WallIndex* index : {static_cast<const WallIndex*>(&grid), static_cast<const WallIndex*>(&bvh)}) {
                got.clear();
                index->query_near(a, b, r, got);
                std::vector<std::uint32_t> sorted = got;
                std::sort(sorted.begin(), sorted.end());
                ASSERT_TRUE(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()) << "a wall twice";
                for (std::uint32_t k = 0; k < walls.size(); ++k) {
                    if (segment_distance(a, b, walls[k].p0, walls[k].p1) > r * (1 - 1e-9)) continue;
                    if (index == &grid) ++within;
                    ASSERT_TRUE(std::binary_search(sorted.begin(), sorted.end(), k))
                        << "wall " << k << " comes within " << r << " of the segment but was not returned";
                }
                if (r == 0.0) {
                    plain.clear();
                    index->query(a, b, plain);
                    EXPECT_EQ(got, plain);
                }
            }
        }
        EXPECT_GT(within, 3000u);
        // Exactly r away: a horizontal leg y = 0 from x = 0 to 10 (scaled) and walls at y = ±r above its middle, and
        // beyond its end at x = 10 + r.
        const double r = 0.75 * scale;
        const std::vector<Wall> at_r = {{{2 * scale, r}, {3 * scale, r}},
                                        {{4 * scale, -r}, {4 * scale, -5 * scale}},
                                        {{10 * scale + r, 0}, {11 * scale, 3 * scale}}};
        const WallGrid g(at_r);
        const WallBvh v(at_r);
        for (const WallIndex* index : {static_cast<const WallIndex*>(&g), static_cast<const WallIndex*>(&v)}) {
            got.clear();
            index->query_near({0, 0}, {10 * scale, 0}, r, got);
            std::sort(got.begin(), got.end());
            EXPECT_EQ(got, (std::vector<std::uint32_t>{0, 1, 2})) << "scale " << scale;
        }
    }
}

TEST(Scale, CopiesOfALongWallStayWithinTheReferenceBudget) {
    // 20 000 copies of one diagonal: with four cells per wall each copy would cross ~280 columns (5.6·10^6
    // references, quadratic in the count); the chosen cells grow until the references fit the budget, and a leg
    // across the diagonal still gets every copy.
    const std::vector<Wall> copies(20000, Wall{{0, 0}, {1, 1}});
    const WallGrid grid(copies);
    EXPECT_LE(grid.references(), k_max_references_per_wall * copies.size());
    std::vector<std::uint32_t> got;
    grid.query({0.25, 0.75}, {0.75, 0.25}, got);
    EXPECT_EQ(got.size(), copies.size());
    // A cell size the caller gives is kept (a caller that wants a fine grid pays for it).
    const std::vector<Wall> few(3, Wall{{0, 0}, {1, 1}});
    EXPECT_EQ(WallGrid(few, {.cell_size = 0x1p-10}).cell_size(), 0x1p-10);
}

TEST(Scale, StaticIndexReturnsEveryShapeHoldingThePoint) {
    Rng rng(15);
    const Scene s = soup(rng, 800, 0);
    const StaticIndex index(s.circles, s.rects);
    for (int i = 0; i < 20000; ++i) {
        Vec2 p{uniform(rng, -5, 105), uniform(rng, -5, 105)};
        // Boundary points: on a circle's rim (rounded) and on a rectangle's corner.
        if (i % 3 == 1) {
            const Circle& c = s.circles[static_cast<std::size_t>(i) % s.circles.size()];
            p = c.c + Vec2{c.r, 0.0};
        }
        if (i % 3 == 2) {
            const Rect& r = s.rects[static_cast<std::size_t>(i) % s.rects.size()];
            p = {r.right, r.top};
        }
        const auto c = index.query(p);
        for (KernelId k : {KernelId::lecture_float, KernelId::robust}) {
            for (std::uint32_t j = 0; j < s.circles.size(); ++j)
                if (point_in_circle(k, p, s.circles[j])) {
                    ASSERT_TRUE(std::binary_search(c.circles.begin(), c.circles.end(), j));
                }
            for (std::uint32_t j = 0; j < s.rects.size(); ++j)
                if (point_in_rect(k, p, s.rects[j])) {
                    ASSERT_TRUE(std::binary_search(c.rects.begin(), c.rects.end(), j));
                }
        }
    }
}

TEST(Scale, EmptyAndDegenerateScenes) {
    const WallGrid none(std::span<const Wall>{});
    std::vector<std::uint32_t> out;
    none.query({0, 0}, {1, 1}, out);
    EXPECT_TRUE(out.empty());
    // Every wall at one point: the grid still answers, and a segment through that point gets them.
    const std::vector<Wall> dots(5, Wall{{3, 3}, {3, 3}});
    const WallGrid grid(dots);
    grid.query({0, 0}, {6, 6}, out);
    EXPECT_EQ(out.size(), 5u);
    out.clear();
    grid.query({0, 0}, {1, 0}, out);
    EXPECT_TRUE(out.empty());
    const StaticIndex statics({}, {});
    EXPECT_TRUE(statics.empty());
    EXPECT_TRUE(statics.query({1, 2}).circles.empty());
}

}  // namespace
}  // namespace ricochet
