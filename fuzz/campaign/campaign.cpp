// `ricochet fuzz`'s campaign (campaign.hpp): the plan, the workers, the failures, the merge, the summary.
#include "ricochet_fuzz/campaign.hpp"

#include <algorithm>
#include <system_error>

#include <fmt/format.h>

#include "cache.hpp"
#include "failure.hpp"
#include "plan.hpp"
#include "workers.hpp"

namespace ricochet::fuzz {

int run_campaign(const CampaignOptions& opt) {
    std::optional<Plan> plan = make_plan(opt);
    // Degenerate: bad usage or missing binaries (make_plan said which).
    if (!plan) return 2;
    const std::string budget = opt.runs > 0 ? fmt::format("{} runs per worker", opt.runs) : fmt::format("{} s", opt.time);
    fmt::print("ricochet fuzz: kernel {}, {}, {} target(s), {} worker(s)\n  binaries {}\n  corpus   {}\n  logs to  {}\n",
               opt.kernel, budget, plan->runs.size(), plan->jobs, plan->bin_dir.string(), plan->cache.string(),
               plan->replay_dir.string());
    const double wall = run_workers(*plan, opt);
    bool any_new = false;
    for (TargetRun& r : plan->runs) {
        convert_failures(r, opt, *plan);
        any_new = any_new || r.new_failures > 0;
    }
    // Merge: keep only the inputs that add coverage, for the next campaign.
    if (!opt.no_merge)
        for (TargetRun& r : plan->runs) merge_corpus(r, plan->cache, opt.kernel);
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
    fmt::print("kernel {}, {:.0f} s, exec/s per worker; {}\n", opt.kernel, wall, any_new ? "NEW FAILURES (exit 1)" : "no new failures");
    return any_new ? 1 : 0;
}

}  // namespace ricochet::fuzz
