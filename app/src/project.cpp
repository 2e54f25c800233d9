// The project folder (ricochet_app/project.hpp).
#include "ricochet_app/project.hpp"

#include <cstdlib>
#include <system_error>

#include <fmt/format.h>

namespace ricochet::app {

namespace fs = std::filesystem;

std::optional<fs::path> find_project_root(const fs::path& start) {
    std::error_code ec;
    fs::path dir = fs::absolute(start, ec);
    // Degenerate: a folder that cannot be named (deleted under us) has no project.
    if (ec) return std::nullopt;
    // Walked as "", "..", "../..": printed paths stay short and as the user would type them.
    fs::path up = ".";
    for (;;) {
        // A CMake build folder has a replays/ of its own (the corpus's CTest files): it is not a project.
        if (fs::is_directory(dir / "replays", ec) && !fs::exists(dir / "CMakeCache.txt", ec)) return up;
        if (!dir.has_relative_path()) return std::nullopt;
        dir = dir.parent_path();
        up = up == "." ? fs::path("..") : up / "..";
    }
}

std::optional<Project> find_project(const std::string& flag) {
    Project p;
    std::error_code ec;
    // Degenerate: a current folder that no longer exists has no project (the flag or variable may still name one).
    if (const fs::path here = fs::current_path(ec); !ec)
        if (const auto root = find_project_root(here)) p.root = *root;
    if (!flag.empty())
        p.replay_dir = flag;
    else if (const char* env = std::getenv(k_replay_dir_env); env != nullptr && *env != '\0')
        p.replay_dir = env;
    else if (!p.root.empty())
        p.replay_dir = p.root == "." ? fs::path("replays") : p.root / "replays";
    else
        return std::nullopt;
    return p;
}

std::string no_project_message(std::string_view command, std::string_view how) {
    std::error_code ec;
    const fs::path here = fs::current_path(ec);
    return fmt::format("ricochet {}: error: no project folder: neither {} nor any folder above it holds replays/; {}, or set {}",
                       command, ec ? std::string(".") : here.string(), how, k_replay_dir_env);
}

}  // namespace ricochet::app
