// The names of the checks.
#include "ricochet/check.hpp"

#include <optional>
#include <string_view>

namespace ricochet {

std::string_view check_name(Check c) {
    switch (c) {
        case Check::no_tunnel: return "no-tunnel";
        case Check::symmetry: return "symmetry";
        case Check::boundary: return "boundary";
        case Check::speed: return "speed";
        case Check::deterministic: return "deterministic";
        case Check::oracle: return "oracle";
        case Check::swap: return "swap";
        case Check::translation: return "translation";
        case Check::broad_phase: return "broad-phase";
        case Check::round_trip: return "round-trip";
        case Check::no_escape: return "no-escape";
        case Check::bounce_side: return "bounce-side";
        case Check::accuracy: return "accuracy";
        case Check::event_order: return "event-order";
        case Check::penetration: return "penetration";
        case Check::ghost_bounce: return "ghost-bounce";
        case Check::plan: return "plan";
        case Check::ball_overlap: return "ball-overlap";
        case Check::pass_through: return "pass-through";
        case Check::momentum: return "momentum";
        case Check::relabel: return "relabel";
        case Check::jump_through: return "jump-through";
    }
    return "?";
}

std::optional<Check> parse_check(std::string_view name) {
    for (Check c : k_all_checks)
        if (check_name(c) == name) return c;
    return std::nullopt;
}

}  // namespace ricochet
