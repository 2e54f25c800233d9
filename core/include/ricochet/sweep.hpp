// Sweep: the answer to one leg of a ball's motion against one wall, hit or the reason it misses.
#pragma once

#include <cstdint>
#include <string_view>

#include "ricochet/vec2.hpp"

namespace ricochet {

/// Why a leg does not hit a wall: the lecture's five tests in order, then the degenerate cases.
enum class Miss : std::uint8_t {
    none,           ///< it hits
    both_inside,    ///< test 1: BC(Bs) < 0 and BC(Be) < 0
    both_outside,   ///< test 2: BC(Bs) > 0 and BC(Be) > 0
    parallel,       ///< test 3: n̂·v = 0
    before_p0,      ///< test 4: the hit point lies before P0
    past_p1,        ///< test 5: the hit point lies past P1
    degenerate,     ///< zero-length wall or zero velocity
    leaving,        ///< Bs is on the wall's line and the ball moves off it
    /// A miss whose reason the kernel does not say (a plug-in's RICOCHET_MISS, plugin.h): the oracle then only
    /// asks whether the wall is hit. No built-in kernel answers it.
    no_reason,
};
/// A short name for a Miss ("hit", "both-inside", …).
std::string_view miss_name(Miss m);

/// The answer to one leg against one wall.
struct Sweep {
    Miss miss = Miss::degenerate;
    double t = 0.0;  ///< t_i in [0, 1] when it hits
    Vec2 point;      ///< B_i when it hits
    /// True if the leg hits the wall.
    bool hit() const { return miss == Miss::none; }
};

}  // namespace ricochet
