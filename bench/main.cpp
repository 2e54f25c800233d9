// ricochet-bench: the `bench` command on its own (the same registration as the `ricochet` CLI's), so
// that bench/ builds, runs and is tested whatever state the rest of the tree is in.
#include <CLI/CLI.hpp>

#include "ricochet_bench/command.hpp"

int main(int argc, char** argv) {
    CLI::App app{"ricochet-bench: run time against error for the ricochet kernels and their peers"};
    app.require_subcommand(1);
    ricochet::bench::register_bench(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // Usage errors, and the command's own exit status (CLI::RuntimeError, printed as nothing).
        return app.exit(e);
    }
    return 0;
}
