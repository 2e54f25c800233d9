// ricochet: run, record, replay, render and check scene logs; fuzz and bench where built.
#include <cstdio>

#include <fmt/format.h>

#include "commands.hpp"

int main(int argc, char** argv) {
    CLI::App app{"ricochet: the 2D collision core's scene logs, replay and checks"};
    app.require_subcommand(1);
    ricochet::cli::register_run(app);
    ricochet::cli::register_record(app);
    ricochet::cli::register_replay(app);
    ricochet::cli::register_render(app);
    ricochet::cli::register_check(app);
    ricochet::cli::register_bench(app);
    ricochet::cli::register_fuzz(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // --help and --version are not errors; every other usage error is bad input: exit 2.
        const int code = app.exit(e);
        return code == 0 ? 0 : 2;
    } catch (const ricochet::cli::Exit& e) {
        std::fflush(stdout);
        return e.code;
    }
    std::fflush(stdout);
    return 0;
}
