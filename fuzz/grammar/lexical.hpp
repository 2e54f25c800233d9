// The lexical layer of the independent scene-log acceptor (docs/scene-log.md, "Lexical rules", "Numbers",
// "Limits"): lines, tokens, numbers and integers. Written from the spec alone; standard library only, no
// ricochet header, so that a bug of the reader is not shared by construction.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ricochet_grammar {

/// Longest line in bytes, its newline ('\n') excluded; a CR before it counts.
inline constexpr std::size_t k_line_limit = 4096;
/// Largest log in bytes (16 MiB).
inline constexpr std::size_t k_file_limit = std::size_t{16} * 1024 * 1024;

/// A line's tokens, after its comment is cut off. Empty for a blank or comment-only line.
using Tokens = std::vector<std::string_view>;

/// Why a line cannot be tokenized (too long, a NUL byte), or empty if it can; tokens filled on success.
std::string tokenize(std::string_view line, Tokens& tokens);

/// A number token read as docs/scene-log.md "Numbers" says.
struct Number {
    double value = 0.0;
    /// Empty if the token is a number in the accepted range, else why not.
    std::string error;
};

/// Reads a number token: one optional leading '-', then a decimal literal or 0x/0X and a hexadecimal one
/// (std::from_chars' syntax), or inf/nan; checks the range (finite, magnitude ≤ 2^256). A literal beyond
/// a double, or a non-zero one that rounds to zero, is "out of the range of a double".
Number read_number(std::string_view token);

/// An integer token: decimal digits, at most one leading '-'.
struct Integer {
    std::int64_t value = 0;
    /// Empty if the token is an integer ≥ 0 that fits in a signed 64-bit integer, else why not.
    std::string error;
};

/// Reads an integer token (frames, frame and ball numbers): no fraction, no '+', not negative (−0 is 0),
/// fits in int64.
Integer read_integer(std::string_view token);

}  // namespace ricochet_grammar
