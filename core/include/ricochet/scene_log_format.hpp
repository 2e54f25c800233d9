// The scene-log text format (format 1, docs/scene-log.md and replays/README.md): the reader, the
// canonical writer and content-derived ids. Files on disk are scene_log.hpp's.
#pragma once

#include <cstddef>
#include <cstdint>
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

/// The UTF-8 byte order mark, refused at the start of a log (docs/scene-log.md, "Lexical rules").
inline constexpr std::string_view k_byte_order_mark = "\xEF\xBB\xBF";

/// What the reader makes of the `expect` lines.
enum class ExpectLines {
    checked,   ///< every rule of docs/scene-log.md: what run, replay and every other reader use
    replaced,  ///< each line read and checked on its own, but not against the rest of the log (its frames,
               ///< balls, checks), and left out of the scene: `ricochet record`, which writes new ones
};

/// Reads a log from memory. filename is only used in diagnostics. Never throws on bad input.
SceneOrDiagnostic parse_scene_log(std::string_view text, std::string_view filename,
                                  ExpectLines expect_lines = ExpectLines::checked);

/// The canonical text of a scene: header, `from` lines, kernel, frames, domain lines, `balls collide`, walls,
/// balls (with R and M on every line when the scene has masses), circles, rects, bumpers, checks, found, expect
/// hash, expect failure, expect states; numbers in shortest round-trip form.
/// parse_scene_log(write_scene_log(s)) gives s back bit for bit.
std::string write_scene_log(const Scene& scene);

/// True if a and b hold the same bits (operator== treats −0 and +0 as equal; this does not): what the round trip
/// promises.
bool same_bits(const Scene& a, const Scene& b);

/// The case's identity: 16 lowercase hex digits of xxh64 over the canonical text of the scene without
/// its `from`, `found` and `expect` lines. Two logs of the same case have the same id.
std::string scene_content_id(const Scene& scene);

}  // namespace ricochet
