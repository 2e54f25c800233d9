// A long closed chain for the reducer: n walls on a circle of radius r around the origin, walked clockwise
// (their outward normals point out of the ring), and a ball inside. The points come from the rational
// parametrisation of the circle, x = r(1 − t²)/(1 + t²), y = 2rt/(1 + t²) with t = k/m, and exact sign flips
// and swaps for the other quadrants: only correctly rounded + − × ÷, so the scene is the same on every
// machine (no libm sine).
#pragma once

#include <cstddef>
#include <vector>

#include "ricochet/scene.hpp"

namespace ricochet::test {

/// The ring of about n walls (a multiple of 8 at least n) under kernel, frames frames, `check no-tunnel`.
inline Scene ring_scene(std::size_t n, KernelId kernel, std::int64_t frames, double r = 100.0) {
    // One eighth of the circle, t = k/m for k = 0..m (angle 0 to 45°: t = tan(θ/2) ≤ tan(22.5°) < 1/2).
    const std::size_t m = (n + 7) / 8;
    std::vector<Vec2> eighth;
    // tan(22.5°) = √2 − 1; the last point is at t with x = y, i.e. 1 − t² = 2t.
    const double t_end = 0.41421356237309503;
    for (std::size_t k = 0; k < m; ++k) {
        const double t = t_end * static_cast<double>(k) / static_cast<double>(m);
        const double d = 1.0 + t * t;
        eighth.push_back({r * (1.0 - t * t) / d, 2.0 * r * t / d});
    }
    // The other seven eighths: (y, x) mirrors across x = y, then quarter turns (x, y) ↦ (−y, x), all exact.
    std::vector<Vec2> quarter = eighth;
    for (std::size_t k = eighth.size(); k-- > 0;) quarter.push_back({eighth[k].y, eighth[k].x});
    std::vector<Vec2> points;
    for (int q = 0; q < 4; ++q)
        for (Vec2& p : quarter) {
            points.push_back(p);
            p = {-p.y, p.x};
        }
    Scene s;
    s.kernel = kernel;
    s.frames = frames;
    // Clockwise (P0 after P1 in angle): the normal (e_y, −e_x) of each wall points away from the centre.
    for (std::size_t i = 0; i < points.size(); ++i) s.walls.push_back({points[(i + 1) % points.size()], points[i]});
    s.balls.push_back({{1.25, 2.5}, {0.37 * r, 0.21 * r}});
    s.checks = {Check::no_tunnel};
    return s;
}

}  // namespace ricochet::test
