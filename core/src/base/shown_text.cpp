// Log text as a diagnostic shows it (shown_text.hpp).
#include "base/shown_text.hpp"

#include <cstdint>

namespace ricochet::detail {
namespace {

/// The length of the well-formed UTF-8 sequence starting text[i] (RFC 3629: no overlong form, no surrogate,
/// nothing past U+10FFFF) and its code point, or 0 if none starts there.
std::size_t utf8_sequence(std::string_view text, std::size_t i, char32_t& cp) {
    const auto byte = [&](std::size_t k) { return static_cast<std::uint8_t>(text[k]); };
    const std::uint8_t b0 = byte(i);
    std::size_t n = 0;
    std::uint8_t lo = 0x80, hi = 0xBF;  // the range of the second byte
    if (b0 >= 0xC2 && b0 <= 0xDF) n = 2;
    else if (b0 >= 0xE0 && b0 <= 0xEF) {
        n = 3;
        if (b0 == 0xE0) lo = 0xA0;  // overlong below U+0800
        if (b0 == 0xED) hi = 0x9F;  // surrogates U+D800–U+DFFF
    } else if (b0 >= 0xF0 && b0 <= 0xF4) {
        n = 4;
        if (b0 == 0xF0) lo = 0x90;  // overlong below U+10000
        if (b0 == 0xF4) hi = 0x8F;  // past U+10FFFF
    } else {
        return 0;  // ASCII is not asked for; 80–C1 and F5–FF start nothing
    }
    if (text.size() - i < n) return 0;
    if (byte(i + 1) < lo || byte(i + 1) > hi) return 0;
    for (std::size_t k = 2; k < n; ++k)
        if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
    cp = static_cast<char32_t>(b0 & (0xFF >> (n + 1)));
    for (std::size_t k = 1; k < n; ++k) cp = (cp << 6) | (byte(i + k) & 0x3F);
    return n;
}

/// Characters a terminal does not show as themselves: C1 controls, and the invisible marks, separators and
/// bidirectional controls that would hide or reorder the text around them ("Trojan Source"). cp is the code
/// point of a multi-byte sequence, so cp ≥ 0x80, and the C1 controls U+0080–U+009F are those up to 0x9F.
bool is_hidden(char32_t cp) {
    return cp <= 0x9F || cp == 0x200E || cp == 0x200F || cp == 0x2028 || cp == 0x2029 ||
           (cp >= 0x202A && cp <= 0x202E) || (cp >= 0x2066 && cp <= 0x2069) || cp == 0xFEFF;
}

void escape(std::string& out, std::string_view bytes) {
    constexpr char k_hex[] = "0123456789abcdef";
    for (char c : bytes) {
        const auto b = static_cast<std::uint8_t>(c);
        out += "\\x";
        out += k_hex[b >> 4];
        out += k_hex[b & 0xF];
    }
}

}  // namespace

std::string shown(std::string_view text) {
    std::string out;
    std::size_t i = 0;
    while (i < text.size()) {
        const auto b = static_cast<std::uint8_t>(text[i]);
        char32_t cp = 0;
        const std::size_t n = b < 0x80 ? 1 : utf8_sequence(text, i, cp);
        const std::size_t len = n == 0 ? 1 : n;  // a byte that starts no sequence stands alone
        // Cut at a character: the one that would pass the limit is not shown.
        if (i + len > k_max_shown_bytes) {
            out += "…";
            return out;
        }
        const std::string_view piece = text.substr(i, len);
        if (b < 0x80 ? (b < 0x20 || b == 0x7F) : (n == 0 || is_hidden(cp))) escape(out, piece);
        else out += piece;
        i += len;
    }
    return out;
}

}  // namespace ricochet::detail
