// Turning a campaign's failures into scene logs (failure.hpp). The fuzz target writes the failure log
// itself (fuzz_common.cpp's fail(), make_failure_log: `from fuzz TARGET SHA1`, the check that failed,
// `found`, `expect failure` for a lecture kernel) when RICOCHET_FUZZ_SCENE_OUT names a file; the campaign
// reduces it (reduce.hpp: libFuzzer minimizes bytes, not scenes) and saves the reduced log as
// fuzz-TARGET-ID.scene through save_scene_log_once, which tells a new case from one already in the folder
// under any name.
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
#include "process.hpp"
#include "ricochet/checks.hpp"
#include "ricochet/plugin_guard.hpp"
#include "ricochet/reduce.hpp"
#include "ricochet/replay.hpp"
#include "ricochet/scene_log.hpp"
#include "ricochet_app/stop_signal.hpp"
#include "run_dir.hpp"
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
/// libFuzzer's -timeout for the one run that tells a slow input from a hang (the workers' own, workers.cpp).
constexpr int k_timeout_seconds = 10;

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

/// The failure log text the target wrote, reduced (reduce_log with its default budget of tries, a count,
/// so a campaign by --runs saves the same log on every machine; the same as `ricochet reduce LOG`); the text
/// as it is if it does not read or cannot be reduced (the reproduction check after saving says so).
std::string reduced_log(const std::string& text, const fs::path& path) {
    const SceneOrDiagnostic parsed = parse_scene_log(text, path.string());
    const Scene* scene = std::get_if<Scene>(&parsed);
    if (scene == nullptr) return text;
    ReduceOptions options;
    // A stopped campaign still saves what it converted: the reduction so far is a failure log too.
    options.stop = [] { return app::stop_requested(); };
    const auto result = reduce_log(*scene, options);
    const auto* reduced = std::get_if<ReducedLog>(&result);
    if (reduced == nullptr || reduced->error) {
        fmt::print("    not reduced: {}\n",
                   reduced == nullptr ? std::get<ReduceRefusal>(result).message : "the log's run stops at an error");
        return text;
    }
    fmt::print("    reduced:      {} to {} entities, {} to {} frames in {} tries\n", reduced->before.entities(),
               reduced->after.entities(), reduced->before.frames, reduced->after.frames, reduced->tries);
    return reduced->log.text();
}

/// reduced_log for a plug-in's failure: the reduction runs a plug-in on scenes no worker has run, and one it
/// crashes or hangs on ends the process it runs in (plugin_guard.hpp), so it runs apart, as `ricochet reduce
/// --plugin PATH` (this program, /proc/self/exe). If that process ends otherwise than with a reduced log, the
/// text is saved as the target wrote it.
std::string reduced_log_apart(const std::string& text, const TargetRun& r, const Plan& plan, const fs::path& scratch) {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) {
        fmt::print("    not reduced: cannot find this program to reduce in a process of its own ({})\n", ec.message());
        return text;
    }
    const fs::path in = r.work / "to-reduce.scene", out = r.work / "reduced.scene";
    std::string error;
    fs::remove(out, ec);
    if (!write_file_atomically(in, text, &error)) {
        fmt::print("    not reduced: {}\n", error);
        return text;
    }
    const auto [rc, output] = run_capture({self.string(), "reduce", in.string(), "-o", out.string(), "--plugin",
                                           plan.plugin.string()},
                                          {}, scratch);
    const std::string reduced = rc == 0 ? read_all(out) : std::string();
    if (reduced.empty()) {
        fmt::print("    not reduced: `ricochet reduce --plugin {}` ended with exit {}{}\n", plan.plugin.string(), rc,
                   rc == k_plugin_fault_exit ? " (the plug-in crashed or hung on a smaller scene)" : "");
        return text;
    }
    // Its summary line, "ricochet reduce: BEFORE → AFTER; …", says what it did.
    constexpr std::string_view summary = "ricochet reduce: ";
    if (const auto at = output.rfind(summary); at != std::string::npos) {
        const auto from = at + summary.size();
        fmt::print("    reduced:      {}\n", output.substr(from, output.find('\n', from) - from));
    }
    return reduced;
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
    // Not a timeout: minimizing one runs its input in a child -runs times over (libFuzzer's way with a file
    // input), each run as slow as the one that timed out, which no cap in time stops.
    const bool timed_out = artifact.starts_with("timeout-");
    const std::uint64_t minimize_runs = opt.runs > 0 ? std::min<std::uint64_t>(opt.runs, k_minimize_runs) : k_minimize_runs;
    std::vector<std::string> argv = {r.bin.string(), "-minimize_crash=1", fmt::format("-runs={}", minimize_runs)};
    if (opt.runs == 0) argv.push_back(fmt::format("-max_total_time={}", k_minimize_seconds));
    if (opt.seed > 0) argv.push_back(fmt::format("-seed={}", opt.seed));
    argv.insert(argv.end(), {"-exact_artifact_path=" + minimized.string(), raw.string()});
    if (!timed_out) run_capture(argv, {"RICOCHET_KERNEL=" + plan.kernel_env}, scratch);
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
    // Run once more, under the workers' timeout (a hang must not hang the campaign here either).
    const auto [rc, out] = run_capture({r.bin.string(), fmt::format("-timeout={}", k_timeout_seconds), input.string()},
                                       {"RICOCHET_KERNEL=" + plan.kernel_env, std::string(k_scene_out_env) + "=" + scene_out.string(),
                                        std::string(k_sha1_env) + "=" + sha},
                                       scratch);
    auto [signature, first_line] = signature_of(out);
    if (rc == 0 && timed_out) {
        // Slow, not failing: every check held, so there is no failure for replay to reproduce. Said, and kept.
        r.notes.push_back(fmt::format("{}: a slow input, not a failure: it ran past libFuzzer's -timeout in the campaign, "
                                      "and run again alone (within {} s) every check held; kept at {} (time `{} {}` to "
                                      "see how slow)",
                                      artifact, k_timeout_seconds, raw.string(), r.bin.string(), raw.string()));
        return;
    }
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
    // The target wrote the failure log (make_failure_log); it is saved reduced, as a failure log of its own. A
    // scene a plug-in crashed or hung on is saved as written: running it here would do the same to this process.
    const std::string written = read_all(scene_out);
    const std::string text = plugin_fault          ? written
                             : !plan.plugin.empty() ? reduced_log_apart(written, r, plan, scratch)
                                                    : reduced_log(written, scene_out);
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
        if (app::stop_requested()) {
            r.notes.push_back(fmt::format("stopped by {}: {} failure artifact(s) kept unconverted in {}", app::stop_signal_name(),
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
