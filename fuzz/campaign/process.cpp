// Child processes of a campaign (process.hpp): posix_spawn, so that nothing runs between fork and exec.
#include "process.hpp"

#include "ricochet_app/stop_signal.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>

#include <algorithm>
#include <fstream>
#include <sstream>

extern char** environ;

namespace ricochet::fuzz {

namespace fs = std::filesystem;

std::string read_all(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

pid_t spawn(const std::vector<std::string>& argv, const std::vector<std::string>& env_extra, const fs::path& log) {
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
    pid_t pid = -1;
    if (posix_spawn(&pid, cargv[0], &fa, nullptr, cargv.data(), cenv.data()) != 0) pid = -1;
    posix_spawn_file_actions_destroy(&fa);
    return pid;
}

std::pair<int, std::string> run_capture(const std::vector<std::string>& argv, const std::vector<std::string>& env_extra,
                                        const fs::path& scratch) {
    std::error_code ec;
    fs::remove(scratch, ec);
    const pid_t pid = spawn(argv, env_extra, scratch);
    // Degenerate: the program could not be started.
    if (pid < 0) return {127, "cannot start " + argv[0]};
    // A stop asked of the campaign (SIGINT, SIGTERM) is passed on to a minimization or merge under way.
    const int rc = app::wait_passing_stop(pid);
    return {rc, read_all(scratch)};
}

}  // namespace ricochet::fuzz
