// Internal: the robust and exact kernels as Kernel types (kernel.hpp), for the registry in kernel.cpp.
#pragma once

#include "kernel_lecture.hpp"
#include "ricochet/kernel.hpp"

namespace ricochet {

/// The robust kernel (kernel_robust.cpp): exact decisions, rounded constructions never accepted across a wall.
struct RobustKernel {
    static Side classify(Vec2 p, const Wall& w);
    static bool point_in_circle(Vec2 p, const Circle& c);
    static bool circles_overlap(const Circle& a, const Circle& b);
    /// Comparisons of doubles are exact: robust shares lecture-double's rectangle tests.
    static bool point_in_rect(Vec2 p, const Rect& r) { return LectureKernel<double>::point_in_rect(p, r); }
    /// Comparisons of doubles are exact: robust shares lecture-double's rectangle tests.
    static bool rects_overlap(const Rect& a, const Rect& b) { return LectureKernel<double>::rects_overlap(a, b); }
    static Sweep sweep(Vec2 bs, Vec2 v, const Wall& w);
    static Vec2 reflect(Vec2 v, const Wall& w);
    static FrameStatus step_ball(Ball& ball, BallMemory& memory, std::span<const Wall> walls,
                                 std::vector<HitEvent>& hits, StepScratch& scratch, const WallIndex* index);
    /// A disc among walls and bumpers, or a point ball in a scene with bumpers (disc/robust_disc.cpp): exact
    /// contacts (disc/contact.hpp), rounded points walked back until the piece to them stays clear of every wall.
    static FrameStatus step_disc(Ball& ball, BallMemory& memory, const Obstacles& obstacles,
                                 std::vector<HitEvent>& hits, StepScratch& scratch);
    /// step_disc bounces balls off bumpers too.
    static constexpr bool k_steps_bumpers = true;
};

/// v reflected about the direction n ≠ 0: v − 2(v·n̂)n̂, robust's reflection (the speed bound of limits.hpp).
Vec2 reflect_about(Vec2 v, Vec2 n);

}  // namespace ricochet

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

/// The exact kernel (kernel_exact.cpp, GMP rationals) as a Kernel type.
struct ExactKernel {
    static Side classify(Vec2 p, const Wall& w) { return exact_kernel::classify(p, w); }
    static bool point_in_circle(Vec2 p, const Circle& c) { return exact_kernel::point_in_circle(p, c); }
    static bool circles_overlap(const Circle& a, const Circle& b) { return exact_kernel::circles_overlap(a, b); }
    /// Comparisons of doubles are exact: exact shares lecture-double's rectangle tests.
    static bool point_in_rect(Vec2 p, const Rect& r) { return LectureKernel<double>::point_in_rect(p, r); }
    /// Comparisons of doubles are exact: exact shares lecture-double's rectangle tests.
    static bool rects_overlap(const Rect& a, const Rect& b) { return LectureKernel<double>::rects_overlap(a, b); }
    static Sweep sweep(Vec2 bs, Vec2 v, const Wall& w) { return exact_kernel::sweep(bs, v, w); }
    static Vec2 reflect(Vec2 v, const Wall& w) { return exact_kernel::reflect(v, w); }
    /// The index is ignored on purpose: the oracle tries every wall, so no broad phase can hide a hit from it.
    static FrameStatus step_ball(Ball& ball, BallMemory& memory, std::span<const Wall> walls,
                                 std::vector<HitEvent>& hits, StepScratch& scratch, const WallIndex* /*index*/) {
        return exact_kernel::step_ball(ball, memory, walls, hits, scratch);
    }
    /// A disc among walls and bumpers, or a point ball in a scene with bumpers (disc/exact_disc.cpp): robust's
    /// exact decisions, every construction correctly rounded, then walked back as robust's until clear.
    static FrameStatus step_disc(Ball& ball, BallMemory& memory, const Obstacles& obstacles,
                                 std::vector<HitEvent>& hits, StepScratch& scratch);
    /// step_disc bounces balls off bumpers too.
    static constexpr bool k_steps_bumpers = true;
};

}  // namespace ricochet
