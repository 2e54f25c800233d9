// `ricochet fuzz`'s campaign (campaign.hpp): the plan, the workers, the failures, the merge, the summary.
#include "ricochet_fuzz/campaign.hpp"

#include <algorithm>
#include <system_error>

#include <fmt/format.h>

#include "cache.hpp"
#include "failure.hpp"
#include "plan.hpp"
#include "ricochet_app/json.hpp"
#include "ricochet_app/json_stdout.hpp"
#include "ricochet_app/stop_signal.hpp"
#include "workers.hpp"

namespace ricochet::fuzz {

namespace {

/// The campaign's --json document (docs/cli-json.md, ricochet-fuzz/1).
std::string json_summary(const Plan& plan, const CampaignOptions& opt, double wall, int code, bool stopped) {
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
    json.member("jobs", plan.jobs).member("seconds", wall);
    json.member("replay_dir", plan.replay_dir.string()).member("cache_dir", plan.cache.string());
    int new_failures = 0, known = 0;
    json.key("targets").begin_array();
    for (const TargetRun& r : plan.runs) {
        new_failures += r.new_failures;
        known += r.known_failures;
        json.begin_object().member("target", r.target).member("workers", r.workers).member("runs", r.runs_done);
        json.member("exec_per_s_per_worker", static_cast<double>(r.runs_done) / std::max(r.seconds, 1e-9) / r.workers);
        json.member("cov", r.cov).member("corpus", r.corpus_size);
        json.member("new_failures", r.new_failures).member("known_failures", r.known_failures);
        json.key("logs").begin_array();
        for (const auto& [path, is_new] : r.logs) json.begin_object().member("path", path).member("new", is_new).end_object();
        json.end_array().key("stopped_early").begin_array();
        for (const std::string& stop : r.stops) json.value(stop);
        json.end_array().end_object();
    }
    json.end_array();
    json.member("new_failures", new_failures).member("known_failures", known).member("stopped", stopped).member("exit", code);
    return json.end_object().str();
}

}  // namespace

int run_campaign(const CampaignOptions& opt) {
    // Under --json everything the campaign prints goes to stderr; stdout gets the document at the end.
    app::JsonStdout json_out(opt.json);
    // SIGINT or SIGTERM: the workers are stopped, the failures found so far are saved (or kept as
    // artifacts), the corpus stays as it is (no merge), and the summary says so; exit 128 + the signal.
    const app::StopOnSignal stop_on_signal;
    std::optional<Plan> plan = make_plan(opt);
    // Degenerate: bad usage or missing binaries (make_plan said which).
    if (!plan) return 2;
    const std::string budget = opt.runs > 0 ? fmt::format("{} runs per worker", opt.runs) : fmt::format("{} s", opt.time);
    const std::string plugin = plan->plugin.empty() ? std::string() : fmt::format(" (plug-in {})", plan->plugin.string());
    fmt::print("ricochet fuzz: kernel {}{}, {}, {} target(s), {} worker(s)\n  binaries {}\n  corpus   {}\n  logs to  {}\n",
               plan->kernel_name, plugin, budget, plan->runs.size(), plan->jobs, plan->bin_dir.string(), plan->cache.string(),
               plan->replay_dir.string());
    // Seen as it starts, also when stdout is a file (a caller waiting for the campaign to be under way).
    std::fflush(stdout);
    const double wall = run_workers(*plan, opt);
    bool any_new = false;
    for (TargetRun& r : plan->runs) {
        convert_failures(r, opt, *plan);
        any_new = any_new || r.new_failures > 0;
    }
    // Merge: keep only the inputs that add coverage, for the next campaign.
    if (!opt.no_merge && !app::stop_requested())
        for (TargetRun& r : plan->runs) merge_corpus(r, plan->cache, plan->kernel_env);
    // Everything worth keeping has left this campaign's own folder (artifacts to the cache, logs to the
    // replay folder).
    std::error_code ec;
    std::filesystem::remove_all(plan->run_dir, ec);
    fmt::print("\n{:<8} {:>10} {:>9} {:>6} {:>7} {:>13} {:>6}\n", "target", "runs", "exec/s", "cov", "corpus", "new failures",
               "known");
    for (const TargetRun& r : plan->runs)
        fmt::print("{:<8} {:>10} {:>9} {:>6} {:>7} {:>13} {:>6}\n", r.target, r.runs_done,
                   human(static_cast<double>(r.runs_done) / std::max(r.seconds, 1e-9) / r.workers), r.cov, r.corpus_size,
                   r.new_failures, r.known_failures);
    for (const TargetRun& r : plan->runs)
        for (const std::string& stop : r.stops) fmt::print("stopped early: {}\n", stop);
    const bool stopped = app::stop_requested();
    const int code = stopped ? app::stop_exit_code() : any_new ? 1 : 0;
    fmt::print("kernel {}, {:.0f} s, exec/s per worker; {}{}\n", plan->kernel_name, wall, any_new ? "NEW FAILURES" : "no new failures",
               stopped ? fmt::format("; stopped by {} (exit {})", app::stop_signal_name(), code) : any_new ? " (exit 1)" : "");
    if (json_out.on()) {
        json_out.restore();
        fmt::print("{}", json_summary(*plan, opt, wall, code, stopped));
    }
    return code;
}

}  // namespace ricochet::fuzz
