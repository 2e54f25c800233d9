// `ricochet fuzz`'s campaign (campaign.hpp): the plan, the workers, the tail (failures converted, corpora
// merged, within the time budget), the summary.
#include "ricochet_fuzz/campaign.hpp"

#include <algorithm>
#include <optional>
#include <system_error>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cache.hpp"
#include "failure.hpp"
#include "fixed_addresses.hpp"
#include "plan.hpp"
#include "rates.hpp"
#include "ricochet_app/json.hpp"
#include "ricochet_app/json_stdout.hpp"
#include "ricochet_app/report.hpp"
#include "ricochet_app/stop_signal.hpp"
#include "ricochet/scene_log.hpp"
#include "workers.hpp"

namespace ricochet::fuzz {

namespace {

/// The fewest seconds left, in a campaign by time, for a corpus merge to start.
constexpr double k_merge_needs_s = 1;

/// What the campaign did not do and left for the next campaign on its cache.
struct Leftovers {
    int pending = 0;                   ///< failure artifacts waiting in pending/ folders
    std::vector<std::string> unmerged; ///< targets whose corpus was not merged (out of time, stopped)
};

/// A failure record as a JSON object (docs/cli-json.md, `failures[]`).
void json_failure(app::JsonWriter& json, const FailureRecord& f) {
    json.begin_object().member("target", f.target).member("kernel", f.kernel).member("status", status_name(f.status));
    json.key("check");
    if (f.check.empty())
        json.null();
    else
        json.value(f.check);
    json.key("frame");
    if (f.frame)
        json.value(*f.frame);
    else
        json.null();
    json.key("ball");
    if (f.ball)
        json.value(*f.ball);
    else
        json.null();
    json.key("log");
    if (f.log.empty())
        json.null();
    else
        json.value(f.log.string());
    json.member("new", f.counts_as_new()).member("artifact", f.artifact.string()).member("message", f.message).end_object();
}

/// The campaign's --json document (docs/cli-json.md, ricochet-fuzz/1).
std::string json_summary(const Plan& plan, const CampaignOptions& opt, double wall, double fuzzed, const Leftovers& left, int code,
                         bool stopped) {
    app::JsonWriter json;
    json.begin_object().member("schema", fmt::format("ricochet-fuzz/{}", app::k_json_schema_version));
    json.member("kernel", plan.kernel_name).key("plugin");
    if (plan.plugin.empty())
        json.null();
    else
        json.value(plan.plugin.string());
    json.key("runs_per_worker");
    if (opt.runs > 0)
        json.value(opt.runs);
    else
        json.null();
    json.key("time_s");
    if (opt.runs > 0)
        json.null();
    else
        json.value(opt.time);
    json.key("seed");
    if (opt.seed > 0)
        json.value(static_cast<std::uint64_t>(opt.seed));
    else
        json.null();
    json.member("jobs", plan.jobs).member("seconds", fuzzed).member("wall_seconds", wall);
    json.member("replay_dir", plan.replay_dir.string()).member("cache_dir", plan.cache.string());
    int new_failures = 0, known = 0;
    double in_all = 0;
    for (const TargetRun& r : plan.runs) in_all += exec_per_s_in_all(r.tallies);
    json.member("exec_per_s", in_all);
    json.key("targets").begin_array();
    for (const TargetRun& r : plan.runs) {
        new_failures += r.new_failures;
        known += r.known_failures;
        json.begin_object().member("target", r.target).member("workers", r.workers).member("runs", r.runs_done);
        // Each worker's runs over its own running time (rates.hpp), never over the campaign's.
        json.member("exec_per_s_per_worker", exec_per_s_per_worker(r.tallies)).member("exec_per_s", exec_per_s_in_all(r.tallies));
        json.member("cov", r.cov).member("corpus", r.corpus_size);
        json.member("new_failures", r.new_failures).member("known_failures", r.known_failures);
        json.member("pending_failures", r.pending_failures).member("merge", r.merge);
        json.key("logs").begin_array();
        for (const auto& [path, is_new] : r.logs) json.begin_object().member("path", path).member("new", is_new).end_object();
        json.end_array().key("stopped_early").begin_array();
        for (const std::string& stop : r.stops) json.value(stop);
        json.end_array().end_object();
    }
    json.end_array();
    json.key("failures").begin_array();
    for (const TargetRun& r : plan.runs)
        for (const FailureRecord& f : r.failures) json_failure(json, f);
    json.end_array();
    json.member("new_failures", new_failures).member("known_failures", known).member("pending_failures", left.pending);
    json.key("unmerged").begin_array();
    for (const std::string& t : left.unmerged) json.value(t);
    json.end_array();
    json.member("stopped", stopped).member("exit", code);
    return json.end_object().str();
}

/// The campaign as a report's suite: a case per target, failed by what fails the campaign (its new failures:
/// saved, no log, unsaved, flaky, pending; and a known one where the kernel is held to the guarantees), a
/// finding each.
app::TestSuite report_suite(const Plan& plan, double fuzzed) {
    app::TestSuite suite{"fuzz", fuzzed, {}};
    for (const TargetRun& r : plan.runs) {
        app::TestCase c{fmt::format("fuzz.{}", plan.kernel_name), r.target, fuzzed, app::TestCase::Outcome::passed, {}, {}};
        for (const FailureRecord& f : r.failures) {
            // A known failure fails the case too where it fails the campaign (a regression still there).
            const bool regression = f.status == FailureStatus::known && plan.known_fails;
            if (!f.counts_as_new() && !regression) continue;
            c.outcome = app::TestCase::Outcome::failed;
            const auto at = [](const std::optional<std::uint64_t>& n) {
                return n ? std::optional<std::int64_t>(static_cast<std::int64_t>(*n)) : std::nullopt;
            };
            // The target's report line says the check and frame again; only a failure with no check needs it.
            const std::string what = regression         ? "a saved failure, failing again"
                                     : !f.check.empty() ? "a new failure"
                                     : f.message.empty() ? "not converted yet"
                                                         : f.message;
            c.findings.push_back({f.check.empty() ? std::string("fuzz") : f.check, at(f.frame), at(f.ball), f.log.string(), {}, {},
                                  fmt::format("{} ({}); input {}", what, status_name(f.status), f.artifact.string())});
        }
        suite.cases.push_back(std::move(c));
    }
    return suite;
}

}  // namespace

int run_campaign(const CampaignOptions& opt) {
    // The command's clock starts here: a campaign by time ends, tail and all, by --time seconds from now.
    const Budget budget(Clock::now(), opt.runs > 0 ? 0.0 : opt.time);
    // A report that cannot be written is refused before any fuzzing.
    const app::ReportFiles reports{opt.junit, opt.sarif};
    if (const std::string problem = app::report_files_problem(reports); !problem.empty()) {
        fmt::print(stderr, "ricochet: error: {}\n", problem);
        return 2;
    }
    // Under --json everything the campaign prints goes to stderr; stdout gets the document at the end.
    app::JsonStdout json_out(opt.json);
    // SIGINT or SIGTERM: the workers are stopped, the failures converted so far are saved, the others wait in
    // the cache's pending/ folders, the corpus stays as it is (no merge), and the summary says so; exit 128 +
    // the signal.
    const app::StopOnSignal stop_on_signal;
    std::optional<Plan> plan = make_plan(opt, budget);
    // Degenerate: bad usage or missing binaries (make_plan said which).
    if (!plan) return 2;
    const std::string how_long = opt.runs > 0 ? fmt::format("{} runs per worker", opt.runs)
                                              : fmt::format("{} s in all (fuzzing until {:.0f} s, then converting failures and "
                                                            "merging corpora)",
                                                            opt.time, budget.fuzz_end_s());
    const std::string plugin = plan->plugin.empty() ? std::string() : fmt::format(" (plug-in {})", plan->plugin.string());
    fmt::print("ricochet fuzz: kernel {}{}, {}, {} target(s), {} worker(s)\n  binaries {}\n  corpus   {}\n  logs to  {}\n",
               plan->kernel_name, plugin, how_long, plan->runs.size(), plan->jobs, plan->bin_dir.string(), plan->cache.string(),
               plan->replay_dir.string());
    // Seen as it starts, also when stdout is a file (a caller waiting for the campaign to be under way).
    std::fflush(stdout);
    // --runs with --seed is reproducible: every worker, minimization and merge at fixed addresses.
    std::optional<FixedAddresses> fixed;
    if (opt.runs > 0 && opt.seed > 0) {
        fixed.emplace();
        if (!fixed->error().empty())
            fmt::print(stderr, "ricochet fuzz: warning: address randomization stays on ({}): coverage, and so the inputs "
                               "run, may differ from one run of this campaign to the next\n",
                       fixed->error());
    }
    const double fuzzed = run_workers(*plan, opt);
    // The tail: each target's failures converted (those earlier campaigns left first), then the corpora merged.
    budget.say("", app::stop_requested() ? "fuzzing stopped; converting nothing more, merging nothing"
                                         : "fuzzing done; converting failures, then merging the corpora");
    const ConvertSettings settings = convert_settings(opt);
    for (TargetRun& r : plan->runs) convert_failures(r, settings, *plan);
    // Merge: keep only the inputs that add coverage, for the next campaign.
    Leftovers left;
    for (TargetRun& r : plan->runs) {
        if (opt.no_merge)
            r.merge = "skipped";
        else if (app::stop_requested())
            r.merge = "stopped";
        else if (budget.timed() && budget.left() < k_merge_needs_s)
            r.merge = "out of time";
        else
            merge_corpus(r, *plan);
        if (r.merge == "stopped" || r.merge == "out of time") left.unmerged.push_back(r.target);
        left.pending += r.pending_failures;
    }
    // Everything worth keeping has left this campaign's own folder (artifacts to the cache, logs to the
    // replay folder).
    std::error_code ec;
    std::filesystem::remove_all(plan->run_dir, ec);
    fmt::print("\n{:<8} {:>10} {:>9} {:>6} {:>7} {:>13} {:>6} {:>8}\n", "target", "runs", "exec/s", "cov", "corpus", "new failures",
               "known", "pending");
    bool any_new = false, any_known = false;
    for (const TargetRun& r : plan->runs) {
        fmt::print("{:<8} {:>10} {:>9} {:>6} {:>7} {:>13} {:>6} {:>8}\n", r.target, r.runs_done,
                   human(exec_per_s_per_worker(r.tallies)), r.cov, r.corpus_size,
                   r.new_failures, r.known_failures, r.pending_failures);
        any_new = any_new || r.new_failures > 0 || r.pending_failures > 0;
        any_known = any_known || r.known_failures > 0;
    }
    for (const TargetRun& r : plan->runs)
        for (const std::string& stop : r.stops) fmt::print("stopped early: {}\n", stop);
    if (left.pending > 0 || !left.unmerged.empty()) {
        std::vector<std::string> what;
        if (left.pending > 0)
            what.push_back(fmt::format("{} failure artifact(s) to convert (in {}/TARGET/{}/pending/; `ricochet fuzz convert ARTIFACT` "
                                       "converts one now)",
                                       left.pending, plan->cache.string(), plan->kernel_name));
        if (!left.unmerged.empty()) what.push_back(fmt::format("the corpus merge of {}", fmt::join(left.unmerged, ", ")));
        fmt::print("left for the next campaign on this cache: {}\n", fmt::join(what, "; "));
    }
    const bool stopped = app::stop_requested();
    // A saved failure met again is a regression still there, for a kernel held to the guarantees; a lecture
    // baseline's or a peer's is its documented weakness seen again.
    const bool regressions = any_known && plan->known_fails;
    const bool failing = any_new || regressions;
    int code = stopped ? app::stop_exit_code() : failing ? 1 : 0;
    // The wall time of the whole command, from its start to this line.
    const double wall = budget.elapsed();
    // The reports before the summary's last line and the document, so that both say the exit: 2 if one could
    // not be written.
    std::string report_error;
    if (!app::write_reports({"ricochet fuzz", wall, {report_suite(*plan, fuzzed)}, {}, {}}, reports, write_file_atomically,
                            &report_error)) {
        fmt::print(stderr, "ricochet: error: {}\n", report_error);
        if (!stopped) code = 2;
    }
    std::string verdict = any_new && left.pending > 0 ? "NEW FAILURES (some not converted yet)"
                          : any_new                   ? "NEW FAILURES"
                                                      : "no new failures";
    if (regressions) verdict += "; saved failures failing again (regressions until fixed)";
    fmt::print("kernel {}, {:.0f} s ({:.0f} s fuzzing), exec/s per worker; {}{}\n", plan->kernel_name, wall, fuzzed, verdict,
               stopped ? fmt::format("; stopped by {} (exit {})", app::stop_signal_name(), code)
               : code != 0 ? fmt::format(" (exit {})", code)
                           : "");
    std::fflush(stdout);
    if (json_out.on()) {
        json_out.restore();
        fmt::print("{}", json_summary(*plan, opt, wall, fuzzed, left, code, stopped));
    }
    return code;
}

}  // namespace ricochet::fuzz
