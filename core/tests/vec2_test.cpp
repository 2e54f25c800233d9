// Vec2 algebra, with numbers worked by hand.
#include <gtest/gtest.h>

#include "ricochet/vec2.hpp"

namespace ricochet {
namespace {

TEST(Vec2, AddSubtractScale) {
    EXPECT_EQ((Vec2{1, 2} + Vec2{3, -5}), (Vec2{4, -3}));
    EXPECT_EQ((Vec2{1, 2} - Vec2{3, -5}), (Vec2{-2, 7}));
    EXPECT_EQ((2.5 * Vec2{2, -4}), (Vec2{5, -10}));
    EXPECT_EQ((Vec2{2, -4} * 0.5), (Vec2{1, -2}));
    EXPECT_EQ((-Vec2{1, -2}), (Vec2{-1, 2}));
}

TEST(Vec2, DotCrossLength) {
    // (3, 4)·(−4, 3) = −12 + 12 = 0: perpendicular
    EXPECT_EQ(dot(Vec2{3, 4}, Vec2{-4, 3}), 0.0);
    EXPECT_EQ(dot(Vec2{1, 2}, Vec2{3, 4}), 11.0);
    EXPECT_EQ(cross(Vec2{1, 0}, Vec2{0, 1}), 1.0);
    EXPECT_EQ(cross(Vec2{0, 1}, Vec2{1, 0}), -1.0);
    EXPECT_EQ(length_squared(Vec2{3, 4}), 25.0);
    EXPECT_EQ(length(Vec2{3, 4}), 5.0);
}

TEST(Vec2, Normalize) {
    EXPECT_EQ(normalize(Vec2{3, 4}), (Vec2{0.6, 0.8}));
    EXPECT_EQ(normalize(Vec2{0, -7}), (Vec2{0, -1}));
    // Degenerate: the zero vector has no direction and is never divided by.
    EXPECT_EQ(normalize(Vec2{0, 0}), (Vec2{0, 0}));
}

TEST(Vec2, PerpIsEdgeRotatedMinus90) {
    // (e_y, −e_x): east (1, 0) turns to south (0, −1), north to east.
    EXPECT_EQ(perp(Vec2{1, 0}), (Vec2{0, -1}));
    EXPECT_EQ(perp(Vec2{0, 1}), (Vec2{1, 0}));
    EXPECT_EQ(perp(Vec2{3, 4}), (Vec2{4, -3}));
    EXPECT_EQ(dot(perp(Vec2{3, 4}), Vec2{3, 4}), 0.0);
}

}  // namespace
}  // namespace ricochet
