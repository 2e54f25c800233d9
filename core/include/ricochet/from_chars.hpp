// A double from text, exactly as std::from_chars reads it, on every standard library: libc++ before 17 (the one
// emscripten 3.1.6 ships, for wasm32) has no floating-point from_chars, and there the same grammar is matched here
// and the matched digits go to strtod, which musl rounds correctly to nearest, as from_chars does.
#pragma once

#include <charconv>

namespace ricochet {

/// std::from_chars(first, last, value, format) for a double: the longest prefix in from_chars' grammar (an
/// optional '-', no '+', no "0x" in hex), value rounded to nearest; invalid_argument (value unchanged) when no
/// prefix matches, result_out_of_range (value unchanged) when the number overflows or underflows to zero.
std::from_chars_result from_chars_double(const char* first, const char* last, double& value,
                                         std::chars_format format = std::chars_format::general);

}  // namespace ricochet
