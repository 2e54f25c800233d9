// Check: the invariants a scene log can ask replay to assert on every frame, and their names.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace ricochet {

/// An invariant that replay asserts on every frame (scene-log `check NAME`; checks.hpp defines each).
/// New checks join at the end, so a value keeps its meaning.
enum class Check : std::uint8_t {
    no_tunnel,
    symmetry,
    boundary,
    speed,
    deterministic,
    oracle,
    swap,
    translation,
    broad_phase,
    round_trip,
    no_escape,
    bounce_side,
    accuracy,
    event_order,
    penetration,
    ghost_bounce,
    plan,
    ball_overlap,  ///< balls that meet: no two balls closer than R_i + R_j once clear
    pass_through,  ///< balls that meet: no two balls pass through each other without a meet
    momentum,      ///< balls that meet: each meet keeps momentum and kinetic energy within the stated bound
    relabel,       ///< balls that meet: renumbering the balls gives the same physics
    jump_through,  ///< balls that meet: no ball's printed jump (two points at one time) passes through another
};
/// Every check, in the order of the enumeration.
inline constexpr std::array<Check, 22> k_all_checks = {
    Check::no_tunnel,    Check::symmetry,    Check::boundary,    Check::speed,       Check::deterministic,
    Check::oracle,       Check::swap,        Check::translation, Check::broad_phase, Check::round_trip,
    Check::no_escape,    Check::bounce_side, Check::accuracy,    Check::event_order, Check::penetration,
    Check::ghost_bounce, Check::plan,        Check::ball_overlap, Check::pass_through, Check::momentum,
    Check::relabel,      Check::jump_through};
/// The check's name as logs spell it ("no-tunnel", …).
std::string_view check_name(Check c);
/// The check called name, or nothing.
std::optional<Check> parse_check(std::string_view name);

}  // namespace ricochet
