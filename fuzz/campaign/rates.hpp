// What a campaign's closing table says of speed: each worker's inputs over its own running time, read from its
// log and its processes' lifetimes, never the whole campaign's time (a fast target's workers end long before a
// slow one's, and over the campaign's time every target would show the same rate).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace ricochet::fuzz {

/// One worker's work: the inputs its processes ran and the seconds they ran, one after another (a worker
/// restarted after a failure has several processes, all counted).
struct WorkerTally {
    std::uint64_t runs = 0;  ///< inputs run (libFuzzer's stat::number_of_executed_units, else its last "#N")
    double seconds = 0.0;    ///< wall seconds from each process's start to its end, summed
};

/// The number after key in line (e.g. "cov: " in libFuzzer's "#N NEW cov: 812 ..."), if digits follow it.
std::optional<std::uint64_t> number_after(std::string_view line, std::string_view key);

/// The inputs run by the libFuzzer processes whose output, one process after another, is log: for each, its
/// final `stat::number_of_executed_units`, else (a process killed before it printed its statistics) its last
/// "#N" line.
std::uint64_t runs_in_log(std::string_view log);

/// One worker's own rate: runs / seconds; 0 for a worker that never ran.
double exec_per_s(const WorkerTally& worker);

/// A target's rate per worker: its workers' runs over their running time, both summed (what one worker did in
/// a second, on average over the time they ran); 0 if none ran.
double exec_per_s_per_worker(std::span<const WorkerTally> workers);

/// A target's rate in all: its workers' own rates summed (they run side by side, so this is the inputs per
/// second of the whole target, what `--jobs` scaling measures).
double exec_per_s_in_all(std::span<const WorkerTally> workers);

}  // namespace ricochet::fuzz
