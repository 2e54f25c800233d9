// A plug-in kernel for the check-failure tests: every function forwards to Mutant::ops, a copy of a
// built-in kernel's table in which a test replaces one function with a wrong one (a Mutation). It is
// registered once per process, so any number of tests each break one invariant with one registry entry.
#pragma once

#include <gtest/gtest.h>

#include <optional>
#include <string_view>
#include <span>
#include <vector>

#include "ricochet/checks.hpp"
#include "ricochet/format.hpp"
#include "ricochet/kernel.hpp"
#include "ricochet/step_trace.hpp"

namespace ricochet::mutant {

/// The registered kernel "mutant": the functions of Mutant::ops (its speed bound is robust's), discs and
/// bumpers included.
struct Mutant {
    static inline KernelOps ops = kernel_ops(KernelId::robust);
    static Side classify(Vec2 p, const Wall& w) { return ops.classify(p, w); }
    static bool point_in_circle(Vec2 p, const Circle& c) { return ops.point_in_circle(p, c); }
    static bool circles_overlap(const Circle& a, const Circle& b) { return ops.circles_overlap(a, b); }
    static bool point_in_rect(Vec2 p, const Rect& r) { return ops.point_in_rect(p, r); }
    static bool rects_overlap(const Rect& a, const Rect& b) { return ops.rects_overlap(a, b); }
    static Sweep sweep(Vec2 bs, Vec2 v, const Wall& w) { return ops.sweep(bs, v, w); }
    static Vec2 reflect(Vec2 v, const Wall& w) { return ops.reflect(v, w); }
    static FrameStatus step_ball(Ball& ball, BallMemory& memory, std::span<const Wall> walls,
                                 std::vector<HitEvent>& hits, StepScratch& scratch, const WallIndex* index) {
        return ops.step_ball(ball, memory, walls, hits, scratch, index);
    }
    static constexpr bool k_steps_bumpers = true;
    static FrameStatus step_disc(Ball& ball, BallMemory& memory, const Obstacles& obstacles,
                                 std::vector<HitEvent>& hits, StepScratch& scratch) {
        return ops.step_disc(ball, memory, obstacles, hits, scratch);
    }
};

/// The mutant's id (registered on first use).
inline KernelId id() {
    static const KernelId k = *register_kernel(make_kernel_ops<Mutant>("mutant"));
    return k;
}

/// robust's table, for a wrong function to start from.
inline const KernelOps& robust() { return kernel_ops(KernelId::robust); }

/// For one test: the mutant is base (robust by default) with the functions the test replaces in ops.
class Mutation {
public:
    explicit Mutation(KernelId base = KernelId::robust) { Mutant::ops = kernel_ops(base); }
    ~Mutation() { Mutant::ops = robust(); }
    Mutation(const Mutation&) = delete;
    Mutation& operator=(const Mutation&) = delete;
    KernelOps& ops = Mutant::ops;
};

/// The first failure of checks over frames of scene under kernel (the mutant by default).
inline std::optional<CheckFailure> first_failure(const Scene& scene, std::int64_t frames, std::vector<Check> checks,
                                                 KernelId kernel = id()) {
    return run_checked(scene, kernel, frames, checks).failure;
}

/// f is a failure of check c at frame and ball whose message contains text.
inline void expect_failure(const std::optional<CheckFailure>& f, Check c, std::int64_t frame, std::uint32_t ball,
                           std::string_view text) {
    ASSERT_TRUE(f) << "expected " << check_name(c) << " to fail";
    EXPECT_EQ(check_name(f->check), check_name(c)) << f->str();
    EXPECT_EQ(f->frame, frame) << f->str();
    EXPECT_EQ(f->ball, ball) << f->str();
    EXPECT_NE(f->message.find(text), std::string::npos) << f->str();
}

/// A scene of walls and balls (and static shapes).
inline Scene scene(std::vector<Wall> walls, std::vector<Ball> balls, std::vector<Circle> circles = {},
                   std::vector<Rect> rects = {}) {
    Scene s;
    s.walls = std::move(walls);
    s.balls = std::move(balls);
    s.circles = std::move(circles);
    s.rects = std::move(rects);
    return s;
}

// The parameters of a step_ball, for the wrapping lambdas of the tests, and robust's step on them.
#define STEP_PARAMS                                                                                          \
    Ball &b, BallMemory &mem, std::span<const Wall> walls, std::vector<HitEvent> &hits, StepScratch &scratch, \
        const WallIndex *index
#define STEP_ROBUST ::ricochet::mutant::robust().step_ball(b, mem, walls, hits, scratch, index)

inline const Wall k_wall{{5, -1}, {5, 1}};   ///< the segment x = 5, −1 ≤ y ≤ 1
inline const Ball k_hitter{{1, 0}, {8, 0}};  ///< (1, 0) → (9, 0) hits k_wall at t = 0.5, (5, 0)

}  // namespace ricochet::mutant
