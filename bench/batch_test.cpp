// The batched decisions must equal sweep(robust)'s, lane for lane, on the inputs where the filter
// is least sure: legs ending on the wall, aimed at its end points, grazing, tiny motions, far away.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

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

const SweepWorkload& workload(const std::vector<SweepWorkload>& wls, const std::string& name) {
    for (const SweepWorkload& wl : wls)
        if (wl.name == name) return wl;
    throw std::runtime_error("no workload " + name);
}

/// q scaled by 2^k: exact while nothing under- or overflows, so a leg ending a rounding away from its wall's line
/// stays that close at every scale; where the scaling rounds, the scaled query is just another degenerate input.
SweepQuery scaled(const SweepQuery& q, int k) {
    const auto s = [k](Vec2 p) { return Vec2{std::ldexp(p.x, k), std::ldexp(p.y, k)}; };
    return {s(q.bs), s(q.v), Wall{s(q.wall.p0), s(q.wall.p1)}};
}

/// Many balls against one wall, every leg ending on it (as the bench's batch rows): every lane degenerate.
std::vector<SweepQuery> one_wall(const char* kind, std::size_t n, std::uint64_t seed) {
    const Wall w{{-0.7 + 0.01 * static_cast<double>(seed), 0.3}, {0.9, -0.55 + 0.02 * static_cast<double>(seed)}};
    return one_wall_workload(kind, w, n, seed).queries;
}

TEST(Batch, EqualsRobustOnLegsEndingOnTheWallAtEveryScale) {
    // The lanes the filter declines and the second stage decides (batch.cpp), from subnormal to near overflow:
    // scales where that stage's guards (|l| + |r| in [2^-900, 2^900]) send lanes on to the exact predicates too.
    const std::vector<SweepWorkload> wls = sweep_workloads(32, 5);
    std::vector<std::pair<std::string, std::vector<SweepQuery>>> sets;
    for (const char* name : {"end-on-wall", "at-endpoint", "grazing"}) sets.emplace_back(name, workload(wls, name).queries);
    for (const char* kind : {"end-on-wall", "grazing"}) sets.emplace_back(std::string(kind) + " one wall", one_wall(kind, 40, 3));
    for (const auto& [name, queries] : sets)
        for (int k = -1074; k <= 1020; k += 53) {
            SCOPED_TRACE(name + " scaled by 2^" + std::to_string(k));
            std::vector<SweepQuery> qs;
            for (const SweepQuery& q : queries) qs.push_back(scaled(q, k));
            expect_same(qs, 8);
        }
}

TEST(Batch, TheSecondStageDecidesLegsEndingOnTheWall) {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
    if (!__builtin_cpu_supports("avx512f")) GTEST_SKIP() << "no AVX-512F: every pair takes the exact predicates";
#else
    GTEST_SKIP() << "not x86-64: every pair takes the exact predicates";
#endif
    // Many balls against one wall, every end point the double nearest a point of the wall: the filter alone leaves
    // about 70 % of these lanes to the exact predicates; with the second stage a lane goes there only if the
    // stage's bound cannot place it. A count, not a time: the same inputs give the same count on every AVX-512F
    // machine.
    std::size_t slow = 0, lanes = 0;
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
        const std::vector<SweepQuery> qs = one_wall("end-on-wall", 1024, seed);
        std::vector<double> x, y, vx, vy;
        for (const SweepQuery& q : qs) x.push_back(q.bs.x), y.push_back(q.bs.y), vx.push_back(q.v.x), vy.push_back(q.v.y);
        std::vector<Miss> out(qs.size());
        slow += sweep_decisions(BallsSoA{x, y, vx, vy}, qs[0].wall, out);
        lanes += qs.size();
        for (std::size_t i = 0; i < qs.size(); ++i)
            ASSERT_EQ(out[i], sweep(KernelId::robust, qs[i].bs, qs[i].v, qs[i].wall).miss) << "seed " << seed << " ball " << i;
    }
    EXPECT_LE(slow * 100, lanes) << slow << " of " << lanes << " lanes left to the exact predicates";
}

}  // namespace
}  // namespace ricochet::bench
