// The kernel registry, the one place a kernel's name or id maps to its code, and the free functions
// that dispatch through it.
#include "ricochet/kernel.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include <fmt/format.h>

#include "kernels/exact/exact_kernel.hpp"
#include "kernels/lecture/lecture_kernel.hpp"
#include "kernels/robust/robust_kernel.hpp"

namespace ricochet {
namespace {

/// The registry, Box2D's s_registers for kernels: entry i is KernelId{i}. Constant-initialized, so a
/// static initializer elsewhere may already parse a kernel name.
constinit std::array<KernelOps, k_max_kernels> s_kernels = {
    make_kernel_ops<LectureKernel<float>>("lecture-float"),
    make_kernel_ops<LectureKernel<double>>("lecture-double"),
    make_kernel_ops<RobustKernel>("robust"),
    make_kernel_ops<ExactKernel>("exact"),
};
/// The ids of the registered kernels, 0 … s_count − 1.
constinit std::array<KernelId, k_max_kernels> s_ids = {KernelId{0}, KernelId{1}, KernelId{2}, KernelId{3}};
constinit std::size_t s_count = k_all_kernels.size();

// k_all_kernels names the built-in entries above, in order.
static_assert(k_all_kernels.size() == 4 && k_all_kernels[0] == KernelId{0} && k_all_kernels[1] == KernelId{1} &&
              k_all_kernels[2] == KernelId{2} && k_all_kernels[3] == KernelId{3});

bool registered(KernelId k) { return static_cast<std::size_t>(k) < s_count; }

/// The names this build knows but lacks, with why (note_absent_kernel): entries 0 … s_absent_count − 1.
struct Absent {
    std::string_view name;
    std::string_view why;
};
constinit std::array<Absent, k_max_kernels> s_absent{};
constinit std::size_t s_absent_count = 0;

}  // namespace

std::optional<KernelId> register_kernel(const KernelOps& ops) {
    if (s_count == k_max_kernels || parse_kernel(ops.name)) return std::nullopt;
    const auto id = static_cast<KernelId>(s_count);
    s_kernels[s_count] = ops;
    s_ids[s_count] = id;
    ++s_count;
    return id;
}

bool note_absent_kernel(std::string_view name, std::string_view why) {
    if (s_absent_count == k_max_kernels || parse_kernel(name) || absent_kernel_message(name)) return false;
    s_absent[s_absent_count++] = {name, why};
    return true;
}

std::optional<std::string> absent_kernel_message(std::string_view name) {
    for (std::size_t i = 0; i < s_absent_count; ++i)
        if (s_absent[i].name == name)
            return fmt::format("kernel '{}' is not built into this ricochet: {}", name, s_absent[i].why);
    return std::nullopt;
}

const KernelOps& kernel_ops(KernelId k) {
    assert(registered(k));
    return s_kernels[static_cast<std::size_t>(k)];
}

std::span<const KernelId> registered_kernels() { return {s_ids.data(), s_count}; }

std::string_view kernel_name(KernelId k) { return registered(k) ? kernel_ops(k).name : "?"; }

std::optional<KernelId> parse_kernel(std::string_view name) {
    for (KernelId k : registered_kernels())
        if (kernel_ops(k).name == name) return k;
    return std::nullopt;
}

std::string kernel_names() {
    std::string out;
    for (KernelId k : registered_kernels()) {
        if (!out.empty()) out += ", ";
        out += kernel_ops(k).name;
    }
    return out;
}

std::string_view miss_name(Miss m) {
    switch (m) {
        case Miss::none: return "hit";
        case Miss::both_inside: return "both-inside";
        case Miss::both_outside: return "both-outside";
        case Miss::parallel: return "parallel";
        case Miss::before_p0: return "before-p0";
        case Miss::past_p1: return "past-p1";
        case Miss::degenerate: return "degenerate";
        case Miss::leaving: return "leaving";
        case Miss::no_reason: return "miss";
    }
    return "?";
}

Side classify(KernelId k, Vec2 p, const Wall& w) { return kernel_ops(k).classify(p, w); }
bool point_in_circle(KernelId k, Vec2 p, const Circle& c) { return kernel_ops(k).point_in_circle(p, c); }
bool circles_overlap(KernelId k, const Circle& a, const Circle& b) { return kernel_ops(k).circles_overlap(a, b); }
bool point_in_rect(KernelId k, Vec2 p, const Rect& r) { return kernel_ops(k).point_in_rect(p, r); }
bool rects_overlap(KernelId k, const Rect& a, const Rect& b) { return kernel_ops(k).rects_overlap(a, b); }
Sweep sweep(KernelId k, Vec2 bs, Vec2 v, const Wall& w) { return kernel_ops(k).sweep(bs, v, w); }
Vec2 reflect(KernelId k, Vec2 v, const Wall& w) { return kernel_ops(k).reflect(v, w); }

std::optional<std::string> unsupported_scene(KernelId k, std::span<const Ball> balls, std::size_t bumpers) {
    const KernelOps& ops = kernel_ops(k);
    for (std::size_t i = 0; i < balls.size(); ++i)
        if (is_disc(balls[i]) && ops.step_disc == nullptr)
            return fmt::format("kernel '{}' steps point balls only: ball {} has radius {}", ops.name, i, balls[i].r);
    if (bumpers > 0 && !ops.steps_bumpers)
        return fmt::format("kernel '{}' does not step bumpers: the scene has {} (bumper 0 first)", ops.name, bumpers);
    return std::nullopt;
}

std::optional<std::string> unsupported_scene(KernelId k, std::span<const Ball> balls, std::size_t bumpers,
                                             bool balls_meet) {
    const KernelOps& ops = kernel_ops(k);
    if (balls_meet && (ops.meet_rule == MeetRule::none || ops.step_disc == nullptr))
        return fmt::format("kernel '{}' does not step balls that meet ('balls collide')", ops.name);
    return unsupported_scene(k, balls, bumpers);
}

namespace {

/// One frame of ball by step, on copies, so that a frame which leaves the range changes nothing.
template <class Step>
FrameStatus step_in_range(Ball& ball, BallMemory& memory, std::vector<HitEvent>& hits, Step&& step) {
    const auto ok = [](const Ball& b) {
        return in_range(b.pos.x) && in_range(b.pos.y) && in_range(b.vel.x) && in_range(b.vel.y);
    };
    if (!ok(ball)) return FrameStatus::out_of_range;
    Ball next = ball;
    BallMemory next_memory = memory;
    const std::size_t first_hit = hits.size();
    const FrameStatus status = step(next, next_memory);
    if (!ok(next)) {
        hits.resize(first_hit);
        return FrameStatus::out_of_range;
    }
    // A kernel writes the state back as {pos, vel}: the radius is the ball's, not the kernel's.
    next.r = ball.r;
    ball = next;
    memory = next_memory;
    return status;
}

}  // namespace

FrameStatus step_ball(KernelId k, Ball& ball, BallMemory& memory, std::span<const Wall> walls,
                      std::vector<HitEvent>& hits, StepScratch& scratch, const WallIndex* index) {
    return step_in_range(ball, memory, hits, [&](Ball& b, BallMemory& m) {
        return kernel_ops(k).step_ball(b, m, walls, hits, scratch, index);
    });
}

FrameStatus step_ball(KernelId k, Ball& ball, BallMemory& memory, const Obstacles& obstacles,
                      std::vector<HitEvent>& hits, StepScratch& scratch) {
    // A point ball among walls alone: the point kernels' own step, bit for bit as before radii existed. Balls
    // that meet are all stepped by the disc frame, whose paths the meets are searched on.
    if (!is_disc(ball) && obstacles.bumpers.empty() && !obstacles.balls_meet)
        return step_ball(k, ball, memory, obstacles.walls, hits, scratch, obstacles.index);
    if (auto why = unsupported_scene(k, std::span<const Ball>(&ball, 1), obstacles.bumpers.size()))
        throw UnsupportedScene(*why);
    return step_in_range(ball, memory, hits, [&](Ball& b, BallMemory& m) {
        return kernel_ops(k).step_disc(b, m, obstacles, hits, scratch);
    });
}

}  // namespace ricochet
