// The `bench` command (with its `stability`, `frames` and `scale` subcommands), registered on a CLI11
// app: the ricochet CLI's and ricochet-bench's.
#pragma once

#include <CLI/CLI.hpp>

namespace ricochet::bench {

/// Registers `bench` on app. Its callback runs the chosen benchmark and, unless it exits 0, throws
/// CLI::RuntimeError with its exit status (2 when an output file cannot be written).
void register_bench(CLI::App& app);

}  // namespace ricochet::bench
