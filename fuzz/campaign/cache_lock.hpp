// An exclusive lock on the cache folder (flock(2) on CACHE/lock), held while a campaign changes what
// campaigns share there: a target's working corpus (the merge) and the replay folder (saving a log).
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>

#include "budget.hpp"

namespace ricochet::fuzz {

/// Holds the lock from construction to destruction. If another campaign holds it, prints one line saying
/// who waits for what, then blocks, until deadline if one is given (then timed_out() says so and the lock is
/// not held). If the lock file cannot be opened or locked it says so and goes on unlocked (a cache on a file
/// system without flock): the saves stay atomic, only the merge may race.
class CacheLock {
public:
    CacheLock(const std::filesystem::path& cache, std::string_view what,
              std::optional<Clock::time_point> deadline = std::nullopt);
    ~CacheLock();
    /// True if the deadline came before the lock: the caller must not do what it guards.
    bool timed_out() const { return timed_out_; }
    CacheLock(const CacheLock&) = delete;
    CacheLock& operator=(const CacheLock&) = delete;

private:
    int fd_ = -1;
    bool timed_out_ = false;
};

}  // namespace ricochet::fuzz
