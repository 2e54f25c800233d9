// Scene logs (format 1, /work/shared/scene-log.md and replays/README.md): the reader, the canonical
// writer, atomic saving and content-derived names.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "ricochet/scene.hpp"

namespace ricochet {

/// Longest accepted line in bytes, newline excluded.
inline constexpr std::size_t k_max_line_length = 4096;
/// Largest accepted log in bytes.
inline constexpr std::size_t k_max_file_size = std::size_t{16} << 20;
/// Most entities of one kind (walls, balls, circles or rects) in one log.
inline constexpr std::size_t k_max_entities = 100'000;
/// Most `expect state` lines in one log.
inline constexpr std::size_t k_max_expect_states = 1'000'000;
/// Most `from` lines in one log.
inline constexpr std::size_t k_max_provenance = 64;

/// A reader's complaint about one place in a log.
struct Diagnostic {
    std::string file;     ///< the name given to the reader
    int line = 0;         ///< 1-based
    int col = 0;          ///< 1-based, in bytes
    std::string message;  ///< what is wrong
    /// "FILE:LINE:COL: error: WHAT", the form every tool prints on stderr.
    std::string str() const;
};

/// A parsed scene, or where and why it could not be parsed.
using SceneOrDiagnostic = std::variant<Scene, Diagnostic>;

/// Reads a log from memory. filename is only used in diagnostics. Never throws on bad input.
SceneOrDiagnostic parse_scene_log(std::string_view text, std::string_view filename);
/// Reads a log from disk (enforcing k_max_file_size before reading it all). Never throws on bad input.
SceneOrDiagnostic read_scene_log(const std::filesystem::path& path);

/// The canonical text of a scene: header, `from` lines, kernel, frames, walls, balls, circles, rects,
/// checks, expect hash, expect failure, expect states; numbers in shortest round-trip form.
/// parse_scene_log(write_scene_log(s)) gives s back bit for bit.
std::string write_scene_log(const Scene& scene);

/// Writes text to path atomically: a temporary file in the same folder, fsync, rename over path,
/// fsync the folder. On failure returns false, sets *error (if given) and leaves path untouched.
bool write_file_atomically(const std::filesystem::path& path, std::string_view text, std::string* error);

/// The case's identity: 16 lowercase hex digits of xxh64 over the canonical text of the scene without
/// its `from` and `expect` lines. Two logs of the same case have the same id.
std::string scene_content_id(const Scene& scene);

/// Saves scene as DIR/PREFIX-ID.scene (ID = scene_content_id) unless a log of that name already exists:
/// the same case is never saved twice. Returns the path (new or existing), or nothing with *error set.
std::optional<std::filesystem::path> save_scene_log_once(const std::filesystem::path& dir, std::string_view prefix,
                                                         const Scene& scene, std::string* error);

/// True if a and b hold the same bits (operator== treats −0 and +0 as equal; this does not).
bool same_bits(const Scene& a, const Scene& b);

}  // namespace ricochet
