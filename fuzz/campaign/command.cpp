// `ricochet fuzz`: the command's options (command.hpp); the campaign itself is campaign.cpp.
#include "ricochet_fuzz/command.hpp"

#include <memory>

#include "ricochet_fuzz/campaign.hpp"

namespace ricochet::fuzz {

void register_fuzz(CLI::App& app) {
    auto opt = std::make_shared<CampaignOptions>();
    CLI::App* sub = app.add_subcommand("fuzz", "run a libFuzzer campaign; failures become scene logs");
    sub->add_option("--target", opt->targets, "target(s): parser, static, sweep, scene (default: all built)");
    sub->add_option("--kernel", opt->kernel, "kernel under test (default robust)");
    sub->add_option("--time", opt->time, "seconds to fuzz (default 60)")->check(CLI::PositiveNumber);
    sub->add_option("--runs", opt->runs, "inputs per worker instead of a time limit (with --seed: a reproducible campaign)")
        ->check(CLI::PositiveNumber);
    sub->add_option("--seed", opt->seed, "libFuzzer seed of the first worker (the next get seed+1, ...; default random)")
        ->check(CLI::PositiveNumber);
    sub->add_option("--jobs", opt->jobs, "worker processes in all, shared out among the targets (default: one per target)")
        ->check(CLI::PositiveNumber);
    sub->add_option("--bin-dir", opt->bin_dir, "folder of the fuzz_* binaries (default: this build's fuzz/, or $RICOCHET_FUZZ_BIN_DIR)");
    sub->add_option("--cache-dir", opt->cache_dir,
                    "working corpus and artifacts (default $RICOCHET_FUZZ_CACHE, $XDG_CACHE_HOME/ricochet/fuzz or ~/.cache/ricochet/fuzz)");
    sub->add_option("--replay-dir", opt->replay_dir, "where failure logs go (default $RICOCHET_REPLAY_DIR or the source tree's replays/)");
    sub->add_flag("--no-merge", opt->no_merge, "skip the corpus merge at the end");
    sub->callback([opt] {
        const int rc = run_campaign(*opt);
        if (rc != 0) throw CLI::RuntimeError(rc);
    });
}

}  // namespace ricochet::fuzz
