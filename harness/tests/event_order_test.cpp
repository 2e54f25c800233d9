// event-order (checks.hpp) on frames written by hand: the order the World prints holds, and each way a
// frame can break the spec's order is named. The World itself cannot be made to misorder its events, so
// the check is fed frames directly (frame_check.hpp, internal).
#include <gtest/gtest.h>

#include <vector>

#include "checks/frame_check.hpp"

namespace ricochet::checks {
namespace {

Event state(std::int64_t f, std::uint32_t ball) { return {Event::Kind::state, f, ball, Event::Shape::none, 0, {}, {}}; }
Event hit(std::int64_t f, std::uint32_t ball, std::uint32_t wall) {
    return {Event::Kind::hit, f, ball, Event::Shape::none, wall, {}, {}};
}
Event bump(std::int64_t f, std::uint32_t ball, std::uint32_t bumper) {
    return {Event::Kind::bump, f, ball, Event::Shape::none, bumper, {}, {}};
}
Event meet(std::int64_t f, std::uint32_t ball, std::uint32_t other) {
    return {Event::Kind::meet, f, ball, Event::Shape::none, other, {}, {}};
}
Event overlap(std::int64_t f, std::uint32_t ball, Event::Shape shape, std::uint32_t k) {
    return {Event::Kind::overlap, f, ball, shape, k, {}, {}};
}

Scene two_balls() {
    Scene s;
    s.walls = {{{0, 0}, {1, 0}}, {{1, 0}, {1, 1}}};
    s.balls = {{{0.5, 0.5}, {1, 0}}, {{0.25, 0.5}, {0, 1}}};
    s.circles = {{{0, 0}, 1}, {{0, 0}, 2}};
    s.rects = {{0, 0, 1, 1}};
    return s;
}

/// The message of event-order's failure on events at frame f, or "" if it holds.
std::string verdict(const Scene& s, std::int64_t f, std::vector<Event> events) {
    auto check = make_event_order(s, KernelId::robust, {});
    const auto r = check->frame(Frame{f, events, {}, {}, {}});
    return r ? r->message : "";
}

using K = Event::Shape;

TEST(EventOrder, TheSpecsOrderHolds) {
    const Scene s = two_balls();
    EXPECT_EQ(verdict(s, 0, {state(0, 0), state(0, 1), overlap(0, 0, K::circle, 0), overlap(0, 0, K::rect, 0),
                             overlap(0, 1, K::circle, 1)}),
              "");
    EXPECT_EQ(verdict(s, 3, {hit(3, 0, 1), hit(3, 0, 0), state(3, 0), state(3, 1), overlap(3, 1, K::rect, 0)}), "");
}

TEST(EventOrder, BumpsGoWithHitsInTheOrderTheyHappened) {
    Scene s = two_balls();
    s.bumpers = {{{5, 5}, 1}};
    EXPECT_EQ(verdict(s, 2, {hit(2, 0, 1), bump(2, 0, 0), hit(2, 0, 0), state(2, 0), bump(2, 1, 0), state(2, 1)}), "");
    const auto has = [](const std::string& m, const char* what) { return m.find(what) != std::string::npos; };
    EXPECT_TRUE(has(verdict(s, 0, {bump(0, 0, 0), state(0, 0), state(0, 1)}), "frame 0 has no bumps"));
    EXPECT_TRUE(has(verdict(s, 1, {bump(1, 0, 1), state(1, 0), state(1, 1)}), "names a bumper of the scene"));
    EXPECT_TRUE(has(verdict(s, 1, {bump(1, 1, 0), state(1, 0), state(1, 1)}), "ball 0's events come next"));
    EXPECT_TRUE(has(verdict(s, 1, {state(1, 0), state(1, 1), bump(1, 1, 0)}), "after the states come only overlaps"));
    Event shaped = bump(1, 0, 0);
    shaped.shape = K::circle;
    EXPECT_TRUE(has(verdict(s, 1, {shaped, state(1, 0), state(1, 1)}), "names a bumper of the scene and no shape"));
}

TEST(EventOrder, EachBreakIsNamed) {
    const Scene s = two_balls();
    const auto has = [](const std::string& m, const char* what) { return m.find(what) != std::string::npos; };
    EXPECT_TRUE(has(verdict(s, 0, {hit(0, 0, 0), state(0, 0), state(0, 1)}), "frame 0 has no hits"));
    // A state before its ball's hits (mutant 26), and a hit of the wrong ball.
    EXPECT_TRUE(has(verdict(s, 1, {state(1, 0), hit(1, 0, 0), state(1, 1)}), "ball 1's events come next"));
    EXPECT_TRUE(has(verdict(s, 1, {hit(1, 1, 0), state(1, 0), state(1, 1)}), "ball 0's events come next"));
    EXPECT_TRUE(has(verdict(s, 1, {hit(1, 0, 2), state(1, 0), state(1, 1)}), "names a wall of the scene"));
    EXPECT_TRUE(has(verdict(s, 1, {hit(1, 0, 0), state(2, 0), state(1, 1)}), "ball 0's state at this frame"));
    EXPECT_TRUE(has(verdict(s, 1, {hit(2, 0, 0), state(1, 0), state(1, 1)}), "not this frame's number"));
    EXPECT_TRUE(has(verdict(s, 1, {state(1, 1), state(1, 0)}), "ball 0's state at this frame"));
    EXPECT_TRUE(has(verdict(s, 1, {state(1, 0)}), "the frame ends before ball 1's state"));
    EXPECT_TRUE(has(verdict(s, 1, {state(1, 0), state(1, 1), state(1, 1)}), "after the states come only overlaps"));
    EXPECT_TRUE(has(verdict(s, 1, {state(1, 0), overlap(1, 0, K::circle, 0)}), "ball 1's state comes next"));
    Event shaped = hit(1, 0, 0);
    shaped.shape = K::circle;
    EXPECT_TRUE(has(verdict(s, 1, {shaped, state(1, 0), state(1, 1)}), "names a wall of the scene and no shape"));
    Event indexed = state(1, 0), with_shape = state(1, 0);
    indexed.index = 1;
    with_shape.shape = K::rect;
    EXPECT_TRUE(has(verdict(s, 1, {indexed, state(1, 1)}), "ball 0's state at this frame"));
    EXPECT_TRUE(has(verdict(s, 1, {with_shape, state(1, 1)}), "ball 0's state at this frame"));
    EXPECT_TRUE(has(verdict(s, 1, {state(1, 0), state(1, 1), overlap(2, 0, K::circle, 0)}), "at this frame"));
    // Overlaps: rect before circle, a repeat, a shape the scene lacks, a ball that does not exist.
    EXPECT_TRUE(has(verdict(s, 1, {state(1, 0), state(1, 1), overlap(1, 0, K::rect, 0), overlap(1, 0, K::circle, 1)}),
                    "circles before rects"));
    EXPECT_TRUE(has(verdict(s, 1, {state(1, 0), state(1, 1), overlap(1, 1, K::circle, 0), overlap(1, 1, K::circle, 0)}),
                    "circles before rects"));
    EXPECT_TRUE(has(verdict(s, 1, {state(1, 0), state(1, 1), overlap(1, 0, K::rect, 1)}), "a circle or rect of the scene"));
    EXPECT_TRUE(has(verdict(s, 1, {state(1, 0), state(1, 1), overlap(1, 2, K::circle, 0)}), "a circle or rect of the scene"));
    EXPECT_TRUE(has(verdict(s, 1, {state(1, 0), state(1, 1), overlap(1, 0, K::none, 0)}), "a circle or rect of the scene"));
}

TEST(EventOrder, MeetsGoWithHitsAndPrintUnderBothBalls) {
    Scene s = two_balls();
    s.balls[0].r = 0.125;
    s.balls_collide = true;
    const auto has = [](const std::string& m, const char* what) { return m.find(what) != std::string::npos; };
    // A meet among a ball's hits, in the order they happened; the same meet under the other ball.
    EXPECT_EQ(verdict(s, 2, {hit(2, 0, 1), meet(2, 0, 1), hit(2, 0, 0), state(2, 0), meet(2, 1, 0), state(2, 1)}), "");
    EXPECT_EQ(verdict(s, 2, {meet(2, 0, 1), meet(2, 0, 1), state(2, 0), meet(2, 1, 0), meet(2, 1, 0), state(2, 1)}), "");
    // Printed under one ball only, or once under one and twice under the other.
    EXPECT_TRUE(has(verdict(s, 1, {meet(1, 0, 1), state(1, 0), state(1, 1)}),
                    "ball 0 prints 1 meet(s) with ball 1, ball 1 prints 0 with ball 0"));
    EXPECT_TRUE(has(verdict(s, 1, {state(1, 0), meet(1, 1, 0), state(1, 1)}),
                    "ball 0 prints 0 meet(s) with ball 1, ball 1 prints 1 with ball 0"));
    EXPECT_TRUE(has(verdict(s, 1, {meet(1, 0, 1), meet(1, 0, 1), state(1, 0), meet(1, 1, 0), state(1, 1)}),
                    "every meet prints under both its balls"));
    // A meet naming its own ball, a ball the scene lacks, or with a shape; at frame 0; the wrong ball's turn.
    EXPECT_TRUE(has(verdict(s, 1, {meet(1, 0, 0), state(1, 0), state(1, 1)}), "a meet names another ball of the scene"));
    EXPECT_TRUE(has(verdict(s, 1, {meet(1, 0, 2), state(1, 0), state(1, 1)}), "a meet names another ball of the scene"));
    Event shaped = meet(1, 0, 1);
    shaped.shape = K::circle;
    EXPECT_TRUE(has(verdict(s, 1, {shaped, state(1, 0), meet(1, 1, 0), state(1, 1)}), "and no shape"));
    EXPECT_TRUE(has(verdict(s, 0, {meet(0, 0, 1), state(0, 0), meet(0, 1, 0), state(0, 1)}), "frame 0 has no meets"));
    EXPECT_TRUE(has(verdict(s, 1, {meet(1, 1, 0), state(1, 0), state(1, 1)}), "ball 0's events come next"));
    EXPECT_TRUE(has(verdict(s, 1, {meet(2, 0, 1), state(1, 0), meet(1, 1, 0), state(1, 1)}), "not this frame's number"));
    // Balls that do not collide never meet; nor do two point balls.
    Scene apart = s;
    apart.balls_collide = false;
    EXPECT_TRUE(has(verdict(apart, 1, {meet(1, 0, 1), state(1, 0), meet(1, 1, 0), state(1, 1)}),
                    "a meet in a scene whose balls do not collide"));
    Scene points = s;
    points.balls[0].r = 0;
    EXPECT_TRUE(has(verdict(points, 1, {meet(1, 0, 1), state(1, 0), meet(1, 1, 0), state(1, 1)}),
                    "two point balls never meet"));
}

}  // namespace
}  // namespace ricochet::checks
