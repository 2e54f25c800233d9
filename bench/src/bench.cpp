// The benchmark driver: every method on the same fixed-seed query sets; errors against the exact
// kernel; ns per query as the median over repetitions of a throughput loop; ratios against
// lecture-double timed in the same repetitions (interleaved, so machine noise hits both alike).
#include "ricochet_bench/bench.hpp"

#include <algorithm>
#include <chrono>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <numbers>
#include <optional>

#include <fmt/format.h>

#include "bench_targets.hpp"
#include "disc_score.hpp"
#include "disc_workloads.hpp"
#include "methods.hpp"
#include "ricochet_bench/result_file.hpp"
#include "ricochet/batch.hpp"
#include "ricochet/predicates.hpp"
#include "ricochet/tunnel.hpp"
#include "row.hpp"
#include "workloads.hpp"

namespace ricochet::bench {
namespace {

/// The calling thread's CPU time: on a machine shared with other jobs, time spent descheduled is not
/// the method's cost, so every figure is CPU time of this thread (CLOCK_THREAD_CPUTIME_ID), not wall time.
struct Clock {
    using time_point = double;
    static double now() {
        timespec ts{};
        clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
        return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
    }
};

double seconds_since(Clock::time_point t0) { return Clock::now() - t0; }

double median(std::vector<double> v) {
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    const std::size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

/// One ulp of x: the gap from |x| to the next double up (the smallest subnormal at 0).
double ulp(double x) {
    const double a = std::fabs(x);
    if (a == 0.0) return std::numeric_limits<double>::denorm_min();
    return std::nextafter(a, INFINITY) - a;
}

/// Keeps the compiler from discarding a result.
volatile double g_sink = 0.0;

struct Sizes {
    std::size_t queries;
    int reps;
    std::size_t balls;
    long frames;
};

Sizes sizes(const Options& o) {
    if (o.smoke) return {400, 1, 4, 300};
    if (o.quick) return {50000, 5, 16, 2000};
    return {200000, 7, 64, 20000};
}

std::string cell(long v) { return v < 0 ? "-" : fmt::format("{}", v); }
std::string cell(double v, const char* f = "{:.3g}") {
    return std::isnan(v) ? "-" : fmt::format(fmt::runtime(f), v);
}

void print_table(const std::vector<Row>& rows) {
    fmt::print("{:<7} {:<17} {:<15} {:>9} {:>7} {:>6} {:>6} {:>6} {:>10} {:>10} {:>10} {:>10} {:>7} {:>7} {:>9}\n", "kind",
               "workload", "method", "ns/query", "x lec-d", "FN", "FP", "conv", "t err ulp1", "t err abs", "pt err ulpS",
               "pt err abs", "tunnels", "escaped", "drift");
    std::string last;
    for (const Row& r : rows) {
        if (r.workload != last) fmt::print("{}\n", std::string(143, '-'));
        last = r.workload;
        fmt::print("{:<7} {:<17} {:<15} {:>9} {:>7} {:>6} {:>6} {:>6} {:>10} {:>10} {:>10} {:>10} {:>7} {:>7} {:>9}\n", r.kind,
                   r.workload, r.method, cell(r.ns, "{:.1f}"), cell(r.ratio, "{:.2f}"), cell(r.fn), cell(r.fp),
                   cell(r.conv), cell(r.t_ulps), cell(r.t_abs), cell(r.p_ulps), cell(r.p_abs), cell(r.tunnels),
                   cell(r.escaped), cell(r.drift));
    }
}

void write_csv(const std::vector<Row>& rows, const std::string& path) {
    ResultFile f(path);
    f.print("kind,workload,method,n,ns_per_query,ratio_lecture_double,false_negatives,false_positives,convention,"
            "max_t_err_ulps,max_t_err_abs,max_point_err_ulps,max_point_err_abs,tunnels,escaped,speed_drift\n");
    auto num = [](double v) { return std::isnan(v) ? std::string() : fmt::format("{}", v); };
    auto cnt = [](long v) { return v < 0 ? std::string() : fmt::format("{}", v); };
    for (const Row& r : rows)
        f.print("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", r.kind, r.workload, r.method, r.n, num(r.ns),
                num(r.ratio), cnt(r.fn), cnt(r.fp), cnt(r.conv), num(r.t_ulps), num(r.t_abs), num(r.p_ulps),
                num(r.p_abs), cnt(r.tunnels), cnt(r.escaped), num(r.drift));
    f.close();
}

void print_disc_table(const std::vector<Row>& rows) {
    fmt::print("{:<7} {:<13} {:<15} {:>9} {:>7} {:>6} {:>6} {:>6} {:>7} {:>7} {:>10} {:>10}\n", "kind", "workload", "method",
               "ns/query", "x lec-d", "FN", "FP", "part", "ghosts", "inside", "depth abs", "depth /R");
    std::string last;
    for (const Row& r : rows) {
        if (r.workload != last) fmt::print("{}\n", std::string(109, '-'));
        last = r.workload;
        fmt::print("{:<7} {:<13} {:<15} {:>9} {:>7} {:>6} {:>6} {:>6} {:>7} {:>7} {:>10} {:>10}\n", r.kind, r.workload,
                   r.method, cell(r.ns, "{:.1f}"), cell(r.ratio, "{:.2f}"), cell(r.fn), cell(r.fp), cell(r.part),
                   cell(r.ghosts), cell(r.inside), cell(r.depth), cell(r.depth_rel));
    }
}

void write_disc_csv(const std::vector<Row>& rows, const std::string& path) {
    ResultFile f(path);
    f.print("kind,workload,method,n,ns_per_query,ratio_lecture_double,false_negatives,false_positives,wrong_part,"
            "ghost_bounces,points_inside,max_depth_abs,max_depth_over_R\n");
    auto num = [](double v) { return std::isnan(v) ? std::string() : fmt::format("{}", v); };
    auto cnt = [](long v) { return v < 0 ? std::string() : fmt::format("{}", v); };
    for (const Row& r : rows)
        f.print("{},{},{},{},{},{},{},{},{},{},{},{},{}\n", r.kind, r.workload, r.method, r.n, num(r.ns), num(r.ratio),
                cnt(r.fn), cnt(r.fp), cnt(r.part), cnt(r.ghosts), cnt(r.inside), num(r.depth), num(r.depth_rel));
    f.close();
}

/// Runs gnuplot on a script; a missing gnuplot is reported, not fatal.
void gnuplot(const std::string& script_path) {
    const std::string cmd = fmt::format("gnuplot '{}'", script_path);
    if (std::system(cmd.c_str()) != 0) fmt::print(stderr, "bench: gnuplot failed or is missing; chart script left at {}\n", script_path);
}

/// Errors of one method's sweep answers against the exact kernel's.
void score_sweeps(std::span<const SweepQuery> qs, std::span<const SweepAnswer> got, std::span<const SweepAnswer> ref,
                  Row& row) {
    row.fn = row.fp = row.conv = 0;
    row.t_ulps = row.t_abs = row.p_ulps = row.p_abs = 0.0;
    bool any_t = false;
    for (std::size_t i = 0; i < qs.size(); ++i) {
        if (got[i].hit != ref[i].hit) {
            (ref[i].hit ? row.fn : row.fp) += 1;
            // Disagreements where exact's answer rests on a stated convention (a leg that starts on the
            // line and leaves, motion along the line) are also counted apart.
            const Sweep s = sweep(KernelId::exact, qs[i].bs, qs[i].v, qs[i].wall);
            if (s.miss == Miss::leaving || s.miss == Miss::parallel) ++row.conv;
            continue;
        }
        if (!ref[i].hit) continue;
        if (got[i].has_t) {
            any_t = true;
            const double e = std::fabs(got[i].t - ref[i].t);
            row.t_abs = std::max(row.t_abs, std::isnan(e) ? INFINITY : e);
            // In ulps of 1 (2^-52): t lies in [0, 1], and an ulp of t itself would blow up near t = 0.
            row.t_ulps = std::max(row.t_ulps, std::isnan(e) ? INFINITY : e / 0x1p-52);
        }
        // The contact point's error in ulps of the query's scale (its largest coordinate): an ulp of a
        // coordinate near 0 would call a 1e-16 error of a unit-size scene millions of ulps.
        const SweepQuery& q = qs[i];
        const Vec2 be = q.bs + q.v;
        const double scale = std::max({std::fabs(q.bs.x), std::fabs(q.bs.y), std::fabs(be.x), std::fabs(be.y),
                                       std::fabs(q.wall.p0.x), std::fabs(q.wall.p0.y), std::fabs(q.wall.p1.x),
                                       std::fabs(q.wall.p1.y)});
        for (int c = 0; c < 2; ++c) {
            const double g = c ? got[i].point.y : got[i].point.x, r = c ? ref[i].point.y : ref[i].point.x;
            const double e = std::fabs(g - r);
            row.p_abs = std::max(row.p_abs, std::isnan(e) ? INFINITY : e);
            row.p_ulps = std::max(row.p_ulps, std::isnan(e) ? INFINITY : e / ulp(scale));
        }
    }
    if (!any_t) row.t_ulps = row.t_abs = NAN;
}

using Methods = std::vector<std::unique_ptr<Method>>;

std::size_t find_method(const Methods& ms, std::string_view name) {
    for (std::size_t i = 0; i < ms.size(); ++i)
        if (ms[i]->name() == name) return i;
    return ms.size();
}

/// Times every method on one sweep workload (interleaved repetitions) and scores it.
std::vector<Row> bench_sweeps(const Methods& ms, const SweepWorkload& wl, int reps) {
    const std::size_t n = wl.queries.size();
    std::vector<std::vector<SweepAnswer>> ans(ms.size(), std::vector<SweepAnswer>(n));
    std::vector<std::vector<double>> ns(ms.size());
    for (int rep = 0; rep < reps; ++rep)
        for (std::size_t m = 0; m < ms.size(); ++m) {
            ms[m]->prepare(wl.queries);
            const auto t0 = Clock::now();
            ms[m]->sweep_all(wl.queries, ans[m]);
            ns[m].push_back(seconds_since(t0) * 1e9 / static_cast<double>(n));
            ms[m]->release();
        }
    const std::size_t ex = find_method(ms, "exact"), ld = find_method(ms, "lecture-double");
    std::vector<Row> rows;
    for (std::size_t m = 0; m < ms.size(); ++m) {
        Row r{"sweep", wl.name, ms[m]->name(), n};
        r.ns = median(ns[m]);
        r.ratio = r.ns / median(ns[ld]);
        score_sweeps(wl.queries, ans[m], ans[ex], r);
        rows.push_back(r);
    }
    return rows;
}

/// Times every method that steps discs on one disc workload (interleaved repetitions) and scores it: hit decisions
/// against truth_hit, the part against the exact kernel's first hit.
std::vector<Row> bench_discs(const Methods& ms, const DiscWorkload& wl, int reps) {
    const std::size_t n = wl.queries.size();
    std::vector<std::vector<DiscAnswer>> ans(ms.size(), std::vector<DiscAnswer>(n));
    std::vector<std::vector<double>> ns(ms.size());
    for (int rep = 0; rep < reps; ++rep)
        for (std::size_t m = 0; m < ms.size(); ++m) {
            if (!ms[m]->has_disc()) continue;
            ms[m]->prepare_discs(wl.queries);
            const auto t0 = Clock::now();
            ms[m]->disc_all(wl.queries, ans[m]);
            ns[m].push_back(seconds_since(t0) * 1e9 / static_cast<double>(n));
            ms[m]->release_discs();
        }
    std::vector<bool> hits(n);
    for (std::size_t i = 0; i < n; ++i) hits[i] = truth_hit(wl.queries[i]);
    const std::size_t ex = find_method(ms, "exact"), ld = find_method(ms, "lecture-double");
    std::vector<Row> rows;
    for (std::size_t m = 0; m < ms.size(); ++m) {
        if (!ms[m]->has_disc()) continue;
        Row r{"disc", wl.name, ms[m]->name(), n};
        r.ns = median(ns[m]);
        r.ratio = r.ns / median(ns[ld]);
        const DiscScore s = score_discs(wl.queries, ans[m], ans[ex], hits, wl.joint);
        r.fn = s.fn, r.fp = s.fp, r.part = s.part, r.ghosts = s.ghosts, r.inside = s.inside;
        r.depth = s.depth, r.depth_rel = s.depth_rel;
        rows.push_back(r);
    }
    return rows;
}

std::vector<Row> bench_statics(const Methods& ms, const StaticWorkload& wl, int reps) {
    const std::size_t n = wl.queries.size();
    std::vector<std::vector<unsigned char>> ans(ms.size(), std::vector<unsigned char>(n));
    std::vector<std::vector<double>> ns(ms.size());
    for (int rep = 0; rep < reps; ++rep)
        for (std::size_t m = 0; m < ms.size(); ++m) {
            if (!ms[m]->has_static(wl.kind)) continue;
            const auto t0 = Clock::now();
            ms[m]->static_all(wl.queries, ans[m]);
            ns[m].push_back(seconds_since(t0) * 1e9 / static_cast<double>(n));
        }
    const std::size_t ex = find_method(ms, "exact"), ld = find_method(ms, "lecture-double");
    std::vector<Row> rows;
    for (std::size_t m = 0; m < ms.size(); ++m) {
        if (!ms[m]->has_static(wl.kind)) continue;
        Row r{"static", wl.name, ms[m]->name(), n};
        r.ns = median(ns[m]);
        r.ratio = r.ns / median(ns[ld]);
        r.fn = r.fp = 0;
        for (std::size_t i = 0; i < n; ++i)
            if (ans[m][i] != ans[ex][i]) (ans[ex][i] ? r.fn : r.fp) += 1;
        rows.push_back(r);
    }
    return rows;
}

/// A peer has no stepper: the naive one a game developer writes around a ray cast (earliest hit over
/// every wall but the one just left, reflect with v' = v − 2(v·n̂)n̂ in double, go on).
void naive_frame(const Method& m, Ball& ball, std::span<const Wall> walls, std::vector<Vec2>& path) {
    Vec2 pos = ball.pos, vel = ball.vel;
    double rest = 1.0;
    std::size_t last = walls.size();
    for (int bounce = 0; bounce <= k_max_bounces; ++bounce) {
        const Vec2 d = rest * vel;
        std::size_t best = walls.size();
        SweepAnswer hit;
        double best_t = INFINITY;
        for (std::size_t i = 0; i < walls.size(); ++i) {
            if (i == last) continue;
            const SweepAnswer a = m.sweep_one({pos, d, walls[i]});
            if (!a.hit) continue;
            // CGAL gives the point only: its leg parameter is |X − Bs|/|d|.
            const double t = a.has_t ? a.t : length(a.point - pos) / length(d);
            if (t < best_t) best_t = t, best = i, hit = a;
        }
        if (best == walls.size() || bounce == k_max_bounces) {
            if (best == walls.size()) pos = pos + d;
            break;
        }
        path.push_back(hit.point);
        vel = reflect(KernelId::lecture_double, vel, walls[best]);
        pos = hit.point;
        rest *= 1.0 - best_t;
        last = best;
    }
    ball = {pos, vel};
    path.push_back(pos);
}

/// Multi-frame closed-box runs: ns per ball-frame, tunnels (exact checker), speed drift.
Row box_run(const Method& m, const std::string& name, Vec2 offset, double angle, const Sizes& sz, std::uint64_t seed) {
    const std::vector<Wall> walls = make_box(offset, angle);
    const std::vector<Ball> balls = make_balls(offset, angle, sz.balls, seed);
    Row row{"box", name, m.name(), sz.balls * static_cast<std::size_t>(sz.frames)};
    row.tunnels = 0;
    row.escaped = 0;
    row.drift = 0.0;
    double secs = 0.0;
    std::vector<HitEvent> hits;
    StepScratch scratch;
    std::vector<Vec2> path;
    for (std::size_t i = 0; i < balls.size(); ++i) {
        Ball b = balls[i];
        BallMemory mem;
        path.clear();
        const auto t0 = Clock::now();
        for (long f = 0; f < sz.frames; ++f) {
            if (const KernelId* k = m.kernel()) {
                hits.clear();
                step_ball(*k, b, mem, walls, hits, scratch);
                for (const HitEvent& h : hits) path.push_back(h.point);
                path.push_back(b.pos);
            } else {
                naive_frame(m, b, walls, path);
            }
        }
        secs += seconds_since(t0);
        // The exact no-tunnel check of the printed path, untimed.
        const Ball start = balls[i];
        TunnelChecker checker(walls, std::span<const Ball>(&start, 1));
        for (Vec2 p : path)
            if (checker.advance(0, p)) ++row.tunnels;
        // Escaped: strictly outside some wall's line, i.e. on the other side of it from the box's centre.
        bool out = false;
        for (const Wall& w : walls) out = out || exact::side(b.pos, w) * exact::side(offset, w) < 0;
        row.escaped += out;
        const double v0 = length(balls[i].vel), v1 = length(b.vel);
        row.drift = std::max(row.drift, std::isfinite(v1) ? std::fabs(v1 / v0 - 1.0) : INFINITY);
    }
    row.ns = secs * 1e9 / static_cast<double>(row.n);
    return row;
}

/// Extra figures: batched decisions, exact sweep with its bounce.
std::vector<Row> extras(const Sizes& sz, std::uint64_t seed, int reps) {
    std::vector<Row> rows;
    // Batched robust decisions, many balls against one wall (SoA), against the same pairs one by one
    // through sweep(robust). uniform: the uniform workload's balls against 64 of its walls; end-on-wall and
    // grazing: balls that all end on, or all graze, the one wall they are tested against (64 walls).
    const std::size_t nb = std::max<std::size_t>(sz.queries, 4096);
    for (const char* which : {"uniform", "end-on-wall", "grazing"}) {
        const std::size_t walls = 64;
        std::vector<SweepWorkload> sets;
        if (std::string_view(which) == "uniform") {
            SweepWorkload u = sweep_workloads(nb, seed)[0];
            for (std::size_t w = 0; w < walls; ++w) {
                SweepWorkload s = u;
                for (SweepQuery& q : s.queries) q.wall = u.queries[w].wall;
                sets.push_back(std::move(s));
            }
        } else {
            Rng r(seed + 5);
            for (std::size_t w = 0; w < walls; ++w) {
                Wall wall{{r.uniform(-1, 1), r.uniform(-1, 1)}, {r.uniform(-1, 1), r.uniform(-1, 1)}};
                sets.push_back(one_wall_workload(which, wall, nb, seed + w));
            }
        }
        std::vector<std::vector<double>> x(walls), y(walls), vx(walls), vy(walls);
        for (std::size_t w = 0; w < walls; ++w)
            for (const SweepQuery& q : sets[w].queries)
                x[w].push_back(q.bs.x), y[w].push_back(q.bs.y), vx[w].push_back(q.v.x), vy[w].push_back(q.v.y);
        std::vector<Miss> out(nb), ref(nb);
        std::vector<double> ns_batch, ns_scalar;
        long wrong = 0;
        std::size_t slow = 0;
        for (int rep = 0; rep < reps; ++rep) {
            auto t0 = Clock::now();
            for (std::size_t w = 0; w < walls; ++w)
                slow += sweep_decisions(BallsSoA{x[w], y[w], vx[w], vy[w]}, sets[w].queries[0].wall, out);
            ns_batch.push_back(seconds_since(t0) * 1e9 / static_cast<double>(nb * walls));
            t0 = Clock::now();
            for (std::size_t w = 0; w < walls; ++w)
                for (std::size_t i = 0; i < nb; ++i) {
                    const SweepQuery& q = sets[w].queries[i];
                    ref[i] = sweep(KernelId::robust, q.bs, q.v, q.wall).miss;
                }
            ns_scalar.push_back(seconds_since(t0) * 1e9 / static_cast<double>(nb * walls));
        }
        for (std::size_t w = 0; w < walls; ++w) {
            sweep_decisions(BallsSoA{x[w], y[w], vx[w], vy[w]}, sets[w].queries[0].wall, out);
            for (std::size_t i = 0; i < nb; ++i) {
                const SweepQuery& q = sets[w].queries[i];
                wrong += out[i] != sweep(KernelId::robust, q.bs, q.v, q.wall).miss;
            }
        }
        Row s{"batch", fmt::format("{}-pairs", which), "robust-scalar", nb * walls};
        s.ns = median(ns_scalar);
        s.ratio = 1.0;
        Row b{"batch", fmt::format("{}-pairs", which), "robust-batch", nb * walls};
        b.ns = median(ns_batch);
        b.ratio = b.ns / s.ns;
        b.fn = wrong;  // here: decisions differing from sweep(robust)
        b.fp = 0;
        // conv column here: the share of lanes left to the exact predicates (after both SIMD stages), per mille.
        b.conv = static_cast<long>(1000.0 * static_cast<double>(slow) / static_cast<double>(nb * walls * static_cast<std::size_t>(reps)));
        rows.push_back(s);
        rows.push_back(b);
    }
    // exact: a sweep with its bounce, on uniform queries that hit.
    {
        const std::vector<SweepWorkload> wls = sweep_workloads(sz.queries, seed);
        std::vector<SweepQuery> hits;
        for (const SweepQuery& q : wls[0].queries)
            if (sweep(KernelId::robust, q.bs, q.v, q.wall).hit()) hits.push_back(q);
        std::vector<double> ns;
        for (int rep = 0; rep < reps; ++rep) {
            const auto t0 = Clock::now();
            double acc = 0;
            for (const SweepQuery& q : hits) {
                const Sweep s = sweep(KernelId::exact, q.bs, q.v, q.wall);
                acc += s.t + reflect(KernelId::exact, q.v, q.wall).x;
            }
            g_sink = acc;
            ns.push_back(seconds_since(t0) * 1e9 / static_cast<double>(std::max<std::size_t>(hits.size(), 1)));
        }
        Row r{"extra", "uniform-hits", "exact+bounce", hits.size()};
        r.ns = median(ns);
        rows.push_back(r);
    }
    // One ball in a closed box, robust step_ball: ns per ball-frame (1e9 / ball-frames per second).
    {
        const std::vector<Wall> walls = make_box({0, 0}, 0.0);
        const long frames = sz.frames * 500;
        std::vector<double> ns;
        for (int rep = 0; rep < reps; ++rep) {
            Ball b{{0.1, 0.2}, {0.0123456789, 0.00987654321}};
            BallMemory mem;
            StepScratch scratch;
            std::vector<HitEvent> hits;
            const auto t0 = Clock::now();
            for (long f = 0; f < frames; ++f) {
                hits.clear();
                step_ball(KernelId::robust, b, mem, walls, hits, scratch);
            }
            ns.push_back(seconds_since(t0) * 1e9 / static_cast<double>(frames));
            g_sink = b.pos.x;
        }
        Row r{"extra", "one-ball-box", "robust-step", static_cast<std::size_t>(frames)};
        r.ns = median(ns);
        rows.push_back(r);
    }
    return rows;
}

/// Geometric mean of positive values.
double geomean(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += std::log(x);
    return v.empty() ? NAN : std::exp(s / static_cast<double>(v.size()));
}

void chart(const std::vector<Row>& rows, const Methods& ms, const Options& opt, int reps) {
    std::size_t sweeps = 0;
    for (const Row& r : rows) sweeps += r.kind == "sweep" && r.method == "exact";
    const std::string dat = opt.out_dir + "/runtime_vs_error.dat";
    const std::string gp = opt.out_dir + "/runtime_vs_error.gp";
    {
        ResultFile f(dat);
        f.print("# method  geomean_ns_per_sweep  wrong_per_million(0 drawn at 0.1)  max_point_err_ulps(0 drawn at 0.1)  wrong\n");
        for (const auto& m : ms) {
            std::vector<double> ns;
            long wrong = 0;
            std::size_t n = 0;
            double pu = 0;
            for (const Row& r : rows)
                if (r.kind == "sweep" && r.method == m->name()) {
                    ns.push_back(r.ns);
                    // Convention-only disagreements (leaving the line, moving along it) are not errors.
                    wrong += r.fn + r.fp - r.conv;
                    n += r.n;
                    // Contact error where the hit is well conditioned: uniform and far. Grazing legs
                    // make t_i itself ill-conditioned, so every method's error there says little.
                    if ((r.workload == "uniform" || r.workload == "far") && std::isfinite(r.p_ulps)) pu = std::max(pu, r.p_ulps);
                }
            const double per_m = 1e6 * static_cast<double>(wrong) / static_cast<double>(n);
            // One block per method (gnuplot's index), so that each gets its own colour and key entry.
            f.print("{} {} {} {} {}\n\n\n", m->name(), geomean(ns), per_m > 0 ? per_m : 0.1, pu > 0 ? pu : 0.1, wrong);
        }
        f.close();
    }
    std::string names;
    for (const auto& m : ms) names += (names.empty() ? "" : " ") + m->name();
    ResultFile f(gp);
    f.print(R"GP(set terminal pngcairo size 1200,520 font ",11"
set output '{0}/runtime_vs_error.png'
set multiplot layout 1,2 title "ricochet bench{1}: run time against error, {2} sweep workloads, median of {3} runs (shared 2-core machine)"
set logscale xy
set grid
set xlabel "ns per sweep query (geometric mean over workloads)"
set ylabel "wrong hit decisions per million (0 at 0.1)"
set key top right
set offsets graph 0.05, graph 0.15, graph 0.12, graph 0.05
names = "{5}"
plot for [i=1:words(names)] '{4}' index (i-1) using 2:3 with points pt (4+i) ps 2 lw 2 title word(names, i)
set ylabel "max contact error, uniform + far (ulps of scale; 0 at 0.1)"
plot for [i=1:words(names)] '{4}' index (i-1) using 2:4 with points pt (4+i) ps 2 lw 2 title word(names, i)
unset multiplot
)GP",
            opt.out_dir, opt.quick ? " --quick" : "", sweeps, reps, dat, names);
    f.close();
    gnuplot(gp);
}

}  // namespace

int run_bench(const Options& opt) {
    const auto t_start = std::chrono::steady_clock::now();
    const Sizes sz = sizes(opt);
    std::filesystem::create_directories(opt.out_dir);
    Methods ms = kernel_methods();
    std::vector<std::string> skipped;
    for (auto& p : peer_methods(skipped)) ms.push_back(std::move(p));
    for (const std::string& s : skipped) fmt::print("{}\n", s);
    fmt::print("ricochet bench{}: {} queries per workload, median of {} runs; ball runs {} balls x {} frames; seed {}\n",
               opt.smoke ? " --smoke" : opt.quick ? " --quick" : "", sz.queries, sz.reps, sz.balls, sz.frames, opt.seed);
    fmt::print("note: times are this thread's CPU time (the machine may be shared), medians of the runs; ratios are against\n"
               "lecture-double timed in the same, interleaved runs\n");

    std::vector<Row> rows;
    const std::vector<SweepWorkload> sweeps = sweep_workloads(sz.queries, opt.seed);
    const std::vector<StaticWorkload> statics = static_workloads(sz.queries, opt.seed + 1);
    const std::vector<DiscWorkload> discs = disc_workloads(sz.queries, opt.seed + 3);
    // Progress on stderr, a line as each workload starts: the table comes only at the end.
    const std::size_t steps = sweeps.size() + statics.size() + discs.size() + box_workloads().size() + 1;
    std::size_t step = 0;
    auto starting = [&](std::string_view what, const std::string& name) {
        fmt::print(stderr, "bench: [{}/{}] {} {}\n", ++step, steps, what, name);
    };
    for (const SweepWorkload& wl : sweeps) {
        starting("sweep", wl.name);
        for (Row& r : bench_sweeps(ms, wl, sz.reps)) rows.push_back(std::move(r));
    }
    for (const StaticWorkload& wl : statics) {
        starting("static", wl.name);
        for (Row& r : bench_statics(ms, wl, sz.reps)) rows.push_back(std::move(r));
    }
    std::vector<Row> disc_rows;
    for (const DiscWorkload& wl : discs) {
        starting("disc", wl.name);
        for (Row& r : bench_discs(ms, wl, sz.reps)) disc_rows.push_back(std::move(r));
    }
    for (const BoxWorkload& b : box_workloads()) {
        starting("closed box", b.name);
        std::vector<Row> group;
        for (const auto& m : ms) {
            // The exact kernel is slow by design: a tenth of the frames keeps --quick quick.
            Sizes s = sz;
            if (m->name() == "exact") s.frames = std::max(10L, s.frames / 10);
            group.push_back(box_run(*m, b.name, b.offset, b.angle, s, opt.seed + 2));
        }
        const double ld = group[find_method(ms, "lecture-double")].ns;
        for (Row& r : group) r.ratio = r.ns / ld;
        for (Row& r : group) rows.push_back(std::move(r));
    }
    starting("batch and maze", "rows");
    for (Row& r : extras(sz, opt.seed, sz.reps)) rows.push_back(std::move(r));

    print_table(rows);
    fmt::print("(t err ulp1: max |t - t_exact| in ulps of 1 (2^-52); pt err ulpS: max contact error in ulps of the query's\n"
               " largest coordinate; both over the hits that method and exact agree on;\n");
    fmt::print(" box rows: ns per ball-frame, tunnels = events where the printed path crosses a wall (exact TunnelChecker;\n"
               " a bounce point rounded past the wall and back counts 2), escaped = balls outside the box at the end, drift = max | |v_end|/|v_0| - 1 |;\n"
               " batch rows: ns per ball-wall decision, FN = decisions differing from sweep(robust), conv = lanes left to the\n"
               " exact predicates after the SIMD filter and second stage, per mille;\n"
               " conv = disagreements where exact's miss rests on a convention: leaving the line, moving along it)\n");
    fmt::print("\n");
    print_disc_table(disc_rows);
    fmt::print("(disc rows: one frame of step_ball per query for the kernels, the peer's own query for the peers; FN/FP =\n"
               " hit decisions differing from the exact truth (truth.hpp); part = hits whose wall, bumper or face/cap differs\n"
               " from exact's; ghosts = hits on a leg sliding past a joint at its radius; inside = printed contact points\n"
               " closer than R (R + r) to an obstacle, exactly; depth = the deepest, R - distance, absolute and over R)\n");
    // The speed targets on this run's own rows: the README's table "Where each speed target stands".
    report_targets(bench_targets(rows, disc_rows),
                   opt.smoke ? "speed targets (--smoke: sizes too small to measure; a check of the table only)"
                             : "speed targets: robust against lecture-double in this run",
                   opt.out_dir + "/targets.md");
    const std::string csv = opt.out_dir + "/bench.csv";
    write_csv(rows, csv);
    fmt::print("wrote {}\n", csv);
    const std::string disc_csv = opt.out_dir + "/disc.csv";
    write_disc_csv(disc_rows, disc_csv);
    fmt::print("wrote {}\n", disc_csv);
    if (opt.chart && !opt.smoke) {
        chart(rows, ms, opt, sz.reps);
        fmt::print("wrote {}/runtime_vs_error.png\n", opt.out_dir);
    }
    int status = 0;
    for (const Row& r : rows) {
        const bool robust = r.method == "robust" || r.method == "robust-batch" || r.method == "exact";
        if (robust && ((r.fn > 0) || (r.fp > 0) || r.tunnels > 0)) {
            fmt::print(stderr, "bench: {} is wrong on {}: FN {} FP {} tunnels {}\n", r.method, r.workload, r.fn, r.fp,
                       r.tunnels);
            status = 1;
        }
    }
    for (const Row& r : disc_rows) {
        DiscScore s;
        s.fn = r.fn, s.fp = r.fp, s.part = r.part, s.ghosts = r.ghosts, s.inside = r.inside;
        if ((r.method == "robust" || r.method == "exact") && !disc_score_clean(s)) {
            fmt::print(stderr, "bench: {} is wrong on {}: FN {} FP {} part {} ghosts {} inside {}\n", r.method, r.workload,
                       r.fn, r.fp, r.part, r.ghosts, r.inside);
            status = 1;
        }
    }
    fmt::print("total {:.1f} s wall\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count());
    return status;
}

int run_stability(const Options& opt) {
    const auto t_start = std::chrono::steady_clock::now();
    const Sizes sz = sizes(opt);
    const std::size_t n = opt.smoke ? 200 : opt.quick ? 4000 : 20000;
    std::filesystem::create_directories(opt.out_dir);
    Methods ms = kernel_methods();
    std::vector<std::string> skipped;
    for (auto& p : peer_methods(skipped)) ms.push_back(std::move(p));
    for (const std::string& s : skipped) fmt::print("{}\n", s);
    fmt::print("ricochet bench stability{}: {} queries per magnitude and angle; seed {}\n",
               opt.smoke ? " --smoke" : opt.quick ? " --quick" : "", n, opt.seed);
    const std::size_t ex = find_method(ms, "exact");
    const std::string csv = opt.out_dir + "/stability.csv";
    ResultFile f(csv);
    f.print("axis,value,method,wrong_decisions,queries,max_point_err_ulps,tunnels,ball_frames\n");
    std::vector<SweepAnswer> ref(n), got(n);
    auto score = [&](const SweepWorkload& wl, std::size_t m, Row& row) {
        ms[m]->sweep_all(wl.queries, got);
        score_sweeps(wl.queries, got, ref, row);
    };
    Sizes boxes_sz = sz;
    boxes_sz.balls = opt.smoke ? 2 : opt.quick ? 8 : 32;
    boxes_sz.frames = opt.smoke ? 100 : opt.quick ? 500 : 2000;
    fmt::print("{:<10} {:>8} {:<15} {:>8} {:>12} {:>8}\n", "axis", "value", "method", "wrong", "pt err ulp", "tunnels");
    for (int k = 0; k <= 15; ++k) {
        const double mag = std::pow(10.0, k);
        const SweepWorkload wl = offset_workload(mag, n, opt.seed + static_cast<std::uint64_t>(k));
        ms[ex]->sweep_all(wl.queries, ref);
        for (std::size_t m = 0; m < ms.size(); ++m) {
            Row row;
            score(wl, m, row);
            Sizes s = boxes_sz;
            if (m == ex) s.frames = std::max(10L, s.frames / 10);
            const Row box = box_run(*ms[m], "box", {mag, -0.5 * mag}, 0.3, s, opt.seed + 7);
            f.print("magnitude,{},{},{},{},{},{},{}\n", mag, ms[m]->name(), row.fn + row.fp, n, row.p_ulps, box.tunnels, box.n);
            fmt::print("{:<10} {:>8.0e} {:<15} {:>8} {:>12.3g} {:>8}\n", "magnitude", mag, ms[m]->name(), row.fn + row.fp,
                       row.p_ulps, box.tunnels);
        }
    }
    for (int k = 0; k <= 15; ++k) {
        const double angle = std::pow(10.0, -k);
        const SweepWorkload wl = angle_workload(angle, n, opt.seed + 100 + static_cast<std::uint64_t>(k));
        ms[ex]->sweep_all(wl.queries, ref);
        for (std::size_t m = 0; m < ms.size(); ++m) {
            Row row;
            score(wl, m, row);
            f.print("angle,{},{},{},{},{},,\n", angle, ms[m]->name(), row.fn + row.fp, n, row.p_ulps);
            fmt::print("{:<10} {:>8.0e} {:<15} {:>8} {:>12.3g} {:>8}\n", "angle", angle, ms[m]->name(), row.fn + row.fp,
                       row.p_ulps, "-");
        }
    }
    f.close();
    fmt::print("wrote {}\n", csv);
    if (opt.chart && !opt.smoke) {
        const std::string gp = opt.out_dir + "/stability.gp";
        ResultFile g(gp);
        std::string plots_mag_wrong, plots_mag_tun, plots_ang_wrong, plots_ang_err;
        for (std::size_t m = 0; m < ms.size(); ++m) {
            auto one = [&](const char* axis, int col, bool plus_floor) {
                return fmt::format("'{}' using (strcol(1) eq '{}' && strcol(3) eq '{}' ? $2 : NaN):(${} {}) with linespoints title '{}'",
                                   csv, axis, ms[m]->name(), col, plus_floor ? "+ 0.1" : "", ms[m]->name());
            };
            const char* sep = m ? ", " : "";
            plots_mag_wrong += sep + one("magnitude", 4, true);
            plots_mag_tun += sep + one("magnitude", 7, true);
            plots_ang_wrong += sep + one("angle", 4, true);
            plots_ang_err += sep + one("angle", 6, true);
        }
        g.print(R"GP(set terminal pngcairo size 1400,900 font ",10"
set output '{0}/stability.png'
set datafile separator ','
set multiplot layout 2,2 title "ricochet bench stability{1}: {2} sweeps per point; closed-box runs {3} balls x {4} frames (exact: 1/10 of the frames)"
set logscale xy
set grid
set key outside right
set xlabel "coordinate magnitude (scene moved by 10^k)"
set ylabel "wrong hit decisions + 0.1"
plot {5}
set ylabel "tunnels in closed-box runs + 0.1"
plot {6}
set xlabel "angle between leg and wall (radians)"
set ylabel "wrong hit decisions + 0.1"
plot {7}
set ylabel "max contact point error, ulps + 0.1"
plot {8}
unset multiplot
)GP",
                opt.out_dir, opt.quick ? " --quick" : "", n, boxes_sz.balls, boxes_sz.frames, plots_mag_wrong, plots_mag_tun,
                plots_ang_wrong, plots_ang_err);
        g.close();
        gnuplot(gp);
        fmt::print("wrote {}/stability.png\n", opt.out_dir);
    }
    fmt::print("total {:.1f} s wall\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count());
    return 0;
}

int run_frames(const Options& opt, long frames) {
    // One ball in the closed box [−1, 1]², robust kernel, frames × step_ball: the ball-frames per second
    // figure. Two speeds: a bounce every ~90 frames, and one every ~3 frames (bounces cost more).
    const std::vector<Wall> walls = make_box({0, 0}, 0.0);
    const int reps = opt.smoke ? 1 : 5;
    fmt::print("frames: one ball, closed box of 4 walls, robust kernel via ricochet::step_ball, thread CPU time\n");
    double slow_rate = 0.0;
    for (const Vec2 v0 : {Vec2{0.0123456789, 0.00987654321}, Vec2{0.6123456789, 0.37654321}}) {
        std::vector<double> rates;
        long bounces = 0;
        Ball b{};
        for (int rep = 0; rep < reps; ++rep) {
            b = {{0.1, 0.2}, v0};
            BallMemory mem;
            StepScratch scratch;
            std::vector<HitEvent> hits;
            hits.reserve(64);
            bounces = 0;
            const auto t0 = Clock::now();
            for (long f = 0; f < frames; ++f) {
                hits.clear();
                step_ball(KernelId::robust, b, mem, walls, hits, scratch);
                bounces += static_cast<long>(hits.size());
            }
            rates.push_back(static_cast<double>(frames) / seconds_since(t0));
        }
        if (slow_rate == 0.0) slow_rate = median(rates);
        fmt::print("v = ({}, {}): {} frames x {} runs, {} bounces per run, median {:.4g} ball-frames/s (min {:.4g}, max {:.4g}); "
                   "ends at ({}, {})\n",
                   v0.x, v0.y, frames, reps, bounces, median(rates), *std::min_element(rates.begin(), rates.end()),
                   *std::max_element(rates.begin(), rates.end()), b.pos.x, b.pos.y);
    }
    fmt::print("target >= 1e7 ball-frames/s on one core (slow ball): {}\n", slow_rate >= 1e7 ? "met" : "missed");
    return 0;
}

}  // namespace ricochet::bench
