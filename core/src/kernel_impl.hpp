// Internal: the robust and exact kernels' entry points, dispatched to by kernel.cpp.
#pragma once

#include "ricochet/kernel.hpp"

namespace ricochet::robust {
Side classify(Vec2 p, const Wall& w);
bool point_in_circle(Vec2 p, const Circle& c);
bool circles_overlap(const Circle& a, const Circle& b);
Sweep sweep(Vec2 bs, Vec2 v, const Wall& w);
Vec2 reflect(Vec2 v, const Wall& w);
FrameStatus step_ball(Ball& ball, BallMemory& memory, std::span<const Wall> walls, std::vector<HitEvent>& hits,
                      StepScratch& scratch, const WallIndex* index);
}  // namespace ricochet::robust

namespace ricochet::exact_kernel {
Side classify(Vec2 p, const Wall& w);
bool point_in_circle(Vec2 p, const Circle& c);
bool circles_overlap(const Circle& a, const Circle& b);
Sweep sweep(Vec2 bs, Vec2 v, const Wall& w);
Vec2 reflect(Vec2 v, const Wall& w);
FrameStatus step_ball(Ball& ball, BallMemory& memory, std::span<const Wall> walls, std::vector<HitEvent>& hits,
                      StepScratch& scratch);
}  // namespace ricochet::exact_kernel
