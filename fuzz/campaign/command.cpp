// `ricochet fuzz`: the command's options (command.hpp); the campaign itself is campaign.cpp.
#include "ricochet_fuzz/command.hpp"

#include <charconv>
#include <limits>
#include <memory>

#include <fmt/format.h>

#include "ricochet/domain.hpp"
#include "ricochet_fuzz/campaign.hpp"

namespace ricochet::fuzz {

namespace {

/// A number of type T from lo to hi, or a message saying what was wrong (CLI11's PositiveNumber would print
/// "not in range 0.000000 to" DBL_MAX's 309 digits). cli/number_option.hpp is the same for cli/.
template <class T>
CLI::Validator number_in(T lo, T hi, std::string what) {
    return CLI::Validator(
        [lo, hi, what](std::string& input) -> std::string {
            T v{};
            const char* end = input.data() + input.size();
            const auto [ptr, ec] = std::from_chars(input.data(), end, v);
            if (input.empty() || ptr != end || (ec != std::errc() && ec != std::errc::result_out_of_range))
                return fmt::format("'{}' is not {} (expected {} to {})", input, what, lo, hi);
            if (ec == std::errc::result_out_of_range || !(lo <= v && v <= hi))
                return fmt::format("'{}' is out of range (expected {} from {} to {})", input, what, lo, hi);
            return {};
        },
        fmt::format("{} to {}", lo, hi));
}

/// The longest campaign by time: a week. The workers' -max_total_time is an int of seconds.
constexpr double k_max_time_s = 7 * 24 * 3600;

}  // namespace

void register_fuzz(CLI::App& app) {
    auto opt = std::make_shared<CampaignOptions>();
    CLI::App* sub = app.add_subcommand("fuzz", "run a libFuzzer campaign; failures become scene logs");
    sub->add_option("--target", opt->targets,
                    "target(s): parser, static, sweep, scene, disc, meet (default: all built; disc only for a kernel that "
                    "steps discs, meet only for one that steps balls that meet)");
    sub->add_option("--kernel", opt->kernel, "kernel under test: a kernel's name, or plugin:PATH (ricochet/plugin.h; default robust)");
    auto domain = std::make_shared<std::string>();
    CLI::Option* domain_opt =
        sub->add_option("--domain", *domain,
                        "the kernel's world: inputs are brought into it or skipped, waived checks are not run, and logs "
                        "state it (e.g. coordinates=1e6,no-subnormals,waive=touching; docs/scene-log.md \"Domain\"; "
                        "default $RICOCHET_DOMAIN, else the whole range)")
            ->type_name("SPEC");
    CLI::Option* time = sub->add_option("--time", opt->time,
                                        "seconds the whole command takes, fuzzing then converting failures and merging "
                                        "(default 60; 1 to 604800, a week)")
                            ->check(number_in(1.0, k_max_time_s, "a number of seconds"));
    CLI::Option* runs = sub->add_option("--runs", opt->runs,
                                        "inputs per worker instead of a time limit (with --seed: a reproducible campaign)")
                            ->check(number_in<std::uint64_t>(1, std::numeric_limits<std::uint64_t>::max(), "a count of inputs"));
    sub->add_option("--seed", opt->seed, "libFuzzer seed of the first worker (the next get seed+1, ...; default random)")
        ->check(number_in<unsigned>(1, std::numeric_limits<unsigned>::max(), "a seed"));
    sub->add_option("--jobs", opt->jobs, "worker processes in all, shared out among the targets (default: one per target)")
        ->check(number_in(1, 4096, "a number of workers"));
    sub->add_option("--bin-dir", opt->bin_dir, "folder of the fuzz_* binaries (default: this build's fuzz/, or $RICOCHET_FUZZ_BIN_DIR)");
    sub->add_option("--cache-dir", opt->cache_dir,
                    "working corpus and artifacts (default $RICOCHET_FUZZ_CACHE, $XDG_CACHE_HOME/ricochet/fuzz or ~/.cache/ricochet/fuzz)");
    sub->add_option("--replay-dir", opt->replay_dir, "where failure logs go (default $RICOCHET_REPLAY_DIR, else the project folder's replays/)");
    sub->add_flag("--no-merge", opt->no_merge, "skip the corpus merge at the end");
    sub->add_flag("--json", opt->json,
                  "print one JSON document (docs/cli-json.md, schema ricochet-fuzz/1) on stdout instead of the summary; "
                  "progress goes to stderr");
    sub->add_option("--junit", opt->junit,
                    "also write a JUnit XML report to FILE (a test case per target, a failure per new failure; "
                    "docs/cli-reports.md), whole or not at all")
        ->type_name("FILE");
    sub->add_option("--sarif", opt->sarif,
                    "also write a SARIF 2.1.0 log to FILE: a result per failure, at its saved log's line "
                    "(docs/cli-reports.md)")
        ->type_name("FILE");
    // After `--`, everything is positional: libFuzzer's own -flag=value arguments.
    sub->add_option("libfuzzer_flags", opt->libfuzzer_flags,
                    "after --: flags passed to every libFuzzer worker after the campaign's own (e.g. -- -max_len=256 -use_cmp=0)");
    sub->footer("Everything after -- goes to every libFuzzer worker, after the campaign's own flags (so it overrides them).");

    auto conv = std::make_shared<ConvertOptions>();
    CLI::App* convert = sub->add_subcommand("convert", "turn failure artifacts into scene logs, as a campaign does");
    convert->add_option("artifacts", conv->artifacts, "libFuzzer's failure inputs (crash-…, timeout-…; those a campaign left in "
                                                      "CACHE/TARGET/KERNEL/pending/)")
        ->required();
    convert->add_option("--target", conv->target, "their target (default: read from the artifact's place in a cache)");
    convert->add_option("--kernel", conv->kernel,
                        "kernel under test: a kernel's name, or plugin:PATH (default: read from the artifact's place, else robust)");
    convert->add_option("--replay-dir", conv->replay_dir, "where the logs go (default $RICOCHET_REPLAY_DIR, else the project folder's replays/)");
    convert->add_option("--cache-dir", conv->cache_dir, "the cache it works in (default as for fuzz)");
    convert->add_option("--bin-dir", conv->bin_dir, "folder of the fuzz_* binaries (default as for fuzz)");
    convert->callback([conv] {
        const int rc = run_convert(*conv);
        if (rc != 0) throw CLI::RuntimeError(rc);
    });

    sub->callback([opt, convert, time, runs, domain, domain_opt] {
        if (convert->parsed()) return;
        // The workers and every process the campaign runs read the domain from RICOCHET_DOMAIN, inherited.
        if (domain_opt->count() > 0) {
            std::string error;
            if (!parse_domain_spec(*domain, &error)) {
                fmt::print(stderr, "ricochet fuzz: error: --domain: {}\n", error);
                throw CLI::RuntimeError(2);
            }
            ::setenv("RICOCHET_DOMAIN", domain->c_str(), 1);
        }
        // A campaign is by count or by clock, never both: a count with --seed repeats, a clock does not.
        if (time->count() > 0 && runs->count() > 0) {
            fmt::print(stderr, "ricochet fuzz: error: --runs and --time exclude each other: --runs N runs N inputs per worker "
                               "(with --seed S, the same inputs every time), --time S ends the whole command by S seconds\n");
            throw CLI::RuntimeError(2);
        }
        const int rc = run_campaign(*opt);
        if (rc != 0) throw CLI::RuntimeError(rc);
    });
}

}  // namespace ricochet::fuzz
