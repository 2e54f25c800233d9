// Running a campaign's workers (workers.hpp). Each worker is a libFuzzer process writing to its
// target's campaign.log; the loop below waits on them, reads what they print and restarts the ones that
// stopped at a failure.
#include "workers.hpp"

#include <signal.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <thread>

#include <fmt/format.h>

#include "cache.hpp"
#include "fuzz_common.hpp"
#include "process.hpp"
#include "rates.hpp"
#include "ricochet_app/stop_signal.hpp"

namespace ricochet::fuzz {
namespace {

namespace fs = std::filesystem;

/// Seconds past the end of fuzzing after which a worker still running is sent SIGTERM (libFuzzer ends at its
/// -max_total_time only between two inputs, and counts whole seconds); one still there at the deadline is killed.
constexpr double k_overrun_grace_s = 1;
/// Most restarts of one target's workers in a campaign.
constexpr int k_max_restarts = 50;
/// How often the loop looks at its workers. A worker's running time ends when the loop finds it ended (waitpid),
/// so this is how closely the table's exec/s times it: 50 ms is 5 % of a worker that ran for a second.
constexpr std::chrono::milliseconds k_poll_every{50};
/// Failures within a second of starting after which a target's workers are not restarted: a corpus
/// input that fails stops every run at start-up.
constexpr int k_max_quick_crashes = 5;

/// Reads what worker w wrote since last time: coverage, corpus size, exec/s.
void poll_log(TargetRun& r, std::size_t w) {
    std::ifstream in(r.logs_of[w], std::ios::binary);
    in.seekg(static_cast<std::streamoff>(r.log_read[w]));
    std::string line;
    std::streamoff consumed = 0;
    while (std::getline(in, line)) {
        if (in.eof()) break;  // a partial last line: read it next time
        consumed += static_cast<std::streamoff>(line.size() + 1);
        if (line.empty() || line[0] != '#') continue;
        // "#RUNS\tNEW|pulse|REDUCE cov: N ft: N corp: N/Nb ... exec/s: N rss: NMb"
        if (auto cov = number_after(line, "cov: ")) r.cov = std::max(r.cov, *cov);
        if (auto corp = number_after(line, "corp: ")) r.corpus_size = *corp;
        if (auto e = number_after(line, "exec/s: ")) r.exec_s = *e;
    }
    r.log_read[w] += static_cast<std::size_t>(consumed);
}

/// The worker output's last line that says why it stopped: a failure line of the target, a sanitizer's or
/// libFuzzer's SUMMARY, ERROR or INFO line, else the last line that is not a progress "#N" one.
std::string last_words(const TargetRun& r, std::size_t w) {
    std::istringstream in(read_all(r.logs_of[w]));
    std::string telling, last;
    for (std::string line; std::getline(in, line);) {
        if (line.starts_with(k_failure_tag) || line.starts_with("SUMMARY:") || line.starts_with("ERROR:") ||
            line.starts_with("==") || line.starts_with("INFO: -max_len") || line.starts_with("INFO: exiting") ||
            line.starts_with("Done "))
            telling = line;
        if (!line.empty() && line[0] != '#') last = line;
    }
    if (!telling.empty()) return telling;
    return last.empty() ? "no output" : last;
}

/// True the first time it is called after a stop was requested (passed records that it was).
bool stop_requested_once(bool& passed) {
    if (passed || !app::stop_requested()) return false;
    passed = true;
    return true;
}

/// How a process ended, in words.
std::string how_it_ended(int status) {
    if (WIFEXITED(status)) return fmt::format("exited with status {}", WEXITSTATUS(status));
    if (WIFSIGNALED(status)) return fmt::format("was killed by signal {}", WTERMSIG(status));
    return "stopped";
}

}  // namespace

std::string human(double x) {
    if (x >= 1e9) return fmt::format("{:.1f}G", x / 1e9);
    if (x >= 1e6) return fmt::format("{:.1f}M", x / 1e6);
    if (x >= 1e3) return fmt::format("{:.1f}k", x / 1e3);
    return fmt::format("{:.0f}", x);
}

double run_workers(Plan& plan, const CampaignOptions& opt) {
    const Budget& budget = plan.budget;
    const auto elapsed = [&] { return budget.elapsed(); };
    const double started_at = elapsed();
    const bool by_runs = opt.runs > 0;
    // A campaign by time fuzzes until the budget's share of fuzzing is spent (budget.hpp); the tail has the rest.
    const double fuzz_end = budget.fuzz_end_s();
    // start: which start of this target's workers it is (0, 1, ...), so that each gets its own seed.
    const auto start_worker = [&](TargetRun& r, std::size_t w, int start) {
        std::vector<std::string> argv = {r.bin.string()};
        // A campaign by runs does not reload the corpus folder: libFuzzer rereads it every second, so what
        // it runs would depend on the clock.
        if (by_runs)
            argv.insert(argv.end(), {fmt::format("-runs={}", opt.runs), "-reload=0"});
        else
            argv.push_back(fmt::format("-max_total_time={}", std::max(1, static_cast<int>(fuzz_end - elapsed()))));
        if (opt.seed > 0) argv.push_back(fmt::format("-seed={}", opt.seed + static_cast<unsigned>(start)));
        argv.insert(argv.end(), {"-timeout=10", "-rss_limit_mb=2048", "-print_final_stats=1",
                                 "-artifact_prefix=" + r.artifacts.string() + "/"});
        if (fs::exists(r.dict)) argv.push_back("-dict=" + r.dict.string());
        // The caller's flags (after `--`) come last: libFuzzer takes a flag's last value, so they override.
        argv.insert(argv.end(), opt.libfuzzer_flags.begin(), opt.libfuzzer_flags.end());
        argv.push_back(r.corpus.string());
        for (const auto& s : r.seeds) argv.push_back(s.string());
        r.pids[w] = spawn(argv, {"RICOCHET_KERNEL=" + plan.kernel_env}, r.logs_of[w]);
        r.started[w] = Clock::now();
    };
    for (TargetRun& r : plan.runs) {
        const auto n = static_cast<std::size_t>(r.workers);
        r.pids.assign(n, -1);
        r.started.assign(n, Clock::now());
        r.ended.assign(n, false);
        r.tallies.assign(n, WorkerTally{});
        r.log_read.assign(n, 0);
        r.logs_of.clear();
        for (std::size_t w = 0; w < n; ++w) r.logs_of.push_back(r.work / fmt::format("worker-{}.log", w));
        for (std::size_t w = 0; w < n; ++w) start_worker(r, w, static_cast<int>(w));
    }
    double last_print = 0;
    bool passed_stop = false, killed = false, out_of_time = false;
    double stop_at = 0;
    for (;;) {
        // A SIGINT or SIGTERM (run_campaign holds a StopOnSignal): every worker gets it once and exits
        // (libFuzzer's interrupt handler); their corpus and artifacts stay.
        if (stop_requested_once(passed_stop)) {
            stop_at = elapsed();
            for (TargetRun& r : plan.runs)
                for (pid_t pid : r.pids)
                    if (pid > 0) kill(pid, app::stop_signal());
        }
        // One still there k_stop_grace_s later is stuck in that handler (it is not async-signal-safe): killed.
        if (passed_stop && !killed && elapsed() - stop_at > app::k_stop_grace_s) {
            killed = true;
            for (TargetRun& r : plan.runs)
                for (std::size_t w = 0; w < r.pids.size(); ++w)
                    if (r.pids[w] > 0) {
                        fmt::print("  {} worker {} did not stop within {:.0f} s of {}: killed\n", r.target, w,
                                   app::k_stop_grace_s, app::stop_signal_name());
                        kill(r.pids[w], SIGKILL);
                    }
        }
        // The deadline of the whole command: a worker still there (stuck in SIGTERM's handler) is killed.
        if (!by_runs && !out_of_time && budget.left() <= 0) {
            out_of_time = true;
            for (TargetRun& r : plan.runs)
                for (std::size_t w = 0; w < r.pids.size(); ++w)
                    if (r.pids[w] > 0) {
                        fmt::print("  {} worker {} did not end by the time limit: killed\n", r.target, w);
                        kill(r.pids[w], SIGKILL);
                    }
        }
        bool any = false;
        for (TargetRun& r : plan.runs) {
            for (std::size_t w = 0; w < r.pids.size(); ++w) {
                if (r.pids[w] < 0) continue;
                int status = 0;
                if (waitpid(r.pids[w], &status, WNOHANG) == 0) {
                    any = true;
                    // A worker past its time limit (an input that runs long): SIGTERM ends it through libFuzzer's
                    // interrupt handler, with its final statistics.
                    if (!by_runs && !r.ended[w] && elapsed() > fuzz_end + k_overrun_grace_s) {
                        r.ended[w] = true;
                        kill(r.pids[w], SIGTERM);
                    }
                    continue;
                }
                r.pids[w] = -1;
                // Its own running time, for its own rate: a fast target's workers end long before a slow one's.
                r.tallies[w].seconds += std::chrono::duration<double>(Clock::now() - r.started[w]).count();
                poll_log(r, w);
                const bool clean = WIFEXITED(status) && WEXITSTATUS(status) == 0;
                if (!clean && std::chrono::duration<double>(Clock::now() - r.started[w]).count() < 1) ++r.quick_crashes;
                // A worker stops at its first failure; restart it while time is left, unless it keeps failing
                // at start-up (a corpus input that fails, or a kernel that fails on nearly every input, as the
                // peers do: more restarts would find the same failures again). A campaign by runs does not restart: each worker
                // runs its inputs once. A stopped campaign restarts nothing and says nothing: it was asked to; nor does
                // one whose workers were ended at their time.
                if (app::stop_requested() || r.ended[w]) continue;
                const bool time_left = !by_runs && elapsed() < fuzz_end - 1;
                if (!clean && time_left && r.restarts < k_max_restarts && r.quick_crashes < k_max_quick_crashes) {
                    ++r.restarts;
                    start_worker(r, w, r.workers - 1 + r.restarts);
                    any = true;
                    continue;
                }
                // Not restarted: say why when it stops before the campaign's time or runs are spent.
                std::string why;
                if (by_runs && !clean)
                    why = fmt::format("it {} before its {} runs (a campaign by runs does not restart workers)", how_it_ended(status),
                                      opt.runs);
                else if (time_left && clean)
                    why = "it exited with status 0 before the time was up";
                else if (time_left && r.quick_crashes >= k_max_quick_crashes)
                    why = fmt::format("it {}, and {} starts failed within a second: an input of the corpus fails at "
                                      "start-up, or the kernel fails on almost any input",
                                      how_it_ended(status), r.quick_crashes);
                else if (time_left)
                    why = fmt::format("it {}, and the target's workers were restarted {} times already (the most)", how_it_ended(status),
                                      r.restarts);
                if (!why.empty()) {
                    const std::string line = fmt::format("{} worker {} stopped early at {:.0f} s: {}; its last words: {}", r.target, w,
                                                         elapsed(), why, last_words(r, w));
                    fmt::print("  {}\n", line);
                    r.stops.push_back(line);
                }
            }
            for (std::size_t w = 0; w < r.pids.size(); ++w) poll_log(r, w);
        }
        if (!any) break;
        if (elapsed() - last_print >= k_progress_every_s) {
            last_print = elapsed();
            for (TargetRun& r : plan.runs) {
                // Slow units are kept as inputs, not failures (failure.cpp): the count is the table's.
                const std::set<std::string> found = list_artifacts(r.artifacts);
                const auto failures = std::count_if(found.begin(), found.end(),
                                                    [](const std::string& a) { return !a.starts_with("slow-unit-"); });
                fmt::print("[{:4.0f}s] {:<7} exec/s {:>7}  cov {:>5}  corpus {:>5}  failures {}\n", elapsed(), r.target,
                           human(static_cast<double>(r.exec_s)), r.cov, r.corpus_size, failures);
            }
            std::fflush(stdout);
        }
        std::this_thread::sleep_for(k_poll_every);
    }
    const double fuzzed = elapsed() - started_at;
    for (TargetRun& r : plan.runs) {
        r.runs_done = 0;
        // One log per worker: the lines of workers sharing one would interleave, and a count of one taken for
        // another's restart.
        for (std::size_t w = 0; w < r.logs_of.size(); ++w) {
            r.tallies[w].runs = runs_in_log(read_all(r.logs_of[w]));
            r.runs_done += r.tallies[w].runs;
        }
        r.corpus_size = count_files(r.corpus);
    }
    return fuzzed;
}

}  // namespace ricochet::fuzz
