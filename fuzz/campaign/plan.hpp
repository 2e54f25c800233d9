// The campaign's plan: one run per target (its binary, folders, workers and what it found), made from
// the options after checking that every binary is a libFuzzer one.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "budget.hpp"
#include "rates.hpp"
#include "ricochet_fuzz/campaign.hpp"

namespace ricochet::fuzz {

/// What became of one failure artifact.
enum class FailureStatus : std::uint8_t {
    saved,      ///< converted: its scene log saved as a new case
    known,      ///< converted: the same case was already in the replay folder
    no_log,     ///< a new failure with no scene log (the parser's inputs, sanitizer reports, hangs): the input reproduces it
    unsaved,    ///< a new failure whose log could not be saved
    flaky,      ///< it did not fail when run again
    duplicate,  ///< the same failure as one converted before it in this campaign
    slow,       ///< ran past libFuzzer's -timeout in the campaign, but every check held when run again alone
    pending,    ///< not converted (stopped, out of time, or past the most converted per campaign): left for the next campaign
};

/// The word JSON documents and tables use for status: "saved", "known", "no-log", ...
std::string_view status_name(FailureStatus status);

/// One failure artifact a campaign (or `ricochet fuzz convert`) met, and what became of it.
struct FailureRecord {
    std::string target;                    ///< the fuzz target
    std::string kernel;                    ///< the kernel under test (a plug-in's own name)
    std::filesystem::path artifact;        ///< the raw input where it is kept (the cache's artifacts/ or pending/)
    FailureStatus status = FailureStatus::pending;
    std::string check;                     ///< the check that failed (the saved log's `found`, else the target's report); empty if none
    std::optional<std::uint64_t> frame;    ///< its frame
    std::optional<std::uint64_t> ball;     ///< its ball (a saved log's `found` line names it)
    std::filesystem::path log;             ///< the saved log (new or the known case's); empty if none
    std::string message;                   ///< the failure's first line (the target's report or the sanitizer's summary)
    /// True for a failure that counts as new: saved, no_log, unsaved, flaky, or pending (not known to be old).
    bool counts_as_new() const;
};

/// One target's campaign: its binary and folders, its workers, what their output says, what it found.
struct TargetRun {
    std::string target;                          ///< parser, static, sweep, scene or disc
    std::filesystem::path bin;                   ///< the fuzz_TARGET binary
    std::filesystem::path dir;                   ///< CACHE/TARGET/KERNEL: shared by the campaigns on this cache
    std::filesystem::path corpus;                ///< dir/corpus: the working corpus (shared)
    std::filesystem::path kept;                  ///< dir/artifacts: artifacts and minimized inputs kept (shared)
    std::filesystem::path pending;               ///< dir/pending: failure artifacts not converted yet (shared)
    std::filesystem::path work;                  ///< RUN/TARGET: this campaign's own files
    std::filesystem::path artifacts;             ///< work/artifacts: this campaign's crash-, timeout-, ... files
    std::vector<std::filesystem::path> logs_of; ///< per worker, work/worker-W.log: the output of its processes
    std::filesystem::path dict;                  ///< fuzz/TARGET.dict in the source tree
    std::vector<std::filesystem::path> seeds;    ///< read-only seed folders (committed inputs)
    int workers = 1;                             ///< worker processes of this target
    std::vector<pid_t> pids;                     ///< per worker, its process (−1: none running)
    std::vector<Clock::time_point> started;      ///< per worker, when its current process started
    std::vector<bool> ended;                     ///< per worker, sent SIGTERM because its time was up
    std::uint64_t runs_done = 0;                 ///< inputs run by all its worker processes
    std::uint64_t cov = 0;                       ///< the highest coverage a worker reported
    std::uint64_t corpus_size = 0;               ///< the latest corpus size a worker reported
    std::uint64_t exec_s = 0;                    ///< the latest exec/s a worker reported
    std::vector<std::size_t> log_read;           ///< per worker, bytes of its log already read
    int restarts = 0;                            ///< workers restarted after a failure
    int quick_crashes = 0;                       ///< workers that failed within a second of starting
    std::vector<WorkerTally> tallies;            ///< per worker, its runs and its processes' running time (rates.hpp)
    int new_failures = 0;                        ///< failures saved (or kept) as new
    int known_failures = 0;                      ///< failures whose log was already saved
    int pending_failures = 0;                    ///< failure artifacts in pending/ at the end, for the next campaign
    std::vector<std::string> notes;              ///< lines for the end of the report
    std::vector<std::pair<std::string, bool>> logs;  ///< failure logs saved (path, true) or found known (path, false)
    std::vector<FailureRecord> failures;         ///< every failure artifact met, converted or not
    std::vector<std::string> stops;              ///< why workers stopped before the campaign's end
    std::string merge;                           ///< how its corpus merge went: "done", "skipped" (--no-merge), "stopped", "out of time", "failed"
};

/// The whole campaign: where things are, and one run per target.
struct Plan {
    std::filesystem::path bin_dir;     ///< folder of the fuzz_* binaries
    std::filesystem::path cache;       ///< the cache folder (working corpora, artifacts, logs)
    std::filesystem::path run_dir;     ///< CACHE/runs/PID-XXXXXX: this campaign's own files (run_dir.hpp)
    std::filesystem::path replay_dir;  ///< where failure logs are saved (the project's, ricochet_app/project.hpp)
    std::filesystem::path project;     ///< the project folder (its fuzz/corpus/ seeds); empty if none was found
    std::filesystem::path source;      ///< the tool's source tree, read only (dictionaries, the targets' own inputs)
    std::string kernel_env;            ///< RICOCHET_KERNEL for every worker: the kernel's name, or plugin:ABSOLUTE-PATH
    std::string kernel_name;           ///< the kernel's name (a plug-in's own): its corpus folder in the cache
    std::filesystem::path plugin;      ///< the plug-in's file, if the kernel is one; empty otherwise
    /// A saved failure met again fails the campaign (exit 1): the kernel is held to the guarantees (robust,
    /// exact, a plug-in), so its saved failures are regressions until fixed. False for a kernel whose failures
    /// are documented weaknesses (the lecture baselines, the peers: KernelOps::failures_documented).
    bool known_fails = true;
    int jobs = 1;                      ///< worker processes in all
    std::vector<TargetRun> runs;       ///< one per target, in the order asked for
    Budget budget;                     ///< the command's clock and, by time, its deadline
};

/// The plan for options, or nothing after printing on stderr why it cannot run (exit status 2). budget is the
/// command's clock, started before the plan is made.
std::optional<Plan> make_plan(const CampaignOptions& options, const Budget& budget);

/// The plan of `ricochet fuzz convert` (one target, no workers), or nothing after printing why not (exit 2).
std::optional<Plan> make_convert_plan(const ConvertOptions& options, const std::string& target, const std::string& kernel);

}  // namespace ricochet::fuzz
