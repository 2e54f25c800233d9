// The speed targets' verdicts (bench_targets.hpp, ricochet_bench/targets.hpp) on rows made by hand: the bound itself
// is met, the next double past it missed, a row the run lacks "not measured", and the peers read from their rows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench_targets.hpp"

namespace ricochet::bench {
namespace {

Row row(std::string kind, std::string workload, std::string method, double ns, double ratio, long tunnels = -1,
        long conv = -1) {
    Row r;
    r.kind = std::move(kind), r.workload = std::move(workload), r.method = std::move(method);
    r.ns = ns, r.ratio = ratio, r.tunnels = tunnels, r.conv = conv;
    return r;
}

const Verdict& named(const std::vector<Verdict>& vs, const std::string& workload) {
    for (const Verdict& v : vs)
        if (v.workload == workload) return v;
    throw std::runtime_error("no target " + workload);
}

TEST(Targets, TheBoundIsMetAndTheNextDoublePastItMissed) {
    const std::vector<Row> rows{
        row("sweep", "uniform", "robust", 20.0, 1.2),
        row("sweep", "end-on-wall", "robust", 40.0, std::nextafter(1.5, 2.0)),
        row("box", "box-turned", "robust", 100.0, 1.49, 0),
        row("batch", "end-on-wall-pairs", "robust-batch", 10.0, 0.1, -1, 700),
        row("batch", "uniform-pairs", "robust-batch", std::nextafter(1.5, 2.0), 0.04),
    };
    const std::vector<Verdict> vs = bench_targets(rows);
    ASSERT_EQ(vs.size(), 14u);
    EXPECT_EQ(verdict_word(named(vs, "sweep, uniform")), "met");
    EXPECT_EQ(verdict_word(named(vs, "sweep, end on the wall")), "**missed**");
    EXPECT_EQ(verdict_word(named(vs, "closed box, turned")), "met");
    EXPECT_EQ(named(vs, "closed box, turned").robust, "100.0 ns per ball-frame, 0 tunnels");
    EXPECT_EQ(named(vs, "closed box, turned").ratio, "1.49×");
    EXPECT_EQ(verdict_word(named(vs, "batch, end-on-wall pairs")), "met");
    EXPECT_EQ(named(vs, "batch, end-on-wall pairs").robust, "10.0 ns per pair, 70.0 % of lanes to the exact predicates");
    EXPECT_EQ(verdict_word(named(vs, "batch, uniform pairs")), "**missed**");
    // Rows the run lacks, and a lecture-double missing from a workload (no ratio): not measured, never met.
    EXPECT_EQ(verdict_word(named(vs, "closed box")), "not measured");
    EXPECT_FALSE(met(named(vs, "closed box")));
    EXPECT_EQ(verdict_word(named(vs, "static point/circle, boundary-heavy")), "not measured");
}

TEST(Targets, DiscRowsAreJudgedFromTheDiscTable) {
    const std::vector<Row> discs{
        row("disc", "disc-uniform", "robust", 130.0, 2.0),
        row("disc", "disc-grazing", "robust", 400.0, std::nextafter(4.0, 5.0)),
        row("disc", "disc-cap", "robust", 300.0, 3.5),
        row("disc", "disc-cap", "box2d", 700.0, 7.12),
    };
    // The disc workloads are read from the disc rows only: the same rows among the point rows judge nothing.
    EXPECT_EQ(verdict_word(named(bench_targets(discs), "discs, uniform")), "not measured");
    const std::vector<Verdict> vs = bench_targets(std::vector<Row>{}, discs);
    EXPECT_EQ(verdict_word(named(vs, "discs, uniform")), "met");
    EXPECT_EQ(named(vs, "discs, uniform").ratio, "2.00×");
    EXPECT_EQ(verdict_word(named(vs, "discs, grazing")), "**missed**");
    EXPECT_EQ(verdict_word(named(vs, "discs, caps")), "met");
    EXPECT_EQ(named(vs, "discs, caps").peers, "Box2D 2.4.1 7.12×");
    EXPECT_EQ(verdict_word(named(vs, "discs among bumpers")), "not measured");
}

TEST(Targets, ASpeedUpIsMetFromBelowItsBound) {
    Verdict v{.workload = "2 threads against 1", .value = 1.96, .limit = 1.96, .at_least = true, .target = "≥ 1.96×"};
    EXPECT_TRUE(met(v));
    v.value = std::nextafter(1.96, 0.0);
    EXPECT_FALSE(met(v));
    v.value = NAN;
    EXPECT_EQ(verdict_word(v), "not measured");
}

TEST(Targets, PeersComeFromTheirOwnRowsWithTheirTunnels) {
    const std::vector<Row> rows{
        row("box", "box", "robust", 118.0, 1.45, 0),
        row("box", "box", "lecture-double", 81.0, 1.0, 8000),
        row("box", "box", "box2d", 150.0, 1.84, 24),
        row("box", "box", "cgal", 90.0, 1.1, 10000),
        row("sweep", "uniform", "robust", 21.8, 0.64),
        row("sweep", "uniform", "chipmunk", 60.0, 1.75),
    };
    const std::vector<Verdict> vs = bench_targets(rows);
    EXPECT_EQ(named(vs, "closed box").peers, "Box2D 2.4.1 1.84× (24 tunnels), CGAL 5.5 1.10× (10000 tunnels)");
    EXPECT_EQ(named(vs, "sweep, uniform").peers, "Chipmunk 7 1.75×");
    EXPECT_EQ(named(vs, "sweep, at an end point").peers, "");
}

TEST(Targets, TheMarkdownHasAHeaderAndALinePerTarget) {
    const std::vector<Verdict> vs = bench_targets(std::vector<Row>{row("sweep", "uniform", "robust", 20.0, 1.3)});
    const std::string md = targets_markdown(vs);
    EXPECT_EQ(md.rfind("| workload | robust | ÷ lecture-double | target | verdict | peers in the same run |\n", 0), 0u);
    EXPECT_EQ(std::count(md.begin(), md.end(), '\n'), 16);
    EXPECT_NE(md.find("| sweep, uniform | 20.0 ns | 1.30× | ≤ 1.2× | **missed** | – |\n"), std::string::npos);
    EXPECT_NE(md.find("| closed box | – | – | ≤ 1.5× | not measured | – |\n"), std::string::npos);
}

}  // namespace
}  // namespace ricochet::bench
