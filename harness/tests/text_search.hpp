// Searching a test's output text (an SVG, a message) for what it must hold.
#pragma once

#include <cstddef>
#include <string>

namespace ricochet::test {

/// How many times what occurs in text (overlapping occurrences counted).
inline std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

/// text holds what.
inline bool has(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

}  // namespace ricochet::test
