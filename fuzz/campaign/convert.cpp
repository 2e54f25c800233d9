// `ricochet fuzz convert` (campaign.hpp's run_convert): failure artifacts turned into scene logs on demand, the
// way a campaign turns its own (failure.hpp), each target and kernel read from the artifact's place in a cache
// (CACHE/TARGET/KERNEL/pending/ or artifacts/) unless given.
#include <algorithm>
#include <map>
#include <set>
#include <system_error>
#include <utility>

#include <fmt/format.h>

#include "failure.hpp"
#include "fixed_addresses.hpp"
#include "plan.hpp"
#include "ricochet_app/stop_signal.hpp"
#include "ricochet_fuzz/campaign.hpp"

namespace ricochet::fuzz {
namespace {

namespace fs = std::filesystem;

/// The seed of a conversion's minimization: fixed, so that one artifact gives one log every time.
constexpr unsigned k_convert_seed = 1;

/// The target and kernel of an artifact kept in a cache, CACHE/TARGET/KERNEL/{pending,artifacts}/NAME; empty
/// strings where its place does not say.
std::pair<std::string, std::string> place_of(const fs::path& artifact) {
    const fs::path folder = fs::absolute(artifact).lexically_normal().parent_path();
    if (folder.filename() != "pending" && folder.filename() != "artifacts") return {};
    const std::string kernel = folder.parent_path().filename().string();
    const std::string target = folder.parent_path().parent_path().filename().string();
    if (std::find(k_campaign_targets.begin(), k_campaign_targets.end(), target) == k_campaign_targets.end()) return {};
    return {target, kernel};
}

}  // namespace

int run_convert(const ConvertOptions& opt) {
    const app::StopOnSignal stop_on_signal;
    // Minimization follows addresses too (fixed_addresses.hpp): at fixed ones, the same artifact gives the same log.
    const FixedAddresses fixed;
    // Every artifact is checked, and its target and kernel known, before anything is converted.
    std::map<std::pair<std::string, std::string>, std::vector<fs::path>> groups;
    for (const std::string& a : opt.artifacts) {
        std::error_code ec;
        if (!fs::is_regular_file(a, ec)) {
            fmt::print(stderr, "ricochet fuzz convert: error: {}: {}\n", a,
                       fs::exists(a, ec) ? "not a file (an artifact is one input, a file)" : "no such file");
            return 2;
        }
        const auto [target, kernel] = place_of(a);
        if (opt.target.empty() && target.empty()) {
            fmt::print(stderr, "ricochet fuzz convert: error: {}: which target is it for? Its place does not say (a campaign "
                               "keeps artifacts in CACHE/TARGET/KERNEL/pending/ or artifacts/); pass --target T\n", a);
            return 2;
        }
        const std::string k = !opt.kernel.empty() ? opt.kernel : !kernel.empty() ? kernel : std::string("robust");
        groups[{opt.target.empty() ? target : opt.target, k}].emplace_back(a);
    }
    int failed = 0, converted = 0;
    for (const auto& [key, artifacts] : groups) {
        const auto& [target, kernel] = key;
        std::optional<Plan> plan = make_convert_plan(opt, target, kernel);
        if (!plan) return 2;
        TargetRun& r = plan->runs.front();
        ConvertSettings settings;
        settings.seed = k_convert_seed;
        fmt::print("ricochet fuzz convert: {} artifact(s) of target {} under kernel {}; logs to {}\n", artifacts.size(), target,
                   plan->kernel_name, plan->replay_dir.string());
        std::set<std::string> signatures;
        for (const fs::path& a : artifacts) {
            if (app::stop_requested()) break;
            const std::optional<FailureRecord> record = convert_artifact(r, settings, *plan, a, signatures);
            if (!record) break;
            const bool ok = record->status == FailureStatus::saved || record->status == FailureStatus::known ||
                            record->status == FailureStatus::no_log || record->status == FailureStatus::duplicate;
            ++(ok ? converted : failed);
            fmt::print("{}: {}{}\n", a.string(), status_name(record->status),
                       record->log.empty() ? std::string() : fmt::format(" {}", record->log.string()));
        }
        std::error_code ec;
        fs::remove_all(plan->run_dir, ec);
        if (app::stop_requested()) break;
    }
    if (app::stop_requested()) {
        fmt::print("ricochet fuzz convert: stopped by {} after {} artifact(s) (exit {})\n", app::stop_signal_name(),
                   converted + failed, app::stop_exit_code());
        return app::stop_exit_code();
    }
    fmt::print("ricochet fuzz convert: {} converted, {} not{}\n", converted, failed, failed > 0 ? " (exit 1)" : "");
    return failed > 0 ? 1 : 0;
}

}  // namespace ricochet::fuzz
