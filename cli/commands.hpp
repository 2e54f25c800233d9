// The `ricochet` command's own subcommands: each file registers one on the app (`bench` and `fuzz` are
// registered by bench/ and fuzz/, ricochet_bench/command.hpp and ricochet_fuzz/command.hpp).
#pragma once

#include <CLI/CLI.hpp>

#include <filesystem>
#include <map>
#include <utility>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "output.hpp"
#include "ricochet/checks.hpp"
#include "ricochet/scene.hpp"
#include "ricochet/scene_log.hpp"
#include "ricochet_app/json.hpp"
#include "ricochet_app/report.hpp"
#include "ricochet_app/stop_signal.hpp"
#include "work_budget.hpp"

namespace ricochet::cli {

/// Thrown by a subcommand's callback to end the program with code (after flushing output).
struct Exit {
    int code = 0;
};

/// `ricochet run LOG [--kernel K] [--frames N]`.
void register_run(CLI::App& app);
/// `ricochet record LOG`.
void register_record(CLI::App& app);
/// `ricochet replay [PATH...] [--hashes]` (default: the project's replays/, ricochet_app/project.hpp).
void register_replay(CLI::App& app);
/// `ricochet render LOG -o FILE.svg [--frames A:B]`.
void register_render(CLI::App& app);
/// `ricochet reduce LOG [-o OUT]`: the smallest log found that fails as LOG does (reduce.hpp).
void register_reduce(CLI::App& app);
/// `ricochet check [--replay-dir DIR]`: the project's corpus, properties and a short fuzz campaign.
void register_check(CLI::App& app);
/// `ricochet help [COMMAND]`: the program's help, or a command's, on stdout.
void register_help(CLI::App& app);
/// `ricochet completion bash|zsh` (a shell's completion script) and the hidden `ricochet __complete` it calls.
void register_completion(CLI::App& app);
/// `ricochet bench` in a build without bench/ (RICOCHET_BENCH=OFF): says how to get it, exits 1.
void register_bench_not_built(CLI::App& app);
/// `ricochet fuzz` in a build without the campaign (RICOCHET_FUZZ_CAMPAIGN=OFF, as on wasm32): says why, exits 1.
void register_fuzz_not_built(CLI::App& app);

/// The program's help (its usage and the list of commands).
std::string program_help(const CLI::App& app);
/// The commands of app (or of a command: its subcommands) a user is shown, in order; not the hidden ones
/// (no group), such as `__complete`.
std::vector<std::string> command_names(const CLI::App& app);
/// True if word names one of app's commands.
bool is_command(const CLI::App& app, const std::string& word);
/// "ricochet: error: unknown command 'WORD'; did you mean 'NAME'?" (or the list of commands) on stderr.
void print_unknown_command(const CLI::App& app, const std::string& word);

/// `-` as a LOG: the log is read from standard input (run, render, reduce, replay).
inline constexpr std::string_view k_stdin_path = "-";
/// How diagnostics name a log read from standard input: `<stdin>:LINE:COL: error: …`.
inline constexpr std::string_view k_stdin_name = "<stdin>";
/// `-` as an output (`-o -`): standard output.
inline constexpr std::string_view k_stdout_path = "-";

/// The one write of a command whose run ends in a file (record, render, reduce): text into path atomically, with
/// SIGINT and SIGTERM held so that the file is whole or untouched. Standard output (path `-`), a device, a FIFO or
/// a link to one is written in place instead (write_file_atomically), under an ExitOnSignal: a signal while it
/// waits on a reader ends the command. It ends running's phase (ExitOnSignal) and
/// puts stop in scope: a signal held during the write, or one after it, is then a request to stop, which the
/// caller answers (stop_requested()) once it has said what it wrote. A failed write is printed, Exit{1}.
void write_file_holding_signals(const std::string& path, std::string_view text,
                                std::optional<app::ExitOnSignal>& running, std::optional<app::StopOnSignal>& stop);
/// Reads a log from a file, or from standard input when path is `-` (diagnostics then name `<stdin>`).
SceneOrDiagnostic read_scene_or_stdin(const std::string& path, ExpectLines expect_lines = ExpectLines::checked);
/// Reads a log (a file, or `-`: standard input), or prints its diagnostic on stderr and throws Exit{2}.
Scene load_scene_or_exit(const std::string& path);
/// Refuses, before anything runs, a scene that kernel k cannot step with these checks (checks.hpp, refusal):
/// "LOG: error: kernel 'box2d' steps point balls only: ball 0 has radius 0.5" on stderr and Exit{2}.
void check_supported_or_exit(const std::string& log, const Scene& scene, KernelId k, std::span<const Check> checks);
/// The kernel a --kernel spec names (a registered name, or plugin:PATH, loaded: kernel_spec.hpp), or a
/// diagnostic on stderr and Exit{2}.
KernelId kernel_or_exit(const std::string& spec);
/// Adds `--plugin PATH` (repeatable) to command: plug-ins to load before any log is read, so that logs naming
/// their kernels read (a log never loads one).
void add_plugin_option(CLI::App& command, std::vector<std::string>& plugins);
/// Loads each plug-in file (plugin_loader.hpp), or prints why one cannot be and throws Exit{2}.
void load_plugins_or_exit(const std::vector<std::string>& plugins);
/// When k is a plug-in kernel, tells its guard what is being stepped (plugin_guard.hpp): "DOING" (a log on
/// disk, so nothing more to keep), for a crash's or hang's report.
void stage_plugin_run(KernelId k, std::string doing);
/// One log's verdict in a replay.
struct LogVerdict {
    std::string path;                   ///< as given or found under a folder
    std::string status;                 ///< passed, failed, unreadable, over-budget, unsupported, skipped or missing
    std::string message;                ///< the line's text: what it checked, or why it failed or was skipped
    std::optional<std::uint64_t> hash;  ///< the run hash, if it ran
    /// Where it failed, for a failed run: the first broken check, its frame and ball (a run that only missed
    /// an expect line, or stopped at a step error, has none).
    std::optional<CheckFailure> failure;
    /// Where a parse error is, for an unreadable log: its line and column.
    std::optional<std::pair<int, int>> place;
    double seconds = 0;  ///< how long it ran (reading it included)
};
/// Where a stop (SIGINT, SIGTERM) ended a replay inside a log.
struct StoppedAt {
    std::string path;          ///< the log being run
    std::int64_t frame = 0;    ///< the last frame stepped
    std::int64_t frames = 0;   ///< the log's frames
};
/// Outcome of replaying some logs (counts, and whether a path or log could not be read or run).
struct ReplaySummary {
    int passed = 0;
    int failed = 0;
    /// Logs not run because they name a kernel this build knows but lacks (a peer built without its library,
    /// or a build with RICOCHET_PEERS=OFF): said, never a failure.
    int skipped = 0;
    std::map<std::string, int> skip_reasons;  ///< why, each with how many logs it skipped
    bool bad_input = false;
    bool stopped = false;             ///< a SIGINT or SIGTERM stopped it before every log was run
    std::optional<StoppedAt> stopped_at;  ///< the log and frame it stopped in, when that was inside a log
    std::size_t total = 0;            ///< logs found (run or not)
    std::vector<LogVerdict> logs;     ///< every log run or skipped and path missing, in order (missing paths first)
    std::vector<std::string> errors;  ///< paths that gave no log (a folder without logs, one that cannot be listed)
};
/// Replays every log under paths (folders recursively, *.scene; `-`: a log on stdin), one line per log on
/// stdout, then "N passed, N failed" (", N skipped" when some were). With hashes_only, prints "HASH PATH" per
/// log instead (and no summary). A path that does not exist, a folder without logs and a log over max_work
/// (work_budget.hpp) are bad input; a log naming a kernel this build lacks (absent_kernel_message) is skipped.
/// Under a StopOnSignal, a SIGINT or SIGTERM stops it between two frames of a log or before the next log
/// (stopped set, summary printed). With kernel, every log runs under it instead of its own (replay_scene: its
/// checks and expect lines asserted as they are).
ReplaySummary replay_paths(const std::vector<std::string>& paths, bool hashes_only, std::uint64_t max_work,
                           std::optional<KernelId> kernel = std::nullopt);

/// "N passed, N failed" and, when some logs were skipped, ", N skipped (WHY: N; …)" without the reasons unless
/// with_reasons.
std::string replay_counts(const ReplaySummary& summary, bool with_reasons);

/// A replay's members of a --json document (docs/cli-json.md): passed, failed, skipped, skip_reasons,
/// bad_input, stopped, stopped_at, total, errors, logs.
void write_replay_members(app::JsonWriter& json, const ReplaySummary& summary);

/// Adds `--junit FILE` to command (and `--sarif FILE` where files.sarif is wanted, sarif true): cases says
/// what a test case is in its report (docs/cli-reports.md).
void add_report_options(CLI::App& command, app::ReportFiles& files, std::string_view cases, bool sarif);
/// Refuses, before any work, a report file that cannot be written: "ricochet: error: cannot write FILE: WHY"
/// on stderr and Exit{2}.
void check_report_files_or_exit(const app::ReportFiles& files);
/// Writes the reports asked for (app::write_reports, atomically); false after printing "ricochet: error:
/// cannot write FILE: WHY" if one could not be (the command then exits 2).
bool write_reports_or_say(const app::Report& report, const app::ReportFiles& files);
/// A replay as a report's suite: a case per log (classname its folder, name its path) and per path that gave
/// no log; a failed log's failure names its check, frame and ball, an unreadable one's error its FILE:LINE:COL.
app::TestSuite replay_suite(const ReplaySummary& summary, double seconds);

}  // namespace ricochet::cli
