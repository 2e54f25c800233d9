// Internal: a disc's frame with exact decisions (contact.hpp), written once for the two kernels that decide
// exactly, robust and exact, which differ only in how they round their constructions: the contact point on
// the leg and the reflected velocity. The frame, the ties, the corner rule and the walk back that keeps every
// printed piece clear are the ones robust_disc.cpp documents.
#pragma once

#include <vector>

#include "contact.hpp"
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

/// One frame of a disc (or of a point ball in a scene with bumpers) among the obstacles: every decision exact,
/// the constructions from make, every rounded contact point walked back until the piece to it keeps the disc
/// clear (robust_disc.cpp).
FrameStatus step_frame(Ball& ball, const Obstacles& obstacles, std::vector<HitEvent>& hits, StepScratch& scratch,
                       const Constructions& make);

}  // namespace ricochet::disc
