// Scene-log files: reading one from disk, atomic saving and saving a case once (scene_log.hpp).
#include "ricochet/scene_log.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>
#include <variant>
#include <vector>

#include <fmt/format.h>

namespace ricochet {

std::variant<std::string, Diagnostic> read_log_text(const std::filesystem::path& path) {
    const std::string name = path.string();
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) return Diagnostic{name, 1, 1, "is a directory, not a scene log"};
    std::ifstream in(path, std::ios::binary);
    if (!in) return Diagnostic{name, 1, 1, fmt::format("cannot open: {}", std::strerror(errno))};
    // Read at most one byte past the limit, so a huge file is refused quickly.
    std::string text(k_max_file_size + 1, '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    text.resize(static_cast<std::size_t>(in.gcount()));
    if (text.size() > k_max_file_size)
        return Diagnostic{name, 1, 1, fmt::format("the file is over the limit of {} bytes", k_max_file_size)};
    return text;
}

SceneOrDiagnostic read_scene_log(const std::filesystem::path& path, ExpectLines expect_lines) {
    auto text = read_log_text(path);
    if (auto* d = std::get_if<Diagnostic>(&text)) return std::move(*d);
    return parse_scene_log(std::get<std::string>(text), path.string(), expect_lines);
}

bool write_file_atomically(const std::filesystem::path& path, std::string_view text, std::string* error) {
    const auto set = [&](std::string what) {
        if (error) *error = fmt::format("{}: {}: {}", path.string(), what, std::strerror(errno));
        return false;
    };
    const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    std::string tmpl = (dir / ("." + path.filename().string() + ".tmp.XXXXXX")).string();
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

namespace {

/// The saved log of the case with content id `id` directly in dir: `name` if it exists, else any readable
/// *.scene of the same content id (in name order, so the answer does not depend on the file system).
std::optional<std::filesystem::path> find_case(const std::filesystem::path& dir, const std::string& name,
                                               const std::string& id) {
    std::error_code ec;
    if (std::filesystem::exists(dir / name, ec)) return dir / name;
    std::vector<std::filesystem::path> logs;
    for (const auto& e : std::filesystem::directory_iterator(dir, ec))
        if (e.path().extension() == ".scene" && e.is_regular_file(ec)) logs.push_back(e.path());
    std::sort(logs.begin(), logs.end());
    for (const auto& path : logs) {
        const SceneOrDiagnostic parsed = read_scene_log(path);
        // A log that does not read (a deliberately malformed one, say) is no case.
        if (const Scene* s = std::get_if<Scene>(&parsed); s != nullptr && scene_content_id(*s) == id) return path;
    }
    return std::nullopt;
}

std::optional<SavedLog> save_once(const std::filesystem::path& dir, std::string_view prefix, const Scene& scene,
                                  std::string_view text, std::string* error) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) {
        if (error) *error = fmt::format("{}: cannot create the folder: {}", dir.string(), ec.message());
        return std::nullopt;
    }
    const std::string id = scene_content_id(scene);
    const std::string name = fmt::format("{}-{}.scene", prefix, id);
    if (auto known = find_case(dir, name, id)) return SavedLog{*known, false};
    const std::filesystem::path path = dir / name;
    if (!write_file_atomically(path, text, error)) return std::nullopt;
    return SavedLog{path, true};
}

}  // namespace

std::optional<SavedLog> save_scene_log_once(const std::filesystem::path& dir, std::string_view prefix,
                                            const Scene& scene, std::string* error) {
    return save_once(dir, prefix, scene, write_scene_log(scene), error);
}

std::optional<SavedLog> save_scene_log_once(const std::filesystem::path& dir, std::string_view prefix,
                                            std::string_view text, std::string* error) {
    const SceneOrDiagnostic parsed = parse_scene_log(text, fmt::format("{}-*.scene", prefix));
    if (const auto* d = std::get_if<Diagnostic>(&parsed)) {
        if (error) *error = fmt::format("not a scene log: {}", d->str());
        return std::nullopt;
    }
    return save_once(dir, prefix, std::get<Scene>(parsed), text, error);
}

}  // namespace ricochet
