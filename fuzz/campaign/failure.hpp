// Turning a campaign's failures into scene logs: each new libFuzzer artifact is minimized, run once more
// to write its log, and saved once into the replay folder (save_scene_log_once).
#pragma once

#include <filesystem>

#include "plan.hpp"
#include "ricochet_fuzz/campaign.hpp"

namespace ricochet::fuzz {

/// Converts up to k_max_failures_converted of run's new artifacts (one per distinct failure) into scene
/// logs in plan.replay_dir, printing what it did; counts them in run.new_failures and run.known_failures.
/// Every artifact and minimized input ends in run.kept; saving holds the cache's lock (cache_lock.hpp).
void convert_failures(TargetRun& run, const CampaignOptions& options, const Plan& plan);

}  // namespace ricochet::fuzz
