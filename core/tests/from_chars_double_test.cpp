// from_chars_double's own path (the one wasm32's libc++ needs, built here on purpose with
// RICOCHET_OWN_FROM_CHARS_DOUBLE) against std::from_chars: the same end, error and value, bit for bit, on every
// shape of input the grammar has, valid or not.
#include <bit>
#include <charconv>
#include <cstdint>
#include <string>

#include <gtest/gtest.h>

#include "ricochet/from_chars.hpp"

namespace {

void expect_same(const std::string& s, std::chars_format format) {
    const char* first = s.data();
    const char* last = s.data() + s.size();
    double ours = 12345.0, theirs = 12345.0;
    const auto a = ricochet::from_chars_double(first, last, ours, format);
    const auto b = std::from_chars(first, last, theirs, format);
    EXPECT_EQ(a.ec, b.ec) << '\'' << s << '\'';
    EXPECT_EQ(a.ptr - first, b.ptr - first) << '\'' << s << '\'';
    if (ours != ours && theirs != theirs) return;  // NaN: the payload is not part of the contract
    EXPECT_EQ(std::bit_cast<std::uint64_t>(ours), std::bit_cast<std::uint64_t>(theirs)) << '\'' << s << '\'';
}

TEST(FromCharsDouble, DecimalAsTheStandardLibrary) {
    for (const char* s : {"0", "-0", "1", "-1", "0.1", ".5", "5.", "1e5", "1E-5", "1e+5", "1e", "1e+", "1e-x", "2.5e3x",
                          "123456789012345678901234567890", "0.30000000000000004", "2.2250738585072011e-308",
                          "4.9406564584124654e-324", "2.4703282292062327e-324", "2.4703282292062328e-324",
                          "1.7976931348623157e308", "1.7976931348623159e308", "1e309", "-1e400", "1e-400", "-1e-400",
                          "9007199254740993", "0.1000000000000000055511151231257827", "inf", "-Infinity", "INFx",
                          "infinit", "nan", "NaN(abc_1)", "nan(", "nan()", "", "-", "+1", "--1", ".", "-.", "e5", "x",
                          " 1", "1 ", "0x10", "00012", "1.2.3", "1..2"})
        expect_same(s, std::chars_format::general);
}

TEST(FromCharsDouble, HexadecimalAsTheStandardLibrary) {
    for (const char* s : {"1", "1.8p-3", "-1.8P-3", "a.bp+4", "ABCDEF", ".8", "8.", "1p", "1p+", "1px", "0x1",
                          "1.fffffffffffffp1023", "1p1024", "1p-1074", "1p-1075", "1.8p-1075", "1.0000000000000018p0",
                          "inf", "nan", "", "-", "g", "p3"})
        expect_same(s, std::chars_format::hex);
}

}  // namespace
