// consumer LOG: reads a scene log, steps it with its own kernel and frame count, and prints its run
// hash, the one `ricochet replay --hashes LOG` prints.
#include <variant>

#include <fmt/core.h>

#include "ricochet/hash.hpp"
#include "ricochet/scene_log.hpp"
#include "ricochet/world.hpp"

int main(int argc, char** argv) {
    if (argc != 2) {
        fmt::print(stderr, "usage: consumer LOG\n");
        return 2;
    }
    const ricochet::SceneOrDiagnostic read = ricochet::read_scene_log(argv[1]);
    if (const auto* bad = std::get_if<ricochet::Diagnostic>(&read)) {
        fmt::print(stderr, "{}\n", bad->str());
        return 2;
    }
    const auto& scene = std::get<ricochet::Scene>(read);
    try {
        const auto events = ricochet::run_scene(scene, scene.kernel, scene.frames);
        fmt::print("{}\n", ricochet::format_hash(ricochet::hash_events(events)));
    } catch (const ricochet::StepFailure& failure) {  // a ball left the accepted range
        fmt::print(stderr, "{}\n", failure.what());
        return 1;
    }
}
