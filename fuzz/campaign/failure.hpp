// Turning failure artifacts into scene logs: each is run once more, and a failure not met before is minimized,
// run again to write its log, reduced, and saved once into the replay folder (save_scene_log_once). What a
// campaign cannot convert (stopped, out of time, past the most it converts) waits in the cache's pending/ folder
// for the next campaign, or for `ricochet fuzz convert`.
#pragma once

#include <cstdint>
#include <filesystem>
#include <set>
#include <string>

#include "plan.hpp"
#include "ricochet_fuzz/campaign.hpp"

namespace ricochet::fuzz {

/// How failures are minimized: the same in a campaign and in `ricochet fuzz convert`, but for its bounds.
struct ConvertSettings {
    std::uint64_t minimize_runs = 20000;  ///< -runs of libFuzzer's -minimize_crash (a count: the same input on every machine)
    bool minimize_by_time = false;        ///< also cap minimization in time (a campaign by time)
    unsigned seed = 0;                    ///< -seed of the minimization; 0: libFuzzer's own random one
    int most = 5;                         ///< most distinct failures minimized per target (0: no limit)
};

/// The settings of a campaign's conversions: its runs (if fewer) and seed, a time cap in a campaign by time.
ConvertSettings convert_settings(const CampaignOptions& options);

/// Converts the failures of run: first those waiting in its pending/ folder from earlier campaigns (each claimed
/// by moving it into this campaign's folder), then this campaign's own, within plan's budget. Prints a progress
/// line per step; records each in run.failures and counts them in run.new_failures and run.known_failures.
/// Every artifact converted and every minimized input ends in run.kept; those left unconverted in run.pending
/// (counted in run.pending_failures). Saving holds the cache's lock (cache_lock.hpp).
void convert_failures(TargetRun& run, const ConvertSettings& settings, const Plan& plan);

/// Converts the one artifact at path (a file of the caller's, left where it is unless it waits in a cache's
/// pending/ folder, which it then leaves for that cache's artifacts/), for `ricochet fuzz convert`. signatures:
/// the failures converted before it in this command. Nothing if a stop came first.
std::optional<FailureRecord> convert_artifact(TargetRun& run, const ConvertSettings& settings, const Plan& plan,
                                              const std::filesystem::path& path, std::set<std::string>& signatures);

}  // namespace ricochet::fuzz
