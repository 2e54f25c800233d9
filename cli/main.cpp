// ricochet: run, record, replay, render and check scene logs; fuzz and bench where built.
#include <cstdio>

#include <fmt/format.h>

#include "commands.hpp"
#include "ricochet_fuzz/command.hpp"
#ifdef RICOCHET_HAVE_BENCH
#include "ricochet_bench/command.hpp"
#endif

int main(int argc, char** argv) {
    CLI::App app{"ricochet: the 2D collision core's scene logs, replay and checks"};
    app.require_subcommand(1);
    ricochet::cli::register_run(app);
    ricochet::cli::register_record(app);
    ricochet::cli::register_replay(app);
    ricochet::cli::register_render(app);
    ricochet::cli::register_check(app);
#ifdef RICOCHET_HAVE_BENCH
    ricochet::bench::register_bench(app);
#else
    ricochet::cli::register_bench_not_built(app);
#endif
    ricochet::fuzz::register_fuzz(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::RuntimeError& e) {
        // bench/ and fuzz/ end their commands with CLI11's own exit-status exception.
        std::fflush(stdout);
        return e.get_exit_code();
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
