// A campaign's own working folder in the cache: CACHE/runs/PID-XXXXXX, so that campaigns sharing one
// cache never share a temporary file. Folders of campaigns whose PID is gone are removed, the failure artifacts
// they had not converted moved first into the pending folder each target's folder names.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace ricochet::fuzz {

/// The file in RUN/TARGET/ that names (one line, absolute) the pending folder its failure artifacts belong to.
inline constexpr const char* k_pending_to = "pending-to";

/// Creates CACHE/runs/PID-XXXXXX (mkdtemp) after removing the run folders of dead PIDs (their targets'
/// failure artifacts, RUN/TARGET/artifacts/, moved first into the folder RUN/TARGET/pending-to names); nothing,
/// with *error set, if it cannot.
std::optional<std::filesystem::path> make_run_dir(const std::filesystem::path& cache, std::string* error);

/// Moves file into dir under its own name (rename: atomic, same folder tree). Files are named by their
/// content (libFuzzer's SHA-1 names), so one already there is the same file and is replaced. Returns the
/// new path, or file itself (with *error set) if it cannot.
std::filesystem::path move_into(const std::filesystem::path& file, const std::filesystem::path& dir, std::string* error);

}  // namespace ricochet::fuzz
