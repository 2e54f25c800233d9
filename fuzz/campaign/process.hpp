// Child processes of a campaign: started with extra environment entries and their output appended to a
// log, or run to completion with their output captured.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace ricochet::fuzz {

/// The whole content of a file (empty if it cannot be read).
std::string read_all(const std::filesystem::path& path);

/// Starts argv (argv[0] a path) with env_extra ("NAME=value", replacing inherited entries of the same
/// name), stdin from /dev/null, stdout and stderr appended to log. Returns the pid, or -1.
pid_t spawn(const std::vector<std::string>& argv, const std::vector<std::string>& env_extra,
            const std::filesystem::path& log);

/// Runs argv to completion with its output in scratch (overwritten). Returns its exit status (128 +
/// signal if killed, 127 if it could not start) and its output.
std::pair<int, std::string> run_capture(const std::vector<std::string>& argv, const std::vector<std::string>& env_extra,
                                        const std::filesystem::path& scratch);

}  // namespace ricochet::fuzz
