// Classification of generated legs (tag / classify, harness.hpp), shared by the kernel- and scene-level
// properties, so that each run reports which regimes it reached.
#pragma once

#include <cmath>

#include "harness.hpp"
#include "oracle.hpp"
#include "ricochet/kernel.hpp"
#include "ricochet/scene.hpp"

namespace ricochet::props {

/// True if any coordinate of p is 0 < |x| < 2^−1022 (subnormal).
inline bool subnormal(Vec2 p) {
    return std::fpclassify(p.x) == FP_SUBNORMAL || std::fpclassify(p.y) == FP_SUBNORMAL;
}
/// Largest |coordinate| of p.
inline double magnitude(Vec2 p) { return std::fmax(std::fabs(p.x), std::fabs(p.y)); }

/// Tags each scene by what its legs reach: the exact decision of every leg against every wall, Be exactly
/// on a wall's line or within a few ulps of it, exactly parallel velocities, zero-length walls, zero
/// velocities, far and subnormal coordinates.
inline void classify_legs(const Scene& s) {
    bool on_line = false, on_segment = false, at_end = false, parallel = false, zero_wall = false, zero_v = false,
         far = false, tiny = false, starts_on = false, inexact_be = false;
    for (const Wall& w : s.walls) {
        zero_wall |= w.p0 == w.p1;
        far |= magnitude(w.p0) > 1e12;
    }
    for (const Ball& b : s.balls) {
        const Vec2 be = b.pos + b.vel;
        zero_v |= b.vel == Vec2{};
        far |= magnitude(b.pos) > 1e12;
        tiny |= subnormal(b.pos) || subnormal(b.vel);
        inexact_be |= !sum_exact(b.pos.x, b.vel.x) || !sum_exact(b.pos.y, b.vel.y);
        for (const Wall& w : s.walls) {
            if (w.p0 == w.p1) continue;
            tag(miss_name(truth::leg_miss(b.pos, be, w)));
            const bool on = truth::side(be, w) == 0;
            on_line |= on;
            on_segment |= on && truth::on_closed_segment(be, w);
            at_end |= be == w.p0 || be == w.p1;
            starts_on |= truth::side(b.pos, w) == 0;
            parallel |= b.vel != Vec2{} && cross_sign(b.vel, w.p1 - w.p0) == 0;
        }
    }
    classify(on_line, "Be exactly on a wall's line");
    classify(on_segment, "Be exactly on a wall");
    classify(at_end, "Be exactly at a wall's end point");
    classify(starts_on, "Bs exactly on a wall's line");
    classify(parallel, "v exactly parallel to a wall");
    classify(zero_wall, "zero-length wall");
    classify(zero_v, "zero velocity");
    classify(far, "coordinates beyond 1e12");
    classify(tiny, "subnormal coordinates");
    classify(inexact_be, "Bs + v rounded");
}

}  // namespace ricochet::props
