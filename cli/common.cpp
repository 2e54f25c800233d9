// Helpers shared by the subcommands: loading logs, kernels, replaying.
#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <chrono>
#include <system_error>
#include <variant>

#include <fmt/format.h>

#include "commands.hpp"
#include "progress.hpp"
#include "ricochet/hash.hpp"
#include "ricochet/kernel_id.hpp"
#include "ricochet/check.hpp"
#include "ricochet/kernel_spec.hpp"
#include "ricochet/plugin_guard.hpp"
#include "ricochet/plugin_loader.hpp"
#include "ricochet/replay.hpp"
#include "ricochet/scene_log.hpp"
#include "ricochet_app/json.hpp"
#include "ricochet_app/report.hpp"
#include "ricochet_app/stop_signal.hpp"

namespace ricochet::cli {

namespace {

/// Seconds from t0 to now.
double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

SceneOrDiagnostic read_scene_or_stdin(const std::string& path, ExpectLines expect_lines) {
    if (path != k_stdin_path) return read_scene_log(path, expect_lines);
    // At most one byte past the limit, as read_log_text reads a file, so a huge stream is refused quickly.
    std::string text;
    std::array<char, 65536> chunk{};
    for (std::size_t n; (n = std::fread(chunk.data(), 1, chunk.size(), stdin)) > 0;) {
        text.append(chunk.data(), n);
        if (text.size() > k_max_file_size)
            return Diagnostic{std::string(k_stdin_name), 1, 1,
                              fmt::format("the input is over the limit of {} bytes", k_max_file_size)};
    }
    if (std::ferror(stdin))
        return Diagnostic{std::string(k_stdin_name), 1, 1, fmt::format("cannot read: {}", std::strerror(errno))};
    return parse_scene_log(text, k_stdin_name, expect_lines);
}

Scene load_scene_or_exit(const std::string& path) {
    auto result = read_scene_or_stdin(path);
    if (auto* d = std::get_if<Diagnostic>(&result)) {
        fmt::print(stderr, "{}\n", d->str());
        throw Exit{2};
    }
    return std::get<Scene>(std::move(result));
}

void check_supported_or_exit(const std::string& log, const Scene& scene, KernelId k, std::span<const Check> checks) {
    if (const auto why = refusal(scene, k)) {
        fmt::print(stderr, "{}: error: {}\n", log, *why);
        throw Exit{2};
    }
}

void write_file_holding_signals(const std::string& path, std::string_view text,
                                std::optional<app::ExitOnSignal>& running, std::optional<app::StopOnSignal>& stop) {
    std::string error;
    bool written = false;
    if (path == k_stdout_path || writes_in_place(path)) {
        // Standard output, a device or a FIFO is written in place: it cannot be whole or untouched, and a
        // write to a FIFO or a pipe waits on its reader, so a signal during it ends the command at once.
        running.reset();
        {
            const app::ExitOnSignal cut("ricochet: the write in place was cut short; stopped by ");
            if (path == k_stdout_path) {
                write_stdout(text);
                std::fflush(stdout);
                check_stdout();
                written = true;
            } else {
                written = write_file_atomically(path, text, &error);
            }
        }
        stop.emplace();
    } else {
        const app::HoldSignals hold;
        running.reset();
        stop.emplace();
        written = write_file_atomically(path, text, &error);
    }
    if (!written) {
        fmt::print(stderr, "ricochet: error: {}\n", error);
        throw Exit{1};
    }
}

KernelId kernel_or_exit(const std::string& spec) {
    std::string error;
    const auto k = resolve_kernel(spec, &error);
    if (!k) {
        fmt::print(stderr, "ricochet: error: {}\n", error);
        throw Exit{2};
    }
    return *k;
}

void add_plugin_option(CLI::App& command, std::vector<std::string>& plugins) {
    command.add_option("--plugin", plugins,
                       "load the plug-in kernel in this shared library first (ricochet/plugin.h), so that logs naming "
                       "it read; repeatable (a log never loads one)")
        // One file per --plugin: the paths after it are the command's own.
        ->allow_extra_args(false);
}

void load_plugins_or_exit(const std::vector<std::string>& plugins) {
    for (const std::string& p : plugins) {
        std::string error;
        if (!load_plugin(p, &error)) {
            fmt::print(stderr, "ricochet: error: {}\n", error);
            throw Exit{2};
        }
    }
}

void stage_plugin_run(KernelId k, std::string doing) {
    if (plugin_info(k) != nullptr) stage_plugin_input({std::move(doing), {}, {}});
}

ReplaySummary replay_paths(const std::vector<std::string>& paths, bool hashes_only, std::uint64_t max_work,
                           std::optional<KernelId> kernel) {
    ReplaySummary s;
    std::vector<std::filesystem::path> logs;
    for (const std::string& p : paths) {
        std::error_code ec;
        if (p == k_stdin_path) {
            logs.emplace_back(p);
        } else if (std::filesystem::is_directory(p, ec)) {
            std::vector<std::filesystem::path> found;
            for (auto it = std::filesystem::recursive_directory_iterator(p, ec);
                 !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec))
                if (it->is_regular_file() && it->path().extension() == ".scene") found.push_back(it->path());
            if (ec) {
                s.errors.push_back(fmt::format("{}:1:1: error: cannot list the folder: {}", p, ec.message()));
                fmt::print(stderr, "{}\n", s.errors.back());
                s.bad_input = true;
            } else if (found.empty()) {
                // An empty or mistyped folder checks nothing: a false green in CI if it passed.
                s.errors.push_back(fmt::format("ricochet: error: no scene logs (*.scene) under {}", p));
                fmt::print(stderr, "{}\n", s.errors.back());
                s.bad_input = true;
            }
            std::sort(found.begin(), found.end());
            logs.insert(logs.end(), found.begin(), found.end());
        } else if (std::filesystem::exists(p, ec)) {
            logs.emplace_back(p);
        } else {
            fmt::print(stderr, "{}:1:1: error: no such file or folder\n", p);
            s.logs.push_back({p, "missing", "no such file or folder", std::nullopt, std::nullopt, std::nullopt, 0});
            s.bad_input = true;
            ++s.failed;
        }
    }
    s.total = logs.size();
    Progress progress("ricochet replay", Progress::Unit::log);
    std::size_t done = 0;
    const auto stopped_line = [&] {
        fmt::print(stderr, "ricochet replay: stopped by {} after {} of {} logs\n", app::stop_signal_name(), done,
                   logs.size());
    };
    for (const auto& log : logs) {
        const auto log_t0 = std::chrono::steady_clock::now();
        // A log boundary: a SIGINT or SIGTERM (the caller holds a StopOnSignal) stops before the next log.
        if (app::stop_requested()) {
            s.stopped = true;
            progress.clear();
            stopped_line();
            break;
        }
        progress.update(static_cast<std::int64_t>(done), static_cast<std::int64_t>(logs.size()));
        auto parsed = read_scene_or_stdin(log.string());
        if (auto* d = std::get_if<Diagnostic>(&parsed)) {
            ++done;
            progress.clear();
            // A log for a kernel this build knows but lacks (a peer left out) is skipped, and said so: the
            // build, not the log, lacks something.
            const auto quote = d->message.find('\'');
            const auto unquote = quote == std::string::npos ? quote : d->message.find('\'', quote + 1);
            if (unquote != std::string::npos && d->message.starts_with("kernel '") &&
                absent_kernel_message(std::string_view(d->message).substr(quote + 1, unquote - quote - 1)) == d->message) {
                if (!hashes_only) write_stdout(fmt::format("skip {}: {}\n", log.string(), d->message));
                s.logs.push_back({log.string(), "skipped", d->message, std::nullopt, std::nullopt, std::nullopt, seconds_since(log_t0)});
                ++s.skipped;
                ++s.skip_reasons[d->message];
                continue;
            }
            fmt::print(stderr, "{}\n", d->str());
            // A plug-in's failure log names its kernel, which only a plug-in loaded first makes known.
            if (d->message.starts_with("unknown kernel"))
                fmt::print(stderr, "ricochet: note: a plug-in's kernel is known once the plug-in is loaded: --plugin PATH\n");
            if (!hashes_only) write_stdout(fmt::format("FAIL {}: unreadable log\n", log.string()));
            s.logs.push_back({log.string(), "unreadable", d->str(), std::nullopt, std::nullopt, std::pair{d->line, d->col}, seconds_since(log_t0)});
            s.bad_input = true;
            ++s.failed;
            continue;
        }
        const Scene& scene = std::get<Scene>(parsed);
        if (const std::string error = work_over_budget(log.string(), scene, scene.frames, max_work); !error.empty()) {
            ++done;
            progress.clear();
            fmt::print(stderr, "ricochet: error: {}\n", error);
            if (!hashes_only) write_stdout(fmt::format("FAIL {}: not run (over --max-work)\n", log.string()));
            s.logs.push_back({log.string(), "over-budget", error, std::nullopt, std::nullopt, std::nullopt, seconds_since(log_t0)});
            s.bad_input = true;
            ++s.failed;
            continue;
        }
        // A kernel that cannot step the log's discs or bumpers: bad input.
        const KernelId k = kernel.value_or(scene.kernel);
        if (const auto why = refusal(scene, k)) {
            ++done;
            progress.clear();
            const std::string error = fmt::format("{}: error: {}", log.string(), *why);
            fmt::print(stderr, "{}\n", error);
            if (!hashes_only) write_stdout(fmt::format("FAIL {}: not run (unsupported)\n", log.string()));
            s.logs.push_back({log.string(), "unsupported", error, std::nullopt, std::nullopt, std::nullopt, seconds_since(log_t0)});
            s.bad_input = true;
            ++s.failed;
            continue;
        }
        stage_plugin_run(k, fmt::format("replaying {}", log.string()));
        // Between two frames: a SIGINT or SIGTERM ends a long log there, as `run` does.
        const ReplayResult r = replay_scene(scene, kernel, [] { return app::stop_requested(); });
        clear_plugin_stage();
        if (r.stopped) {
            s.stopped = true;
            s.stopped_at = StoppedAt{log.string(), r.run.frames_run, scene.frames};
            progress.clear();
            fmt::print(stderr, "ricochet replay: stopped by {} in {} after frame {} of {}\n", app::stop_signal_name(),
                       log.string(), r.run.frames_run, scene.frames);
            stopped_line();
            break;
        }
        ++done;
        if (hashes_only)
            write_stdout(fmt::format("{} {}\n", format_hash(r.run.hash), log.string()));
        else
            write_stdout(fmt::format("{} {}: {}\n", r.passed ? "ok  " : "FAIL", log.string(), r.message));
        (r.passed ? s.passed : s.failed) += 1;
        s.logs.push_back({log.string(), r.passed ? "passed" : "failed", r.message, r.run.hash, r.run.failure, std::nullopt, seconds_since(log_t0)});
        // Line by line, so a reader (and a failed write) sees each verdict as it comes.
        std::fflush(stdout);
        check_stdout();
    }
    if (!hashes_only) write_stdout(replay_counts(s, false) + "\n");
    std::fflush(stdout);
    check_stdout();
    return s;
}

std::string replay_counts(const ReplaySummary& s, bool with_reasons) {
    std::string out = fmt::format("{} passed, {} failed", s.passed, s.failed);
    if (s.skipped == 0) return out;
    out += fmt::format(", {} skipped", s.skipped);
    if (!with_reasons) return out;
    std::string why;
    for (const auto& [reason, n] : s.skip_reasons) why += fmt::format("{}{}: {}", why.empty() ? "" : "; ", reason, n);
    return fmt::format("{} ({})", out, why);
}

void write_replay_members(app::JsonWriter& json, const ReplaySummary& s) {
    json.member("passed", s.passed).member("failed", s.failed).member("skipped", s.skipped);
    json.key("skip_reasons").begin_object();
    for (const auto& [reason, n] : s.skip_reasons) json.member(reason, n);
    json.end_object();
    json.member("bad_input", s.bad_input);
    json.member("stopped", s.stopped).member("total", static_cast<std::uint64_t>(s.total));
    json.key("stopped_at");
    if (s.stopped_at)
        json.begin_object()
            .member("path", s.stopped_at->path)
            .member("frame", s.stopped_at->frame)
            .member("frames", s.stopped_at->frames)
            .end_object();
    else
        json.null();
    json.key("errors").begin_array();
    for (const std::string& e : s.errors) json.value(e);
    json.end_array();
    json.key("logs").begin_array();
    // A member that is absent for this log: null.
    const auto maybe = [&](std::string_view name, const auto& v, bool present) -> app::JsonWriter& {
        return present ? json.member(name, v) : json.key(name).null();
    };
    for (const LogVerdict& v : s.logs) {
        json.begin_object().member("path", v.path).member("status", v.status).member("message", v.message).key("hash");
        if (v.hash)
            json.value(format_hash(*v.hash));
        else
            json.null();
        maybe("check", v.failure ? std::string(check_name(v.failure->check)) : std::string(), v.failure.has_value());
        maybe("frame", v.failure ? v.failure->frame : std::int64_t{0}, v.failure.has_value());
        maybe("ball", v.failure ? std::int64_t{v.failure->ball} : std::int64_t{0}, v.failure.has_value());
        maybe("line", v.place ? v.place->first : 0, v.place.has_value());
        maybe("column", v.place ? v.place->second : 0, v.place.has_value());
        json.end_object();
    }
    json.end_array();
}

void add_report_options(CLI::App& command, app::ReportFiles& files, std::string_view cases, bool sarif) {
    command.add_option("--junit", files.junit,
                       fmt::format("also write a JUnit XML report to FILE ({}; docs/cli-reports.md), whole or not at all",
                                   cases))
        ->type_name("FILE");
    if (sarif)
        command.add_option("--sarif", files.sarif,
                           "also write a SARIF 2.1.0 log to FILE: a result per failure, at its saved log's line "
                           "(docs/cli-reports.md)")
            ->type_name("FILE");
}

void check_report_files_or_exit(const app::ReportFiles& files) {
    if (const std::string problem = app::report_files_problem(files); !problem.empty()) {
        fmt::print(stderr, "ricochet: error: {}\n", problem);
        throw Exit{2};
    }
}

bool write_reports_or_say(const app::Report& report, const app::ReportFiles& files) {
    std::string error;
    if (app::write_reports(report, files, write_file_atomically, &error)) return true;
    fmt::print(stderr, "ricochet: error: {}\n", error);
    return false;
}

app::TestSuite replay_suite(const ReplaySummary& s, double seconds) {
    using O = app::TestCase::Outcome;
    app::TestSuite suite{"replay", seconds, {}};
    for (const std::string& e : s.errors) suite.cases.push_back({"replay", e, 0, O::error, e, {{"missing", {}, {}, {}, {}, {}, e}}});
    for (const LogVerdict& v : s.logs) {
        const std::string folder = std::filesystem::path(v.path).parent_path().generic_string();
        app::TestCase c{folder.empty() ? "." : folder, v.path, v.seconds, O::passed, {}, {}};
        // A log that ran: its run's first broken check (none when only an expect line missed), at the log.
        app::Finding f{v.status, {}, {}, v.status == "missing" ? std::string() : v.path, {}, {}, v.message};
        if (v.failure) {
            f.rule = check_name(v.failure->check);
            f.frame = v.failure->frame;
            f.ball = v.failure->ball;
            // The line's text says the check, frame and ball again; the check's own message is the rest.
            f.detail = v.failure->message;
        } else if (v.status == "failed") {
            f.rule = "expect";
        }
        if (v.place) f.line = v.place->first, f.column = v.place->second;
        if (v.status == "failed") {
            c.outcome = O::failed;
            c.findings.push_back(std::move(f));
        } else if (v.status == "skipped") {
            c.outcome = O::skipped;
            c.message = v.message;
        } else if (v.status != "passed") {
            // Unreadable, missing, over the work bound, unsupported: bad input, as replay's exit status 2 says.
            c.outcome = O::error;
            c.message = v.message;
            c.findings.push_back(std::move(f));
        }
        suite.cases.push_back(std::move(c));
    }
    return suite;
}

}  // namespace ricochet::cli
