// ricochet: run, record, replay, render, reduce and check scene logs; fuzz and bench where built.
//
// Exit status: 0 success; 1 a check or expectation failed, a run stopped, or output could not be
// written; 2 bad usage or input (an unknown command or option, a bad value, a malformed or missing log,
// a log over the work bound, no project folder, a plug-in that cannot be loaded); 3 a plug-in kernel crashed, hung
// or broke ricochet/plugin.h (plugin_guard.hpp); 128 + the signal when SIGINT or SIGTERM stopped run, replay,
// record, reduce, check or fuzz (ricochet_app/stop_signal.hpp).
#include <cstdio>
#include <string>
#include <system_error>

#include <fmt/format.h>

#include "commands.hpp"
#include "ricochet/kernel.hpp"
#include "ricochet_peers/peers.hpp"
#ifdef RICOCHET_HAVE_BENCH
#include "ricochet_bench/command.hpp"
#endif
#ifdef RICOCHET_HAVE_FUZZ_CAMPAIGN
#include "ricochet_fuzz/command.hpp"
#endif

namespace {

/// CLI11's usage errors as ours: "ricochet: error: WHAT" and where to look.
std::string usage_error(const CLI::App*, const CLI::Error& e) {
    return fmt::format("ricochet: error: {}\nRun 'ricochet help' for more information.\n", e.what());
}

}  // namespace

int main(int argc, char** argv) {
    // Before any kernel name is parsed (options, logs, completion): the peers join the kernel registry.
    ricochet::peers::register_peer_kernels();
    CLI::App app{"ricochet: the 2D collision core's scene logs, replay and checks", "ricochet"};
    // Before the commands are added: each copies its parent's failure message.
    app.failure_message(usage_error);
    app.require_subcommand(1);
    app.set_version_flag("--version", "ricochet " RICOCHET_VERSION, "print the version and exit");
    ricochet::cli::register_run(app);
    ricochet::cli::register_record(app);
    ricochet::cli::register_replay(app);
    ricochet::cli::register_render(app);
    ricochet::cli::register_reduce(app);
    ricochet::cli::register_check(app);
#ifdef RICOCHET_HAVE_BENCH
    ricochet::bench::register_bench(app);
#else
    ricochet::cli::register_bench_not_built(app);
#endif
#ifdef RICOCHET_HAVE_FUZZ_CAMPAIGN
    ricochet::fuzz::register_fuzz(app);
#else
    ricochet::cli::register_fuzz_not_built(app);
#endif
    ricochet::cli::register_help(app);
    ricochet::cli::register_completion(app);

    // Degenerate: no arguments at all is a usage error; the help says what to type.
    if (argc < 2) {
        fmt::print(stderr, "{}", ricochet::cli::program_help(app));
        return 2;
    }
    // A first word that is not an option must name a command ("did you mean" if it is a typo).
    if (const std::string first = argv[1]; !first.starts_with('-') && !ricochet::cli::is_command(app, first)) {
        ricochet::cli::print_unknown_command(app, first);
        return 2;
    }
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
    } catch (const ricochet::UnsupportedScene& e) {
        // Every command asks first (check_supported_or_exit); a scene refused deeper in is bad input all the same.
        fmt::print(stderr, "ricochet: error: {}\n", e.what());
        code = 2;
    } catch (const ricochet::cli::OutputError& e) {
        return ricochet::cli::report_output_error(e.error);
    } catch (const std::system_error& e) {
        // fmt::print throws this when its write fails.
        if (!std::ferror(stdout)) throw;
        return ricochet::cli::report_output_error(e.code().value());
    }
    return ricochet::cli::finish_stdout(code);
}
