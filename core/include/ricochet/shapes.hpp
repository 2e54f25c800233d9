// Shapes: plain value structs, as the lecture draws them.
#pragma once

#include "ricochet/vec2.hpp"

namespace ricochet {

/// A static circle with centre c and radius r ≥ 0: an overlap sensor (`overlap` events), not solid.
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

/// A solid static circle with centre c and radius r ≥ 0 that balls bounce off (scene-log `bumper`).
struct Bumper {
    Vec2 c;
    double r = 0.0;
    friend constexpr bool operator==(const Bumper&, const Bumper&) = default;
};

/// A ball at pos moving vel per frame, B(t) = Bs + v·t, t in [0, 1]: a disc of radius r ≥ 0 centred at pos.
/// r = 0 (or −0) is the lecture's point ball, stepped exactly as before radii existed. A state (a
/// `state` event, an `expect state` line) has no radius: r is 0 there.
struct Ball {
    Vec2 pos;
    Vec2 vel;
    double r = 0.0;
    friend constexpr bool operator==(const Ball&, const Ball&) = default;
};

/// True if the ball has a radius (r > 0): a disc rather than a point.
constexpr bool is_disc(const Ball& b) { return b.r > 0.0; }

}  // namespace ricochet
