// std::from_chars for doubles, or its grammar in front of strtod where the library has none (from_chars.hpp).
#include "ricochet/from_chars.hpp"

// The own path where the library has none; from_chars_double_test also builds it on purpose (defining the macro)
// and compares it with std::from_chars.
#if defined(_LIBCPP_VERSION) && _LIBCPP_VERSION < 170000 && !defined(RICOCHET_OWN_FROM_CHARS_DOUBLE)
#define RICOCHET_OWN_FROM_CHARS_DOUBLE 1
#endif
#if defined(RICOCHET_OWN_FROM_CHARS_DOUBLE)
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string>
#endif

namespace ricochet {

#if defined(RICOCHET_OWN_FROM_CHARS_DOUBLE)
namespace {

bool is_digit(char c, bool hex) {
    return (c >= '0' && c <= '9') || (hex && ((c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F')));
}
char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }
/// Whether [p, last) starts with word (lower case), ignoring case.
bool starts_with(const char* p, const char* last, const char* word) {
    for (; *word != '\0'; ++p, ++word)
        if (p == last || lower(*p) != *word) return false;
    return true;
}

/// The end of the number at p in from_chars' grammar (sign excluded), or p if there is none:
/// inf | infinity | nan | nan(n-char-sequence) | digits [. digits] [exponent], with a digit somewhere in the
/// mantissa, the exponent (e or, in hex, p; a sign; digits) taken only when complete.
const char* number_end(const char* p, const char* last, bool hex) {
    if (starts_with(p, last, "infinity")) return p + 8;
    if (starts_with(p, last, "inf")) return p + 3;
    if (starts_with(p, last, "nan")) {
        const char* q = p + 3;
        if (q != last && *q == '(') {
            const char* r = q + 1;
            while (r != last && (is_digit(*r, false) || (lower(*r) >= 'a' && lower(*r) <= 'z') || *r == '_')) ++r;
            if (r != last && *r == ')') return r + 1;
        }
        return q;
    }
    const char* q = p;
    bool digits = false;
    while (q != last && is_digit(*q, hex)) ++q, digits = true;
    if (q != last && *q == '.') {
        ++q;
        while (q != last && is_digit(*q, hex)) ++q, digits = true;
    }
    if (!digits) return p;
    if (q != last && lower(*q) == (hex ? 'p' : 'e')) {
        const char* e = q + 1;
        if (e != last && (*e == '+' || *e == '-')) ++e;
        if (e != last && is_digit(*e, false)) {
            while (e != last && is_digit(*e, false)) ++e;
            q = e;
        }
    }
    return q;
}

}  // namespace
#endif

std::from_chars_result from_chars_double(const char* first, const char* last, double& value, std::chars_format format) {
#if defined(RICOCHET_OWN_FROM_CHARS_DOUBLE)
    const bool hex = format == std::chars_format::hex;
    const bool negative = first != last && *first == '-';
    const char* body = first + (negative ? 1 : 0);
    const char* end = number_end(body, last, hex);
    if (end == body) return {first, std::errc::invalid_argument};
    // strtod reads hexadecimal with its "0x" only; the C locale's '.' (this program never sets another).
    const bool digits = is_digit(*body, true) || *body == '.';  // not inf or nan
    const std::string text = std::string(negative ? "-" : "") + (hex && digits ? "0x" : "") + std::string(body, end);
    errno = 0;
    const double v = std::strtod(text.c_str(), nullptr);
    if (errno == ERANGE && (std::isinf(v) || v == 0.0)) return {end, std::errc::result_out_of_range};
    value = v;
    return {end, std::errc{}};
#else
    return std::from_chars(first, last, value, format);
#endif
}

}  // namespace ricochet
