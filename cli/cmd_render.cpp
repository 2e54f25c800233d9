// `ricochet render LOG -o FILE.svg [--frames A:B] [--view failure|all] [--max-balls N] [--max-points N]
// [--width PX] [--kernel K] [--max-work N] [--plugin PATH...]`: a picture of the scene and its run, drawn as the run streams by.
// SIGINT or SIGTERM during the run ends it at once with nothing written (exit 128 + the signal); one during
// the write waits for the rename, so the picture is whole or absent. `-o -` writes the picture on stdout (what
// was written is said on stderr); a device or a FIFO is written in place, never replaced.
#include <charconv>
#include <optional>

#include <fmt/format.h>

#include "commands.hpp"
#include "number_option.hpp"
#include "progress.hpp"
#include "ricochet/render.hpp"
#include "ricochet/scene_log.hpp"
#include "ricochet_app/stop_signal.hpp"

namespace ricochet::cli {

void register_render(CLI::App& app) {
    struct Options {
        std::string log;
        std::string out;
        std::string frames;
        std::string kernel;
        std::vector<std::string> plugins;
        std::string view = "failure";
        std::uint32_t max_balls = RenderOptions{}.max_balls;
        std::uint32_t max_points = RenderOptions{}.max_points;
        int width = RenderOptions{}.width;
        std::uint64_t max_work = k_default_max_work;
    };
    auto opt = std::make_shared<Options>();
    CLI::App* sub = app.add_subcommand("render", "draw a log's scene and run as SVG, framed on the first failure");
    sub->footer(
        "The run is checked as `replay` checks it and drawn as it streams by: only the drawn balls' points of\n"
        "frames A..B and the failing frame are kept. It stops after frame B once the first failure is found\n"
        "(with --view all: at frame B); past B it goes on only to find that failure, so the mark is the one\n"
        "`replay` reports. --view failure (the default) frames the failing frame: the failing ball's path in it\n"
        "and the walls it met, marked where a no-tunnel piece crossed its wall (else at the ball's state); a run\n"
        "without a failure is drawn whole. At most --max-balls paths are drawn (balls 0, 1, ... and the failing\n"
        "ball always) and at most --max-points points in all; the caption says what was left out.");
    sub->add_option("LOG", opt->log, "scene log (-: standard input)")->required();
    sub->add_option("-o,--output", opt->out,
                    "the SVG file to write (atomically; a device or a FIFO in place; -: standard output)")
        ->required();
    sub->add_option("--frames", opt->frames, "A:B, the frames whose paths are drawn (default: every frame run)");
    sub->add_option("--view", opt->view, "failure: frame the failing frame (default); all: the whole scene")
        ->check(CLI::Validator(
            [](std::string& input) -> std::string {
                if (input == "failure" || input == "all") return {};
                return fmt::format("'{}' is not a view (expected failure or all)", input);
            },
            "failure|all"));
    sub->add_option("--max-balls", opt->max_balls, "draw the paths of at most N balls (default 64)")
        ->check(number_in(std::uint32_t{1}, std::uint32_t{100000}, "a ball count"));
    sub->add_option("--max-points", opt->max_points, "draw at most N path points in all (default 100000)")
        ->check(number_in(std::uint32_t{1}, std::uint32_t{10000000}, "a point count"));
    sub->add_option("--width", opt->width, "picture width in pixels (default 800)")
        ->check(number_in(100, 20000, "a width in pixels"));
    sub->add_option("--kernel", opt->kernel, "override the log's kernel: a kernel's name, or plugin:PATH (ricochet/plugin.h)");
    add_max_work_option(*sub, opt->max_work);
    add_plugin_option(*sub, opt->plugins);
    sub->callback([opt] {
        // Plug-ins and the kernel first: a plug-in loaded by --plugin or --kernel plugin:PATH makes its name known
        // to the log.
        load_plugins_or_exit(opt->plugins);
        const std::optional<KernelId> chosen = opt->kernel.empty() ? std::nullopt : std::optional(kernel_or_exit(opt->kernel));
        Scene scene = load_scene_or_exit(opt->log);
        if (chosen) scene.kernel = *chosen;
        stage_plugin_run(scene.kernel, fmt::format("rendering {}", opt->log));
        RenderOptions r;
        r.view = opt->view == "all" ? RenderView::all : RenderView::failure;
        r.max_balls = opt->max_balls;
        r.max_points = opt->max_points;
        r.width = opt->width;
        if (!opt->frames.empty()) {
            const auto colon = opt->frames.find(':');
            std::int64_t a = 0, b = 0;
            const std::string& s = opt->frames;
            const bool ok = colon != std::string::npos &&
                            std::from_chars(s.data(), s.data() + colon, a).ptr == s.data() + colon &&
                            std::from_chars(s.data() + colon + 1, s.data() + s.size(), b).ptr == s.data() + s.size() &&
                            0 <= a && a <= b;
            if (!ok) {
                fmt::print(stderr, "ricochet: error: --frames: '{}' is not a frame range (expected A:B, integers with 0 <= A <= B)\n", s);
                throw Exit{2};
            }
            r.first_frame = a;
            r.last_frame = b;
        }
        check_work_or_exit(opt->log, scene, scene.frames, opt->max_work);
        check_supported_or_exit(opt->log, scene, scene.kernel, scene.checks);
        RenderResult result;
        // Nothing is written before the run ends, so a signal during it may end the process there and then.
        std::optional<app::ExitOnSignal> exit_on_signal;
        exit_on_signal.emplace("ricochet render: nothing written; stopped by ");
        {
            Progress progress(fmt::format("ricochet render {}", opt->log));
            result = render_run(scene, scene.kernel, r,
                                [&](std::int64_t done, std::int64_t total) { progress.update(done, total); });
        }
        std::optional<app::StopOnSignal> stop;
        write_file_holding_signals(opt->out, result.svg, exit_on_signal, stop);
        const std::string marked = result.failure ? fmt::format(" (marked: {})", result.failure->str()) : "";
        // The picture itself on standard output: what was written is said on stderr.
        if (opt->out == k_stdout_path)
            fmt::print(stderr, "ricochet render: wrote the picture to standard output{}\n", marked);
        else
            write_stdout(fmt::format("wrote {}{}\n", opt->out, marked));
        if (app::stop_requested()) throw Exit{app::stop_exit_code()};
    });
}

}  // namespace ricochet::cli
