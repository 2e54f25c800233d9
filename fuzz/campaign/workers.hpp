// Running a campaign's workers: every target's libFuzzer processes at once, restarted after a failure
// while time is left, with a progress line per target every few seconds.
#pragma once

#include <string>

#include "plan.hpp"
#include "ricochet_fuzz/campaign.hpp"

namespace ricochet::fuzz {

/// Runs every worker of plan until its time (or its runs) is spent, printing progress on stdout; then
/// fills in each run's runs_done, seconds and corpus_size. Returns the wall time in seconds.
double run_workers(Plan& plan, const CampaignOptions& options);

/// x with a k, M or G suffix and one decimal (below 1000: a whole number), as progress lines print counts.
std::string human(double x);

}  // namespace ricochet::fuzz
