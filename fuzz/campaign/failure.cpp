// Turning a campaign's failures into scene logs (failure.hpp). The fuzz target writes the log itself
// (fuzz_common.cpp's fail(): `from fuzz TARGET SHA1`, the check replay sees break, `expect failure` for
// a lecture kernel) when RICOCHET_FUZZ_SCENE_OUT names a file; the campaign reads it back and saves it as
// fuzz-TARGET-ID.scene through save_scene_log_once, so a case already saved is never saved twice.
#include "failure.hpp"

#include <set>
#include <sstream>
#include <string>
#include <system_error>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include "cache.hpp"
#include "fuzz_common.hpp"
#include "ricochet/replay.hpp"
#include "process.hpp"
#include "ricochet/checks.hpp"
#include "ricochet/scene_log.hpp"
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

/// The scene logs directly in dir, by file name.
std::set<std::string> scene_logs_in(const fs::path& dir) {
    std::set<std::string> out;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec))
        if (e.path().extension() == ".scene") out.insert(e.path().filename().string());
    return out;
}

/// The failure's signature (the target's failure line without its frame, or the sanitizer's summary)
/// and the line to print; both empty if the output has neither.
std::pair<std::string, std::string> signature_of(const std::string& out) {
    std::string signature, first_line;
    std::istringstream lines(out);
    for (std::string line; std::getline(lines, line);) {
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
void handle_failure(TargetRun& r, const CampaignOptions& opt, const fs::path& replay_dir, const std::string& artifact,
                    std::set<std::string>& signatures) {
    const fs::path raw = r.artifacts / artifact;
    const fs::path minimized = r.artifacts / ("minimized-" + artifact);
    const fs::path scratch = r.dir / "scratch.log";
    // Minimize: libFuzzer keeps the input failing while it shrinks it; capped in runs (and time).
    std::vector<std::string> argv = {r.bin.string(), "-minimize_crash=1", fmt::format("-runs={}", k_minimize_runs)};
    if (opt.runs == 0) argv.push_back(fmt::format("-max_total_time={}", k_minimize_seconds));
    if (opt.seed > 0) argv.push_back(fmt::format("-seed={}", opt.seed));
    argv.insert(argv.end(), {"-exact_artifact_path=" + minimized.string(), raw.string()});
    run_capture(argv, {"RICOCHET_KERNEL=" + opt.kernel}, scratch);
    std::error_code ec;
    const fs::path input = fs::exists(minimized) && fs::file_size(minimized, ec) > 0 ? minimized : raw;
    const std::string sha = sha1_hex(read_all(input));
    const fs::path scene_out = r.dir / "failure.scene";
    fs::remove(scene_out, ec);
    const auto [rc, out] = run_capture({r.bin.string(), input.string()},
                                       {"RICOCHET_KERNEL=" + opt.kernel, std::string(k_scene_out_env) + "=" + scene_out.string(),
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
    if (!fs::exists(scene_out)) {
        // The parser's inputs, and sanitizer crashes, have no scene: the input is the reproducer.
        fmt::print("    no scene log (run `{} {}` to reproduce; add it to fuzz/corpus/{}/ once fixed)\n", r.bin.string(),
                   input.string(), r.target);
        ++r.new_failures;
        return;
    }
    const SceneOrDiagnostic parsed = read_scene_log(scene_out);
    const Scene* scene = std::get_if<Scene>(&parsed);
    if (scene == nullptr) {
        fmt::print("    the target wrote an unreadable log: {}\n", std::get<Diagnostic>(parsed).str());
        ++r.new_failures;
        return;
    }
    // save_scene_log_once returns the existing log for a case saved before: the folder's logs before the
    // call tell a new log from a known one.
    const std::set<std::string> before = scene_logs_in(replay_dir);
    std::string error;
    const auto saved = save_scene_log_once(replay_dir, "fuzz-" + r.target, *scene, &error);
    if (!saved) {
        fmt::print("    cannot save the log: {}\n", error);
        ++r.new_failures;
        return;
    }
    if (before.contains(saved->filename().string())) {
        fmt::print("    known: an equal log is already there: {}\n", saved->string());
        ++r.known_failures;
        return;
    }
    fmt::print("    scene log: {}  (ricochet replay {})\n", saved->string(), saved->string());
    // A failure of the target's own oracle that none of replay's checks sees: the log passes replay
    // without expecting any failure, so it documents the case but does not guard against it. Say so.
    if (!scene->expect_failure && replay_scene(*scene).passed)
        fmt::print("    note: replay's checks do not see this failure (the target's oracle is stricter); the log "
                   "documents the case only\n");
    ++r.new_failures;
}

}  // namespace

void convert_failures(TargetRun& r, const CampaignOptions& opt, const fs::path& replay_dir) {
    std::set<std::string> fresh;
    for (const std::string& a : list_artifacts(r.artifacts))
        if (!r.artifacts_before.contains(a) && !a.starts_with("slow-unit-")) fresh.insert(a);
    std::set<std::string> signatures;
    int converted = 0;
    for (const std::string& a : fresh) {
        if (converted++ == k_max_failures_converted) {
            r.notes.push_back(fmt::format("{} more failure artifact(s) left unconverted in {}", fresh.size() - k_max_failures_converted,
                                          r.artifacts.string()));
            break;
        }
        handle_failure(r, opt, replay_dir, a, signatures);
    }
    for (const auto& n : r.notes) fmt::print("  {}: {}\n", r.target, n);
}

}  // namespace ricochet::fuzz
