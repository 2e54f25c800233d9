// The parser target's mutation of whole tokens (parser_fuzz.cpp): the grammar's edges set as tokens of their own.
// libFuzzer's mutations insert and overwrite bytes, so an edge of the dictionary (parser.dict) lands as a token only
// where the bytes around it happen to end one: 200 000 inputs on each of three seeds never made a number of magnitude
// exactly 2^256 (the range limit) out of the committed corpus. Header-only, standard library only, so that its test
// (token_mutator_test.cpp) needs neither libFuzzer nor the core.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <random>
#include <string_view>

namespace ricochet::fuzz {

/// Values on either side of docs/scene-log.md's limits ("Numbers", "Limits", the mass's range): 2^256 in hexadecimal
/// and decimal and its neighbouring doubles, 2^−256 and below it, the subnormals' ends and below them, the largest
/// finite magnitude and past it, −0, inf and nan, the frame count's limit and past it, the 64-bit integers' end.
inline constexpr std::array<std::string_view, 26> k_edge_tokens = {
    "0x1p256", "-0x1p256", "0x1.0000000000001p256", "0x1.fffffffffffffp255",
    "115792089237316195423570985008687907853269984665640564039457584007913129639936",
    "1.157920892373162e+77", "1.1579208923731621e+77", "0x1p-256", "0x1p-257", "8e-78",
    "0x1p-1074", "4e-324", "0x1p-1075", "2e-324", "1e-400", "1e308", "1e309", "-0", "inf", "nan",
    "10000000", "10000001", "9223372036854775807", "9223372036854775808", "-1", "0"};

/// A byte between tokens: space, tab, CR or LF.
inline bool token_gap(std::uint8_t c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

/// For one mutation in four (drawn from seed, libFuzzer's own, by std::minstd_rand: the same seed, the same choice):
/// one whole token of data[0, size) (a run of bytes other than token_gap), drawn from seed, replaced in place by an
/// edge value, drawn from seed; returns the new size. Returns 0, data untouched, for the other three, for a text with
/// no token, and where the new text would be longer than max_size.
inline std::size_t replace_token(std::uint8_t* data, std::size_t size, std::size_t max_size, unsigned int seed) {
    std::minstd_rand draw(seed);
    if (draw() % 4 != 0) return 0;
    const auto starts_token = [&](std::size_t i) { return !token_gap(data[i]) && (i == 0 || token_gap(data[i - 1])); };
    std::size_t tokens = 0;
    for (std::size_t i = 0; i < size; ++i) tokens += starts_token(i) ? 1u : 0u;
    if (tokens == 0) return 0;
    // The chosen token [begin, end), and its replacement.
    std::size_t pick = draw() % tokens, begin = 0;
    for (std::size_t i = 0; i < size; ++i)
        if (starts_token(i) && pick-- == 0) {
            begin = i;
            break;
        }
    std::size_t end = begin;
    while (end < size && !token_gap(data[end])) ++end;
    const std::string_view edge = k_edge_tokens[draw() % k_edge_tokens.size()];
    const std::size_t new_size = size - (end - begin) + edge.size();
    if (new_size > max_size) return 0;
    std::memmove(data + begin + edge.size(), data + end, size - end);
    std::memcpy(data + begin, edge.data(), edge.size());
    return new_size;
}

}  // namespace ricochet::fuzz
