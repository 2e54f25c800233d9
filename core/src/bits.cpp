// Bit-for-bit equality of whole scenes (bits.hpp).
#include "ricochet/bits.hpp"

#include <cstddef>

#include "ricochet/scene.hpp"

namespace ricochet {

bool same_bits(const Scene& a, const Scene& b) {
    if (!(a == b)) return false;
    const auto all = [](const auto& x, const auto& y) {
        for (std::size_t i = 0; i < x.size(); ++i)
            if (!same_bits(x[i], y[i])) return false;
        return true;
    };
    if (!all(a.walls, b.walls) || !all(a.balls, b.balls) || !all(a.circles, b.circles) || !all(a.rects, b.rects) ||
        !all(a.bumpers, b.bumpers))
        return false;
    for (std::size_t i = 0; i < a.expect_states.size(); ++i)
        if (!same_bits(a.expect_states[i].state, b.expect_states[i].state)) return false;
    return true;
}

}  // namespace ricochet
