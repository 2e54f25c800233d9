// An exclusive lock on the cache folder (cache_lock.hpp).
#include "cache_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <thread>

#include <fmt/format.h>

namespace ricochet::fuzz {

CacheLock::CacheLock(const std::filesystem::path& cache, std::string_view what, std::optional<Clock::time_point> deadline) {
    const std::filesystem::path file = cache / "lock";
    fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) {
        fmt::print("  note: cannot open the lock {} ({}); {} unlocked\n", file.string(), std::strerror(errno), what);
        return;
    }
    if (::flock(fd_, LOCK_EX | LOCK_NB) == 0) return;
    if (errno == EWOULDBLOCK) {
        fmt::print("  waiting for {}: another campaign on this cache holds it ({})\n", file.string(), what);
        std::fflush(stdout);
        int rc = 0;
        if (deadline) {
            // Asked again every 100 ms until the deadline: flock has no timeout of its own.
            while ((rc = ::flock(fd_, LOCK_EX | LOCK_NB)) != 0 && (errno == EWOULDBLOCK || errno == EINTR)) {
                if (Clock::now() >= *deadline) {
                    timed_out_ = true;
                    ::close(fd_);
                    fd_ = -1;
                    return;
                }
                std::this_thread::sleep_for(std::chrono::milliseconds(100));
            }
        } else {
            while ((rc = ::flock(fd_, LOCK_EX)) != 0 && errno == EINTR) {
            }
        }
        if (rc == 0) return;
    }
    fmt::print("  note: cannot lock {} ({}); {} unlocked\n", file.string(), std::strerror(errno), what);
    ::close(fd_);
    fd_ = -1;
}

CacheLock::~CacheLock() {
    // Closing the descriptor releases the flock.
    if (fd_ >= 0) ::close(fd_);
}

}  // namespace ricochet::fuzz
