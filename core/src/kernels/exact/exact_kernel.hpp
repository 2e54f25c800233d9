// Internal: the exact kernel as a Kernel type (kernel.hpp), for the registry (registry.cpp).
#pragma once

#include "kernels/meet/response.hpp"
#include "kernels/rect_tests.hpp"
#include "ricochet/kernel.hpp"

namespace ricochet::exact_kernel {
Side classify(Vec2 p, const Wall& w);
bool point_in_circle(Vec2 p, const Circle& c);
bool circles_overlap(const Circle& a, const Circle& b);
Sweep sweep(Vec2 bs, Vec2 v, const Wall& w);
Vec2 reflect(Vec2 v, const Wall& w);
FrameStatus step_ball(Ball& ball, BallMemory& memory, std::span<const Wall> walls, std::vector<HitEvent>& hits,
                      StepScratch& scratch);
}  // namespace ricochet::exact_kernel

namespace ricochet {

/// The exact kernel (exact_kernel.cpp, GMP rationals) as a Kernel type.
struct ExactKernel {
    static Side classify(Vec2 p, const Wall& w) { return exact_kernel::classify(p, w); }
    static bool point_in_circle(Vec2 p, const Circle& c) { return exact_kernel::point_in_circle(p, c); }
    static bool circles_overlap(const Circle& a, const Circle& b) { return exact_kernel::circles_overlap(a, b); }
    /// Comparisons of doubles are exact: exact shares the rectangle tests of every kernel.
    static bool point_in_rect(Vec2 p, const Rect& r) { return point_in_rect_in<double>(p, r); }
    /// Comparisons of doubles are exact: exact shares the rectangle tests of every kernel.
    static bool rects_overlap(const Rect& a, const Rect& b) { return rects_overlap_in<double>(a, b); }
    static Sweep sweep(Vec2 bs, Vec2 v, const Wall& w) { return exact_kernel::sweep(bs, v, w); }
    static Vec2 reflect(Vec2 v, const Wall& w) { return exact_kernel::reflect(v, w); }
    /// The index is ignored on purpose: the oracle tries every wall, so no broad phase can hide a hit from it.
    static FrameStatus step_ball(Ball& ball, BallMemory& memory, std::span<const Wall> walls,
                                 std::vector<HitEvent>& hits, StepScratch& scratch, const WallIndex* /*index*/) {
        return exact_kernel::step_ball(ball, memory, walls, hits, scratch);
    }
    /// A disc among walls and bumpers, or a point ball in a scene with bumpers (exact_disc.cpp): robust's
    /// exact decisions, every construction correctly rounded, then walked back as robust's until clear.
    static FrameStatus step_disc(Ball& ball, BallMemory& memory, const Obstacles& obstacles,
                                 std::vector<HitEvent>& hits, StepScratch& scratch);
    /// step_disc bounces balls off bumpers too.
    static constexpr bool k_steps_bumpers = true;
    /// Balls that meet: in exact time order on their paths (meet.hpp, docs/scene-log.md "Balls that meet").
    static constexpr MeetRule k_meet_rule = MeetRule::swept;
    /// The elastic response at a meet, each component the double nearest its exact value (response.hpp).
    static bool respond(Ball& a, Ball& b, double ma, double mb) { return meet::respond_nearest(a, b, ma, mb); }
};

}  // namespace ricochet
