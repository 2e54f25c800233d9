// `ricochet bench` when the build has no benchmarks (RICOCHET_BENCH=OFF): says how to get them.
#include <fmt/format.h>

#include "commands.hpp"

namespace ricochet::cli {

void register_bench_not_built(CLI::App& app) {
    CLI::App* sub = app.add_subcommand("bench", "benchmarks (not in this build: configure with -DRICOCHET_BENCH=ON)");
    sub->allow_extras();
    sub->callback([] {
        fmt::print(stderr, "ricochet bench: not built (configure with -DRICOCHET_BENCH=ON)\n");
        throw Exit{1};
    });
}

}  // namespace ricochet::cli
