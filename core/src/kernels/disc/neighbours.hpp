// The doubles around a point: a rounded point moved by whole ulps, one coordinate at a time, where a construction
// needs the nearest representable point that clears something (a disc's contact point off a wall, a meet's centre off
// another ball, a stop off another ball's path).
#pragma once

#include <cmath>
#include <cstdlib>

#include "ricochet/vec2.hpp"

namespace ricochet {

/// x moved n doubles up (n > 0) or down (n < 0).
inline double ulps_from(double x, int n) {
    for (; n > 0; --n) x = std::nextafter(x, HUGE_VAL);
    for (; n < 0; ++n) x = std::nextafter(x, -HUGE_VAL);
    return x;
}

/// Calls f(c) for every finite point c whose coordinates lie i and j doubles from x's, max(|i|, |j|) = r (r ≥ 1: the
/// ring r ulps out; r = 1 is the eight neighbouring doubles), i then j ascending.
template <class F>
void for_each_on_ring(Vec2 x, int r, F&& f) {
    for (int i = -r; i <= r; ++i)
        for (int j = -r; j <= r; ++j) {
            if (std::max(std::abs(i), std::abs(j)) != r) continue;
            const Vec2 c{ulps_from(x.x, i), ulps_from(x.y, j)};
            if (std::isfinite(c.x) && std::isfinite(c.y)) f(c);
        }
}

}  // namespace ricochet
