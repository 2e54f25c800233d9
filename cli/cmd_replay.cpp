// `ricochet replay [PATH...] [--hashes] [--json] [--junit FILE] [--kernel K] [--max-work N] [--plugin PATH...]`:
// every log's checks and expect lines; exit 0 all passed (logs for a kernel this build lacks are skipped, and said
// so), 1 some failed, 2 some path or log could not be read (a missing path, a folder without logs, a malformed log),
// was over the work bound, no PATH was given and no project folder was found, or the JUnit report (a case per log,
// docs/cli-reports.md) could not be written; 128 + the signal if SIGINT or SIGTERM
// stopped it (between two frames of a log or two logs: the summary says how many ran, and where it stopped).
#include <chrono>
#include <filesystem>

#include <fmt/format.h>

#include "commands.hpp"
#include "ricochet_app/json.hpp"
#include "ricochet_app/json_stdout.hpp"
#include "ricochet_app/project.hpp"
#include "ricochet_app/stop_signal.hpp"

namespace ricochet::cli {

void register_replay(CLI::App& app) {
    struct Options {
        std::vector<std::string> paths;
        std::vector<std::string> plugins;
        std::string kernel;
        bool hashes = false;
        bool json = false;
        app::ReportFiles reports;
        std::uint64_t max_work = k_default_max_work;
    };
    auto opt = std::make_shared<Options>();
    CLI::App* sub = app.add_subcommand(
        "replay", "replay logs (default: the project's replays/ or $RICOCHET_REPLAY_DIR; folders: every *.scene under them)");
    sub->add_option("PATH", opt->paths,
                    "logs or folders (-: a log on standard input; a missing path or a folder without *.scene is an "
                    "error, exit 2)");
    sub->add_flag("--hashes", opt->hashes, "print 'HASH PATH' per log (for comparing builds) instead");
    sub->add_flag("--json", opt->json,
                  "print one JSON document (docs/cli-json.md, schema ricochet-replay/1) on stdout instead; "
                  "the per-log lines go to stderr");
    add_report_options(*sub, opt->reports, "a test case per log", false);
    sub->add_option("--kernel", opt->kernel,
                    "run every log under this kernel instead of its own: a kernel's name, or plugin:PATH "
                    "(ricochet/plugin.h); its checks and expect lines are asserted as they are");
    add_max_work_option(*sub, opt->max_work);
    add_plugin_option(*sub, opt->plugins);
    sub->callback([opt] {
        // Plug-ins and the kernel first: a plug-in loaded by --plugin or --kernel plugin:PATH makes its name known
        // to the logs.
        check_report_files_or_exit(opt->reports);
        load_plugins_or_exit(opt->plugins);
        const std::optional<KernelId> kernel = opt->kernel.empty() ? std::nullopt : std::optional(kernel_or_exit(opt->kernel));
        std::vector<std::string> paths = opt->paths;
        if (paths.empty()) {
            // The project's corpus, never the tree this binary was built from.
            const auto project = app::find_project();
            if (!project) {
                fmt::print(stderr, "{}\n", app::no_project_message("replay", "name the logs or folders to replay (ricochet replay PATH...)"));
                throw Exit{2};
            }
            paths.push_back(project->replay_dir.string());
        }
        app::JsonStdout json_out(opt->json);
        const app::StopOnSignal stop;
        const auto t0 = std::chrono::steady_clock::now();
        const ReplaySummary s = replay_paths(paths, opt->hashes, opt->max_work, kernel);
        int code = s.stopped ? app::stop_exit_code() : s.bad_input ? 2 : s.failed > 0 ? 1 : 0;
        // The reports before the document, so that its exit is the command's: 2 if one could not be written.
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (!write_reports_or_say({"ricochet replay", seconds, {replay_suite(s, seconds)}, {}, {}}, opt->reports) && !s.stopped)
            code = 2;
        if (json_out.on()) {
            json_out.restore();
            app::JsonWriter json;
            json.begin_object().member("schema", fmt::format("ricochet-replay/{}", app::k_json_schema_version)).member("exit", code);
            write_replay_members(json, s);
            write_stdout(json.end_object().str());
        }
        throw Exit{code};
    });
}

}  // namespace ricochet::cli
