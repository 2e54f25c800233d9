// A campaign's own working folder (run_dir.hpp).
#include "run_dir.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstring>
#include <fstream>
#include <system_error>

#include <fmt/format.h>

#include "cache.hpp"

namespace ricochet::fuzz {
namespace {

namespace fs = std::filesystem;

/// The PID of a run folder's name "PID-XXXXXX", or 0 if name is not one.
pid_t run_owner(const std::string& name) {
    const auto dash = name.find('-');
    if (dash == std::string::npos || dash == 0 || name.size() - dash - 1 != 6) return 0;
    int pid = 0;
    const auto [end, ec] = std::from_chars(name.data(), name.data() + dash, pid);
    if (ec != std::errc{} || end != name.data() + dash || pid <= 0) return 0;
    return static_cast<pid_t>(pid);
}

/// Moves the failure artifacts of a dead campaign's run folder into the pending folders its targets name, so that
/// the next campaign converts them. Best effort.
void rescue_artifacts(const fs::path& run) {
    std::error_code ec;
    for (const auto& t : fs::directory_iterator(run, ec)) {
        std::error_code e2;
        if (!t.is_directory(e2)) continue;
        std::ifstream in(t.path() / k_pending_to);
        std::string to;
        if (!std::getline(in, to) || to.empty() || !fs::is_directory(to, e2)) continue;
        for (const std::string& name : list_artifacts(t.path() / "artifacts"))
            if (!name.starts_with("slow-unit-")) fs::rename(t.path() / "artifacts" / name, fs::path(to) / name, e2);
    }
}

/// Removes the run folders of runs whose PID no longer exists (kill(pid, 0) gives ESRCH), their failure
/// artifacts rescued first; a live PID's, ours or another user's, is kept. Best effort.
void remove_stale_runs(const fs::path& runs) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(runs, ec)) {
        const pid_t pid = run_owner(e.path().filename().string());
        if (pid == 0 || pid == ::getpid()) continue;
        if (::kill(pid, 0) == 0 || errno != ESRCH) continue;
        std::error_code e2;
        if (!e.is_directory(e2) || e.is_symlink(e2)) continue;
        rescue_artifacts(e.path());
        fs::remove_all(e.path(), e2);
    }
}

}  // namespace

std::optional<fs::path> make_run_dir(const fs::path& cache, std::string* error) {
    const fs::path runs = cache / "runs";
    std::error_code ec;
    fs::create_directories(runs, ec);
    if (ec) {
        if (error) *error = fmt::format("{}: cannot create the folder: {}", runs.string(), ec.message());
        return std::nullopt;
    }
    remove_stale_runs(runs);
    std::string tmpl = (runs / fmt::format("{}-XXXXXX", ::getpid())).string();
    if (::mkdtemp(tmpl.data()) == nullptr) {
        if (error) *error = fmt::format("{}: cannot create a working folder: {}", runs.string(), std::strerror(errno));
        return std::nullopt;
    }
    return fs::path(tmpl);
}

fs::path move_into(const fs::path& file, const fs::path& dir, std::string* error) {
    const fs::path to = dir / file.filename();
    std::error_code ec;
    fs::rename(file, to, ec);
    if (ec) {
        if (error) *error = fmt::format("cannot move {} to {}: {}", file.string(), to.string(), ec.message());
        return file;
    }
    return to;
}

}  // namespace ricochet::fuzz
