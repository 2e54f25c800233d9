// `ricochet bench scale` (scale_bench.hpp): mazes from 10 to 10^6 walls, 1 to 10^6 balls.
#include "scale_bench.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <memory>
#include <random>
#include <thread>
#include <utility>

#include <time.h>

#include "box2d_peer.hpp"
#include "chipmunk_peer.hpp"
#include "ricochet_bench/result_file.hpp"
#include "ricochet_bench/targets.hpp"
#include "ricochet/checks.hpp"
#include "ricochet/predicates.hpp"
#include "ricochet/wall_grid.hpp"
#include "ricochet/world.hpp"

namespace ricochet {

#ifndef RICOCHET_HAVE_BOX2D
namespace scale {
bool box2d_available() { return false; }
struct Box2dPeer::Impl {};
Box2dPeer::Box2dPeer(std::span<const Wall>) {}
Box2dPeer::~Box2dPeer() = default;
void Box2dPeer::step(FloatBall&, std::vector<Vec2>*) const {}
void Box2dPeer::step_disc(FloatBall&, float, std::vector<Vec2>*) const {}
}  // namespace scale
#endif
#ifndef RICOCHET_HAVE_CHIPMUNK
namespace scale {
bool chipmunk_available() { return false; }
struct ChipmunkPeer::Impl {};
ChipmunkPeer::ChipmunkPeer(std::span<const Wall>) {}
ChipmunkPeer::~ChipmunkPeer() = default;
void ChipmunkPeer::step(Ball&, std::vector<Vec2>*) const {}
}  // namespace scale
#endif

namespace scale {

std::vector<Wall> make_maze(int n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::bernoulli_distribution coin(0.5);
    std::vector<Wall> walls;
    const auto at = [](int x, int y) { return Vec2{static_cast<double>(x), static_cast<double>(y)}; };
    for (int i = 0; i < n; ++i) {
        walls.push_back({at(i, 0), at(i + 1, 0)});
        walls.push_back({at(n, i), at(n, i + 1)});
        walls.push_back({at(i + 1, n), at(i, n)});
        walls.push_back({at(0, i + 1), at(0, i)});
    }
    for (int x = 0; x < n; ++x)
        for (int y = 1; y < n; ++y) {
            if (coin(rng)) walls.push_back({at(x, y), at(x + 1, y)});
            if (coin(rng)) walls.push_back({at(y, x), at(y, x + 1)});
        }
    return walls;
}

std::vector<Ball> make_balls(std::size_t count, int n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> pos(0.001, n - 0.001), angle(0.0, 6.283185307179586), speed(0.05, 0.5);
    std::vector<Ball> balls(count);
    for (Ball& b : balls) {
        const double a = angle(rng), s = speed(rng);
        b.pos = {pos(rng), pos(rng)};
        b.vel = {s * std::cos(a), s * std::sin(a)};
    }
    return balls;
}

std::vector<Ball> make_discs(std::size_t count, int n, std::uint64_t seed, double r) {
    std::vector<Ball> balls = make_balls(count, n, seed);
    const auto inside = [](double x) { return std::floor(x) + 0.15 + 0.7 * (x - std::floor(x)); };
    for (Ball& b : balls) b = {{inside(b.pos.x), inside(b.pos.y)}, b.vel, r};
    return balls;
}

std::vector<Wall> make_box(std::size_t count) {
    const double side = 2.0 * std::ceil(std::sqrt(static_cast<double>(count)));
    const Vec2 c[4] = {{0, 0}, {side, 0}, {side, side}, {0, side}};
    std::vector<Wall> walls;
    for (int i = 0; i < 4; ++i) walls.push_back({c[i], c[(i + 1) % 4]});
    return walls;
}

std::vector<Ball> make_box_discs(std::size_t count, std::uint64_t seed, double r) {
    const auto m = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(count))));
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> at(0.2, 1.8), angle(0.0, 6.283185307179586), speed(0.05, 0.5);
    std::vector<Ball> balls(count);
    for (std::size_t i = 0; i < count; ++i) {
        const double x = 2.0 * static_cast<double>(i % m) + at(rng), y = 2.0 * static_cast<double>(i / m) + at(rng);
        const double a = angle(rng), v = speed(rng);
        balls[i] = {{x, y}, {v * std::cos(a), v * std::sin(a)}, r};
    }
    return balls;
}

}  // namespace scale

namespace {

using Clock = std::chrono::steady_clock;
using scale::FloatBall;
using scale::make_balls;
using scale::make_maze;

/// Seconds per frame: wall-clock and this thread's CPU time (on a shared machine the CPU time leaves
/// out the time the thread waited for a core).
struct FrameTime {
    double wall = 0, cpu = 0;
};

double thread_cpu_seconds() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// One workload's frames timed in chunks: as many frames as take ~2 ms (from one warm-up frame), each chunk's
/// seconds per frame kept (wall and CPU).
class ChunkTimer {
public:
    explicit ChunkTimer(const std::function<void()>& frame) : frame_(frame) {
        const auto t0 = Clock::now();
        frame_();
        const double first = seconds_since(t0);
        chunk_ = std::max(1, static_cast<int>(std::ceil(2e-3 / std::max(first, 1e-9))));
    }

    void run_chunk() {
        const auto t0 = Clock::now();
        const double c0 = thread_cpu_seconds();
        for (int i = 0; i < chunk_; ++i) frame_();
        cpu_.push_back((thread_cpu_seconds() - c0) / chunk_);
        wall_.push_back(seconds_since(t0) / chunk_);
    }

    std::size_t chunks() const { return wall_.size(); }

    /// The median seconds per frame over the chunks (wall and CPU, each its own median).
    FrameTime medians() {
        const auto median = [](std::vector<double>& v) {
            std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
            return v[v.size() / 2];
        };
        return {median(wall_), median(cpu_)};
    }

private:
    const std::function<void()>& frame_;
    int chunk_ = 1;
    std::vector<double> wall_, cpu_;
};

/// Median seconds per frame: chunks of frames (ChunkTimer) until budget seconds have passed (at least 3 chunks, at
/// most 200).
FrameTime time_per_frame(const std::function<void()>& frame, double budget) {
    ChunkTimer timer(frame);
    const auto start = Clock::now();
    while (timer.chunks() < 3 || (seconds_since(start) < budget && timer.chunks() < 200)) timer.run_chunk();
    return timer.medians();
}

/// time_per_frame for two workloads side by side: rounds of 5 chunks of a, then 5 of b, for twice the budget (at
/// least 5 chunks of each, at most 200), so that a slow spell of the machine falls on both alike and their ratio
/// keeps (as the interleaved repetitions of `ricochet bench` keep theirs). The first chunk of a round finds the
/// caches holding the other workload's data; the median passes over it.
std::pair<FrameTime, FrameTime> time_per_frame_side_by_side(const std::function<void()>& a,
                                                            const std::function<void()>& b, double budget) {
    constexpr int round = 5;
    ChunkTimer ta(a), tb(b);
    const auto start = Clock::now();
    do {
        for (int k = 0; k < round; ++k) ta.run_chunk();
        for (int k = 0; k < round; ++k) tb.run_chunk();
    } while (seconds_since(start) < 2 * budget && ta.chunks() < 200);
    return {ta.medians(), tb.medians()};
}

/// True if the piece q → r goes strictly from one side of a wall to the other through its closed
/// segment (exact predicates); the grid supplies the candidates.
bool tunnels(Vec2 q, Vec2 r, std::span<const Wall> walls, const WallGrid& grid, std::vector<std::uint32_t>& scratch) {
    if (q == r) return false;
    scratch.clear();
    grid.query(q, r, scratch);
    for (std::uint32_t i : scratch) {
        const Wall& w = walls[i];
        if (exact::side(q, w) * exact::side(r, w) >= 0) continue;
        if (exact::orient(q, r, w.p0) * exact::orient(q, r, w.p1) <= 0) return true;
    }
    return false;
}

/// True if the centre c is closer than reach to a wall (squared distances in double: the margin the bench asks,
/// a hundredth of a cell, is far above their rounding); the grid supplies the candidates.
bool within(Vec2 c, double reach, std::span<const Wall> walls, const WallGrid& grid,
            std::vector<std::uint32_t>& scratch) {
    scratch.clear();
    grid.query_near(c, c, reach, scratch);
    for (std::uint32_t i : scratch) {
        const Wall& w = walls[i];
        const Vec2 d = w.p1 - w.p0, e = c - w.p0;
        // The nearest point of the segment: p0 + s·d, s = (e·d)/(d·d) clamped to [0, 1].
        const double dd = dot(d, d), s = dd > 0 ? std::clamp(dot(e, d) / dd, 0.0, 1.0) : 0.0;
        const Vec2 off = e - s * d;
        if (dot(off, off) < reach * reach) return true;
    }
    return false;
}

Vec2 centre_of(const FloatBall& b) { return {b.x, b.y}; }
Vec2 centre_of(const Ball& b) { return b.pos; }

struct Row {
    std::string sweep, method;
    std::size_t walls = 0, balls = 0;
    unsigned threads = 1;
    double ms_per_frame = 0, ns_per_ball_frame = 0;
    double cpu_ns_per_ball_frame = 0;  // this thread's CPU time (one-thread rows)
    double hits_per_ball_frame = -1;  // from the checked frames, -1 if not checked
    long long tunnels = -1;           // pieces crossing a wall in the checked frames, -1 if not checked
    long long penetrations = -1;      // disc rows: contacts or ends inside a wall's reach, -1 if not checked
    std::size_t checked_ball_frames = 0;
    double meets_per_ball_frame = 0;  // meet rows: from the checked frames
};

struct Config {
    bool quick;          // leave out the BVH in the balls sweep
    double budget;       // seconds of timing per point
    double brute_limit;  // brute force only when walls·balls ≤ this
    std::size_t check_balls;
    int check_frames;
    std::vector<std::size_t> wall_sizes;  // the walls sweep, with sweep_balls balls
    std::size_t sweep_balls;
    std::vector<std::size_t> ball_sizes;  // the balls sweep, in a maze of about maze_walls walls
    std::size_t maze_walls;
    std::size_t thread_balls;  // the threads sweep: thread_balls balls in that maze
    std::vector<std::size_t> meet_sizes;  // the meet sweep: this many discs in a box, without and with balls collide
};

Config config(ScaleSize size) {
    switch (size) {
        case ScaleSize::smoke: return {true, 0.002, 4e6, 100, 5, {10, 100}, 100, {1, 100}, 100, 1000, {100}};
        case ScaleSize::quick:
            return {true, 0.15, 4e6, 4000, 20, {10, 100, 1000, 10000, 100000}, 2000, {1, 100, 10000, 100000},
                    10000, 100000, {1000, 10000}};
        case ScaleSize::full: break;
    }
    return {false, 0.6, 2e7, 20000, 50, {10, 100, 1000, 10000, 100000, 1000000}, 10000,
            {1, 10, 100, 1000, 10000, 100000, 1000000}, 10000, 100000, {1000, 10000}};
}

const char* size_flag(ScaleSize size) {
    return size == ScaleSize::smoke ? " --smoke" : size == ScaleSize::quick ? " --quick" : "";
}

/// Measures one (walls, balls) point for every method and appends the rows.
void measure(const Config& cfg, const std::string& sweep, int n, std::size_t ball_count, std::vector<Row>& rows) {
    const std::vector<Wall> walls = make_maze(n, 1000 + static_cast<std::uint64_t>(n));
    const std::vector<Ball> start = make_balls(ball_count, n, 2000 + ball_count);
    const WallGrid grid(walls);
    const auto base = [&](const char* method) {
        Row r;
        r.sweep = sweep;
        r.method = method;
        r.walls = walls.size();
        r.balls = ball_count;
        return r;
    };
    const auto finish = [&](Row r, FrameTime t) {
        r.ms_per_frame = t.wall * 1e3;
        r.ns_per_ball_frame = t.wall * 1e9 / static_cast<double>(ball_count);
        r.cpu_ns_per_ball_frame = t.cpu * 1e9 / static_cast<double>(ball_count);
        rows.push_back(r);
        fmt::print("{:<7} {:>8} walls {:>8} balls  {:<17} {:>10.4f} ms/frame {:>9.1f} ns/ball-frame ({:>7.1f} CPU)",
                   r.sweep, r.walls, r.balls, r.method, r.ms_per_frame, r.ns_per_ball_frame, r.cpu_ns_per_ball_frame);
        if (r.tunnels >= 0)
            fmt::print("  {:.3f} hits/ball-frame, {} tunnels{} in {} checked ball-frames", r.hits_per_ball_frame,
                       r.tunnels, r.penetrations >= 0 ? fmt::format(", {} penetrations", r.penetrations) : "",
                       r.checked_ball_frames);
        fmt::print("\n");
        std::fflush(stdout);
    };

    // The checked run: the first check_balls balls for check_frames frames, every piece of every path
    // tested exactly against every wall the grid returns.
    const std::size_t cb = std::min(ball_count, cfg.check_balls);
    std::vector<std::uint32_t> scratch;
    const auto check_ours = [&](Row& r) {
        std::vector<Ball> balls(start.begin(), start.begin() + static_cast<std::ptrdiff_t>(cb));
        std::vector<BallMemory> mem(cb);
        std::vector<HitEvent> hits;
        StepScratch ss;
        long long t = 0, h = 0;
        for (int f = 0; f < cfg.check_frames; ++f)
            for (std::size_t i = 0; i < cb; ++i) {
                hits.clear();
                Vec2 q = balls[i].pos;
                step_ball(KernelId::robust, balls[i], mem[i], walls, hits, ss, &grid);
                h += static_cast<long long>(hits.size());
                for (const HitEvent& e : hits) {
                    t += tunnels(q, e.point, walls, grid, scratch);
                    q = e.point;
                }
                t += tunnels(q, balls[i].pos, walls, grid, scratch);
            }
        r.tunnels = t;
        r.checked_ball_frames = cb * static_cast<std::size_t>(cfg.check_frames);
        r.hits_per_ball_frame = static_cast<double>(h) / static_cast<double>(r.checked_ball_frames);
    };

    // Ours: a World under the robust kernel, one thread, with the grid, the BVH, and brute force; a
    // frame's time includes making its events, as every user of World pays it.
    Scene scene;
    scene.walls = walls;
    scene.balls = start;
    const auto ours = [&](const char* method, BroadPhase broad_phase, bool check) {
        World world(scene, KernelId::robust, {.broad_phase = broad_phase, .threads = 1});
        std::vector<Event> events;
        Row r = base(method);
        if (check) check_ours(r);
        finish(r, time_per_frame(
                      [&] {
                          events.clear();
                          (void)world.step(events);
                      },
                      cfg.budget));
    };
    ours("robust+grid", BroadPhase::grid, true);
    const bool walls_sweep = sweep == "walls";
    if (walls_sweep || !cfg.quick) ours("robust+bvh", BroadPhase::bvh, false);
    if (static_cast<double>(walls.size()) * static_cast<double>(ball_count) <= cfg.brute_limit)
        ours("robust-brute", BroadPhase::none, false);

    // Discs against points: the same balls in the middle of their cells, as discs of a tenth of a cell and as
    // points, each World with the grid; the disc run checked by the harness's no-tunnel and penetration checks
    // over the checked frames (a failure counts as one, and robust has none).
    if (walls_sweep) {
        Scene discs = scene;
        discs.balls = scale::make_discs(ball_count, n, 2000 + ball_count);
        Scene points = discs;
        for (Ball& b : points.balls) b.r = 0.0;
        const auto stepped = [&](const char* method, const Scene& s, BroadPhase broad_phase, bool check) {
            World world(s, KernelId::robust, {.broad_phase = broad_phase, .threads = 1});
            std::vector<Event> events;
            Row r = base(method);
            if (check) {
                Scene checked = s;
                checked.balls.resize(cb);
                const Check checks[] = {Check::no_tunnel, Check::penetration};
                long long hits = 0;
                CheckOptions options;
                options.keep_events = false;
                options.on_frame = [&](std::span<const Event> frame) {
                    for (const Event& e : frame) hits += e.kind == Event::Kind::hit || e.kind == Event::Kind::bump;
                };
                const CheckedRun run = run_checked(checked, KernelId::robust, cfg.check_frames, checks, options);
                // The first failure only (the checked run stops there): never expected.
                const bool penetrated = run.failure && run.failure->check == Check::penetration;
                r.tunnels = (run.failure && !penetrated) || run.error ? 1 : 0;
                r.penetrations = penetrated ? 1 : 0;
                r.checked_ball_frames = cb * static_cast<std::size_t>(cfg.check_frames);
                r.hits_per_ball_frame = static_cast<double>(hits) / static_cast<double>(r.checked_ball_frames);
            }
            finish(r, time_per_frame(
                          [&] {
                              events.clear();
                              (void)world.step(events);
                          },
                          cfg.budget));
        };
        stepped("robust-point+grid", points, BroadPhase::grid, false);
        stepped("robust-disc+grid", discs, BroadPhase::grid, true);
        if (static_cast<double>(walls.size()) * static_cast<double>(ball_count) <= cfg.brute_limit)
            stepped("robust-disc-brute", discs, BroadPhase::none, false);
    }

    // The peers, each through its own loop (box2d_peer.hpp, chipmunk_peer.hpp), the points as they start and, in
    // the walls sweep, the discs of the disc rows. Checked over the first cb balls for check_frames frames: the
    // centre's pieces through the walls (tunnels) and, for discs, every contact and frame end whose centre is
    // closer to a wall than R − 0.01 (penetrations). Box2D stops a circle R − 0.005 from an edge by design (its
    // edges' skin of 2 slops, less the 3 slops its time of impact aims short of), give or take a quarter slop:
    // 0.01 is twice its slop.
    const std::vector<Ball> discs = walls_sweep ? scale::make_discs(ball_count, n, 2000 + ball_count) : std::vector<Ball>{};
    const auto peer = [&](const char* method, auto states, auto step, bool disc) {
        Row row = base(method);
        {
            auto c = states;
            c.resize(cb);
            std::vector<Vec2> hits;
            long long t = 0, pen = 0, h = 0;
            for (int f = 0; f < cfg.check_frames; ++f)
                for (auto& b : c) {
                    hits.clear();
                    Vec2 q = centre_of(b);
                    step(b, &hits);
                    h += static_cast<long long>(hits.size());
                    hits.push_back(centre_of(b));
                    for (Vec2 p : hits) {
                        t += tunnels(q, p, walls, grid, scratch);
                        if (disc) pen += within(p, scale::k_disc_radius - 0.01, walls, grid, scratch);
                        q = p;
                    }
                }
            row.tunnels = t;
            row.penetrations = disc ? pen : -1;
            row.checked_ball_frames = cb * static_cast<std::size_t>(cfg.check_frames);
            row.hits_per_ball_frame = static_cast<double>(h) / static_cast<double>(row.checked_ball_frames);
        }
        finish(row, time_per_frame(
                        [&] {
                            for (auto& b : states) step(b, nullptr);
                        },
                        cfg.budget));
    };
    if (scale::box2d_available()) {
        const scale::Box2dPeer box2d(walls);
        const auto floats = [](const std::vector<Ball>& balls) {
            std::vector<FloatBall> fb;
            for (const Ball& b : balls)
                fb.push_back({static_cast<float>(b.pos.x), static_cast<float>(b.pos.y), static_cast<float>(b.vel.x),
                              static_cast<float>(b.vel.y)});
            return fb;
        };
        peer("box2d-2.4.1", floats(start), [&](FloatBall& b, std::vector<Vec2>* hits) { box2d.step(b, hits); }, false);
        if (walls_sweep) {
            const float r = static_cast<float>(scale::k_disc_radius);
            peer("box2d-disc-2.4.1", floats(discs),
                 [&](FloatBall& b, std::vector<Vec2>* hits) { box2d.step_disc(b, r, hits); }, true);
        }
    }
    if (scale::chipmunk_available()) {
        const scale::ChipmunkPeer chipmunk(walls);
        const auto step = [&](Ball& b, std::vector<Vec2>* hits) { chipmunk.step(b, hits); };
        peer("chipmunk-7", start, step, false);
        if (walls_sweep) peer("chipmunk-disc-7", discs, step, true);
    }
}

/// The meet sweep at one size: count discs in a box (scale::make_box_discs), stepped by robust with the grid on one
/// thread, without and with `balls collide`. Each is first checked: the first check_balls discs (alone in the box) for
/// check_frames frames under the harness's no-tunnel and penetration, which read a meet as a printed point of the
/// path (a failure counts as one, robust has none), counting the contacts with walls and the meets. The two are then
/// timed side by side (time_per_frame_side_by_side): the target is their ratio.
void measure_meets(const Config& cfg, std::size_t count, std::vector<Row>& rows) {
    Scene base;
    base.walls = scale::make_box(count);
    base.balls = scale::make_box_discs(count, 3000 + count);
    Row measured[2];
    std::vector<std::unique_ptr<World>> worlds;
    for (const bool collide : {false, true}) {
        Scene scene = base;
        scene.balls_collide = collide;
        Row& r = measured[collide];
        r.sweep = "meet";
        r.method = collide ? "robust-meet+grid" : "robust-disc+grid";
        r.walls = scene.walls.size();
        r.balls = count;
        Scene checked = scene;
        checked.balls.resize(std::min(count, cfg.check_balls));
        const Check checks[] = {Check::no_tunnel, Check::penetration};
        long long hits = 0, meets = 0;
        CheckOptions options;
        options.keep_events = false;
        options.on_frame = [&](std::span<const Event> frame) {
            for (const Event& e : frame) {
                hits += e.kind == Event::Kind::hit;
                meets += e.kind == Event::Kind::meet;  // once under each of its two balls
            }
        };
        const CheckedRun run = run_checked(checked, KernelId::robust, cfg.check_frames, checks, options);
        const bool penetrated = run.failure && run.failure->check == Check::penetration;
        r.tunnels = (run.failure && !penetrated) || run.error ? 1 : 0;
        r.penetrations = penetrated ? 1 : 0;
        r.checked_ball_frames = checked.balls.size() * static_cast<std::size_t>(cfg.check_frames);
        r.hits_per_ball_frame = static_cast<double>(hits) / static_cast<double>(r.checked_ball_frames);
        r.meets_per_ball_frame = static_cast<double>(meets) / 2 / static_cast<double>(r.checked_ball_frames);
        worlds.push_back(std::make_unique<World>(scene, KernelId::robust,
                                                 WorldOptions{.broad_phase = BroadPhase::grid, .threads = 1}));
    }
    std::vector<Event> events;
    const auto stepper = [&events](World* world) {
        return [&events, world] {
            events.clear();
            (void)world->step(events);
        };
    };
    const std::function<void()> without = stepper(worlds[0].get()), with = stepper(worlds[1].get());
    const auto [t_without, t_with] = time_per_frame_side_by_side(without, with, cfg.budget);
    for (const bool collide : {false, true}) {
        Row& r = measured[collide];
        const FrameTime& t = collide ? t_with : t_without;
        r.ms_per_frame = t.wall * 1e3;
        r.ns_per_ball_frame = t.wall * 1e9 / static_cast<double>(count);
        r.cpu_ns_per_ball_frame = t.cpu * 1e9 / static_cast<double>(count);
        rows.push_back(r);
        fmt::print("{:<7} {:>8} walls {:>8} balls  {:<17} {:>10.4f} ms/frame {:>9.1f} ns/ball-frame ({:>7.1f} CPU)  "
                   "{:.3f} hits and {:.4f} meets/ball-frame, {} tunnels, {} penetrations in {} checked ball-frames\n",
                   r.sweep, r.walls, r.balls, r.method, r.ms_per_frame, r.ns_per_ball_frame, r.cpu_ns_per_ball_frame,
                   r.hits_per_ball_frame, r.meets_per_ball_frame, r.tunnels, r.penetrations, r.checked_ball_frames);
        std::fflush(stdout);
    }
}

/// The meet targets at `balls` discs: with `balls collide` at most 3× the cost per ball-frame of the same scene
/// without, and at most 1 µs per ball-frame on one core.
std::vector<bench::Verdict> meet_targets(const std::vector<Row>& rows, std::size_t balls, std::string label) {
    bench::Verdict ratio{.workload = label + ", against without", .limit = 3.0, .target = "≤ 3× without"};
    bench::Verdict time{.workload = label, .limit = 1000.0, .target = "≤ 1000 ns"};
    for (const Row& m : rows)
        if (m.sweep == "meet" && m.method == "robust-meet+grid" && m.balls == balls)
            for (const Row& d : rows)
                if (d.sweep == "meet" && d.method == "robust-disc+grid" && d.balls == balls) {
                    ratio.value = m.ns_per_ball_frame / d.ns_per_ball_frame;
                    ratio.robust = fmt::format("{:.0f} ns per ball-frame, without {:.0f} ns: {:.2f}×",
                                               m.ns_per_ball_frame, d.ns_per_ball_frame, ratio.value);
                    time.value = m.ns_per_ball_frame;
                    time.robust = fmt::format("{:.0f} ns per ball-frame ({} discs, R = {}), {} failed checks",
                                              m.ns_per_ball_frame, m.balls, scale::k_disc_radius,
                                              m.tunnels + m.penetrations);
                }
    return {ratio, time};
}

/// scale.csv's columns, one row a line.
void write_csv(const std::vector<Row>& rows, const std::string& path) {
    bench::ResultFile csv(path);
    csv.print("sweep,method,walls,balls,threads,ms_per_frame,ns_per_ball_frame,cpu_ns_per_ball_frame,"
              "hits_per_ball_frame,tunnels,checked_ball_frames,penetrations\n");
    for (const Row& r : rows)
        csv.print("{},{},{},{},{},{},{},{},{},{},{},{}\n", r.sweep, r.method, r.walls, r.balls, r.threads,
                  r.ms_per_frame, r.ns_per_ball_frame, r.cpu_ns_per_ball_frame, r.hits_per_ball_frame, r.tunnels,
                  r.checked_ball_frames, r.penetrations);
    csv.close();
}

/// The targets' peers column: each peer's row at ours's point, its time and ratio to ours, its failures.
std::string peers_column(const std::vector<Row>& rows, const Row& ours,
                         std::initializer_list<std::pair<const char*, const char*>> peers) {
    std::string out;
    for (const auto& [method, name] : peers)
        for (const Row& p : rows)
            if (p.sweep == ours.sweep && p.walls == ours.walls && p.balls == ours.balls && p.method == method) {
                out += fmt::format("{}{} {:.0f} ns ({:.1f}×), {} tunnels", out.empty() ? "" : "; ", name,
                                   p.ns_per_ball_frame, p.ns_per_ball_frame / ours.ns_per_ball_frame, p.tunnels);
                if (p.penetrations >= 0) out += fmt::format(", {} penetrations", p.penetrations);
            }
    return out;
}

/// The maze targets: robust+grid at most limit ns per ball-frame in the walls sweep's maze of about `walls` walls
/// (within a factor of 2: the lattice rounds), with Box2D's row at the same point.
bench::Verdict maze_target(const std::vector<Row>& rows, std::string label, double walls, double limit) {
    bench::Verdict v{.workload = std::move(label), .limit = limit, .target = fmt::format("≤ {} ns", limit)};
    const auto at = [&](const Row& r, const char* method) {
        const double w = static_cast<double>(r.walls);
        return r.sweep == "walls" && r.method == method && w >= walls / 2 && w <= walls * 2;
    };
    for (const Row& r : rows)
        if (at(r, "robust+grid")) {
            v.value = r.ns_per_ball_frame;
            v.robust = fmt::format("{:.0f} ns per ball-frame ({} walls, {} balls), {} tunnels", r.ns_per_ball_frame,
                                   r.walls, r.balls, r.tunnels);
            v.peers = peers_column(rows, r, {{"box2d-2.4.1", "Box2D 2.4.1"}, {"chipmunk-7", "Chipmunk 7"}});
        }
    return v;
}

/// The disc target: robust-disc+grid at most 1.5× robust-point+grid (the same balls) in the walls sweep's maze of
/// about `walls` walls.
bench::Verdict disc_target(const std::vector<Row>& rows, std::string label, double walls) {
    bench::Verdict v{.workload = std::move(label), .limit = 1.5, .target = "≤ 1.5× a point's"};
    const auto at = [&](const Row& r, const char* method) {
        const double w = static_cast<double>(r.walls);
        return r.sweep == "walls" && r.method == method && w >= walls / 2 && w <= walls * 2;
    };
    for (const Row& d : rows)
        if (at(d, "robust-disc+grid"))
            for (const Row& p : rows)
                if (at(p, "robust-point+grid") && p.walls == d.walls) {
                    v.value = d.ns_per_ball_frame / p.ns_per_ball_frame;
                    v.robust = fmt::format("{:.0f} ns per ball-frame, points {:.0f} ns: {:.2f}× ({} walls, {} balls, R = "
                                           "{}), {} failed checks",
                                           d.ns_per_ball_frame, p.ns_per_ball_frame, v.value, d.walls, d.balls,
                                           scale::k_disc_radius, d.tunnels + d.penetrations);
                    v.peers = peers_column(rows, d, {{"box2d-disc-2.4.1", "Box2D 2.4.1 discs"},
                                                     {"chipmunk-disc-7", "Chipmunk 7 discs"}});
                }
    return v;
}

/// The maze and thread targets of one run (bench/include/ricochet_bench/targets.hpp); speed_up2: the thread sweep's
/// speed-up on 2 threads, NaN if it had fewer.
std::vector<bench::Verdict> scale_targets(const std::vector<Row>& rows, double speed_up2, std::size_t walls,
                                          std::size_t balls) {
    std::vector<bench::Verdict> out{maze_target(rows, "maze, 10^4 walls", 1e4, 50),
                                    maze_target(rows, "maze, 10^5 walls", 1e5, 80),
                                    maze_target(rows, "maze, 10^6 walls", 1e6, 80),
                                    disc_target(rows, "discs in the maze, 10^4 walls", 1e4),
                                    disc_target(rows, "discs in the maze, 10^5 walls", 1e5)};
    bench::Verdict t{.workload = "2 threads against 1", .value = speed_up2, .limit = 1.96, .at_least = true,
                     .target = "≥ 1.96× (kept)"};
    if (!std::isnan(speed_up2)) t.robust = fmt::format("speed-up {:.2f}× ({} walls, {} balls)", speed_up2, walls, balls);
    out.push_back(t);
    for (const auto& [n, label] : {std::pair<std::size_t, const char*>{1000, "discs that meet in a box, 10^3"},
                                   std::pair<std::size_t, const char*>{10000, "discs that meet in a box, 10^4"}})
        for (bench::Verdict& v : meet_targets(rows, n, label)) out.push_back(std::move(v));
    return out;
}

int lattice_for(std::size_t walls) { return std::max(2, static_cast<int>(std::lround(std::sqrt(static_cast<double>(walls))))); }

}  // namespace

int run_scale_bench(ScaleSize size, unsigned threads, const std::string& out_dir) {
    const Config cfg = config(size);
    const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
    const unsigned max_threads = threads == 0 ? hw : threads;
    fmt::print("ricochet bench scale{}: robust kernel, maze of unit cells, balls at 0.05-0.5 cells/frame; one thread "
               "unless stated; {} hardware threads{}\n",
               size_flag(size), hw,
               std::string(scale::box2d_available() ? "" : "; Box2D not found, its columns skipped") +
                   (scale::chipmunk_available() ? "" : "; Chipmunk not found, its columns skipped"));
    std::vector<Row> rows;
    for (std::size_t w : cfg.wall_sizes) measure(cfg, "walls", lattice_for(w), cfg.sweep_balls, rows);
    for (std::size_t b : cfg.ball_sizes) measure(cfg, "balls", lattice_for(cfg.maze_walls), b, rows);
    for (std::size_t b : cfg.meet_sizes) measure_meets(cfg, b, rows);

    double speed_up2 = NAN;
    std::size_t thread_walls = 0;
    // Threads: the headline scene (10^4 walls, 10^5 balls; smaller with --smoke) on 1 .. max_threads threads.
    {
        const int n = lattice_for(cfg.maze_walls);
        const std::vector<Wall> walls = make_maze(n, 1000 + static_cast<std::uint64_t>(n));
        const std::size_t nb = cfg.thread_balls;
        Scene scene;
        scene.walls = walls;
        scene.balls = make_balls(nb, n, 2000 + nb);
        std::vector<unsigned> counts;
        for (unsigned t = 1; t < max_threads; t *= 2) counts.push_back(t);
        counts.push_back(max_threads);
        double one = 0;
        thread_walls = walls.size();
        for (unsigned t : counts) {
            World world(scene, KernelId::robust, {.broad_phase = BroadPhase::grid, .threads = t});
            std::vector<Event> events;
            const double s = time_per_frame(
                                 [&] {
                                     events.clear();
                                     (void)world.step(events);
                                 },
                                 cfg.budget)
                                 .wall;
            if (t == 1) one = s;
            if (t == 2) speed_up2 = one / s;
            Row r;
            r.sweep = "threads";
            r.method = "robust+grid";
            r.walls = walls.size();
            r.balls = nb;
            r.threads = t;
            r.ms_per_frame = s * 1e3;
            r.ns_per_ball_frame = s * 1e9 / static_cast<double>(nb);
            rows.push_back(r);
            fmt::print("threads {:>3}: {:>8} walls {:>8} balls {:>9.3f} ms/frame, speed-up {:.2f}\n", t, r.walls, nb,
                       r.ms_per_frame, one / s);
        }
    }

    // CSV, gnuplot data and chart.
    std::filesystem::create_directories(out_dir);
    const std::string csv_path = out_dir + "/scale.csv";
    write_csv(rows, csv_path);
    const std::vector<std::string> methods{"robust+grid",      "robust+bvh",       "robust-brute",
                                           "box2d-2.4.1",      "chipmunk-7",       "robust-disc+grid",
                                           "box2d-disc-2.4.1", "chipmunk-disc-7"};
    {
        bench::ResultFile dat(out_dir + "/scale.dat");
        for (const char* sweep : {"walls", "balls"})
            for (const std::string& m : methods) {
                dat.print("# {} {}\n", sweep, m);
                bool any = false;
                for (const Row& r : rows)
                    if (r.sweep == sweep && r.method == m) {
                        dat.print("{} {}\n", std::string_view(sweep) == "walls" ? r.walls : r.balls, r.ns_per_ball_frame);
                        any = true;
                    }
                if (!any) dat.print("nan nan\n");
                dat.print("\n\n");
            }
        dat.close();
    }
    {
        bench::ResultFile gp(out_dir + "/scale.gp");
        gp.print("set terminal pngcairo size 1400,560 font ',11'\nset output '{}/scale.png'\n", out_dir);
        gp.print("set multiplot layout 1,2 title 'ricochet bench scale{}: ns per ball-frame (one thread, shared "
                 "machine)'\nset logscale xy\nset grid\nset ylabel 'ns per ball-frame'\nset key top left\n",
                 size_flag(size));
        for (int s = 0; s < 2; ++s) {
            gp.print("set xlabel '{}'\n", s == 0 ? fmt::format("walls ({} balls)", cfg.sweep_balls) : fmt::format("balls ({}-wall maze)", cfg.maze_walls));
            gp.print("plot ");
            for (std::size_t m = 0; m < methods.size(); ++m)
                gp.print("{}'{}/scale.dat' index {} with linespoints lw 2 title '{}'", m ? ", " : "", out_dir,
                         s * static_cast<int>(methods.size()) + static_cast<int>(m), methods[m]);
            gp.print("\n");
        }
        gp.print("unset multiplot\n");
        gp.close();
    }
    const std::string cmd = fmt::format("gnuplot '{}/scale.gp'", out_dir);
    if (std::system(cmd.c_str()) != 0) fmt::print("gnuplot failed; the data is in {}\n", csv_path);
    fmt::print("wrote {}, {}/scale.png\n", csv_path, out_dir);

    bench::report_targets(scale_targets(rows, speed_up2, thread_walls, cfg.thread_balls),
                          size == ScaleSize::smoke
                              ? "scale targets (--smoke: sizes too small to measure; a check of the table only)"
                              : fmt::format("scale targets: ricochet bench scale{}, one thread unless stated",
                                            size_flag(size)),
                          out_dir + "/scale_targets.md");

    long long robust_tunnels = 0;
    for (const Row& r : rows)
        if (r.method == "robust+grid" || r.method == "robust-disc+grid" || r.method == "robust-meet+grid")
            robust_tunnels += std::max(0LL, r.tunnels) + std::max(0LL, r.sweep == "meet" ? r.penetrations : 0LL);
    return robust_tunnels == 0 ? 0 : 1;
}

int run_meet_bench(ScaleSize size, const std::string& out_dir) {
    const Config cfg = config(size);
    fmt::print("ricochet bench scale --meet{}: robust kernel, grid, one thread; discs of radius {} in a box, one per "
               "2x2 cell, 0.05-0.5 units/frame, without and with balls collide\n",
               size_flag(size), scale::k_disc_radius);
    std::vector<Row> rows;
    for (std::size_t b : cfg.meet_sizes) measure_meets(cfg, b, rows);
    std::filesystem::create_directories(out_dir);
    write_csv(rows, out_dir + "/meet.csv");
    std::vector<bench::Verdict> verdicts;
    for (const auto& [n, label] : {std::pair<std::size_t, const char*>{1000, "discs that meet in a box, 10^3"},
                                   std::pair<std::size_t, const char*>{10000, "discs that meet in a box, 10^4"}})
        for (bench::Verdict& v : meet_targets(rows, n, label)) verdicts.push_back(std::move(v));
    bench::report_targets(verdicts,
                          size == ScaleSize::smoke
                              ? "meet targets (--smoke: sizes too small to measure; a check of the table only)"
                              : fmt::format("meet targets: ricochet bench scale --meet{}, one thread", size_flag(size)),
                          out_dir + "/meet_targets.md");
    fmt::print("wrote {}/meet.csv\n", out_dir);
    for (const Row& r : rows)
        if (r.tunnels > 0 || r.penetrations > 0) return 1;
    return 0;
}

}  // namespace ricochet
