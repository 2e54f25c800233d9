// Ball memory: what a kernel remembers of a ball between frames (the walls it lies on, the wall it
// last bounced off), so that a printed path never tunnels.
#pragma once

#include <array>
#include <cstdint>

namespace ricochet {

/// A wall the ball is lying on, and the side it arrived from (±1).
struct Contact {
    std::uint32_t wall = 0;
    std::int8_t side = 0;
};
/// What a kernel remembers of a ball between frames: the walls it lies on and where it came from.
struct BallMemory {
    std::array<Contact, 4> contacts{};
    std::uint8_t count = 0;
    /// The last wall bounced off and the side (±1) it was met from; 0: none yet. Moving straight on
    /// from a bounce the ball stays in that side's half-plane, so until its next bounce no printed point
    /// may lie on that wall's far side, even beyond the wall's ends.
    std::int8_t bounced_from = 0;
    std::uint32_t bounced_wall = 0;
};

}  // namespace ricochet
