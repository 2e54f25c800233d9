// Writing a file atomically, through a symbolic link, cleaning up after killed writers; a device or a FIFO in
// place (scene_log.hpp).
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <climits>
#include <cstring>
#include <system_error>

#include <fmt/format.h>

#include "ricochet/scene_log.hpp"

namespace ricochet {
namespace {

/// About when this process started: a temporary file younger than it may be a live writer's, whatever its PID
/// says (a PID of another host or PID namespace sharing the folder).
const std::filesystem::file_time_type k_process_start = std::filesystem::file_time_type::clock::now();

/// The PID in a temporary file's name ".NAME.tmp.PID.XXXXXX" (mkstemp's six letters or digits), or 0 if
/// file is not one of NAME's.
pid_t temporary_owner(std::string_view file, std::string_view name) {
    const std::string prefix = fmt::format(".{}.tmp.", name);
    if (!file.starts_with(prefix)) return 0;
    file.remove_prefix(prefix.size());
    const auto dot = file.find('.');
    if (dot == std::string_view::npos || dot == 0 || file.size() - dot - 1 != 6) return 0;
    for (char c : file.substr(dot + 1))
        if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'))) return 0;
    int pid = 0;
    const auto [end, ec] = std::from_chars(file.data(), file.data() + dot, pid);
    if (ec != std::errc{} || end != file.data() + dot || pid <= 0) return 0;
    return static_cast<pid_t>(pid);
}

/// Removes the temporaries of dir/name that killed writers left: named by write_file_atomically, owned by a
/// PID that no longer exists (kill(pid, 0) gives ESRCH: a live one, ours or another user's, is kept), and
/// older than this process. Best effort: whatever cannot be listed or removed stays.
void remove_stale_temporaries(const std::filesystem::path& dir, const std::string& name) {
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
        const pid_t pid = temporary_owner(entry.path().filename().string(), name);
        if (pid == 0 || pid == ::getpid()) continue;
        if (::kill(pid, 0) == 0 || errno != ESRCH) continue;
        std::error_code e;
        // A link or a folder of that name is nobody's temporary file.
        if (!entry.is_regular_file(e) || entry.is_symlink(e)) continue;
        const auto written = std::filesystem::last_write_time(entry.path(), e);
        if (e || written >= k_process_start) continue;
        std::filesystem::remove(entry.path(), e);
    }
}

/// Writes text to path, which names (or links to) a device, a FIFO or a socket, through one open(2) of it: no
/// temporary file and no rename, which would put a regular file in the node's place. Blocks, as any writer of a
/// FIFO does, until a reader opens it.
bool write_in_place(const std::filesystem::path& path, std::string_view text, std::string* error) {
    const auto set = [&](std::string what) {
        if (error) *error = fmt::format("{}: {}: {}", path.string(), what, std::strerror(errno));
        return false;
    };
    // No O_TRUNC and no O_CREAT: a node is neither truncated nor made; O_NOCTTY keeps a terminal from
    // becoming ours.
    int fd = -1;
    do fd = ::open(path.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
    while (fd < 0 && errno == EINTR);
    if (fd < 0) return set("cannot open for writing");
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            const int saved = errno;
            ::close(fd);
            errno = saved;
            return set("cannot write");
        }
        done += static_cast<std::size_t>(n);
    }
    if (::close(fd) != 0 && errno != EINTR) return set("cannot close");
    return true;
}

}  // namespace

bool writes_in_place(const std::filesystem::path& path) {
    // stat follows a symbolic link: a link to a device is written as the device is.
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) return false;
    return !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode);
}

bool write_file_atomically(const std::filesystem::path& given, std::string_view text, std::string* error) {
    const auto set = [&](std::string what) {
        if (error) *error = fmt::format("{}: {}: {}", given.string(), what, std::strerror(errno));
        return false;
    };
    // A device, a FIFO or a socket (or a link to one) is written in place: renaming a regular file over it
    // would replace the node (as root, `-o /dev/null` would replace the system's /dev/null).
    if (writes_in_place(given)) return write_in_place(given, text, error);
    // Through a symbolic link: the rename replaces the file it resolves to, not the link.
    std::filesystem::path path = given;
    std::error_code ec;
    if (std::filesystem::is_symlink(given, ec)) {
        path = std::filesystem::canonical(given, ec);
        if (ec) {
            errno = ec.value();
            return set("cannot resolve the symbolic link");
        }
    }
    const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    const std::string name = path.filename().string();
    remove_stale_temporaries(dir, name);
    // The PID in the name tells a later writer whether this one may still be at work (remove_stale_temporaries).
    std::string tmpl = (dir / fmt::format(".{}.tmp.{}.XXXXXX", name, ::getpid())).string();
    const int fd = ::mkstemp(tmpl.data());
    if (fd < 0) return set("cannot create a temporary file");
    const auto abandon = [&](std::string what) {
        const int saved = errno;
        ::close(fd);
        ::unlink(tmpl.c_str());
        errno = saved;
        return set(std::move(what));
    };
    std::size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;  // a signal before any byte was written: not forced in tests
            return abandon("cannot write the temporary file");
        }
        done += static_cast<std::size_t>(n);
    }
    // Keep the original file's permission bits if there is one, else the usual 0644.
    struct stat st {};
    const mode_t mode = ::stat(path.c_str(), &st) == 0 ? (st.st_mode & 07777) : 0644;
    // fchmod, fsync and close of a file just written fail only on a failing medium (EIO) or a network
    // file system (EDQUOT at close): kept as errors, not reached by the tests on a local disk.
    if (::fchmod(fd, mode) != 0) return abandon("cannot set permissions");
    if (::fsync(fd) != 0) return abandon("cannot sync the temporary file");
    if (::close(fd) != 0) {
        const int saved = errno;
        ::unlink(tmpl.c_str());
        errno = saved;
        return set("cannot close the temporary file");
    }
    if (::rename(tmpl.c_str(), path.c_str()) != 0) {
        const int saved = errno;
        ::unlink(tmpl.c_str());
        errno = saved;
        return set("cannot rename the temporary file into place");
    }
    // Make the rename itself durable (best effort: the folder just renamed into is there to open; it fails
    // only without read permission on it, which mkstemp and rename do not need: not forced in tests, as root).
    const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
    if (dfd >= 0) {
        ::fsync(dfd);
        ::close(dfd);
    }
    return true;
}

}  // namespace ricochet
