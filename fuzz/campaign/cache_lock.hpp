// An exclusive lock on the cache folder (flock(2) on CACHE/lock), held while a campaign changes what
// campaigns share there: a target's working corpus (the merge) and the replay folder (saving a log).
#pragma once

#include <filesystem>
#include <string_view>

namespace ricochet::fuzz {

/// Holds the lock from construction to destruction. If another campaign holds it, prints one line saying
/// who waits for what, then blocks. If the lock file cannot be opened or locked it says so and goes on
/// unlocked (a cache on a file system without flock): the saves stay atomic, only the merge may race.
class CacheLock {
public:
    CacheLock(const std::filesystem::path& cache, std::string_view what);
    ~CacheLock();
    CacheLock(const CacheLock&) = delete;
    CacheLock& operator=(const CacheLock&) = delete;

private:
    int fd_ = -1;
};

}  // namespace ricochet::fuzz
