// Turning a campaign's failures into scene logs (failure.hpp). The fuzz target writes the failure log
// itself (fuzz_common.cpp's fail(), make_failure_log: `from fuzz TARGET SHA1`, the check that failed,
// `found`, `expect failure` for a lecture kernel) when RICOCHET_FUZZ_SCENE_OUT names a file; the campaign
// saves it as fuzz-TARGET-ID.scene through save_scene_log_once, which tells a new case from one already
// in the folder under any name.
#include "failure.hpp"

#include <algorithm>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>
#include <string>
#include <system_error>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include "cache.hpp"
#include "cache_lock.hpp"
#include "fuzz_common.hpp"
#include "ricochet/replay.hpp"
#include "process.hpp"
#include "run_dir.hpp"
#include "ricochet/checks.hpp"
#include "ricochet/plugin_guard.hpp"
#include "ricochet/scene_log.hpp"
#include "ricochet_cli/stop_signal.hpp"
#include "sha1.hpp"

namespace ricochet::fuzz {
namespace {

namespace fs = std::filesystem;

/// Most failures of one target minimized and converted per campaign (the rest keep their artifacts).
constexpr int k_max_failures_converted = 5;
/// Runs cap for -minimize_crash (keeps minimization to seconds).
constexpr int k_minimize_runs = 20000;
/// Seconds cap for -minimize_crash in a campaign by time (a campaign by runs is capped by runs only, so
/// that it minimizes to the same input whatever the load).
constexpr int k_minimize_seconds = 20;

/// The failure's signature (the target's failure line without its frame, a plug-in guard's report without the
/// call's numbers, or the sanitizer's summary) and the line to print; both empty if the output has none.
std::pair<std::string, std::string> signature_of(const std::string& out) {
    std::string signature, first_line;
    std::istringstream lines(out);
    for (std::string line; std::getline(lines, line);) {
        // The plug-in crashed, hung or broke plugin.h: its report names it and what it was doing, before
        // whatever the handler after it (libFuzzer's, a sanitizer's) prints.
        if (line.starts_with(k_plugin_fault_prefix)) return {line.substr(0, line.find(", called with")), line};
        if (line.starts_with(k_failure_tag)) {
            const auto k = line.find(" check=");
            const auto f = line.find(" frame=");
            const auto kind = line.find(" kind=");
            return {line.substr(k, f - k) + line.substr(kind), line};
        }
        if (line.starts_with("SUMMARY:")) signature = first_line = line;
    }
    return {signature, first_line};
}

/// Minimizes one failure, converts it to a scene log, saves it unless it was saved before.
void handle_failure(TargetRun& r, const CampaignOptions& opt, const Plan& plan, const std::string& artifact,
                    std::set<std::string>& signatures) {
    const fs::path& replay_dir = plan.replay_dir;
    // The raw artifact joins the cache's kept ones: named by its SHA-1, so the same name is the same bytes.
    std::string moved;
    const fs::path raw = move_into(r.artifacts / artifact, r.kept, &moved);
    if (!moved.empty()) r.notes.push_back(moved);
    // Everything else is written in this campaign's own folder first.
    const fs::path minimized = r.work / ("minimized-" + artifact);
    const fs::path scratch = r.work / "scratch.log";
    // Minimize: libFuzzer keeps the input failing while it shrinks it; capped in runs (and time). A campaign
    // of fewer --runs per worker minimizes with as many: N bounds every libFuzzer process it starts.
    const std::uint64_t minimize_runs = opt.runs > 0 ? std::min<std::uint64_t>(opt.runs, k_minimize_runs) : k_minimize_runs;
    std::vector<std::string> argv = {r.bin.string(), "-minimize_crash=1", fmt::format("-runs={}", minimize_runs)};
    if (opt.runs == 0) argv.push_back(fmt::format("-max_total_time={}", k_minimize_seconds));
    if (opt.seed > 0) argv.push_back(fmt::format("-seed={}", opt.seed));
    argv.insert(argv.end(), {"-exact_artifact_path=" + minimized.string(), raw.string()});
    run_capture(argv, {"RICOCHET_KERNEL=" + plan.kernel_env}, scratch);
    std::error_code ec;
    fs::path input = raw;
    std::string sha = sha1_hex(read_all(raw));
    if (fs::exists(minimized) && fs::file_size(minimized, ec) > 0) {
        // Kept as minimized-SHA1 (its own bytes' name): two campaigns keeping it keep one file.
        sha = sha1_hex(read_all(minimized));
        const fs::path named = r.work / ("minimized-" + sha);
        fs::rename(minimized, named, ec);
        moved.clear();
        input = ec ? minimized : move_into(named, r.kept, &moved);
        if (!moved.empty()) r.notes.push_back(moved);
    }
    const fs::path scene_out = r.work / "failure.scene";
    fs::remove(scene_out, ec);
    const auto [rc, out] = run_capture({r.bin.string(), input.string()},
                                       {"RICOCHET_KERNEL=" + plan.kernel_env, std::string(k_scene_out_env) + "=" + scene_out.string(),
                                        std::string(k_sha1_env) + "=" + sha},
                                       scratch);
    auto [signature, first_line] = signature_of(out);
    if (rc == 0) {
        r.notes.push_back(fmt::format("{}: does not fail when run again (flaky?); kept at {}", artifact, raw.string()));
        ++r.new_failures;
        return;
    }
    if (signature.empty()) signature = fmt::format("exit {}", rc);
    if (!signatures.insert(signature).second) {
        r.notes.push_back(fmt::format("{}: same failure as one above ({})", artifact, signature));
        return;
    }
    fmt::print("  {} failure: {}\n    raw artifact: {}\n    minimized:    {} (sha1 {})\n", r.target, first_line, raw.string(),
               input.string(), sha);
    const bool plugin_fault = signature.starts_with(k_plugin_fault_prefix);
    if (!fs::exists(scene_out)) {
        // The parser's inputs, and sanitizer crashes, have no scene: the input is the reproducer.
        const std::string env = plan.kernel_env == "robust" ? std::string() : fmt::format("RICOCHET_KERNEL={} ", plan.kernel_env);
        fmt::print("    no scene log (run `{}{} {}` to reproduce; add it to fuzz/corpus/{}/ once fixed)\n", env,
                   r.bin.string(), input.string(), r.target);
        ++r.new_failures;
        return;
    }
    // The target wrote the failure log (make_failure_log); saved verbatim, its note comment kept.
    const std::string text = read_all(scene_out);
    std::string error;
    // Under the cache's lock, so that of two campaigns saving the same case one saves it, one finds it known.
    std::optional<SavedLog> saved;
    {
        const CacheLock lock(plan.cache, "saving a failure log");
        saved = save_scene_log_once(replay_dir, "fuzz-" + r.target, std::string_view(text), &error);
    }
    if (!saved) {
        fmt::print("    cannot save the log: {}\n", error);
        ++r.new_failures;
        return;
    }
    if (!saved->is_new) {
        fmt::print("    known: the same case is already there: {}\n", saved->path.string());
        r.logs.emplace_back(saved->path.string(), false);
        ++r.known_failures;
        return;
    }
    // A plug-in's log names its kernel: replay loads the plug-in first.
    const std::string plugin = plan.plugin.empty() ? std::string() : fmt::format("--plugin {} ", plan.plugin.string());
    fmt::print("    scene log: {}  (ricochet replay {}{})\n", saved->path.string(), plugin, saved->path.string());
    r.logs.emplace_back(saved->path.string(), true);
    ++r.new_failures;
    // The scene the plug-in crashed or hung on: replaying it here would do the same to this process.
    if (plugin_fault) {
        fmt::print("    the plug-in crashed or hung on this scene; replaying the log does the same (exit {})\n",
                   k_plugin_fault_exit);
        return;
    }
    // The contract: replay shows the failure the target saw. A log that passes replay without expecting a
    // failure would guard against nothing: say so.
    const SceneOrDiagnostic parsed = read_scene_log(saved->path);
    if (const Scene* scene = std::get_if<Scene>(&parsed); scene != nullptr && !scene->expect_failure &&
                                                         replay_scene(*scene).passed)
        fmt::print("    note: replay's checks do not see this failure; the log documents the case only\n");
}

}  // namespace

void convert_failures(TargetRun& r, const CampaignOptions& opt, const Plan& plan) {
    // Every artifact in this campaign's own folder is one of its workers'.
    std::set<std::string> fresh;
    for (const std::string& a : list_artifacts(r.artifacts))
        if (!a.starts_with("slow-unit-")) fresh.insert(a);
    std::set<std::string> signatures;
    int converted = 0;
    for (const std::string& a : fresh) {
        // A stopped campaign minimizes nothing more: the artifacts are kept below, to convert another time.
        if (cli::stop_requested()) {
            r.notes.push_back(fmt::format("stopped by {}: {} failure artifact(s) kept unconverted in {}", cli::stop_signal_name(),
                                          fresh.size() - static_cast<std::size_t>(converted), r.kept.string()));
            break;
        }
        if (converted++ == k_max_failures_converted) {
            r.notes.push_back(fmt::format("{} more failure artifact(s) left unconverted in {}", fresh.size() - k_max_failures_converted,
                                          r.kept.string()));
            break;
        }
        handle_failure(r, opt, plan, a, signatures);
    }
    // The rest (unconverted, slow units) join the kept ones before this campaign's folder goes.
    for (const std::string& a : list_artifacts(r.artifacts)) {
        std::string moved;
        move_into(r.artifacts / a, r.kept, &moved);
        if (!moved.empty()) r.notes.push_back(moved);
    }
    for (const auto& n : r.notes) fmt::print("  {}: {}\n", r.target, n);
}

}  // namespace ricochet::fuzz
