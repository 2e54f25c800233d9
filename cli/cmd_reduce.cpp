// `ricochet reduce LOG [-o OUT] [--kernel K] [--max-tries N] [--max-work N] [--plugin PATH…]`: the smallest log found that fails
// as LOG does (reduce.hpp), written to OUT atomically (a device or a FIFO in place) or to stdout (no -o, or
// -o -); LOG (- reads it from stdin) is never written (-o naming it, through a link or not, is refused). Progress on stderr while it works, then one summary line.
// SIGINT or SIGTERM stops the reduction between two tries: the smallest failing log found so far is written
// (whole, atomically), then exit 128 + the signal.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <system_error>

#include <fmt/format.h>

#include "commands.hpp"
#include "number_option.hpp"
#include "progress.hpp"
#include "ricochet/format.hpp"
#include "ricochet/reduce.hpp"
#include "ricochet_app/stop_signal.hpp"

namespace ricochet::cli {

namespace {

/// "10000 walls, 1 balls, 0 circles, 0 rects, 17 frames" (", N bumpers" before the frames when there are any).
std::string describe(const SceneSize& s) {
    const std::string bumpers = s.bumpers > 0 ? fmt::format(", {} bumpers", s.bumpers) : "";
    return fmt::format("{} walls, {} balls, {} circles, {} rects{}, {} frames", s.walls, s.balls, s.circles, s.rects,
                       bumpers, s.frames);
}

}  // namespace

void register_reduce(CLI::App& app) {
    struct Options {
        std::string log;
        std::string out;
        std::string kernel;
        std::uint64_t max_tries = k_reduce_default_tries;
        std::uint64_t max_work = k_default_max_work;
        std::vector<std::string> plugins;
    };
    auto opt = std::make_shared<Options>();
    CLI::App* sub = app.add_subcommand("reduce", "shrink a failing log to a small one that fails the same check");
    sub->footer(
        "The failure kept is the log's first one under its checks: check C breaks at some frame for some ball,\n"
        "with `check C` alone (or, for a log whose run stops at a ball leaving the accepted range before any\n"
        "check breaks, such a stop). It cuts frames, balls, walls, circles and rects, then simplifies numbers,\n"
        "trying candidates until none is smaller or --max-tries is reached; the same log gives the same output.\n"
        "The output is a failure log: `ricochet replay` reproduces it at its `found` check and frame. A log\n"
        "whose checks all hold is refused (exit 2). LOG is never changed.");
    sub->add_option("LOG", opt->log, "the failing scene log (-: standard input)")->required();
    sub->add_option("-o,--output", opt->out,
                    "write the reduced log here (atomically; a device or a FIFO in place; default or -: stdout)");
    sub->add_option("--kernel", opt->kernel,
                    "run under this kernel instead of the log's: a kernel's name, or plugin:PATH (ricochet/plugin.h)");
    sub->add_option("--max-tries", opt->max_tries,
                    fmt::format("stop after N candidate runs (default {})", k_reduce_default_tries))
        ->option_text("N")
        ->check(number_in<std::uint64_t>(1, std::numeric_limits<std::uint32_t>::max(), "a number of tries"));
    add_max_work_option(*sub, opt->max_work);
    add_plugin_option(*sub, opt->plugins);
    sub->callback([opt] {
        // Plug-ins and the kernel first: a plug-in loaded by --plugin or --kernel plugin:PATH makes its name known
        // to the log.
        load_plugins_or_exit(opt->plugins);
        if (opt->out == k_stdout_path) opt->out.clear();
        ReduceOptions options;
        if (!opt->kernel.empty()) options.kernel = kernel_or_exit(opt->kernel);
        const Scene scene = load_scene_or_exit(opt->log);
        stage_plugin_run(options.kernel.value_or(scene.kernel), fmt::format("reducing {}", opt->log));
        options.max_tries = opt->max_tries;
        // Never the input: -o naming LOG, by another path or through a link, would replace what is reduced.
        std::error_code ec;
        if (!opt->out.empty() && opt->log != k_stdin_path && std::filesystem::equivalent(opt->log, opt->out, ec)) {
            fmt::print(stderr, "ricochet: error: -o {} is the log being reduced; reduce never changes its input\n", opt->out);
            throw Exit{2};
        }
        // Each try runs at most the log's own frames and entities.
        check_work_or_exit(opt->log, scene, scene.frames, opt->max_work);
        check_supported_or_exit(opt->log, scene, options.kernel.value_or(scene.kernel), scene.checks);

        const auto start = std::chrono::steady_clock::now();
        std::optional<app::StopOnSignal> stop;
        stop.emplace();
        options.stop = [] { return app::stop_requested(); };
        Progress progress(fmt::format("ricochet reduce {}", opt->log), Progress::Unit::frame, Progress::Shown::output_at_end);
        options.on_progress = [&](const ReduceProgress& p) {
            progress.update([&] {
                return fmt::format("{} tries, {} entities, {} frames left ({})", p.tries, p.size.entities(), p.size.frames,
                                   p.pass);
            });
        };
        auto result = reduce_log(scene, options);
        progress.clear();
        if (const auto* refused = std::get_if<ReduceRefusal>(&result)) {
            fmt::print(stderr, "{}: error: {}\n", opt->log, refused->message);
            throw Exit{2};
        }
        const ReducedLog& reduced = std::get<ReducedLog>(result);
        const std::string text = reduced.log.text();
        if (opt->out.empty()) {
            // Written and flushed before the summary, which would otherwise report a log that never got out.
            write_stdout(text);
            std::fflush(stdout);
            check_stdout();
        } else {
            std::optional<app::ExitOnSignal> none;
            write_file_holding_signals(opt->out, text, none, stop);
        }
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const std::string end = reduced.end == ReduceEnd::fixed_point ? "nothing smaller found"
                                : reduced.end == ReduceEnd::budget  ? fmt::format("stopped at --max-tries {}", opt->max_tries)
                                                                     : fmt::format("stopped by {}", app::stop_signal_name());
        fmt::print(stderr, "ricochet reduce: {} → {}; {} tries, {:.1f} s, {}{}\n", describe(reduced.before),
                   describe(reduced.after), reduced.tries, seconds, end,
                   opt->out.empty() ? std::string() : fmt::format("; wrote {}", opt->out));
        if (app::stop_requested()) throw Exit{app::stop_exit_code()};
    });
}

}  // namespace ricochet::cli
