// Shapes: plain value structs, as the lecture draws them.
#pragma once

#include "ricochet/vec2.hpp"

namespace ricochet {

/// A static circle (a bumper) with centre c and radius r ≥ 0.
struct Circle {
    Vec2 c;
    double r = 0.0;
    friend constexpr bool operator==(const Circle&, const Circle&) = default;
};

/// An axis-aligned rectangle, y up: left ≤ right, bottom ≤ top.
struct Rect {
    double left = 0.0;
    double bottom = 0.0;
    double right = 0.0;
    double top = 0.0;
    friend constexpr bool operator==(const Rect&, const Rect&) = default;
};

/// A two-sided wall: the directed segment p0 → p1. Its outward normal (e_y, −e_x) points to the
/// right of p0 → p1.
struct Wall {
    Vec2 p0;
    Vec2 p1;
    friend constexpr bool operator==(const Wall&, const Wall&) = default;
};

/// A point ball at pos moving vel per frame: B(t) = Bs + v·t, t in [0, 1].
struct Ball {
    Vec2 pos;
    Vec2 vel;
    friend constexpr bool operator==(const Ball&, const Ball&) = default;
};

}  // namespace ricochet
