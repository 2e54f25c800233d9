// `ricochet render LOG -o FILE.svg [--frames A:B] [--kernel K] [--max-work N]`: a picture of the scene and its run.
#include <charconv>

#include <fmt/format.h>

#include "commands.hpp"
#include "ricochet/render.hpp"
#include "ricochet/scene_log.hpp"

namespace ricochet::cli {

void register_render(CLI::App& app) {
    struct Options {
        std::string log;
        std::string out;
        std::string frames;
        std::string kernel;
        std::uint64_t max_work = k_default_max_work;
    };
    auto opt = std::make_shared<Options>();
    CLI::App* sub = app.add_subcommand("render", "draw a log's scene and run as SVG");
    sub->add_option("LOG", opt->log, "scene log")->required();
    sub->add_option("-o,--output", opt->out, "the SVG file to write")->required();
    sub->add_option("--frames", opt->frames, "A:B, the frames whose paths are drawn");
    sub->add_option("--kernel", opt->kernel, "override the log's kernel");
    add_max_work_option(*sub, opt->max_work);
    sub->callback([opt] {
        Scene scene = load_scene_or_exit(opt->log);
        if (!opt->kernel.empty()) scene.kernel = kernel_or_exit(opt->kernel);
        RenderOptions r;
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
        const CheckedRun run = run_checked(scene, scene.kernel, scene.frames, scene.checks);
        std::string error;
        if (!write_file_atomically(opt->out, render_svg(scene, run, r), &error)) {
            fmt::print(stderr, "ricochet: error: {}\n", error);
            throw Exit{1};
        }
        write_stdout(fmt::format("wrote {}{}\n", opt->out, run.failure ? fmt::format(" (marked: {})", run.failure->str()) : ""));
    });
}

}  // namespace ricochet::cli
