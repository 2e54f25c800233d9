// Standard output that is checked: a write that fails (a full disk, a closed pipe) ends the command with
// "ricochet: error: writing standard output: WHY" and exit status 1 instead of a silent success.
#pragma once

#include <string_view>

namespace ricochet::cli {

/// Thrown when standard output could not be written; main() reports it (exit status 1).
struct OutputError {
    int error = 0;  ///< the errno of the failed write, 0 if unknown
};

/// Writes text to stdout; throws OutputError if it could not.
void write_stdout(std::string_view text);

/// Throws OutputError if a write to stdout has failed so far (stdio's error flag). Cheap: a long
/// command calls it between units of work to stop early.
void check_stdout();

/// Prints "ricochet: error: writing standard output: WHY" (err: the errno, 0 if unknown); returns 1.
int report_output_error(int err);

/// Flushes stdout and checks it; returns exit_code, or 1 after printing the error on stderr.
/// main() ends every command through it.
int finish_stdout(int exit_code);

}  // namespace ricochet::cli
