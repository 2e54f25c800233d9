// "Did you mean": the nearest of some names to a misspelt one, by edit distance.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ricochet::cli {

/// Optimal-string-alignment distance: insertions, deletions, substitutions and swaps of two adjacent
/// characters, one each ("replya" → "replay" is 1).
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The name nearest to word if it is close enough to be a typo (distance ≤ 2, and less than word's
/// length); the first of equally near names.
std::optional<std::string> nearest_name(std::string_view word, const std::vector<std::string>& names);

}  // namespace ricochet::cli
