// Placeholder: the fuzz colleague replaces this file with the real `ricochet fuzz`.
#include <fmt/format.h>

#include "commands.hpp"

namespace ricochet::cli {

void register_fuzz(CLI::App& app) {
    CLI::App* sub = app.add_subcommand("fuzz", "fuzz (not built yet)");
    sub->allow_extras();
    sub->callback([] {
        fmt::print(stderr, "ricochet fuzz: not built yet\n");
        throw Exit{1};
    });
}

}  // namespace ricochet::cli
