// The disc checks themselves on paths written by hand (frame_check.hpp), which no sound kernel gives: penetration
// fails on a piece that comes too close, ghost-bounce on a hit only a tangent could make.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "checks/frame_check.hpp"
#include "ricochet/checks.hpp"

namespace ricochet {
namespace {

// The penetration check on paths written by hand (frame_check.hpp): the kernel never gives such a path.
std::string penetration_verdict(const Scene& s, const std::vector<std::vector<Event>>& frames) {
    auto check = checks::make_penetration(s, KernelId::robust, {});
    std::vector<Event> start;
    for (std::uint32_t b = 0; b < s.balls.size(); ++b)
        start.push_back({Event::Kind::state, 0, b, Event::Shape::none, 0, s.balls[b].pos, s.balls[b].vel});
    if (auto r = check->frame({0, start, {}, {}, {}})) return r->message;
    for (std::size_t f = 0; f < frames.size(); ++f)
        if (auto r = check->frame({static_cast<std::int64_t>(f + 1), frames[f], {}, {}, {}})) return r->message;
    return "";
}

Event state(std::int64_t f, Vec2 p) { return {Event::Kind::state, f, 0, Event::Shape::none, 0, p, {}}; }
Event hit(std::int64_t f, Vec2 p) { return {Event::Kind::hit, f, 0, Event::Shape::none, 0, p, {}}; }

TEST(DiscChecks, PenetrationCatchesAPieceTooClose) {
    Scene s;
    s.walls = {{{0, 0}, {10, 0}}};
    s.bumpers = {{{20, 20}, 2}};
    s.balls = {{{5, 3}, {}, 1}};
    // Down to exactly R and back: clear (δ = 0, touching allowed).
    EXPECT_EQ(penetration_verdict(s, {{hit(1, {5, 1}), state(1, {5, 3})}}), "");
    // One ulp closer than R at a hit point.
    EXPECT_NE(penetration_verdict(s, {{hit(1, {5, std::nextafter(1.0, 0.0)}), state(1, {5, 3})}}), "");
    // Both ends clear, the piece between them not: from (8, 2) to (12, −2) it passes through P1 = (10, 0).
    EXPECT_EQ(penetration_verdict(s, {{state(1, {8, 2})}}), "");
    EXPECT_NE(penetration_verdict(s, {{state(1, {8, 2})}, {state(2, {12, -2})}}), "");
    // A bumper: R + r = 3 from (20, 20); 17 is exactly 3 away, 17.5 is not.
    EXPECT_EQ(penetration_verdict(s, {{state(1, {17, 20})}}), "");
    EXPECT_NE(penetration_verdict(s, {{state(1, {17.5, 20})}}), "");
    // Starting overlapping the wall: held to it only once a printed point is clear.
    Scene deep = s;
    deep.balls = {{{5, 0.5}, {}, 1}};
    EXPECT_EQ(penetration_verdict(deep, {{state(1, {5, 0.25})}, {state(2, {5, 1})}}), "");
    EXPECT_NE(penetration_verdict(deep, {{state(1, {5, 1})}, {state(2, {5, 0.75})}}), "");
    // A point ball and a bumper: r from the centre, exactly; a wall holds nothing for it (R = 0).
    Scene point_bumper = s;
    point_bumper.balls = {{{25, 20}, {}, 0}};
    EXPECT_EQ(penetration_verdict(point_bumper, {{state(1, {22, 20})}, {hit(2, {30, 10}), state(2, {6, 10})},
                                                 {state(3, {5, -3})}}),
              "");
    EXPECT_NE(penetration_verdict(point_bumper, {{state(1, {std::nextafter(22.0, 0.0), 20})}}), "");
    EXPECT_NE(penetration_verdict(point_bumper, {{state(1, {22, 22})}, {state(2, {18, 18})}}), "");
    // Point balls among walls alone: nothing to hold.
    Scene point = s;
    point.bumpers.clear();
    point.balls = {{{5, 3}, {}, 0}};
    EXPECT_EQ(penetration_verdict(point, {{state(1, {5, -3})}}), "");
}


// The ghost-bounce check on frames written by hand: what makes a first hit a ghost, and what does not.
std::string ghost_verdict(const Scene& s, std::vector<Ball> before, const std::vector<Event>& frame1) {
    auto check = checks::make_ghost_bounce(s, KernelId::robust, {});
    if (auto r = check->frame({0, {}, {}, {}, {}})) return r->message;
    if (auto r = check->frame({1, frame1, before, {}, {}})) return r->message;
    return "";
}

Event hit_wall(std::uint32_t w, Vec2 p) { return {Event::Kind::hit, 1, 0, Event::Shape::none, w, p, {}}; }

TEST(DiscChecks, GhostBounceCatchesAHitOnlyATangentCouldMake) {
    Scene s;
    // A 3-4-5 chain through (0, 10): the disc of radius 5 moves along (0.75, 1), exactly 5 from the line.
    s.walls = {{{0, 10}, {3, 14}}, {{3, 14}, {6, 18}}};
    s.balls = {{{4, 7}, {0.75, 1}, 5}};
    const std::vector<Ball> sliding = s.balls;
    EXPECT_NE(ghost_verdict(s, sliding, {hit_wall(1, {7, 11}), state(1, {7, 11})}), "");
    EXPECT_NE(ghost_verdict(s, sliding, {hit_wall(0, {7, 11}), state(1, {7, 11})}), "");
    // One ulp closer than R to the line: it can enter a cap, a real hit.
    std::vector<Ball> closer = sliding;
    closer[0].pos.x = std::nextafter(4.0, 0.0);
    EXPECT_EQ(ghost_verdict(s, closer, {hit_wall(1, {7, 11})}), "");
    // A leg not parallel by an ulp of its end (8 + 2^−48): not judged (it may cross the line at a grazing angle).
    // Off by less, the rounded leg is parallel again and judged.
    std::vector<Ball> askew = sliding;
    askew[0].vel.y = 1 + std::ldexp(1.0, -48);
    EXPECT_EQ(ghost_verdict(s, askew, {hit_wall(1, {7, 11})}), "");
    askew[0].vel.y = std::nextafter(1.0, 2.0);
    EXPECT_NE(ghost_verdict(s, askew, {hit_wall(1, {7, 11})}), "");
    // Only the first hit or bump of a frame is judged: its velocity is the one before the frame.
    Scene with_bumper = s;
    with_bumper.bumpers = {{{20, 20}, 1}};
    const Event bump{Event::Kind::bump, 1, 0, Event::Shape::none, 0, {7, 11}, {}};
    EXPECT_EQ(ghost_verdict(with_bumper, sliding, {bump, hit_wall(1, {7, 11})}), "");
    // A point ball moving along a wall's own line (R = 0, on the line): a hit there is a ghost too.
    Scene point;
    point.walls = {{{0, 0}, {10, 0}}};
    point.balls = {{{-5, 0}, {1, 0}, 0}};
    EXPECT_NE(ghost_verdict(point, point.balls, {hit_wall(0, {0, 0})}), "");
    // The leg is Bs → Bs + v as rounded, not v: v = (1.8e16, 1.8e16) is parallel to the wall along y = x, but from
    // (123, 124) the leg ends at (1.8e16 + 124, 1.8e16 + 124) (the ulp there is 4), on the wall's line: it meets
    // the wall, a real hit (found by the disc campaign when the check read v).
    Scene far;
    far.walls = {{{1e16, 1e16}, {2e16, 2e16}}};
    far.balls = {{{123, 124}, {1.8e16, 1.8e16}, 0}};
    EXPECT_EQ(ghost_verdict(far, far.balls, {hit_wall(0, {1.8000000000000124e16, 1.8000000000000124e16})}), "");
    Scene far_run = far;
    far_run.frames = 1;
    far_run.checks = {Check::ghost_bounce};
    EXPECT_FALSE(run_checked(far_run, KernelId::robust, 1, far_run.checks).failure);
    // A ball that does not move, or a wall of no length: not judged.
    std::vector<Ball> resting = point.balls;
    resting[0].vel = {0, 0};
    EXPECT_EQ(ghost_verdict(point, resting, {hit_wall(0, {0, 0})}), "");
    Scene dot = point;
    dot.walls = {{{3, 0}, {3, 0}}};
    EXPECT_EQ(ghost_verdict(dot, point.balls, {hit_wall(0, {3, 0})}), "");
}

}  // namespace
}  // namespace ricochet
