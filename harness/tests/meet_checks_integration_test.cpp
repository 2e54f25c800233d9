// The checks of balls that meet on runs the World makes: robust and exact keep every check through head-on meets,
// masses, a Newton's cradle and a box of 10^3 discs; lecture-double lets two fast balls pass through each other, and
// pass-through says so.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ricochet/checks.hpp"

namespace ricochet {
namespace {

/// A square box of walls, side 2·half, about the origin.
std::vector<Wall> box(double half) {
    return {{{-half, -half}, {half, -half}}, {{half, -half}, {half, half}}, {{half, half}, {-half, half}},
            {{-half, half}, {-half, -half}}};
}

Scene colliding(std::vector<Ball> balls) {
    Scene s;
    s.balls_collide = true;
    s.walls = box(100);
    s.balls = std::move(balls);
    return s;
}

std::vector<Check> every_check() { return {k_all_checks.begin(), k_all_checks.end()}; }

std::vector<Event> meets_of(const CheckedRun& run) {
    std::vector<Event> out;
    for (const Event& e : run.events)
        if (e.kind == Event::Kind::meet) out.push_back(e);
    return out;
}

TEST(MeetChecksOnRuns, AHeadOnMeetKeepsEveryCheck) {
    // Equal discs 10 apart closing at 10 a frame meet at t = 0.8, 2 apart, and exchange their velocities.
    const Scene s = colliding({{{0, 0}, {5, 0}, 1}, {{10, 0}, {-5, 0}, 1}});
    for (KernelId k : {KernelId::robust, KernelId::exact}) {
        const CheckedRun run = run_checked(s, k, 4, every_check());
        EXPECT_FALSE(run.failure) << run.failure->str();
        const std::vector<Event> meets = meets_of(run);
        ASSERT_EQ(meets.size(), 2u);
        EXPECT_EQ(meets[0].frame, 1);
        EXPECT_EQ(meets[0].vel, (Vec2{-5, 0}));
        EXPECT_EQ(meets[1].vel, (Vec2{5, 0}));
    }
}

TEST(MeetChecksOnRuns, MassesAndACradleKeepEveryCheck) {
    // 1 against 3 at rest: the light one comes back at half its speed.
    Scene heavy = colliding({{{0, 0}, {4, 0}, 1}, {{6, 0}, {0, 0}, 1}});
    heavy.masses = {1, 3};
    const CheckedRun run = run_checked(heavy, KernelId::robust, 4, every_check());
    EXPECT_FALSE(run.failure) << run.failure->str();
    EXPECT_FALSE(meets_of(run).empty());
    // Three touching discs, the first moving in: the momentum runs down the line within one time.
    const Scene cradle = colliding({{{-10, 0}, {5, 0}, 1}, {{0, 0}, {}, 1}, {{2, 0}, {}, 1}, {{4, 0}, {}, 1}});
    const CheckedRun line = run_checked(cradle, KernelId::robust, 6, every_check());
    EXPECT_FALSE(line.failure) << line.failure->str();
}

TEST(MeetChecksOnRuns, BallsThatMetAreLeftToTheNewChecks) {
    // speed, oracle and accuracy step each ball again alone: a ball that met would fail them; it is not judged there.
    const Scene s = colliding({{{0, 0}, {5, 0}, 1}, {{10, 0}, {-5, 0}, 1}, {{50, 50}, {3, 1}, 0}});
    const std::vector<Check> traced = {Check::speed, Check::oracle, Check::accuracy, Check::momentum};
    const CheckedRun run = run_checked(s, KernelId::robust, 3, traced);
    EXPECT_FALSE(run.failure) << run.failure->str();
}

TEST(MeetChecksOnRuns, TheLectureKernelLetsFastBallsPassThroughEachOther) {
    // 20 a frame each way, 10 apart: at the frame's end 30 apart on the other sides, never overlapping there.
    const Scene s = colliding({{{0, 0}, {20, 0}, 1}, {{10, 0}, {-20, 0}, 1}});
    const std::vector<Check> checks = {Check::ball_overlap, Check::pass_through};
    const CheckedRun run = run_checked(s, KernelId::lecture_double, 1, checks);
    ASSERT_TRUE(run.failure);
    EXPECT_EQ(run.failure->check, Check::pass_through);
    EXPECT_EQ(run.failure->frame, 1);
    EXPECT_EQ(run.failure->ball, 0u);
    // Robust meets them.
    EXPECT_FALSE(run_checked(s, KernelId::robust, 1, checks).failure);
}

TEST(MeetChecksOnRuns, AThousandDiscsInABox) {
    // 32 × 32 discs of radius 0.25 on a grid 1 apart, each moving its own way: every pair judged through the sort.
    std::vector<Ball> balls;
    for (int i = 0; i < 32; ++i)
        for (int j = 0; j < 32; ++j)
            balls.push_back({{i - 16.0, j - 16.0}, {std::sin(i * 7.0 + j) * 0.75, std::cos(i + j * 5.0) * 0.75}, 0.25});
    Scene s = colliding(balls);
    s.walls = box(20);
    const std::vector<Check> checks = {Check::ball_overlap, Check::pass_through, Check::momentum, Check::event_order,
                                       Check::no_tunnel, Check::penetration};
    const CheckedRun run = run_checked(s, KernelId::robust, 8, checks);
    EXPECT_FALSE(run.failure) << run.failure->str();
    EXPECT_FALSE(meets_of(run).empty());
}

}  // namespace
}  // namespace ricochet
