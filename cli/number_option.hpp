// Validators for numeric options that say what was wrong: not a number at all, or a number out of
// range, each with the range expected ("--frames: 'abc' is not a frame count (expected 0 to 10000000)"),
// instead of CLI11's "not in range" with a 309-digit bound.
#pragma once

#include <CLI/CLI.hpp>

#include <charconv>
#include <string>

#include <fmt/format.h>

namespace ricochet::cli {

/// Accepts a value of T (decimal, nothing after it) from lo to hi inclusive; what names the quantity.
template <class T>
CLI::Validator number_in(T lo, T hi, std::string what) {
    const std::string range = fmt::format("{} to {}", lo, hi);
    return CLI::Validator(
        [lo, hi, what, range](std::string& input) -> std::string {
            T v{};
            const char* end = input.data() + input.size();
            const auto [ptr, ec] = std::from_chars(input.data(), end, v);
            if (ec == std::errc::result_out_of_range)
                return fmt::format("'{}' is out of range (expected {} from {})", input, what, range);
            if (ec != std::errc() || ptr != end || input.empty())
                return fmt::format("'{}' is not {} (expected {})", input, what, range);
            if (!(lo <= v && v <= hi)) return fmt::format("'{}' is out of range (expected {} from {})", input, what, range);
            return {};
        },
        range);
}

}  // namespace ricochet::cli
