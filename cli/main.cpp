// ricochet: run, record, replay, render and check scene logs; fuzz and bench where built.
//
// Exit status: 0 success; 1 a check or expectation failed, a run stopped, or output could not be
// written; 2 bad usage or input.
#include <cstdio>
#include <system_error>

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
    int code = 0;
    try {
        app.parse(argc, argv);
    } catch (const CLI::RuntimeError& e) {
        // bench/ and fuzz/ end their commands with CLI11's own exit-status exception.
        code = e.get_exit_code();
    } catch (const CLI::ParseError& e) {
        // --help and --version are not errors; every other usage error is bad input: exit 2.
        code = app.exit(e) == 0 ? 0 : 2;
    } catch (const ricochet::cli::Exit& e) {
        code = e.code;
    } catch (const ricochet::cli::OutputError& e) {
        return ricochet::cli::report_output_error(e.error);
    } catch (const std::system_error& e) {
        // fmt::print throws this when its write fails.
        if (!std::ferror(stdout)) throw;
        return ricochet::cli::report_output_error(e.code().value());
    }
    return ricochet::cli::finish_stdout(code);
}
