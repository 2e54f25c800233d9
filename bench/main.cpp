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
    } catch (const CLI::RuntimeError& e) {
        // The command's own exit status (1: robust was wrong; 2: a result could not be written).
        return e.get_exit_code();
    } catch (const CLI::ParseError& e) {
        // --help is not an error; every other usage error is bad input: exit 2, as `ricochet bench` does.
        return app.exit(e) == 0 ? 0 : 2;
    }
    return 0;
}
