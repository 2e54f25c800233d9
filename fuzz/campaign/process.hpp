// Child processes of a campaign: started with extra environment entries and their output appended to a
// log, or run to completion (within a deadline, if any) with their output captured.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ricochet::fuzz {

/// The whole content of a file (empty if it cannot be read).
std::string read_all(const std::filesystem::path& path);

/// Starts argv (argv[0] a path) with env_extra ("NAME=value", replacing inherited entries of the same
/// name), stdin from /dev/null, stdout and stderr appended to log; with own_group, in a process group of its
/// own (its pid), so that it and every process it starts can be signalled at once. Returns the pid, or -1
/// with *error (if given) saying why.
pid_t spawn(const std::vector<std::string>& argv, const std::vector<std::string>& env_extra,
            const std::filesystem::path& log, bool own_group = false, std::string* error = nullptr);

/// How a child run to completion ended.
struct RunResult {
    int rc = 0;               ///< exit status; 128 + signal if killed; 127 if it could not start
    std::string out;          ///< its output (stdout and stderr)
    bool cut = false;         ///< it was killed at the deadline
};

/// Runs argv to completion in a process group of its own (libFuzzer's minimization and merge run their steps
/// as children of their own), its output in scratch (overwritten). A stop asked of the campaign (SIGINT,
/// SIGTERM) is passed on to the group once, and a group still there app::k_stop_grace_s later is killed; at
/// deadline, if given, the group is killed (SIGKILL) and the result says cut. tick, if given, is called about
/// once a second while it runs (progress lines).
RunResult run_bounded(const std::vector<std::string>& argv, const std::vector<std::string>& env_extra,
                      const std::filesystem::path& scratch,
                      std::optional<std::chrono::steady_clock::time_point> deadline = std::nullopt,
                      const std::function<void()>& tick = {});

/// run_bounded with no deadline: its exit status and its output.
std::pair<int, std::string> run_capture(const std::vector<std::string>& argv, const std::vector<std::string>& env_extra,
                                        const std::filesystem::path& scratch);

}  // namespace ricochet::fuzz
