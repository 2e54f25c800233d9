// Running a campaign's workers: every target's libFuzzer processes at once, restarted after a failure
// while time is left, with a progress line per target every few seconds.
#pragma once

#include <string>

#include "plan.hpp"
#include "ricochet_fuzz/campaign.hpp"

namespace ricochet::fuzz {

/// Runs every worker of plan until its runs, or in a campaign by time the budget's share of fuzzing, are spent
/// (a worker still there a second later gets SIGTERM, and SIGKILL at the deadline), printing progress on stdout;
/// then fills in each run's tallies (each worker's runs and running time), runs_done and corpus_size. Returns the seconds the workers fuzzed.
double run_workers(Plan& plan, const CampaignOptions& options);

/// x with a k, M or G suffix and one decimal (below 1000: a whole number), as progress lines print counts.
std::string human(double x);

}  // namespace ricochet::fuzz
