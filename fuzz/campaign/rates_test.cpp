// rates.hpp: the runs read from libFuzzer's own output (fixed text, as fuzz_static printed it), and each
// worker's rate over its own running time. Numbers fed in decide every verdict; no clock runs.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "rates.hpp"

namespace ricochet::fuzz {
namespace {

// One process run to its -runs: `RICOCHET_KERNEL=robust fuzz_static -seed=1 -runs=1000 -print_final_stats=1 CORPUS`,
// CORPUS a copy of fuzz/corpus/static/, shortened.
const std::string k_done =
    "INFO: Running with entropic power schedule (0xFF, 100).\n"
    "INFO: Seed: 1\n"
    "INFO:       25 files found in corpus\n"
    "INFO: seed corpus: files: 25 min: 1b max: 8b total: 110b rss: 41Mb\n"
    "#26\tINITED cov: 1772 ft: 2511 corp: 25/110b exec/s: 0 rss: 45Mb\n"
    "#28\tNEW    cov: 1772 ft: 2521 corp: 26/115b lim: 8 exec/s: 0 rss: 46Mb L: 5/8 MS: 2 InsertByte-CrossOver-\n"
    "#599\tREDUCE cov: 1804 ft: 2938 corp: 68/418b lim: 8 exec/s: 599 rss: 115Mb L: 6/8 MS: 1 EraseBytes-\n"
    "#1000\tDONE   cov: 1807 ft: 2965 corp: 75/468b lim: 8 exec/s: 1000 rss: 157Mb\n"
    "Done 1000 runs in 1 second(s)\n"
    "stat::number_of_executed_units: 1000\n"
    "stat::average_exec_per_sec:     1000\n"
    "stat::new_units_added:          55\n"
    "stat::slowest_unit_time_sec:    0\n"
    "stat::peak_rss_mb:              157\n";

TEST(RunsInLog, FinalStatistics) {
    EXPECT_EQ(runs_in_log(k_done), 1000u);
}

TEST(RunsInLog, RestartedAfterAFailureThenKilled) {
    // A process stops at a failure (its statistics printed by libFuzzer's crash handler), the worker is
    // restarted into the same log, and the restart is killed (SIGKILL) before it prints statistics: its last
    // "#N" counts.
    const std::string crashed =
        "#27\tINITED cov: 2813 ft: 4310 corp: 26/1466b exec/s: 0 rss: 61Mb\n"
        "#4096\tpulse  cov: 2830 ft: 4400 corp: 40/2kb lim: 128 exec/s: 2048 rss: 70Mb\n"
        "==ricochet-fuzz== FAILURE target=static kernel=lecture-double check=side frame=0 kind=side\n"
        "==4242== ERROR: libFuzzer: deadly signal\n"
        "stat::number_of_executed_units: 4321\n"
        "stat::average_exec_per_sec:     2160\n";
    const std::string killed =
        "#41\tINITED cov: 2830 ft: 4400 corp: 40/2kb exec/s: 0 rss: 62Mb\n"
        "#2048\tpulse  cov: 2831 ft: 4402 corp: 41/2kb lim: 128 exec/s: 1024 rss: 66Mb\n";
    EXPECT_EQ(runs_in_log(crashed + killed), 4321u + 2048u);
    EXPECT_EQ(runs_in_log(killed + k_done), 2048u + 1000u);
}

TEST(RunsInLog, NothingRun) {
    EXPECT_EQ(runs_in_log(""), 0u);
    EXPECT_EQ(runs_in_log("INFO: Seed: 1\n==17== ERROR: libFuzzer: out-of-memory\n"), 0u);
}

TEST(Rates, EachTargetOverItsOwnTime) {
    // `ricochet check`'s campaign: 10 000 inputs per target, one worker each, side by side. The campaign's
    // workers fuzzed for 39.8 s, the disc target's time; over that time every target showed 251 exec/s.
    // Over its own time, each shows its own rate.
    const std::vector<WorkerTally> parser = {{10000, 0.8}}, sweep = {{10000, 8.0}}, disc = {{10000, 39.8}};
    EXPECT_DOUBLE_EQ(exec_per_s_per_worker(parser), 12500.0);
    EXPECT_DOUBLE_EQ(exec_per_s_per_worker(sweep), 1250.0);
    EXPECT_NEAR(exec_per_s_per_worker(disc), 251.26, 0.01);
    // One worker: per worker and in all are the same number.
    EXPECT_DOUBLE_EQ(exec_per_s_in_all(sweep), exec_per_s_per_worker(sweep));
}

TEST(Rates, SeveralWorkers) {
    // Two workers of one target (--jobs 2): one ran 3000 inputs in 2 s, the other 1000 in 1 s (it started late,
    // or stopped at a failure and was not restarted).
    const std::vector<WorkerTally> two = {{3000, 2.0}, {1000, 1.0}};
    // Per worker: 4000 inputs in 3 worker-seconds.
    EXPECT_DOUBLE_EQ(exec_per_s_per_worker(two), 4000.0 / 3.0);
    // In all: side by side, 1500 + 1000 inputs a second.
    EXPECT_DOUBLE_EQ(exec_per_s_in_all(two), 2500.0);
}

TEST(Rates, Degenerate) {
    // A worker that never ran (no time) adds nothing, and is no division by zero.
    EXPECT_EQ(exec_per_s(WorkerTally{}), 0.0);
    EXPECT_EQ(exec_per_s_per_worker({}), 0.0);
    EXPECT_EQ(exec_per_s_in_all({}), 0.0);
    const std::vector<WorkerTally> one_idle = {{500, 0.5}, {0, 0.0}};
    EXPECT_DOUBLE_EQ(exec_per_s_in_all(one_idle), 1000.0);
    EXPECT_DOUBLE_EQ(exec_per_s_per_worker(one_idle), 1000.0);
}

}  // namespace
}  // namespace ricochet::fuzz
