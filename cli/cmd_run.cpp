// `ricochet run LOG [--kernel K] [--frames N] [--max-work N]` (LOG `-`: standard input): the run's events as docs/scene-log.md prints
// them, stepped with the default WorldOptions (the broad phase on, one thread). SIGINT or SIGTERM stops it
// after a whole frame: every event up to it is printed, then "stopped" on stderr, exit 128 + the signal.
#include <cstdio>
#include <optional>

#include <fmt/format.h>

#include "commands.hpp"
#include "number_option.hpp"
#include "progress.hpp"
#include "ricochet/event.hpp"
#include "ricochet/world.hpp"
#include "ricochet_app/stop_signal.hpp"

namespace ricochet::cli {

void register_run(CLI::App& app) {
    struct Options {
        std::string log;
        std::string kernel;
        std::int64_t frames = -1;
        std::uint64_t max_work = k_default_max_work;
    };
    auto opt = std::make_shared<Options>();
    CLI::App* sub = app.add_subcommand("run", "print a log's run: state/hit/bump/overlap lines, frame 0 = initial state");
    sub->add_option("LOG", opt->log, "scene log (-: standard input)")->required();
    sub->add_option("--kernel", opt->kernel, "override the log's kernel: a kernel's name, or plugin:PATH (ricochet/plugin.h)");
    sub->add_option("--frames", opt->frames, "override the log's frame count")
        ->check(number_in(std::int64_t{0}, k_max_frames, "a frame count"));
    add_max_work_option(*sub, opt->max_work);
    sub->callback([opt] {
        // The kernel first: a plug-in loaded by --kernel plugin:PATH makes its name known to the log.
        const std::optional<KernelId> chosen = opt->kernel.empty() ? std::nullopt : std::optional(kernel_or_exit(opt->kernel));
        Scene scene = load_scene_or_exit(opt->log);
        const KernelId k = chosen.value_or(scene.kernel);
        stage_plugin_run(k, fmt::format("running {}", opt->log));
        const std::int64_t frames = opt->frames >= 0 ? opt->frames : scene.frames;
        check_work_or_exit(opt->log, scene, frames, opt->max_work);
        // `run` asserts no check: only the kernel must be able to step the scene.
        check_supported_or_exit(opt->log, scene, k, {});
        World world(scene, k);
        std::vector<Event> events;
        std::string out;
        // Print in chunks: a long run streams rather than piling up in memory, and a failed write
        // (write_stdout throws) stops it at once.
        const auto flush = [&] {
            for (const Event& e : events) append_event_line(out, e);
            events.clear();
            write_stdout(out);
            out.clear();
        };
        Progress progress(fmt::format("ricochet run {}", opt->log));
        const app::StopOnSignal stop;
        world.start(events);
        for (std::int64_t f = 1; f <= frames; ++f) {
            // A frame boundary: the output so far is whole frames.
            if (app::stop_requested()) {
                flush();
                std::fflush(stdout);
                check_stdout();
                fmt::print(stderr, "ricochet run: stopped by {} after frame {} of {}\n", app::stop_signal_name(), f - 1, frames);
                throw Exit{app::stop_exit_code()};
            }
            const auto error = world.step(events);
            if (error) {
                flush();
                std::fflush(stdout);
                fmt::print(stderr, "{}: error: {}\n", opt->log, error->message());
                throw Exit{1};
            }
            if (events.size() > 4096) flush();
            progress.update(f, frames);
        }
        flush();
    });
}

}  // namespace ricochet::cli
