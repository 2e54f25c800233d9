// The project folder, found the way git finds .git: the current folder, or the nearest folder above it
// that holds replays/ (a CMake build folder, one with CMakeCache.txt, is passed over: its replays/ holds
// the corpus's CTest files, not logs). Every command takes its defaults from there (the replays to read, where failures
// are saved, the project's own fuzz seeds), never from the tree the binary was built from.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace ricochet::app {

/// The environment variable that names the replay folder directly (also read by the property suite).
inline constexpr const char* k_replay_dir_env = "RICOCHET_REPLAY_DIR";

/// Where a command's defaults come from.
struct Project {
    std::filesystem::path root;        ///< the project folder; empty when only RICOCHET_REPLAY_DIR named the replays
    std::filesystem::path replay_dir;  ///< the replay folder: the flag, RICOCHET_REPLAY_DIR, or ROOT/replays
};

/// The nearest folder from start upward (start itself first) that holds a replays/ folder and is not a
/// build folder, as a path
/// relative to start when it is start or above it ("." for start itself); nothing if no folder up to the
/// file system's root holds one.
std::optional<std::filesystem::path> find_project_root(const std::filesystem::path& start);

/// The project of a command run in the current folder. The replay folder is flag if not empty, else
/// $RICOCHET_REPLAY_DIR if set, else ROOT/replays; nothing when none of them gives one.
std::optional<Project> find_project(const std::string& flag = {});

/// "ricochet COMMAND: error: no project folder: none of FOLDER or the folders above it holds replays/;
/// HOW, or set RICOCHET_REPLAY_DIR" (the caller prints it on stderr and exits 2).
std::string no_project_message(std::string_view command, std::string_view how);

}  // namespace ricochet::app
