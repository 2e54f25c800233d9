// Internal: the robust kernel as a Kernel type (kernel.hpp), for the registry (registry.cpp) and for the plug-in
// kernels, which fall back on it for what a plug-in leaves out (plugin/plugin_kernel.cpp).
#pragma once

#include "kernels/meet/response.hpp"
#include "kernels/rect_tests.hpp"
#include "ricochet/kernel.hpp"

namespace ricochet {

/// The robust kernel (robust_kernel.cpp): exact decisions, rounded constructions never accepted across a wall.
struct RobustKernel {
    static Side classify(Vec2 p, const Wall& w);
    static bool point_in_circle(Vec2 p, const Circle& c);
    static bool circles_overlap(const Circle& a, const Circle& b);
    /// Comparisons of doubles are exact: robust shares the rectangle tests of every kernel.
    static bool point_in_rect(Vec2 p, const Rect& r) { return point_in_rect_in<double>(p, r); }
    /// Comparisons of doubles are exact: robust shares the rectangle tests of every kernel.
    static bool rects_overlap(const Rect& a, const Rect& b) { return rects_overlap_in<double>(a, b); }
    static Sweep sweep(Vec2 bs, Vec2 v, const Wall& w);
    static Vec2 reflect(Vec2 v, const Wall& w);
    static FrameStatus step_ball(Ball& ball, BallMemory& memory, std::span<const Wall> walls,
                                 std::vector<HitEvent>& hits, StepScratch& scratch, const WallIndex* index);
    /// A disc among walls and bumpers, or a point ball in a scene with bumpers (robust_disc.cpp): exact
    /// contacts (kernels/disc/contact.hpp), rounded points walked back until the piece to them stays clear of every wall.
    static FrameStatus step_disc(Ball& ball, BallMemory& memory, const Obstacles& obstacles,
                                 std::vector<HitEvent>& hits, StepScratch& scratch);
    /// step_disc bounces balls off bumpers too.
    static constexpr bool k_steps_bumpers = true;
    /// Balls that meet: in exact time order on their paths (meet.hpp, docs/scene-log.md "Balls that meet").
    static constexpr MeetRule k_meet_rule = MeetRule::swept;
    /// The elastic response at a meet, in doubles (response.hpp).
    static bool respond(Ball& a, Ball& b, double ma, double mb) { return meet::respond_rounded(a, b, ma, mb); }
};

/// v reflected about the direction n ≠ 0: v − 2(v·n̂)n̂, robust's reflection (the speed bound of limits.hpp).
Vec2 reflect_about(Vec2 v, Vec2 n);

}  // namespace ricochet
