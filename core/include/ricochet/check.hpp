// Check: the invariants a scene log can ask replay to assert on every frame, and their names.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace ricochet {

/// An invariant that replay asserts on every frame (scene-log `check NAME`; checks.hpp defines each).
enum class Check : std::uint8_t { no_tunnel, symmetry, boundary, speed, deterministic, oracle };
/// The check's name as logs spell it ("no-tunnel", …).
std::string_view check_name(Check c);
/// The check called name, or nothing.
std::optional<Check> parse_check(std::string_view name);

}  // namespace ricochet
