// `ricochet record LOG [--max-work N]`: runs a log and writes its expect lines back, atomically. The log's other
// lines (comments included) are kept as they are; old expect lines are replaced, even ones that no longer fit
// the log. A symbolic link is written through (write_file_atomically). SIGINT or SIGTERM before the write
// ends it at once, the log unchanged (exit 128 + the signal); one during the write waits for the rename.
#include <sstream>
#include <variant>

#include <fmt/format.h>

#include "commands.hpp"
#include "progress.hpp"
#include "ricochet/format.hpp"
#include "ricochet/hash.hpp"
#include "ricochet/record.hpp"
#include "ricochet/scene_log.hpp"
#include "ricochet_app/stop_signal.hpp"

namespace ricochet::cli {

namespace {

/// The log's text without its `expect` lines (and without trailing blank lines).
std::string without_expect_lines(const std::string& text) {
    std::string out;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        const auto start = line.find_first_not_of(" \t");
        if (start != std::string::npos && line.compare(start, 6, "expect") == 0 &&
            (line.size() == start + 6 || line[start + 6] == ' ' || line[start + 6] == '\t' || line[start + 6] == '\r'))
            continue;
        out += line;
        out += '\n';
    }
    while (out.size() >= 2 && out[out.size() - 1] == '\n' && out[out.size() - 2] == '\n') out.pop_back();
    return out;
}

}  // namespace

void register_record(CLI::App& app) {
    struct Options {
        std::string log;
        std::vector<std::string> plugins;
        std::uint64_t max_work = k_default_max_work;
    };
    auto opt = std::make_shared<Options>();
    CLI::App* sub = app.add_subcommand("record", "run a log and write its expect lines back (atomically)");
    sub->add_option("LOG", opt->log, "scene log")->required();
    add_max_work_option(*sub, opt->max_work);
    add_plugin_option(*sub, opt->plugins);
    sub->callback([opt] {
        load_plugins_or_exit(opt->plugins);
        // Degenerate: standard input has nowhere to write the expect lines back to.
        if (opt->log == k_stdin_path) {
            fmt::print(stderr, "ricochet: error: record writes its log back: it needs a file, not standard input (-)\n");
            throw Exit{2};
        }
        // One read: the text that is parsed is the text that is rewritten.
        auto read = read_log_text(opt->log);
        if (auto* d = std::get_if<Diagnostic>(&read)) {
            fmt::print(stderr, "{}\n", d->str());
            throw Exit{2};
        }
        const std::string& original = std::get<std::string>(read);
        // The expect lines are what record replaces: stale ones (a frame past a lowered `frames`, a ball or a
        // check taken out) are no reason to refuse, a malformed one still is.
        auto parsed = parse_scene_log(original, opt->log, ExpectLines::replaced);
        if (auto* d = std::get_if<Diagnostic>(&parsed)) {
            fmt::print(stderr, "{}\n", d->str());
            throw Exit{2};
        }
        Scene scene = std::get<Scene>(std::move(parsed));
        check_work_or_exit(opt->log, scene, scene.frames, opt->max_work);
        check_supported_or_exit(opt->log, scene, scene.kernel, scene.checks);
        stage_plugin_run(scene.kernel, fmt::format("recording {}", opt->log));
        // The run is one call into the core, with no frame to stop at; nothing is written yet, so a signal
        // may end the process there and then.
        std::optional<app::ExitOnSignal> exit_on_signal;
        exit_on_signal.emplace("ricochet record: the log is unchanged; stopped by ");
        // frame 0 (the initial states) is the first call.
        Progress progress(fmt::format("ricochet record {}", opt->log));
        std::int64_t frame = -1;
        const CheckedRun run = record_expectations(scene, [&](std::span<const Event>) { progress.update(++frame, scene.frames); });
        progress.clear();
        if (run.error) {
            fmt::print(stderr, "{}: error: {}; the log is unchanged\n", opt->log, run.error->message());
            throw Exit{1};
        }
        std::string text = without_expect_lines(original);
        // The expect lines exactly as the canonical writer prints them.
        Scene expects_only;
        expects_only.expect_hash = scene.expect_hash;
        expects_only.expect_failure = scene.expect_failure;
        expects_only.expect_states = scene.expect_states;
        const std::string canonical = write_scene_log(expects_only);
        const auto first_expect = canonical.find("expect ");
        if (first_expect != std::string::npos) text += canonical.substr(first_expect);
        // The write is whole or not at all: a signal now waits until the rename is done (the report below
        // still says what was written; the exit status says a signal came).
        std::optional<app::StopOnSignal> stop;
        write_file_holding_signals(opt->log, text, exit_on_signal, stop);
        write_stdout(fmt::format("recorded {}: hash {}, {} expect state line(s){}\n", opt->log, format_hash(run.hash),
                                 scene.expect_states.size(),
                                 run.failure ? fmt::format(", expect failure {} {} ({})", run.failure->check,
                                                           run.failure->frame, run.failure->message)
                                             : std::string()));
        if (app::stop_requested()) throw Exit{app::stop_exit_code()};
    });
}

}  // namespace ricochet::cli
