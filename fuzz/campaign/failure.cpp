// Turning failure artifacts into scene logs (failure.hpp). The fuzz target writes the failure log itself
// (fuzz_common.cpp's fail(), make_failure_log: `from fuzz TARGET SHA1`, the check that failed, `found`, `expect
// failure` for a lecture kernel) when RICOCHET_FUZZ_SCENE_OUT names a file; the campaign reduces it (reduce.hpp:
// libFuzzer minimizes bytes, not scenes) and saves the reduced log as fuzz-TARGET-ID.scene through
// save_scene_log_once, which tells a new case from one already in the folder under any name.
#include "failure.hpp"

#include <algorithm>
#include <charconv>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
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

/// Most runs of libFuzzer's -minimize_crash (keeps minimization to seconds).
constexpr std::uint64_t k_minimize_runs = 20000;
/// In a campaign by time, the most seconds one minimization takes (and never more than half of what is left).
constexpr double k_minimize_seconds = 20;
/// libFuzzer's -timeout for the one run that tells a slow input from a hang (the workers' own, workers.cpp).
constexpr int k_timeout_seconds = 10;
/// In a campaign by time, the fewest seconds left for a conversion to start (running, minimizing, reducing an
/// input takes a few): with fewer, the artifact waits for the next campaign.
constexpr double k_convert_needs_s = 2;

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

/// The word after key in line up to the next space ("check=" in the target's failure line), or empty.
std::string field_of(std::string_view line, std::string_view key) {
    const auto at = line.find(key);
    if (at == std::string_view::npos) return {};
    const auto from = at + key.size();
    return std::string(line.substr(from, line.find(' ', from) - from));
}

/// A whole decimal number, or nothing.
std::optional<std::uint64_t> number_of(std::string_view s) {
    std::uint64_t v = 0;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
    return v;
}

/// Fills record's check, frame and ball from a failure log's `found C F B` line, else from the target's failure
/// line (check and frame).
void where_it_failed(FailureRecord& record, const std::string& log_text, const std::string& failure_line) {
    std::istringstream lines(log_text);
    for (std::string line; std::getline(lines, line);) {
        std::istringstream words(line);
        std::string word, check, frame, ball;
        if (words >> word >> check >> frame >> ball && word == "found") {
            record.check = check;
            record.frame = number_of(frame);
            record.ball = number_of(ball);
            return;
        }
    }
    if (failure_line.starts_with(k_failure_tag)) {
        record.check = field_of(failure_line, " check=");
        record.frame = number_of(field_of(failure_line, " frame="));
    }
}

/// A line every k_progress_every_s calls (run_bounded calls its tick about once a second), "WHAT, N s so far".
std::function<void()> every_few_seconds(const Budget& budget, const std::string& target, std::string what) {
    return [&budget, target, what = std::move(what), began = Clock::now(), ticks = 0]() mutable {
        if (++ticks % k_progress_every_s == 0)
            budget.say(target, fmt::format("{}, {:.0f} s so far", what, std::chrono::duration<double>(Clock::now() - began).count()));
    };
}

/// The failure log text the target wrote, reduced (reduce_log with its default budget of tries, a count,
/// so a campaign by --runs saves the same log on every machine; the same as `ricochet reduce LOG`); the text
/// as it is if it does not read or cannot be reduced (the reproduction check after saving says so). A stop, or
/// in a campaign by time the deadline, ends the reduction with the smallest failing log found so far.
std::string reduced_log(const std::string& text, const fs::path& path, const TargetRun& r, const Budget& budget) {
    const SceneOrDiagnostic parsed = parse_scene_log(text, path.string());
    const Scene* scene = std::get_if<Scene>(&parsed);
    if (scene == nullptr) return text;
    ReduceOptions options;
    // A stopped campaign still saves what it converted: the reduction so far is a failure log too.
    options.stop = [&budget] { return app::stop_requested() || budget.left() <= 0; };
    Clock::time_point next = Clock::now() + std::chrono::seconds(k_progress_every_s);
    options.on_progress = [&](const ReduceProgress& p) {
        if (Clock::now() < next) return;
        next = Clock::now() + std::chrono::seconds(k_progress_every_s);
        budget.say(r.target, fmt::format("reducing, {} tries so far ({} entities, {} frames)", p.tries, p.size.entities(),
                                         p.size.frames));
    };
    budget.say(r.target, "reducing the log");
    const auto result = reduce_log(*scene, options);
    const auto* reduced = std::get_if<ReducedLog>(&result);
    if (reduced == nullptr || reduced->error) {
        fmt::print("    not reduced: {}\n",
                   reduced == nullptr ? std::get<ReduceRefusal>(result).message : "the log's run stops at an error");
        return text;
    }
    fmt::print("    reduced:      {} to {} entities, {} to {} frames in {} tries{}\n", reduced->before.entities(),
               reduced->after.entities(), reduced->before.frames, reduced->after.frames, reduced->tries,
               reduced->end != ReduceEnd::stopped ? ""
               : app::stop_requested()            ? fmt::format(" (stopped by {})", app::stop_signal_name())
                                                  : " (cut at the time limit)");
    return reduced->log.text();
}

/// reduced_log for a plug-in's failure: the reduction runs a plug-in on scenes no worker has run, and one it
/// crashes or hangs on ends the process it runs in (plugin_guard.hpp), so it runs apart, as `ricochet reduce
/// --plugin PATH` (this program, /proc/self/exe). If that process ends otherwise than with a reduced log (or is
/// cut at the time limit), the text is saved as the target wrote it.
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
    plan.budget.say(r.target, "reducing the log (`ricochet reduce --plugin`, a process of its own)");
    const RunResult run = run_bounded({self.string(), "reduce", in.string(), "-o", out.string(), "--plugin", plan.plugin.string()},
                                      {}, scratch, plan.budget.deadline(), every_few_seconds(plan.budget, r.target, "reducing"));
    const std::string reduced = run.rc == 0 && !run.cut ? read_all(out) : std::string();
    if (reduced.empty()) {
        fmt::print("    not reduced: `ricochet reduce --plugin {}` {}{}\n", plan.plugin.string(),
                   run.cut ? std::string("was cut at the time limit") : fmt::format("ended with exit {}", run.rc),
                   run.rc == k_plugin_fault_exit ? " (the plug-in crashed or hung on a smaller scene)" : "");
        return text;
    }
    // Its summary line, "ricochet reduce: BEFORE → AFTER; …", says what it did.
    constexpr std::string_view summary = "ricochet reduce: ";
    if (const auto at = run.out.rfind(summary); at != std::string::npos) {
        const auto from = at + summary.size();
        fmt::print("    reduced:      {}\n", run.out.substr(from, run.out.find('\n', from) - from));
    }
    return reduced;
}

/// Why a conversion did not end: a stop, or the deadline (its artifact then waits in pending/).
struct NotConverted {};

/// One run of input under the workers' timeout, writing the failure log to scene_out: its exit status and output;
/// NotConverted if a stop or the deadline came first.
std::variant<RunResult, NotConverted> run_once(const TargetRun& r, const Plan& plan, const fs::path& input, const std::string& sha,
                                               const fs::path& scene_out) {
    std::error_code ec;
    fs::remove(scene_out, ec);
    RunResult run = run_bounded({r.bin.string(), fmt::format("-timeout={}", k_timeout_seconds), input.string()},
                                {"RICOCHET_KERNEL=" + plan.kernel_env, std::string(k_scene_out_env) + "=" + scene_out.string(),
                                 std::string(k_sha1_env) + "=" + sha},
                                r.work / "scratch.log", plan.budget.deadline());
    if (run.cut || app::stop_requested()) return NotConverted{};
    return run;
}

/// Converts the artifact r.artifacts/name (this campaign's, or one claimed from pending/): runs it once, and a
/// failure not among signatures is minimized, run again to write its log, reduced and saved. The record, with
/// the raw artifact moved to r.kept; nothing (the artifact left where it is) if a stop or the deadline came
/// first, or if it is a new failure and settings.most were minimized already (*most_reached set).
std::optional<FailureRecord> convert_one(TargetRun& r, const ConvertSettings& settings, const Plan& plan, const std::string& name,
                                         std::set<std::string>& signatures, int& minimized, bool* most_reached) {
    const Budget& budget = plan.budget;
    const fs::path raw = r.artifacts / name;
    const fs::path scratch = r.work / "scratch.log";
    FailureRecord record;
    record.target = r.target;
    record.kernel = plan.kernel_name;
    record.artifact = raw;
    std::error_code ec;
    const auto keep_raw = [&] {
        std::string moved;
        record.artifact = move_into(raw, r.kept, &moved);
        if (!moved.empty()) r.notes.push_back(moved);
    };
    // Run once, as the worker did: a slow input or a flaky one is told apart here, and a failure met before in
    // this campaign is not minimized again.
    const std::string raw_sha = sha1_hex(read_all(raw));
    const fs::path raw_scene = r.work / "raw.scene";
    budget.say(r.target, fmt::format("{}: running it again", name));
    auto first = run_once(r, plan, raw, raw_sha, raw_scene);
    if (std::holds_alternative<NotConverted>(first)) return std::nullopt;
    const RunResult once = std::get<RunResult>(first);
    const bool timed_out = name.starts_with("timeout-");
    if (once.rc == 0 && timed_out) {
        // Slow, not failing: every check held, so there is no failure for replay to reproduce. Said, and kept.
        keep_raw();
        r.notes.push_back(fmt::format("{}: a slow input, not a failure: it ran past libFuzzer's -timeout in the campaign, "
                                      "and run again alone (within {} s) every check held; kept at {} (time `{} {}` to "
                                      "see how slow)",
                                      name, k_timeout_seconds, record.artifact.string(), r.bin.string(), record.artifact.string()));
        record.status = FailureStatus::slow;
        return record;
    }
    if (once.rc == 0) {
        keep_raw();
        r.notes.push_back(fmt::format("{}: does not fail when run again (flaky?); kept at {}", name, record.artifact.string()));
        record.status = FailureStatus::flaky;
        return record;
    }
    auto [raw_signature, raw_line] = signature_of(once.out);
    if (raw_signature.empty()) raw_signature = fmt::format("exit {}", once.rc);
    if (signatures.contains(raw_signature)) {
        keep_raw();
        r.notes.push_back(fmt::format("{}: same failure as one above ({})", name, raw_signature));
        record.status = FailureStatus::duplicate;
        record.message = raw_line;
        where_it_failed(record, read_all(raw_scene), raw_line);
        return record;
    }
    if (settings.most > 0 && minimized >= settings.most) {
        *most_reached = true;
        return std::nullopt;
    }
    ++minimized;
    // Minimize: libFuzzer keeps the input failing while it shrinks it, capped in runs (and, by time, in seconds
    // and by the deadline: what it shrank so far is in its output file, each step's). A campaign of fewer --runs
    // per worker minimizes with as many: N bounds every libFuzzer process it starts. Not a timeout: minimizing one
    // runs its input in a child -runs times over (libFuzzer's way with a file input), each run as slow as the one
    // that timed out.
    const fs::path minimized_path = r.work / ("minimized-" + name);
    fs::remove(minimized_path, ec);
    if (!timed_out) {
        std::vector<std::string> argv = {r.bin.string(), "-minimize_crash=1", fmt::format("-runs={}", settings.minimize_runs)};
        std::optional<Clock::time_point> until;
        if (settings.minimize_by_time) {
            const double seconds = std::min(k_minimize_seconds, budget.left() / 2);
            argv.push_back(fmt::format("-max_total_time={}", std::max(1, static_cast<int>(seconds))));
            until = budget.within(seconds);
        }
        if (settings.seed > 0) argv.push_back(fmt::format("-seed={}", settings.seed));
        argv.insert(argv.end(), {"-exact_artifact_path=" + minimized_path.string(), raw.string()});
        budget.say(r.target, fmt::format("{}: minimizing", name));
        const RunResult m = run_bounded(argv, {"RICOCHET_KERNEL=" + plan.kernel_env}, scratch, until,
                                        every_few_seconds(budget, r.target, "minimizing"));
        if (app::stop_requested() || budget.left() <= 0) return std::nullopt;
        if (m.cut) budget.say(r.target, "minimizing cut at its share of the time; going on with the smallest input so far");
    }
    // The input converted: the minimized one if it still fails, else the raw one (and its run above).
    fs::path input = raw;
    std::string sha = raw_sha;
    RunResult run = once;
    fs::path scene_out = raw_scene;
    if (fs::exists(minimized_path) && fs::file_size(minimized_path, ec) > 0) {
        const std::string min_sha = sha1_hex(read_all(minimized_path));
        const fs::path min_scene = r.work / "failure.scene";
        budget.say(r.target, fmt::format("{}: running the minimized input", name));
        auto again = run_once(r, plan, minimized_path, min_sha, min_scene);
        if (std::holds_alternative<NotConverted>(again)) return std::nullopt;
        if (std::get<RunResult>(again).rc != 0) {
            // Kept as minimized-SHA1 (its own bytes' name): two campaigns keeping it keep one file.
            const fs::path named = r.work / ("minimized-" + min_sha);
            fs::rename(minimized_path, named, ec);
            std::string moved;
            input = ec ? minimized_path : move_into(named, r.kept, &moved);
            if (!moved.empty()) r.notes.push_back(moved);
            sha = min_sha;
            run = std::get<RunResult>(again);
            scene_out = min_scene;
        } else {
            r.notes.push_back(fmt::format("{}: its minimized input did not fail when run again; the raw input is converted", name));
        }
    }
    keep_raw();
    if (input == raw) input = record.artifact;
    auto [signature, first_line] = signature_of(run.out);
    if (signature.empty()) signature = fmt::format("exit {}", run.rc);
    signatures.insert(raw_signature);
    record.message = first_line;
    if (!signatures.insert(signature).second && signature != raw_signature) {
        r.notes.push_back(fmt::format("{}: same failure as one above ({})", name, signature));
        record.status = FailureStatus::duplicate;
        where_it_failed(record, read_all(scene_out), first_line);
        return record;
    }
    fmt::print("  {} failure: {}\n    raw artifact: {}\n    minimized:    {} (sha1 {})\n", r.target, first_line,
               record.artifact.string(), input.string(), sha);
    const bool plugin_fault = signature.starts_with(k_plugin_fault_prefix);
    if (!fs::exists(scene_out)) {
        // The parser's inputs, and sanitizer crashes, have no scene: the input is the reproducer.
        const std::string env = plan.kernel_env == "robust" ? std::string() : fmt::format("RICOCHET_KERNEL={} ", plan.kernel_env);
        fmt::print("    no scene log (run `{}{} {}` to reproduce; add it to fuzz/corpus/{}/ once fixed)\n", env,
                   r.bin.string(), input.string(), r.target);
        record.status = FailureStatus::no_log;
        where_it_failed(record, {}, first_line);
        return record;
    }
    // The target wrote the failure log (make_failure_log); it is saved reduced, as a failure log of its own. A
    // scene a plug-in crashed or hung on is saved as written: running it here would do the same to this process.
    const std::string written = read_all(scene_out);
    const std::string text = plugin_fault          ? written
                             : !plan.plugin.empty() ? reduced_log_apart(written, r, plan, scratch)
                                                    : reduced_log(written, scene_out, r, budget);
    where_it_failed(record, text, first_line);
    std::string error;
    // Under the cache's lock, so that of two campaigns saving the same case one saves it, one finds it known.
    std::optional<SavedLog> saved;
    {
        const CacheLock lock(plan.cache, "saving a failure log");
        saved = save_scene_log_once(plan.replay_dir, "fuzz-" + r.target, std::string_view(text), &error);
    }
    if (!saved) {
        fmt::print("    cannot save the log: {}\n", error);
        record.status = FailureStatus::unsaved;
        return record;
    }
    record.log = saved->path;
    if (!saved->is_new) {
        fmt::print("    known: the same case is already there: {}\n", saved->path.string());
        record.status = FailureStatus::known;
        return record;
    }
    // A plug-in's log names its kernel: replay loads the plug-in first.
    const std::string plugin = plan.plugin.empty() ? std::string() : fmt::format("--plugin {} ", plan.plugin.string());
    fmt::print("    scene log: {}  (ricochet replay {}{})\n", saved->path.string(), plugin, saved->path.string());
    record.status = FailureStatus::saved;
    // The scene the plug-in crashed or hung on: replaying it here would do the same to this process.
    if (plugin_fault) {
        fmt::print("    the plug-in crashed or hung on this scene; replaying the log does the same (exit {})\n",
                   k_plugin_fault_exit);
        return record;
    }
    // The contract: replay shows the failure the target saw. A log that passes replay without expecting a
    // failure would guard against nothing: say so.
    const SceneOrDiagnostic parsed = read_scene_log(saved->path);
    if (const Scene* scene = std::get_if<Scene>(&parsed); scene != nullptr && !scene->expect_failure &&
                                                         replay_scene(*scene).passed)
        fmt::print("    note: replay's checks do not see this failure; the log documents the case only\n");
    return record;
}

/// Counts record in r (new, known) and keeps it.
void tally(TargetRun& r, FailureRecord record) {
    if (record.status == FailureStatus::known) {
        ++r.known_failures;
        r.logs.emplace_back(record.log.string(), false);
    } else if (record.counts_as_new() && record.status != FailureStatus::pending) {
        ++r.new_failures;
        if (!record.log.empty()) r.logs.emplace_back(record.log.string(), true);
    }
    r.failures.push_back(std::move(record));
}

}  // namespace

ConvertSettings convert_settings(const CampaignOptions& opt) {
    ConvertSettings s;
    s.minimize_runs = opt.runs > 0 ? std::min<std::uint64_t>(opt.runs, k_minimize_runs) : k_minimize_runs;
    s.minimize_by_time = opt.runs == 0;
    s.seed = opt.seed;
    return s;
}

void convert_failures(TargetRun& r, const ConvertSettings& settings, const Plan& plan) {
    const Budget& budget = plan.budget;
    std::error_code ec;
    // Those earlier campaigns left, claimed by moving them here (of two campaigns claiming one, one moves it).
    std::vector<std::string> order;
    for (const std::string& a : list_artifacts(r.pending)) {
        fs::rename(r.pending / a, r.artifacts / a, ec);
        if (!ec) order.push_back(a);
    }
    const std::size_t earlier = order.size();
    // Then this campaign's own (slow units are not failures: they are kept as they are, below).
    for (const std::string& a : list_artifacts(r.artifacts))
        if (!a.starts_with("slow-unit-") && std::find(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(earlier), a) ==
                                                order.begin() + static_cast<std::ptrdiff_t>(earlier))
            order.push_back(a);
    if (!order.empty())
        budget.say(r.target, fmt::format("{} failure artifact(s) to convert{}", order.size(),
                                         earlier > 0 ? fmt::format(" ({} left by earlier campaigns)", earlier) : std::string()));
    std::set<std::string> signatures;
    int minimized = 0;
    std::string left_why;
    for (const std::string& a : order) {
        if (left_why.empty() && app::stop_requested()) left_why = fmt::format("stopped by {}", app::stop_signal_name());
        if (left_why.empty() && budget.timed() && budget.left() < k_convert_needs_s) left_why = "the time was up";
        if (!left_why.empty()) break;
        bool most_reached = false;
        std::optional<FailureRecord> record = convert_one(r, settings, plan, a, signatures, minimized, &most_reached);
        if (record) {
            tally(r, std::move(*record));
            continue;
        }
        if (most_reached) continue;  // a new failure past the most: it waits, the others may be duplicates
        left_why = app::stop_requested() ? fmt::format("stopped by {}", app::stop_signal_name()) : "the time was up";
    }
    if (minimized >= settings.most && settings.most > 0 && left_why.empty()) left_why = fmt::format("{} converted already, the most per campaign", settings.most);
    // What is not converted waits in pending/ for the next campaign on this cache; slow units join the kept ones.
    std::size_t left = 0;
    for (const std::string& a : list_artifacts(r.artifacts)) {
        std::string moved;
        if (a.starts_with("slow-unit-")) {
            move_into(r.artifacts / a, r.kept, &moved);
        } else {
            FailureRecord record;
            record.target = r.target;
            record.kernel = plan.kernel_name;
            record.artifact = move_into(r.artifacts / a, r.pending, &moved);
            record.status = FailureStatus::pending;
            r.failures.push_back(std::move(record));
            ++left;
        }
        if (!moved.empty()) r.notes.push_back(moved);
    }
    r.pending_failures = static_cast<int>(list_artifacts(r.pending).size());
    if (left > 0)
        budget.say(r.target, fmt::format("{} failure artifact(s) left unconverted ({}): they wait in {} for the next campaign on "
                                         "this cache, or `ricochet fuzz convert`",
                                         left, left_why.empty() ? "not reached" : left_why, r.pending.string()));
    for (const auto& n : r.notes) fmt::print("  {}: {}\n", r.target, n);
}

std::optional<FailureRecord> convert_artifact(TargetRun& r, const ConvertSettings& settings, const Plan& plan, const fs::path& path,
                                              std::set<std::string>& signatures) {
    const std::string name = path.filename().string();
    std::error_code ec;
    // A copy in this command's own folder: the caller's file stays as it is.
    fs::copy_file(path, r.artifacts / name, fs::copy_options::overwrite_existing, ec);
    if (ec) {
        fmt::print("  {}: cannot copy it: {}\n", path.string(), ec.message());
        FailureRecord record;
        record.target = r.target;
        record.kernel = plan.kernel_name;
        record.artifact = path;
        record.status = FailureStatus::unsaved;
        record.message = ec.message();
        return record;
    }
    int minimized = 0;
    bool most_reached = false;
    ConvertSettings one = settings;
    one.most = 0;
    std::optional<FailureRecord> record = convert_one(r, one, plan, name, signatures, minimized, &most_reached);
    fs::remove(r.artifacts / name, ec);
    if (!record) return std::nullopt;
    record->artifact = path;
    // An artifact that waited in a cache's pending/ folder leaves it for the cache's artifacts/: converted.
    if (path.parent_path().filename() == "pending") {
        const fs::path kept = path.parent_path().parent_path() / "artifacts";
        if (fs::is_directory(kept, ec)) {
            std::string moved;
            record->artifact = move_into(path, kept, &moved);
        }
    }
    for (const auto& n : r.notes) fmt::print("  {}: {}\n", r.target, n);
    r.notes.clear();
    return record;
}

}  // namespace ricochet::fuzz
