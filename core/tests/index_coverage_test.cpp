// The broad-phase indices on small layouts worked by hand: the wall grid (a given cell size, the cell cap,
// the cell budget of a flat box, walls on one line, points it cannot reason about), the wall BVH (leaves, the line test that prunes a box
// the segment's box overlaps), and the static index far from the origin.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "ricochet/bvh.hpp"
#include "ricochet/static_index.hpp"
#include "ricochet/wall_grid.hpp"

namespace ricochet {
namespace {

std::vector<std::uint32_t> query(const WallIndex& index, Vec2 a, Vec2 b) {
    std::vector<std::uint32_t> out;
    index.query(a, b, out);
    return out;
}

std::vector<std::uint32_t> sorted(std::vector<std::uint32_t> v) {
    std::sort(v.begin(), v.end());
    return v;
}

using Ids = std::vector<std::uint32_t>;

// Two unit walls far apart: (0, 0)–(1, 0) and (10, 10)–(11, 10).
const std::vector<Wall> k_two = {{{0, 0}, {1, 0}}, {{10, 10}, {11, 10}}};

TEST(WallGridLayout, AGivenCellSizeSeparatesFarWalls) {
    // Cells of 1 from (−0.5, −0.5): wall 0 lies in row 0, wall 1 in row 10.
    const WallGrid grid(k_two, {.cell_size = 1.0});
    EXPECT_EQ(query(grid, {0.5, -0.3}, {0.5, 0.3}), Ids{0});
    EXPECT_EQ(query(grid, {10.5, 9.7}, {10.5, 10.3}), Ids{1});
    EXPECT_EQ(query(grid, {0, 5}, {0.5, 5.2}), Ids{});
    // The diagonal meets both, each once, in the order of the cells walked (wall 0's first).
    EXPECT_EQ(query(grid, {0, 0}, {11, 10}), (Ids{0, 1}));
    // Entirely outside the grid: nothing.
    EXPECT_EQ(query(grid, {-50, -50}, {-40, -45}), Ids{});
    EXPECT_EQ(query(grid, {50, 0}, {60, 1}), Ids{});
}

TEST(WallGridLayout, PointsTheGridCannotReasonAboutGetEveryWall) {
    const WallGrid grid(k_two);
    EXPECT_EQ(query(grid, {NAN, 0}, {1, 1}), (Ids{0, 1}));
    EXPECT_EQ(query(grid, {0, 0}, {1, INFINITY}), (Ids{0, 1}));
    // Finite, but |a| + |b| overflows: every wall too.
    EXPECT_EQ(query(grid, {1e308, 0}, {-1e308, 0}), (Ids{0, 1}));
}

TEST(WallGridLayout, TheCellCapCoarsensTheGrid) {
    // Cells of 1e-2 over 11 × 10 are 1102 × 1002 (4.4 MB of CSR starts); capped at 100 the side grows by
    // 1.5 until (11/h + 3)(10/h + 3) ≤ 100: h = 0.01·1.5^13 ≈ 1.95, 8 × 7 cells.
    const WallGrid fine(k_two, {.cell_size = 1e-2});
    const WallGrid capped(k_two, {.cell_size = 1e-2, .max_cells = 100});
    EXPECT_GT(fine.bytes(), std::size_t{4} << 20);
    EXPECT_LE(capped.bytes(), 4 * (101 + 2 * 100u));
    // Still the right walls: cells of ~1.95 keep the two walls apart.
    EXPECT_EQ(query(capped, {0.5, -0.3}, {0.5, 0.3}), Ids{0});
    EXPECT_EQ(query(capped, {10.5, 9.7}, {10.5, 10.3}), Ids{1});
}

TEST(WallGridLayout, WallsOnOneLineGetCellsFromTheirLength) {
    // No area: h = length / 4n = 3 / 8; the two walls are 1 apart, several cells.
    const std::vector<Wall> line = {{{0, 0}, {1, 0}}, {{2, 0}, {3, 0}}};
    const WallGrid grid(line);
    EXPECT_EQ(query(grid, {0.5, -1}, {0.5, 1}), Ids{0});
    EXPECT_EQ(query(grid, {2.5, -1}, {2.5, 1}), Ids{1});
    EXPECT_EQ(query(grid, {1.5, -1}, {1.5, 1}), Ids{});
    // A vertical line of walls (no width) likewise.
    const std::vector<Wall> column = {{{0, 0}, {0, 1}}, {{0, 2}, {0, 3}}};
    const WallGrid vertical(column);
    EXPECT_EQ(query(vertical, {-1, 2.5}, {1, 2.5}), Ids{1});
}

TEST(WallGridLayout, AFlatBoxGetsAFewCellsNotMillions) {
    // A box 2^40 wide and 1 tall (the scene fuzz target's boxes come from any two points): √(area / 16)
    // alone gives h = 2^18 and (2^22 + 3)·3 cells, 50 MB of CSR starts for four walls, built again by
    // every World a check makes. The budget, max(64, 16 · 4n) = 256 cells, coarsens it.
    const double w = 0x1p40;
    const std::vector<Wall> box = {{{w, 0}, {0, 0}}, {{w, 1}, {w, 0}}, {{0, 1}, {w, 1}}, {{0, 0}, {0, 1}}};
    const WallGrid grid(box);
    EXPECT_LE(std::size_t{grid.columns()} * grid.rows(), 256u);
    EXPECT_LE(grid.bytes(), 4 * (257 + 256 * 4u));
    // Still conservative: a leg through the bottom wall near each end, and one along the box's middle.
    // Cells about 2^40 / 82 wide: the first column holds the left wall and the two long ones.
    EXPECT_EQ(sorted(query(grid, {0.5, 0.5}, {0.5, -0.5})), (Ids{0, 2, 3}));
    EXPECT_EQ(sorted(query(grid, {w - 0.5, 0.5}, {w - 0.5, -0.5})), (Ids{0, 1, 2}));
    EXPECT_EQ(sorted(query(grid, {0.5, 0.5}, {w - 0.5, 0.5})), (Ids{0, 1, 2, 3}));
    // A cell size the caller gives is kept (up to max_cells): the budget only bounds the chosen one.
    const WallGrid given(box, {.cell_size = 0x1p30});
    EXPECT_EQ(given.columns(), 1026u);
}

TEST(WallGridLayout, ANonPositiveOrNonFiniteCellSizeIsChosenInstead) {
    for (double h : {-1.0, double(NAN), double(INFINITY)}) {
        const WallGrid grid(k_two, {.cell_size = h});
        EXPECT_EQ(grid.bytes(), WallGrid(k_two).bytes()) << h;
        EXPECT_EQ(query(grid, {0.5, -0.3}, {0.5, 0.3}), Ids{0}) << h;
    }
}

TEST(WallGridLayout, ASubnormalCellSizeIsFirstGrownToHaveAFiniteInverse) {
    // 1/2^-1070 overflows; doubling from 2^-1070 the first size with a finite inverse is 2^-1023 (1/2^-1024
    // = 2^1024 still overflows). From there both grids grow alike to fit the cell cap: the same layout.
    const WallGrid sub(k_two, {.cell_size = 0x1p-1070, .max_cells = 1024});
    const WallGrid smallest(k_two, {.cell_size = 0x1p-1023, .max_cells = 1024});
    EXPECT_TRUE(std::isfinite(1.0 / sub.cell_size()));
    EXPECT_EQ(sub.cell_size(), smallest.cell_size());
    EXPECT_EQ(sub.columns(), smallest.columns());
    EXPECT_EQ(sub.rows(), smallest.rows());
    EXPECT_LE(std::size_t{sub.columns()} * sub.rows(), 1024u);
    EXPECT_EQ(sorted(query(sub, {0.5, -0.3}, {0.5, 0.3})), Ids{0});
}

// Two clusters of four walls through (5, 5) and (1005, 5), each in the box [0, 10]² shifted by 0 or
// 1000 in x: the root splits them along x into two leaves of four.
std::vector<Wall> clusters() {
    std::vector<Wall> w;
    for (double dx : {0.0, 1000.0})
        for (Wall s : {Wall{{0, 0}, {10, 10}}, Wall{{0, 10}, {10, 0}}, Wall{{0, 5}, {10, 5}}, Wall{{5, 0}, {5, 10}}})
            w.push_back({{s.p0.x + dx, s.p0.y}, {s.p1.x + dx, s.p1.y}});
    return w;
}

TEST(WallBvhLayout, LeavesOfFourAndTheirBoxes) {
    const WallBvh bvh(clusters());
    EXPECT_EQ(bvh.nodes(), 3u);  // a root and two leaves
    EXPECT_EQ(sorted(query(bvh, {2, -1}, {2, 11})), (Ids{0, 1, 2, 3}));
    EXPECT_EQ(sorted(query(bvh, {1002, -1}, {1002, 11})), (Ids{4, 5, 6, 7}));
    EXPECT_EQ(sorted(query(bvh, {-1, 5}, {1011, 5})), (Ids{0, 1, 2, 3, 4, 5, 6, 7}));
    // Far from both: the root's box alone rejects it.
    EXPECT_EQ(query(bvh, {0, 50}, {10, 60}), Ids{});
}

TEST(WallBvhLayout, TheLineTestPrunesABoxThatOnlyTheSegmentsBoxOverlaps) {
    // (9, 25) → (25, 9) lies on x + y = 34: its box [9, 25]² overlaps the left leaf's [0, 10]², but the
    // box's farthest corner (10, 10) has x + y = 20, so the line misses it.
    const WallBvh bvh(clusters());
    EXPECT_EQ(query(bvh, {9, 25}, {25, 9}), Ids{});
    // On x + y = 19 the line crosses that box: the leaf is returned.
    EXPECT_EQ(sorted(query(bvh, {9, 10}, {10, 9})), (Ids{0, 1, 2, 3}));
}

TEST(WallBvhLayout, ColumnsSplitAlongYAndNonFinitePointsGetEveryWall) {
    // Nine unit walls stacked in y: the centres spread along y only, so every split is along y.
    std::vector<Wall> stack;
    for (int k = 0; k < 9; ++k) stack.push_back({{0, 10.0 * k}, {1, 10.0 * k}});
    const WallBvh bvh(stack);
    // Leaves {0..3}, {4, 5}, {6, 7, 8} (medians of 9 and of 5).
    EXPECT_EQ(bvh.nodes(), 5u);
    EXPECT_EQ(sorted(query(bvh, {0.5, -1}, {0.5, 1})), (Ids{0, 1, 2, 3}));
    EXPECT_EQ(sorted(query(bvh, {0.5, 79}, {0.5, 81})), (Ids{6, 7, 8}));
    EXPECT_EQ(sorted(query(bvh, {NAN, 0}, {0, 0})), (Ids{0, 1, 2, 3, 4, 5, 6, 7, 8}));
    EXPECT_EQ(sorted(query(bvh, {0, 0}, {0, -INFINITY})), (Ids{0, 1, 2, 3, 4, 5, 6, 7, 8}));
    // No walls: no tree, nothing returned.
    const WallBvh none(std::span<const Wall>{});
    EXPECT_EQ(none.nodes(), 0u);
    EXPECT_EQ(query(none, {0, 0}, {1, 1}), Ids{});
}

TEST(StaticIndexLayout, ShapesBeyondTwoToTheHundredArePushedToTheFarRange) {
    // Circle 0 at (2^110, 0) and rect 0 reaching to x = −2^111 + 2^60: their boxes are pushed out to
    // ±2^120, and query points are clamped to the same range, so points past 2^120 still find them; the
    // origin lies in neither box's cells.
    const std::vector<Circle> circles = {{{0x1p110, 0}, 1}};
    const std::vector<Rect> rects = {{-0x1p111, -1, -0x1p111 + 0x1p60, 1}};
    const StaticIndex index(circles, rects);
    ASSERT_FALSE(index.empty());
    const auto far_right = index.query({0x1p130, 0});
    EXPECT_EQ(Ids(far_right.circles.begin(), far_right.circles.end()), Ids{0});
    EXPECT_TRUE(far_right.rects.empty());
    const auto far_left = index.query({-INFINITY, 0});
    EXPECT_TRUE(far_left.circles.empty());
    EXPECT_EQ(Ids(far_left.rects.begin(), far_left.rects.end()), Ids{0});
    // Two statics get a budget of 64 cells: 20 to 30 columns of about 2^116 over [−2^120, 2^120], so the
    // circle's box (from 2^110) and the rect's (to −2^111) both reach the origin's column; halfway out on
    // either side only one of them is a candidate.
    const auto origin = index.query({0, 0});
    EXPECT_EQ(origin.circles.size() + origin.rects.size(), 2u);
    const auto right = index.query({0x1p119, 0}), left = index.query({-0x1p119, 0});
    EXPECT_EQ(Ids(right.circles.begin(), right.circles.end()), Ids{0});
    EXPECT_TRUE(right.rects.empty());
    EXPECT_TRUE(left.circles.empty());
    EXPECT_EQ(Ids(left.rects.begin(), left.rects.end()), Ids{0});
}

TEST(StaticIndexLayout, OneShapeAtAPointAndShapesOnALine) {
    // A radius-0 circle: only its slack, 2^-18·4 + 2^-60 either way, around the point.
    const std::vector<Circle> dot = {{{3, 4}, 0}};
    const StaticIndex one(dot, {});
    EXPECT_EQ(one.query({3, 4}).circles.size(), 1u);
    // Rects of height 0 side by side along y = 0: boxes only their slack tall; each point finds its own.
    const std::vector<Rect> flat = {{0, 0, 1, 0}, {5, 0, 6, 0}};
    const StaticIndex line({}, flat);
    const auto a = line.query({0.5, 0}), b = line.query({5.5, 0});
    EXPECT_EQ(Ids(a.rects.begin(), a.rects.end()), Ids{0});
    EXPECT_EQ(Ids(b.rects.begin(), b.rects.end()), Ids{1});
    EXPECT_TRUE(a.circles.empty());
}

}  // namespace
}  // namespace ricochet

namespace ricochet {
namespace {

TEST(WallGridLayout, WallsBeyondTheRangeWhoseAreaOverflowsStillGetAGrid) {
    // Two walls crossing at the origin, 4e200 across: width·height overflows, so the cell side falls
    // back to 1 and then grows by 1.5 until the cell cap fits; both walls still pass through the origin.
    const std::vector<Wall> huge = {{{-1e200, -1e200}, {1e200, 1e200}}, {{-1e200, 1e200}, {1e200, -1e200}}};
    const WallGrid grid(huge);
    EXPECT_EQ(sorted(query(grid, {-1, 0}, {1, 0})), (Ids{0, 1}));
    EXPECT_LE(grid.bytes(), 4 * ((std::size_t{1} << 24) + 1 + 2 * 4096));
}

TEST(WallGridLayout, AnEmptyGridIgnoresCacheHints) {
    // No cells to fetch from: every stage returns before reading the (empty) cell arrays.
    const WallGrid none(std::span<const Wall>{});
    for (int stage : {0, 1, 2}) none.prefetch({0, 0}, stage, {});
    EXPECT_EQ(none.bytes(), 0u);
}

TEST(StaticIndexLayout, ShapesPastTwoToThe120SitAtTheFarBound) {
    // A circle at (2^200, 2^200): both box ends clamp to 2^120 in x and in y, no width and no height, so
    // one cell of side 1 holds it; a point anywhere finds it (a superset, as the index promises).
    const std::vector<Circle> corner = {{{0x1p200, 0x1p200}, 1}};
    const StaticIndex one(corner, {});
    EXPECT_EQ(one.query({0x1p200, 0x1p200}).circles.size(), 1u);
    EXPECT_EQ(one.query({0, 0}).circles.size(), 1u);
    // With a rect at the origin: x spans the range, y too; the far circle and the rect part ways.
    const std::vector<Circle> far_right = {{{0x1p200, 0}, 1}};
    const StaticIndex two(far_right, std::vector<Rect>{{-1, -1, 1, 1}});
    const auto at_far = two.query({0x1p200, 0}), at_origin = two.query({0, 0});
    EXPECT_EQ(at_far.circles.size(), 1u);
    EXPECT_TRUE(at_far.rects.empty());
    EXPECT_TRUE(at_origin.circles.empty());
    EXPECT_EQ(at_origin.rects.size(), 1u);
}

}  // namespace
}  // namespace ricochet
