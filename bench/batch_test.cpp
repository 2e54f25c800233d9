// The batched decisions must equal sweep(robust)'s, lane for lane, on the inputs where the filter
// is least sure: legs ending on the wall, aimed at its end points, grazing, tiny motions, far away.
#include <gtest/gtest.h>

#include "ricochet/batch.hpp"
#include "workloads.hpp"

namespace ricochet::bench {
namespace {

void expect_same(const std::vector<SweepQuery>& qs, std::size_t walls) {
    const std::size_t n = qs.size();
    std::vector<double> x(n), y(n), vx(n), vy(n), x0(n), y0(n), x1(n), y1(n);
    for (std::size_t i = 0; i < n; ++i) {
        x[i] = qs[i].bs.x, y[i] = qs[i].bs.y, vx[i] = qs[i].v.x, vy[i] = qs[i].v.y;
        x0[i] = qs[i].wall.p0.x, y0[i] = qs[i].wall.p0.y, x1[i] = qs[i].wall.p1.x, y1[i] = qs[i].wall.p1.y;
    }
    std::vector<Miss> out(n);
    // Each query's own wall, as one ball against many walls (the diagonal pairs are the degenerate ones).
    for (std::size_t i = 0; i < n; ++i) {
        sweep_decisions(qs[i].bs, qs[i].v, WallsSoA{x0, y0, x1, y1}, out);
        for (std::size_t j = 0; j < std::min(n, walls); ++j)
            ASSERT_EQ(out[j], sweep(KernelId::robust, qs[i].bs, qs[i].v, qs[j].wall).miss) << "ball " << i << " wall " << j;
        ASSERT_EQ(out[i], sweep(KernelId::robust, qs[i].bs, qs[i].v, qs[i].wall).miss) << "ball " << i << " own wall";
    }
    // Many balls against one wall: every query's wall in turn.
    for (std::size_t w = 0; w < n; ++w) {
        sweep_decisions(BallsSoA{x, y, vx, vy}, qs[w].wall, out);
        ASSERT_EQ(out[w], sweep(KernelId::robust, qs[w].bs, qs[w].v, qs[w].wall).miss) << "wall " << w;
        if (w < walls) {
            for (std::size_t i = 0; i < n; ++i)
                ASSERT_EQ(out[i], sweep(KernelId::robust, qs[i].bs, qs[i].v, qs[w].wall).miss) << "ball " << i << " wall " << w;
        }
    }
}

TEST(Batch, EqualsRobustOnEveryWorkload) {
    // 203 queries: not a multiple of the 8 lanes, so the tail path is covered too.
    for (const SweepWorkload& wl : sweep_workloads(203, 77)) {
        SCOPED_TRACE(wl.name);
        expect_same(wl.queries, 16);
    }
}

TEST(Batch, EqualsRobustOnExactlyDegenerateLegs) {
    std::vector<SweepQuery> qs;
    const Wall w{{0, 0}, {4, 2}};
    // Both ends on the line, start on it and leave, end exactly on P0 / P1 / the middle, zero motion,
    // zero-length wall, through an end point exactly.
    qs.push_back({{-2, -1}, {4, 2}, w});
    qs.push_back({{2, 1}, {1, -3}, w});
    qs.push_back({{0, 3}, {0, -3}, w});
    qs.push_back({{4, 5}, {0, -3}, w});
    qs.push_back({{2, 5}, {0, -4}, w});
    qs.push_back({{1, 1}, {0, 0}, w});
    qs.push_back({{1, 1}, {1, -2}, Wall{{3, 3}, {3, 3}}});
    qs.push_back({{-1, 1}, {2, -2}, w});
    qs.push_back({{3, 3}, {2, -2}, w});
    qs.push_back({{5, 0}, {-2, 4}, w});
    qs.push_back({{1e300, 1e300}, {-1e300, -1e300}, w});
    qs.push_back({{1e-310, 3e-310}, {2e-310, -4e-310}, Wall{{0, 0}, {4e-310, 2e-310}}});
    expect_same(qs, qs.size());
}

}  // namespace
}  // namespace ricochet::bench
