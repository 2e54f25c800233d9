// The names of the checks.
#include "ricochet/check.hpp"

#include <array>
#include <optional>
#include <string_view>

namespace ricochet {

namespace {
constexpr std::array<Check, 6> k_all_checks = {Check::no_tunnel, Check::symmetry,      Check::boundary,
                                               Check::speed,     Check::deterministic, Check::oracle};
}  // namespace

std::string_view check_name(Check c) {
    switch (c) {
        case Check::no_tunnel: return "no-tunnel";
        case Check::symmetry: return "symmetry";
        case Check::boundary: return "boundary";
        case Check::speed: return "speed";
        case Check::deterministic: return "deterministic";
        case Check::oracle: return "oracle";
    }
    return "?";
}

std::optional<Check> parse_check(std::string_view name) {
    for (Check c : k_all_checks)
        if (check_name(c) == name) return c;
    return std::nullopt;
}

}  // namespace ricochet
