// `ricochet bench` (command.hpp): run time against error (the main table), `bench stability`,
// `bench frames`, `bench scale`. The heavy lifting is in the ricochet_bench and ricochet_scale libraries;
// this file only wires the options.
#include "ricochet_bench/command.hpp"

#include <cstdint>
#include <exception>
#include <memory>

#include <fmt/format.h>

#include "ricochet_bench/bench.hpp"
#include "scale_bench.hpp"
#ifdef RICOCHET_HAVE_MEET_BENCH
#include "meet_bench.hpp"
#endif

namespace ricochet::bench {

void register_bench(CLI::App& app) {
    auto opt = std::make_shared<ricochet::bench::Options>();
    auto frames = std::make_shared<long>(20'000'000);
    CLI::App* cmd = app.add_subcommand("bench", "Benchmark run time against error: every kernel and peer on the same workloads");
    cmd->add_flag("--quick", opt->quick, "Smaller query sets (under 2 minutes)");
    cmd->add_flag("--smoke", opt->smoke, "Tiny sets, one repetition: a correctness check (exit 1 if robust is ever wrong)")
        ->excludes("--quick");
    cmd->add_option("--out", opt->out_dir, "Folder for the CSV and the charts")->capture_default_str();
    cmd->add_option("--seed", opt->seed, "Seed of every workload")->capture_default_str();
    cmd->add_flag("!--no-chart", opt->chart, "Do not run gnuplot");

    CLI::App* stab = cmd->add_subcommand("stability", "Error and tunnelling against coordinate magnitude and angle to the wall");
    stab->add_flag("--quick", opt->quick, "Smaller query sets");
    stab->add_flag("--smoke", opt->smoke, "Tiny sets")->excludes("--quick");
    stab->add_option("--out", opt->out_dir, "Folder for the CSV and the charts")->capture_default_str();
    stab->add_option("--seed", opt->seed, "Seed of every workload")->capture_default_str();
    stab->add_flag("!--no-chart", opt->chart, "Do not run gnuplot");
    CLI::App* fr = cmd->add_subcommand("frames", "One ball in a closed box, robust kernel: ball-frames per second");
    fr->add_option("--frames", *frames, "Frames per run")->capture_default_str();
    fr->add_flag("--smoke", opt->smoke, "One run");
    // The scaling benchmark (bench/scale, ricochet_scale): walls and balls from 10 to 10^6.
    auto threads = std::make_shared<unsigned>(0);
    CLI::App* sc = cmd->add_subcommand("scale", "Per-frame cost as walls and balls grow: brute force, grid, BVH, Box2D");
    sc->add_flag("--quick", opt->quick, "Smaller scenes (about a minute)");
    sc->add_flag("--smoke", opt->smoke, "Tiny scenes, a second: a correctness check (exit 1 if robust tunnelled)")
        ->excludes("--quick");
    auto meet_only = std::make_shared<bool>(false);
    sc->add_flag("--meet", *meet_only, "Only the meet sweep: discs in a box without and with balls collide");
    sc->add_option("--threads", *threads, "Worker threads (0: all cores)")->capture_default_str();
    sc->add_option("--out", opt->out_dir, "Folder for the CSV and the chart")->capture_default_str();

    auto meet_frames = std::make_shared<std::int64_t>(0);  // 0: the size's own
#ifdef RICOCHET_HAVE_MEET_BENCH
    // What the peers miss when balls meet (bench/meet, ricochet_meet).
    CLI::App* mt = cmd->add_subcommand("meet", "Balls that meet: robust, lecture-double, Box2D and Chipmunk side by side");
    // (ricochet_meet_bench --quick: a quarter of the frames, 3 runs.)
    mt->add_flag("--smoke", opt->smoke, "25 discs, 5 frames: a correctness check (exit 1 if robust missed a meet)");
    mt->add_option("--seed", opt->seed, "Seed of the scenes");
    mt->add_option("--frames", *meet_frames, "Frames of the slow and fast scenes (the cost scene: a quarter)");
#else
    CLI::App* mt = nullptr;
#endif

    cmd->callback([cmd, stab, fr, sc, mt, opt, frames, threads, meet_frames, meet_only] {
        int rc = 0;
        try {
            if (stab->parsed()) rc = run_stability(*opt);
            else if (fr->parsed()) rc = run_frames(*opt, *frames);
#ifdef RICOCHET_HAVE_MEET_BENCH
            else if (mt->parsed())
                rc = meet_bench::run_meet_bench(opt->smoke ? meet_bench::MeetSize::smoke : meet_bench::MeetSize::full,
                                                opt->seed, *meet_frames);
#endif
            else if (sc->parsed()) {
                const ScaleSize size = opt->smoke ? ScaleSize::smoke : opt->quick ? ScaleSize::quick : ScaleSize::full;
                rc = *meet_only ? ricochet::run_meet_bench(size, opt->out_dir)
                                : ricochet::run_scale_bench(size, *threads, opt->out_dir);
            }
            else rc = run_bench(*opt);
        } catch (const std::exception& e) {
            // An output folder or file that cannot be written (the only failure a run can meet).
            fmt::print(stderr, "{}: error: {}\n", opt->out_dir, e.what());
            throw CLI::RuntimeError(2);
        }
        (void)cmd;
        (void)mt;
        (void)meet_frames;
        if (rc != 0) throw CLI::RuntimeError(rc);
    });
}

}  // namespace ricochet::bench
