// Lines, tokens, numbers and integers of a scene log (lexical.hpp), from docs/scene-log.md alone.
#include "lexical.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace ricochet_grammar {
namespace {

bool is_separator(char c) { return c == ' ' || c == '\t' || c == '\r'; }
bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool is_hex_digit(char c) { return is_digit(c) || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F'); }
char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

bool equals_ignoring_case(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (lower(a[i]) != lower(b[i])) return false;
    return true;
}

// The spellings from_chars reads as infinity or NaN: inf, infinity, nan, nan(n-char-sequence), any case.
bool is_non_finite_word(std::string_view s) {
    if (equals_ignoring_case(s, "inf") || equals_ignoring_case(s, "infinity") || equals_ignoring_case(s, "nan"))
        return true;
    if (s.size() < 5 || !equals_ignoring_case(s.substr(0, 4), "nan(") || s.back() != ')') return false;
    for (char c : s.substr(4, s.size() - 5))
        if (!(is_digit(c) || (lower(c) >= 'a' && lower(c) <= 'z') || c == '_')) return false;
    return true;
}

// A literal without sign or prefix: digits [. digits] or . digits, then an optional exponent (e or p, an
// optional sign, decimal digits). Sets nonzero when a digit of the mantissa is not 0.
bool is_literal(std::string_view s, bool hex, bool& nonzero) {
    const auto digit = [hex](char c) { return hex ? is_hex_digit(c) : is_digit(c); };
    std::size_t i = 0, digits = 0;
    for (; i < s.size() && digit(s[i]); ++i, ++digits) nonzero = nonzero || s[i] != '0';
    if (i < s.size() && s[i] == '.')
        for (++i; i < s.size() && digit(s[i]); ++i, ++digits) nonzero = nonzero || s[i] != '0';
    if (digits == 0) return false;
    if (i == s.size()) return true;
    if (lower(s[i]) != (hex ? 'p' : 'e')) return false;
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    if (i == s.size()) return false;
    for (; i < s.size(); ++i)
        if (!is_digit(s[i])) return false;
    return true;
}

}  // namespace

std::string tokenize(std::string_view line, Tokens& tokens) {
    tokens.clear();
    if (line.size() > k_line_limit) return "line over the limit of 4096 bytes";
    if (line.find('\0') != std::string_view::npos) return "NUL byte";
    line = line.substr(0, line.find('#'));
    std::size_t i = 0;
    while (i < line.size()) {
        if (is_separator(line[i])) {
            ++i;
            continue;
        }
        const std::size_t start = i;
        while (i < line.size() && !is_separator(line[i])) ++i;
        tokens.push_back(line.substr(start, i - start));
    }
    return {};
}

Number read_number(std::string_view token) {
    const std::string quoted = "'" + std::string(token) + "'";
    std::string_view body = token;
    if (!body.empty() && body.front() == '-') body.remove_prefix(1);
    const bool hex = body.size() > 2 && body[0] == '0' && lower(body[1]) == 'x';
    const std::string_view digits = hex ? body.substr(2) : body;
    if (is_non_finite_word(digits)) return {0.0, quoted + " is outside the accepted range"};
    bool nonzero = false;
    if (!is_literal(digits, hex, nonzero)) return {0.0, quoted + " is not a number"};
    // strtod reads both forms (0x included) with the same rounding to nearest; the syntax is checked above.
    const std::string text(token);
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size()) return {0.0, quoted + " is not a number"};
    if (std::isinf(v) || (v == 0.0 && nonzero)) return {0.0, quoted + " is out of the range of a double"};
    if (!(std::fabs(v) <= 0x1p256)) return {0.0, quoted + " is outside the accepted range"};
    return {v, {}};
}

Integer read_integer(std::string_view token) {
    const std::string quoted = "'" + std::string(token) + "'";
    std::string_view s = token;
    const bool negative = !s.empty() && s.front() == '-';
    if (negative) s.remove_prefix(1);
    if (s.empty()) return {0, quoted + " is not an integer"};
    // Magnitudes up to 2^63 fit (−2^63 does); beyond, the token does not fit in 64 bits.
    constexpr std::uint64_t k_limit = std::uint64_t{1} << 63;
    std::uint64_t m = 0;
    bool too_big = false;
    for (char c : s) {
        if (!is_digit(c)) return {0, quoted + " is not an integer"};
        const auto d = static_cast<std::uint64_t>(c - '0');
        if (m > (k_limit - d) / 10) too_big = true;
        else m = m * 10 + d;
    }
    if (too_big || (!negative && m == k_limit)) return {0, quoted + " does not fit in 64 bits"};
    if (negative && m != 0) return {0, quoted + " is negative"};
    return {static_cast<std::int64_t>(m), {}};
}

}  // namespace ricochet_grammar
