// Google Benchmark microbenchmarks of the core's hot paths: the orient filter (certain and falling
// back), the robust sweep (uniform and grazing), the batched decisions, step_ball in a closed box.
#include <benchmark/benchmark.h>

#include "ricochet/batch.hpp"
#include "ricochet/predicates.hpp"
#include "workloads.hpp"

namespace {

using namespace ricochet;
using namespace ricochet::bench;

// Queries per workload, a power of two (the loops wrap with a mask). Large on purpose: with 4096
// queries replayed over and over the branch predictor learns the sequence, and lecture-double then
// measures 24 ns instead of 45 ns per sweep (robust 39 instead of 48) on the dev box.
#ifndef RICOCHET_MICRO_N
#define RICOCHET_MICRO_N 65536
#endif
constexpr std::size_t k_n = RICOCHET_MICRO_N;

const SweepWorkload& workload(const char* name) {
    static const std::vector<SweepWorkload> wls = sweep_workloads(k_n, 1);
    for (const SweepWorkload& w : wls)
        if (w.name == name) return w;
    return wls[0];
}

void orient_uniform(benchmark::State& st) {
    const auto& qs = workload("uniform").queries;
    std::size_t i = 0;
    for (auto _ : st) {
        const SweepQuery& q = qs[i++ & (k_n - 1)];
        benchmark::DoNotOptimize(exact::orient(q.wall.p0, q.wall.p1, q.bs));
    }
}
BENCHMARK(orient_uniform);

void orient_on_line(benchmark::State& st) {
    // Be lies on the wall: the filter cannot decide, the expansion fallback does.
    const auto& qs = workload("end-on-wall").queries;
    std::size_t i = 0;
    for (auto _ : st) {
        const SweepQuery& q = qs[i++ & (k_n - 1)];
        benchmark::DoNotOptimize(exact::orient(q.wall.p0, q.wall.p1, q.bs + q.v));
    }
}
BENCHMARK(orient_on_line);

void sweep_kernel(benchmark::State& st, KernelId k, const char* wl) {
    const auto& qs = workload(wl).queries;
    std::size_t i = 0;
    for (auto _ : st) {
        const SweepQuery& q = qs[i++ & (k_n - 1)];
        benchmark::DoNotOptimize(sweep(k, q.bs, q.v, q.wall));
    }
}
BENCHMARK_CAPTURE(sweep_kernel, lecture_double_uniform, KernelId::lecture_double, "uniform");
BENCHMARK_CAPTURE(sweep_kernel, robust_uniform, KernelId::robust, "uniform");
BENCHMARK_CAPTURE(sweep_kernel, robust_grazing, KernelId::robust, "grazing");
BENCHMARK_CAPTURE(sweep_kernel, robust_end_on_wall, KernelId::robust, "end-on-wall");
BENCHMARK_CAPTURE(sweep_kernel, exact_uniform, KernelId::exact, "uniform");

void batch_many_balls(benchmark::State& st) {
    const auto& qs = workload("uniform").queries;
    std::vector<double> x, y, vx, vy;
    for (const SweepQuery& q : qs) x.push_back(q.bs.x), y.push_back(q.bs.y), vx.push_back(q.v.x), vy.push_back(q.v.y);
    std::vector<Miss> out(qs.size());
    std::size_t w = 0;
    for (auto _ : st) {
        sweep_decisions(BallsSoA{x, y, vx, vy}, qs[w++ & (k_n - 1)].wall, out);
        benchmark::DoNotOptimize(out.data());
    }
    st.SetItemsProcessed(static_cast<std::int64_t>(st.iterations() * qs.size()));
}
BENCHMARK(batch_many_balls);

void step_ball_box(benchmark::State& st) {
    const std::vector<Wall> walls = {{{-1, -1}, {1, -1}}, {{1, -1}, {1, 1}}, {{1, 1}, {-1, 1}}, {{-1, 1}, {-1, -1}}};
    Ball b{{0.1, 0.2}, {0.0123456789, 0.00987654321}};
    BallMemory mem;
    StepScratch scratch;
    std::vector<HitEvent> hits;
    for (auto _ : st) {
        hits.clear();
        benchmark::DoNotOptimize(step_ball(KernelId::robust, b, mem, walls, hits, scratch));
    }
    st.SetItemsProcessed(st.iterations());
}
BENCHMARK(step_ball_box);

}  // namespace

BENCHMARK_MAIN();
