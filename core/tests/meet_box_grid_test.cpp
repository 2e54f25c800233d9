// The meet step's broad phase (kernels/meet/box_grid.hpp) against every pair tried: build lists each two boxes
// it enters that overlap exactly once, and query() lists every ball whose current box overlaps the one asked
// about, after boxes entered again with insert(). A pair it missed would be a meet never searched, so this is the
// grid's whole promise. Fixed seeds; box sets like the meet bench's, boxes of every size up to the whole scene, and
// the degenerate extents the grid falls back on (every box one point, a line, boxes reaching infinity).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "kernels/meet/box_grid.hpp"

namespace ricochet::meet {
namespace {

using Pair = std::pair<std::uint32_t, std::uint32_t>;

std::set<Pair> overlapping(const std::vector<Box>& boxes) {
    std::set<Pair> out;
    for (std::uint32_t i = 0; i < boxes.size(); ++i)
        for (std::uint32_t j = i + 1; j < boxes.size(); ++j)
            if (boxes_overlap(boxes[i], boxes[j])) out.insert({i, j});
    return out;
}

/// Builds the grid over boxes and checks the pairs it lists: every overlapping pair once, i < j, no pair twice.
void expect_pairs(BoxGrid& grid, const std::vector<Box>& boxes) {
    std::map<Pair, int> listed;
    grid.build(boxes, [&](std::uint32_t i, std::uint32_t j) {
        EXPECT_LT(i, j);
        ++listed[{i, j}];
    });
    for (const Pair& p : overlapping(boxes)) {
        const auto it = listed.find(p);
        ASSERT_NE(it, listed.end()) << "pair " << p.first << ", " << p.second << " of " << boxes.size() << " missed";
        EXPECT_EQ(it->second, 1) << "pair " << p.first << ", " << p.second << " listed " << it->second << " times";
    }
}

/// Checks query(): every ball whose box in `current` overlaps b is listed.
void expect_query(const BoxGrid& grid, const std::vector<Box>& current, const Box& b) {
    std::set<std::uint32_t> listed;
    grid.query(b, [&](std::uint32_t j) { listed.insert(j); });
    for (std::uint32_t j = 0; j < current.size(); ++j) {
        if (boxes_overlap(current[j], b)) {
            EXPECT_TRUE(listed.count(j)) << "ball " << j << " missed";
        }
    }
}

Box around(Vec2 p, Vec2 q, double r) {
    return {{std::min(p.x, q.x) - r, std::min(p.y, q.y) - r}, {std::max(p.x, q.x) + r, std::max(p.y, q.y) + r}};
}

/// n boxes as the meet bench's paths make them (one disc in each 2 × 2 cell of a lattice, moving up to vmax, padded
/// by r), with a share of them `far` times as long.
std::vector<Box> bench_like(std::size_t n, std::uint64_t seed, double r, double vmax, double long_share, double far) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> at(0.0, 2.0), angle(0.0, 6.283185307179586), speed(0.0, vmax), u(0.0, 1.0);
    const auto m = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(n))));
    std::vector<Box> boxes(n);
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 p{2.0 * static_cast<double>(i % m) + at(rng), 2.0 * static_cast<double>(i / m) + at(rng)};
        const double a = angle(rng), v = speed(rng) * (u(rng) < long_share ? far : 1.0);
        boxes[i] = around(p, p + Vec2{v * std::cos(a), v * std::sin(a)}, r);
    }
    return boxes;
}

TEST(MeetBoxGrid, ListsEveryOverlappingPairOnceOnBenchLikeScenes) {
    BoxGrid grid;  // reused, as a frame reuses it
    for (std::uint64_t seed = 1; seed <= 6; ++seed) {
        expect_pairs(grid, bench_like(900, seed, 0.1, 0.5, 0.0, 1.0));
        expect_pairs(grid, bench_like(900, seed, 0.3, 2.0, 0.0, 1.0));           // crowded: boxes over several cells
        expect_pairs(grid, bench_like(900, seed, 0.1, 0.5, 0.02, 300.0));        // a few reaching over many cells
        expect_pairs(grid, bench_like(900, seed, 0.1, 0.5, 0.02, 3000.0));       // over too many: listed as everywhere
        expect_pairs(grid, bench_like(400, seed, 0.0, 0.5, 0.0, 1.0));           // points
        expect_pairs(grid, bench_like(37, seed, 1e-3, 1e-2, 0.1, 1e5));          // few balls, one crossing all
    }
}

TEST(MeetBoxGrid, FallsBackOnDegenerateExtents) {
    BoxGrid grid;
    const double inf = std::numeric_limits<double>::infinity();
    // Every box one point (no extent, so no cell size): one cell, everyone.
    expect_pairs(grid, std::vector<Box>(50, Box{{3.0, 4.0}, {3.0, 4.0}}));
    // All on a horizontal line, as points and as segments.
    std::vector<Box> line;
    for (int i = 0; i < 200; ++i) line.push_back({{0.5 * i, 7.0}, {0.5 * i + (i % 3), 7.0}});
    expect_pairs(grid, line);
    // A box reaching infinity among ordinary ones, and one far out.
    std::vector<Box> boxes = bench_like(300, 9, 0.1, 0.5, 0.0, 1.0);
    boxes[17] = {{-inf, 3.0}, {5.0, 3.5}};
    boxes[200] = {{1e300, 1e300}, {1e300, 1e300}};
    expect_pairs(grid, boxes);
    // Two boxes each over too many cells (listed as reaching everywhere), overlapping each other and the rest.
    boxes = bench_like(300, 10, 0.1, 0.5, 0.0, 1.0);
    boxes[3] = {{-1.0, -1.0}, {40.0, 40.0}};
    boxes[250] = {{0.0, 0.0}, {39.0, 39.0}};
    expect_pairs(grid, boxes);
    // One ball, and none.
    expect_pairs(grid, {Box{{0.0, 0.0}, {1.0, 1.0}}});
    expect_pairs(grid, {});
}

TEST(MeetBoxGrid, QueryListsEveryOverlappingBallAfterInserts) {
    std::mt19937_64 rng(5);
    for (const double far : {1.0, 300.0}) {
        std::vector<Box> boxes = bench_like(900, 11, 0.1, 0.5, 0.05, far);
        BoxGrid grid;
        grid.build(boxes);
        EXPECT_EQ(grid.inserted(), 0u);
        std::uniform_int_distribution<std::uint32_t> ball(0, 899);
        std::uniform_real_distribution<double> coord(-5.0, 65.0), len(0.0, 3.0);
        for (int step = 0; step < 400; ++step) {
            // A meet's two balls: new paths, entered again (their old entries stay, stale).
            for (int k = 0; k < 2; ++k) {
                const std::uint32_t i = ball(rng);
                const Vec2 p{coord(rng), coord(rng)};
                boxes[i] = around(p, p + Vec2{len(rng), -len(rng)} * (step % 50 == 0 ? 40.0 : 1.0), 0.1);
                const std::size_t before = grid.inserted();
                grid.insert(i, boxes[i]);
                EXPECT_GE(grid.inserted(), before + 1);  // at least one entry (a cell, or everywhere)
            }
            // Built afresh over the current boxes, as the meet step does once the entries made since are many.
            if (step % 100 == 99) {
                grid.build(boxes);
                EXPECT_EQ(grid.inserted(), 0u);
            }
            const Vec2 p{coord(rng), coord(rng)};
            expect_query(grid, boxes, around(p, p + Vec2{len(rng), len(rng)}, 0.1));
            expect_query(grid, boxes, boxes[ball(rng)]);
        }
        // Far outside the grid on every side: clamped to its border cells.
        expect_query(grid, boxes, Box{{-1e9, -1e9}, {1e9, -1e8}});
        expect_query(grid, boxes, Box{{-1e9, -1e9}, {1e9, 1e9}});
    }
}

}  // namespace
}  // namespace ricochet::meet
