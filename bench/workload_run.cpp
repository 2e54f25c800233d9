// One bench workload through one kernel, once, and what the exact predicates' fallbacks did: the program
// callgrind counts instructions per query on (README, "Benchmarks"), the queries' loop in run_queries alone:
//
//   valgrind --tool=callgrind --toggle-collect='*run_queries*' ricochet_workload circle-circle robust 50000 1
//
//   ricochet_workload WORKLOAD [KERNEL] [N] [SEED]   defaults: robust, 50000 queries, seed 1
//
// WORKLOAD is a static test (point-circle, circle-circle, point-rect, rect-rect) or a sweep workload (uniform,
// far, end-on-wall, at-endpoint, grazing, tiny-v, huge-v) of src/workloads.cpp, N queries of it from SEED; or a
// closed box (box, box-turned, box-far-1e6, box-far-1e12: N ball-frames, 8 balls of `ricochet bench --quick`'s
// box stepped N/8 frames each, the loop in run_frames alone:  --toggle-collect='*run_frames*'); or a disc workload
// (disc-uniform, disc-grazing, disc-cap, disc-joint, bumper) of src/disc_workloads.cpp: one frame of step_ball per
// query, as `ricochet bench` times it, the loop in run_queries; "hit" counts the frames with a contact; or the maze
// of `ricochet bench scale` (maze: 10 444 walls, 2 000 balls in a World with the grid, N/2000 frames, the loop in
// run_frames; "hit" counts the events). The fallback
// counts are the point predicates' (predicates.hpp): the disc code keeps none, so they read 0 for a disc workload.
// Exit status 2 for an unknown workload or kernel, or a count or seed that is not a number.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "ricochet/kernel.hpp"
#include "ricochet/predicates.hpp"
#include "ricochet/world.hpp"
#include "disc_workloads.hpp"
#include "scale_bench.hpp"
#include "workloads.hpp"

using namespace ricochet;
using namespace ricochet::bench;

namespace {

/// The static queries, answered by kernel k: how many are inside or overlapping.
[[gnu::noinline]] long run_queries(const StaticWorkload& w, KernelId k) {
    long yes = 0;
    for (const StaticQuery& q : w.queries) {
        switch (q.kind) {
            case StaticKind::point_circle: yes += point_in_circle(k, q.p, q.a); break;
            case StaticKind::circle_circle: yes += circles_overlap(k, q.a, q.b); break;
            case StaticKind::point_rect: yes += point_in_rect(k, q.p, q.ra); break;
            case StaticKind::rect_rect: yes += rects_overlap(k, q.ra, q.rb); break;
        }
    }
    return yes;
}

/// The sweep queries, answered by kernel k: how many hit.
[[gnu::noinline]] long run_queries(const SweepWorkload& w, KernelId k) {
    long hits = 0;
    for (const SweepQuery& q : w.queries) hits += sweep(k, q.bs, q.v, q.wall).hit();
    return hits;
}

/// The disc queries, one frame of step_ball each through kernel k: how many hit something.
[[gnu::noinline]] long run_queries(const DiscWorkload& w, KernelId k) {
    std::vector<HitEvent> hits;
    StepScratch scratch;
    long n = 0;
    for (const DiscQuery& q : w.queries) {
        Ball b{q.bs, q.v, q.R};
        BallMemory memory;
        hits.clear();
        step_ball(k, b, memory, Obstacles{q.wall_span(), q.bumper_span(), nullptr}, hits, scratch);
        n += !hits.empty();
    }
    return n;
}

/// The closed box's balls, stepped by kernel k for frames frames each: how many bounces.
[[gnu::noinline]] long run_frames(const BoxWorkload& box, std::vector<Ball> balls, std::uint64_t frames, KernelId k) {
    const std::vector<Wall> walls = make_box(box.offset, box.angle);
    std::vector<HitEvent> hits;
    StepScratch scratch;
    long bounces = 0;
    for (Ball& b : balls) {
        BallMemory memory;
        for (std::uint64_t f = 0; f < frames; ++f) {
            hits.clear();
            step_ball(k, b, memory, walls, hits, scratch);
            bounces += static_cast<long>(hits.size());
        }
    }
    return bounces;
}

/// A World stepped frames frames (the maze: the scale bench's scene, grid on, one thread): how many events.
[[gnu::noinline]] long run_frames(World& world, std::uint64_t frames) {
    std::vector<Event> events;
    long n = 0;
    for (std::uint64_t f = 0; f < frames; ++f) {
        events.clear();
        (void)world.step(events);
        n += static_cast<long>(events.size());
    }
    return n;
}

std::optional<std::uint64_t> number(const char* s) {
    try {
        std::size_t used = 0;
        const unsigned long long v = std::stoull(s, &used);
        if (s[used] != '\0') return std::nullopt;
        return v;
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

int usage(const std::string& what) {
    fmt::print(stderr, "ricochet_workload: error: {}\nusage: ricochet_workload WORKLOAD [KERNEL] [N] [SEED]\n", what);
    return 2;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2 || argc > 5) return usage("expected a workload, then optionally a kernel, a count and a seed");
    const std::string name = argv[1];
    const std::optional<KernelId> kernel = parse_kernel(argc > 2 ? argv[2] : "robust");
    if (!kernel) return usage(fmt::format("unknown kernel '{}' (one of {})", argv[2], kernel_names()));
    const std::optional<std::uint64_t> n = argc > 3 ? number(argv[3]) : 50000;
    if (!n || *n == 0) return usage(fmt::format("the count must be a positive number, not '{}'", argv[3]));
    const std::optional<std::uint64_t> seed = argc > 4 ? number(argv[4]) : 1;
    if (!seed) return usage(fmt::format("the seed must be a number, not '{}'", argv[4]));

    std::optional<long> answers;
    for (const StaticWorkload& w : static_workloads(*n, *seed))
        if (w.name == name) answers = run_queries(w, *kernel);
    if (!answers)
        for (const SweepWorkload& w : sweep_workloads(*n, *seed))
            if (w.name == name) answers = run_queries(w, *kernel);
    // Disc workloads cost more to make (each start is checked exactly): made only when one is named.
    const auto disc_names = disc_workload_names();
    if (!answers && std::find(disc_names.begin(), disc_names.end(), name) != disc_names.end())
        for (const DiscWorkload& w : disc_workloads(*n, *seed))
            if (w.name == name) answers = run_queries(w, *kernel);
    for (const BoxWorkload& box : box_workloads())
        if (!answers && box.name == name) {
            // 8 balls, as `ricochet bench --quick`, from SEED + 2 as the bench draws its boxes from its seed + 2.
            constexpr std::uint64_t k_balls = 8;
            const std::vector<Ball> balls = make_balls(box.offset, box.angle, k_balls, *seed + 2);
            answers = run_frames(box, balls, std::max<std::uint64_t>(*n / k_balls, 1), *kernel);
        }
    if (!answers && name == "maze") {
        // The scale bench's maze of lattice 100 (10 444 walls, drawn from seed 1100 as the bench draws it) and 2 000
        // balls (seed 4000, as its walls sweep with --quick), the World made first; N ball-frames; SEED unused.
        constexpr int k_lattice = 100;
        constexpr std::uint64_t k_balls = 2000;
        Scene scene;
        scene.walls = scale::make_maze(k_lattice, 1000 + k_lattice);
        scene.balls = scale::make_balls(k_balls, k_lattice, 2000 + k_balls);
        World world(scene, *kernel, {.broad_phase = BroadPhase::grid, .threads = 1});
        answers = run_frames(world, std::max<std::uint64_t>(*n / k_balls, 1));
    }
    if (!answers) return usage(fmt::format("unknown workload '{}'", name));

    const exact::FallbackCounts f = exact::fallback_counts();
    fmt::print("{} {}: {} queries from seed {}, {} yes or hit; filter declined {}: ordered {}, bounded {}, "
               "complete {}, gmp {}\n",
               name, kernel_name(*kernel), *n, *seed, *answers, f.expansion + f.gmp, f.ordered, f.bounded,
               f.complete, f.gmp);
    return 0;
}
