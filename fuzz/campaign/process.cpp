// Child processes of a campaign (process.hpp): posix_spawn, so that nothing runs between fork and exec.
#include "process.hpp"

#include "ricochet_app/stop_signal.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

#include <fmt/format.h>

extern char** environ;

namespace ricochet::fuzz {

namespace fs = std::filesystem;

namespace {

/// How often run_bounded looks at its child, the stop request and the clock.
constexpr std::chrono::milliseconds k_wait_poll{20};
/// How often run_bounded calls its tick.
constexpr std::chrono::seconds k_tick_every{1};

}  // namespace

std::string read_all(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

pid_t spawn(const std::vector<std::string>& argv, const std::vector<std::string>& env_extra, const fs::path& log,
            bool own_group, std::string* error) {
    std::vector<std::string> env;
    for (char** e = environ; *e != nullptr; ++e) {
        const std::string s = *e;
        const bool overridden = std::any_of(env_extra.begin(), env_extra.end(), [&](const std::string& x) {
            return s.compare(0, x.find('=') + 1, x, 0, x.find('=') + 1) == 0;
        });
        if (!overridden) env.push_back(s);
    }
    env.insert(env.end(), env_extra.begin(), env_extra.end());
    std::vector<char*> cargv, cenv;
    for (const auto& a : argv) cargv.push_back(const_cast<char*>(a.c_str()));
    cargv.push_back(nullptr);
    for (const auto& e : env) cenv.push_back(const_cast<char*>(e.c_str()));
    cenv.push_back(nullptr);
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 1, log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    posix_spawn_file_actions_adddup2(&fa, 1, 2);
    posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    if (own_group) {
        posix_spawnattr_setpgroup(&attr, 0);
        posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP);
    }
    pid_t pid = -1;
    if (const int rc = posix_spawn(&pid, cargv[0], &fa, &attr, cargv.data(), cenv.data()); rc != 0) {
        pid = -1;
        if (error) *error = fmt::format("cannot start {}: {}", argv[0], std::strerror(rc));
    }
    posix_spawnattr_destroy(&attr);
    posix_spawn_file_actions_destroy(&fa);
    return pid;
}

RunResult run_bounded(const std::vector<std::string>& argv, const std::vector<std::string>& env_extra, const fs::path& scratch,
                      std::optional<std::chrono::steady_clock::time_point> deadline, const std::function<void()>& tick) {
    using Clock = std::chrono::steady_clock;
    std::error_code ec;
    fs::remove(scratch, ec);
    std::string error;
    const pid_t pid = spawn(argv, env_extra, scratch, /*own_group=*/true, &error);
    // Degenerate: the program could not be started.
    if (pid < 0) return {127, error, false};
    std::optional<Clock::time_point> passed;
    bool killed = false, cut = false;
    Clock::time_point next_tick = Clock::now() + k_tick_every;
    int rc = 127;
    for (;;) {
        int status = 0;
        const pid_t got = ::waitpid(pid, &status, WNOHANG);
        if (got == pid) {
            rc = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
            break;
        }
        if (got < 0 && errno != EINTR) break;
        // The whole group: a minimization's or a merge's steps are children of the process started here.
        if (!passed && app::stop_requested()) {
            ::kill(-pid, app::stop_signal());
            passed = Clock::now();
        }
        if (passed && !killed && std::chrono::duration<double>(Clock::now() - *passed).count() > app::k_stop_grace_s) {
            ::kill(-pid, SIGKILL);
            killed = true;
        }
        if (deadline && !cut && Clock::now() >= *deadline) {
            ::kill(-pid, SIGKILL);
            cut = true;
        }
        if (tick && Clock::now() >= next_tick) {
            tick();
            next_tick += k_tick_every;
        }
        std::this_thread::sleep_for(k_wait_poll);
    }
    // What is left of the group (a step the process started and did not wait for) goes with it.
    if (cut || killed) ::kill(-pid, SIGKILL);
    return {rc, read_all(scratch), cut};
}

std::pair<int, std::string> run_capture(const std::vector<std::string>& argv, const std::vector<std::string>& env_extra,
                                        const fs::path& scratch) {
    RunResult r = run_bounded(argv, env_extra, scratch);
    return {r.rc, std::move(r.out)};
}

}  // namespace ricochet::fuzz
