// `ricochet fuzz` when the build has no campaign (RICOCHET_FUZZ_CAMPAIGN=OFF, as on wasm32, which has no child
// processes to run the fuzz targets in): says so.
#include <fmt/format.h>

#include "commands.hpp"

namespace ricochet::cli {

void register_fuzz_not_built(CLI::App& app) {
    CLI::App* sub = app.add_subcommand(
        "fuzz", "fuzz campaign (not in this build: configure with -DRICOCHET_FUZZ_CAMPAIGN=ON on a system with processes)");
    sub->allow_extras();
    sub->callback([] {
        fmt::print(stderr,
                   "ricochet fuzz: not built (the campaign runs the fuzz targets as child processes; configure with "
                   "-DRICOCHET_FUZZ_CAMPAIGN=ON, which wasm32 cannot have)\n");
        throw Exit{1};
    });
}

}  // namespace ricochet::cli
