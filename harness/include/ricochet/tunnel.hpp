// The no-tunnelling invariant, checked exactly on the printed path (see kernel.hpp for the
// definition). Every decision is an exact predicate on the printed doubles.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "ricochet/shapes.hpp"

namespace ricochet {

/// Follows every ball's printed path and reports the first wall it tunnels through.
class TunnelChecker {
public:
    /// Starts at the balls' initial positions.
    TunnelChecker(std::span<const Wall> walls, std::span<const Ball> balls);
    /// Ball i's path goes on to point next (a hit point or a frame's end). Returns the lowest-indexed
    /// wall the piece tunnels through, or nothing.
    std::optional<std::uint32_t> advance(std::size_t i, Vec2 next);

private:
    struct State {
        std::int8_t last_side = 0;  // side of the last point strictly off the line, 0 if forgotten
        bool touched = false;       // the path reached the closed segment since then
    };
    std::vector<Wall> walls_;
    std::vector<Vec2> at_;
    std::vector<State> state_;  // ball-major: state_[i * walls + w]
};

}  // namespace ricochet
