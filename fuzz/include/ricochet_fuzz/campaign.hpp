// `ricochet fuzz`'s campaign: libFuzzer workers over this build's fuzz targets, a working corpus in a
// cache folder, and each new failure minimized and saved as a scene log (fuzz/README.md); and `ricochet fuzz
// convert`, which turns failure artifacts into scene logs on demand.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ricochet::fuzz {

/// Every target fuzz/ defines, in the order the summary lists them.
inline constexpr std::array<std::string_view, 6> k_campaign_targets = {"parser", "static", "sweep", "scene", "disc",
                                                                         "meet"};

/// What a campaign runs and where it keeps things; an empty folder takes its default.
struct CampaignOptions {
    std::vector<std::string> targets;  ///< the targets to fuzz; empty: every target this build has
    std::string kernel = "robust";     ///< the kernel under test (RICOCHET_KERNEL of every worker)
    double time = 60;                  ///< seconds the whole command takes, fuzzing and its tail; unused when runs > 0
    std::uint64_t runs = 0;            ///< inputs per worker instead of a time limit (0: a campaign by time)
    unsigned seed = 0;                 ///< libFuzzer's -seed of worker w is seed + w; 0: a random one each
    int jobs = 0;                      ///< worker processes in all, shared out among the targets (0: one each)
    std::string bin_dir;               ///< folder of the fuzz_* binaries
    std::string cache_dir;             ///< working corpus and artifacts
    std::string replay_dir;            ///< where failure logs are saved
    bool no_merge = false;             ///< skip the corpus merge at the end
    bool json = false;                 ///< the summary as one JSON document on stdout (docs/cli-json.md); the rest on stderr
    std::string junit;                 ///< where to write a JUnit XML report (docs/cli-reports.md); empty: none
    std::string sarif;                 ///< where to write a SARIF 2.1.0 log (docs/cli-reports.md); empty: none
    std::vector<std::string> libfuzzer_flags;  ///< passed to every worker after the campaign's own flags
};

/// Runs a campaign, printing progress and a summary on stdout. Returns 0 if nothing new failed, 1 if
/// something did (or a failure was left unconverted), 2 on bad usage, missing binaries or a report that could
/// not be written, 128 + the signal if stopped.
int run_campaign(const CampaignOptions& options);

/// What `ricochet fuzz convert` converts and where; an empty string takes its default.
struct ConvertOptions {
    std::vector<std::string> artifacts;  ///< failure artifacts (libFuzzer's crash-, timeout-, oom-, leak- files, or any input)
    std::string target;                  ///< their target; empty: read from each artifact's place in a cache
    std::string kernel;                  ///< the kernel; empty: read from each artifact's place in a cache, else robust
    std::string bin_dir;                 ///< folder of the fuzz_* binaries
    std::string cache_dir;               ///< where the conversion works (its own folder there, removed at the end)
    std::string replay_dir;              ///< where the logs are saved
};

/// Converts each artifact as a campaign converts its failures (minimized, run once more to write its log,
/// reduced, saved once), printing what it did. Returns 0 if every artifact was converted (a log saved, or its
/// case found known), 1 if one did not fail when run again or its log could not be saved, 2 on bad usage,
/// 128 + the signal if stopped.
int run_convert(const ConvertOptions& options);

}  // namespace ricochet::fuzz
