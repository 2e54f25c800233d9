// Log text as a diagnostic shows it: escaped so that no byte of a log can drive the terminal, and cut short.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace ricochet::detail {

/// Most bytes of log text one quotation in a diagnostic shows; a longer text is cut and ends in "…".
inline constexpr std::size_t k_max_shown_bytes = 64;

/// text as a diagnostic quotes it (docs/scene-log.md, "Diagnostics"): printable ASCII and valid UTF-8 kept;
/// control bytes, DEL, bytes that are not UTF-8, and the invisible or reordering characters (C1 controls,
/// U+200E/U+200F, U+2028/U+2029, U+202A–U+202E, U+2066–U+2069, U+FEFF) written byte by byte as \xHH.
/// Only the first k_max_shown_bytes of text are shown, cut at a character, then "…".
std::string shown(std::string_view text);

}  // namespace ricochet::detail
