// Scene-log files: reading a log from disk, writing a file atomically, and saving a case once under
// a name derived from its content. The text format itself is scene_log_format.hpp (included).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "ricochet/scene.hpp"
#include "ricochet/scene_log_format.hpp"

namespace ricochet {

/// Reads a log from disk (enforcing k_max_file_size before reading it all). Never throws on bad input.
SceneOrDiagnostic read_scene_log(const std::filesystem::path& path);

/// Writes text to path atomically: a temporary file in the same folder, fsync, rename over path,
/// fsync the folder. On failure returns false, sets *error (if given) and leaves path untouched.
bool write_file_atomically(const std::filesystem::path& path, std::string_view text, std::string* error);

/// Saves scene as DIR/PREFIX-ID.scene (ID = scene_content_id) unless a log of that name already exists:
/// the same case is never saved twice. Returns the path (new or existing), or nothing with *error set.
std::optional<std::filesystem::path> save_scene_log_once(const std::filesystem::path& dir, std::string_view prefix,
                                                         const Scene& scene, std::string* error);

}  // namespace ricochet
