// ricochet-bench: the `bench` command on its own (the same registration as the `ricochet` CLI's), so
// that bench/ builds, runs and is tested whatever state the rest of cli/ is in.
#include <CLI/CLI.hpp>

#include "commands.hpp"

int main(int argc, char** argv) {
    CLI::App app{"ricochet-bench: run time against error for the ricochet kernels and their peers"};
    app.require_subcommand(1);
    ricochet::cli::register_bench(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    } catch (const ricochet::cli::Exit& e) {
        return e.code;
    }
    return 0;
}
