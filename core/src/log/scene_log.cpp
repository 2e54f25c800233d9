// Scene-log files: reading one from disk and saving a case once (scene_log.hpp; atomic saving is
// atomic_write.cpp).
#include "ricochet/scene_log.hpp"

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
