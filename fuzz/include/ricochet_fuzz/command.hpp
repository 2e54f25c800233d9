// The `ricochet fuzz` command, registered on a CLI11 app (the ricochet CLI's, or any other).
#pragma once

#include <CLI/CLI.hpp>

namespace ricochet::fuzz {

/// Registers `fuzz` on app. Its callback runs the campaign and, unless it exits 0, throws
/// CLI::RuntimeError with the campaign's exit status.
void register_fuzz(CLI::App& app);

}  // namespace ricochet::fuzz
