// Internal: a disc's frame with exact decisions (contact.hpp), written once for the two kernels that decide
// exactly, robust and exact, which differ only in how they round their constructions: the contact point on
// the leg and the reflected velocity. The frame, the ties, the corner rule and the walk back that keeps every
// printed piece clear are documented in frame.cpp.
#pragma once

#include <vector>

#include "kernels/disc/contact.hpp"
#include "ricochet/kernel.hpp"

namespace ricochet::disc {

/// The rounded numbers a frame builds.
struct Constructions {
    /// A contact's leg fraction t in [0, 1] and its point on the leg q → b, each rounded to a double.
    struct Point {
        double t = 0.0;
        Vec2 x;
    };
    /// Where contact c on obstacle o lies on the leg (never at_start: the frame takes q itself then).
    Point (*contact_point)(const Leg& leg, const Obstacle& o, const Contact& c) = nullptr;
    /// v reflected about obstacle o's outward normal at the printed point x (normal_at's part).
    Vec2 (*reflect)(Vec2 v, Vec2 x, const Obstacle& o) = nullptr;
};

/// The correctly rounded contact point (nearest.cpp), the exact kernel's: t and each coordinate of B_i the doubles
/// nearest their exact values. Robust takes it where its own double construction is ill-conditioned.
Constructions::Point nearest_contact_point(const Leg& leg, const Obstacle& o, const Contact& c);

/// The correctly rounded bounce (nearest.cpp), the exact kernel's: v reflected about the exact outward normal at x,
/// each coordinate the nearest double. Robust takes it where its own reflection in doubles still goes into the
/// obstacle.
Vec2 nearest_reflection(Vec2 v, Vec2 x, const Obstacle& o);

/// x, or the first point on the way back towards q whose printed piece from q keeps a ball of radius R clear (the
/// clearance rule of frame.cpp; q itself at worst): 1, 2, 4, … ulps of the piece's largest coordinate, x's
/// neighbours, then half the piece, then q. A meet's rounded centre is placed by it too (meet.hpp).
Vec2 walk_back(Vec2 q, Vec2 x, double R, const Obstacles& obstacles, StepScratch& scratch);

/// One frame of a disc (or of a point ball in a scene with bumpers) among the obstacles: every decision exact,
/// the constructions from make, every rounded contact point walked back until the piece to it keeps the disc
/// clear (frame.cpp).
FrameStatus step_frame(Ball& ball, const Obstacles& obstacles, std::vector<HitEvent>& hits, StepScratch& scratch,
                       const Constructions& make);

}  // namespace ricochet::disc
