// Scene-log files: reading a log from disk, writing a file atomically, and saving a case once under
// a name derived from its content. The text format itself is scene_log_format.hpp (included).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "ricochet/scene.hpp"
#include "ricochet/scene_log_format.hpp"

namespace ricochet {

/// A log's bytes from disk (k_max_file_size enforced before reading it all), or why not (at 1:1).
std::variant<std::string, Diagnostic> read_log_text(const std::filesystem::path& path);

/// Reads a log from disk (enforcing k_max_file_size before reading it all). Never throws on bad input.
SceneOrDiagnostic read_scene_log(const std::filesystem::path& path, ExpectLines expect_lines = ExpectLines::checked);

/// True if write_file_atomically writes path in place: it names, or links to, something that exists and is
/// neither a regular file nor a folder (a device, a FIFO, a socket).
bool writes_in_place(const std::filesystem::path& path);

/// Writes text to path atomically: a temporary file in the same folder, fsync, rename over path,
/// fsync the folder. On failure returns false, sets *error (if given) and leaves path untouched.
/// Atomic replacement is for regular files and new paths: a path writes_in_place names (a device, a FIFO, or
/// a link to one) is opened and written in place instead, never replaced (a reader of a FIFO sees the text as
/// it is written; a failed write may leave part of it).
/// A symbolic link is written through: the temporary file goes next to the file it resolves to, which the
/// rename replaces, and the link stays. The temporary file is named `.NAME.tmp.PID.XXXXXX`; temporaries of
/// the same NAME that a killed writer left (its PID gone, the file older than this process) are removed.
/// (atomic_write.cpp)
bool write_file_atomically(const std::filesystem::path& path, std::string_view text, std::string* error);

/// Where save_scene_log_once left a case.
struct SavedLog {
    std::filesystem::path path;  ///< the log of the case: the one written, or the one already there
    bool is_new = false;         ///< true if this call wrote it, false if the case was saved before
};

/// Saves scene's canonical text as DIR/PREFIX-ID.scene (ID = scene_content_id) unless the folder already
/// holds the same case: a log of that name, or any readable *.scene directly in DIR with the same content
/// id (whatever its name, provenance or expect lines). The same case is never saved twice. Returns where
/// the case is and whether this call wrote it, or nothing with *error set.
std::optional<SavedLog> save_scene_log_once(const std::filesystem::path& dir, std::string_view prefix,
                                            const Scene& scene, std::string* error);

/// As above for a log given as text: text must read as a scene log (else nothing, *error set to its
/// diagnostic); it is saved verbatim, so its comment lines are kept.
std::optional<SavedLog> save_scene_log_once(const std::filesystem::path& dir, std::string_view prefix,
                                            std::string_view text, std::string* error);

}  // namespace ricochet
