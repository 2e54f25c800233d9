// The benchmark driver behind `ricochet bench`: run time against error for every method and workload,
// the stability sweep, the ball-frames/s run. Prints with fmt, writes CSV and gnuplot charts.
#pragma once

#include <cstdint>
#include <string>

namespace ricochet::bench {

/// How big a run is and where its files go.
struct Options {
    bool quick = false;                     ///< smaller query sets: under 2 minutes on 2 cores
    bool smoke = false;                     ///< tiny sets, one repetition: a correctness check for CTest
    std::string out_dir = "bench-results";  ///< CSV and charts: in the current folder, never the tracked bench/results unless asked
    std::uint64_t seed = 20261123;          ///< every workload is generated from this seed
    bool chart = true;                      ///< draw the charts with gnuplot
};

/// The main table. Returns 0, or 1 if robust made a wrong decision or tunnelled (a bug, whatever the mode).
int run_bench(const Options& opt);
/// Error and tunnelling against coordinate magnitude (1..1e15) and angle to the wall (1..1e-15).
int run_stability(const Options& opt);
/// One ball bouncing in a closed box of walls with the robust kernel: ball-frames per second.
int run_frames(const Options& opt, long frames);

}  // namespace ricochet::bench
