// truth.hpp's disc contacts on cases worked by hand: faces, caps, bumpers, tangents, the start-in-reach rule, a
// contact at t = 1, zero-length walls, the point ball among bumpers, ties and contact times that differ by less
// than a double can tell; and the disc sensor overlaps.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ricochet/truth.hpp"

namespace ricochet {
namespace {

using truth::DiscContact;
using Obstacle = DiscContact::Obstacle;
using Part = DiscContact::Part;

DiscContact first(Vec2 a, Vec2 b, double R, std::vector<Wall> walls, std::vector<Bumper> bumpers = {}) {
    return truth::disc_first_contact(a, b, R, walls, bumpers);
}

void expect_contact(const DiscContact& c, Obstacle o, std::uint32_t index, Part part, bool at_start) {
    EXPECT_EQ(c.obstacle, o);
    EXPECT_EQ(c.index, index);
    EXPECT_EQ(c.part, part);
    EXPECT_EQ(c.at_start, at_start);
}

const Wall k_floor{{0, 0}, {10, 0}};

TEST(TruthDiscs, FacesCapsAndBumpers) {
    // Straight down onto the face: the disc of radius 1 meets it with its centre at y = 1.
    expect_contact(first({5, 3}, {5, -1}, 1, {k_floor}), Obstacle::wall, 0, Part::face, false);
    // Two floors: the higher one first, whatever their order.
    expect_contact(first({5, 3}, {5, -1}, 1, {k_floor, {{0, 0.5}, {10, 0.5}}}), Obstacle::wall, 1, Part::face, false);
    // Moving left at y = 0.5 from beyond P1: the cap at P1, entered at (10 + √0.75, 0.5).
    expect_contact(first({12, 0.5}, {8, 0.5}, 1, {k_floor}), Obstacle::wall, 0, Part::cap1, false);
    expect_contact(first({-2, -0.5}, {2, -0.5}, 1, {k_floor}), Obstacle::wall, 0, Part::cap0, false);
    // A bumper: R + r from its centre.
    expect_contact(first({5, 10}, {5, 5}, 1, {k_floor}, {{{5, 4}, 2}}), Obstacle::bumper, 0, Part::circle, false);
    // The leg stops short: nothing; ends exactly at R, approaching: a contact (t = 1).
    expect_contact(first({5, 3}, {5, 1}, 1, {k_floor}), Obstacle::wall, 0, Part::face, false);
    EXPECT_EQ(first({5, 3}, {5, std::nextafter(1.0, 2.0)}, 1, {k_floor}).obstacle, Obstacle::none);
    EXPECT_TRUE(truth::disc_meets_wall({5, 3}, {5, 1}, 1, k_floor));
    EXPECT_FALSE(truth::disc_meets_wall({5, 3}, {5, 1.5}, 1, k_floor));
}

TEST(TruthDiscs, TangentsStartsAndDegenerateCases) {
    // Sliding along the face at exactly R, past both caps: tangents everywhere, no contact.
    EXPECT_FALSE(truth::disc_meets_wall({-5, 1}, {15, 1}, 1, k_floor));
    // Past a cap at exactly R from P1: a tangent.
    EXPECT_FALSE(truth::disc_meets_wall({11, 5}, {11, -5}, 1, k_floor));
    EXPECT_TRUE(truth::disc_meets_wall({std::nextafter(11.0, 0.0), 5}, {std::nextafter(11.0, 0.0), -5}, 1, k_floor));
    // Within reach: moving closer meets the nearest part at t = 0; moving away or along, nothing.
    expect_contact(first({5, 0.5}, {5, 0.4}, 1, {k_floor}), Obstacle::wall, 0, Part::face, true);
    expect_contact(first({10.5, 0}, {10.25, 0}, 1, {k_floor}), Obstacle::wall, 0, Part::cap1, true);
    EXPECT_FALSE(truth::disc_meets_wall({5, 0.5}, {5, 0.6}, 1, k_floor));
    EXPECT_FALSE(truth::disc_meets_wall({5, 0.5}, {6, 0.5}, 1, k_floor));
    // Touching (exactly R) and moving closer: at once.
    expect_contact(first({5, 1}, {5, 0}, 1, {k_floor}), Obstacle::wall, 0, Part::face, true);
    // A centre on the segment has no normal.
    EXPECT_FALSE(truth::disc_meets_wall({5, 0}, {5, 1}, 1, k_floor));
    EXPECT_FALSE(truth::disc_meets_wall({0, 0}, {-1, 0}, 1, k_floor));
    // A leg of no length moves nowhere.
    EXPECT_FALSE(truth::disc_meets_wall({5, 0.5}, {5, 0.5}, 1, k_floor));
    // A zero-length wall is its cap.
    expect_contact(first({0, 5}, {0, -5}, 1, {{{0, 0}, {0, 0}}}), Obstacle::wall, 0, Part::cap0, false);
    // A point ball (R = 0): a wall's face is its segment, crossed or reached; a bumper its circle; a zero-length
    // wall or a bumper of radius 0 is never met.
    expect_contact(first({5, 1}, {5, -1}, 0, {k_floor}), Obstacle::wall, 0, Part::face, false);
    expect_contact(first({5, 1}, {5, 0}, 0, {k_floor}), Obstacle::wall, 0, Part::face, false);
    EXPECT_FALSE(truth::disc_meets_wall({-1, 1}, {1, -1}, 0, Wall{{0, 0}, {0, 0}}));
    expect_contact(first({0, 5}, {0, 0}, 0, {}, {{{0, 0}, 1}}), Obstacle::bumper, 0, Part::circle, false);
    EXPECT_EQ(first({0, 5}, {0, -5}, 0, {}, {{{0, 0}, 0}}).obstacle, Obstacle::none);
}

TEST(TruthDiscs, TiesAndNearTies) {
    // The face and the cap met at the same time at the face's end: the face.
    expect_contact(first({10, 3}, {10, -1}, 1, {k_floor}), Obstacle::wall, 0, Part::face, false);
    // The same wall twice: the lower index; a wall and a bumper met at once (centre at (5, 1)): the wall.
    expect_contact(first({5, 3}, {5, -1}, 1, {k_floor, k_floor}), Obstacle::wall, 0, Part::face, false);
    expect_contact(first({5, 3}, {5, -1}, 1, {k_floor}, {{{5, -1}, 1}}), Obstacle::wall, 0, Part::face, false);
    // Two walls with a gap of 2^−52 between w0's P1 = (1, 0) and w1's P0: a disc of radius 0.75 coming down at
    // x = 1 meets w0 at y = 0.75 (its face's end) and w1's cap at y = √(0.5625 − 2^−104), a time later by about
    // 2^−106: the rationals tell them apart, in either order of the walls; at x = 1 + 2^−52 the other way round.
    const double gap = 1 + 0x1p-52;
    const Wall w0{{-1, 0}, {1, 0}}, w1{{gap, 0}, {3, 0}};
    expect_contact(first({1, 5}, {1, -5}, 0.75, {w0, w1}), Obstacle::wall, 0, Part::face, false);
    expect_contact(first({1, 5}, {1, -5}, 0.75, {w1, w0}), Obstacle::wall, 1, Part::face, false);
    expect_contact(first({gap, 5}, {gap, -5}, 0.75, {w0, w1}), Obstacle::wall, 1, Part::face, false);
    expect_contact(first({gap, 5}, {gap, -5}, 0.75, {w1, w0}), Obstacle::wall, 0, Part::face, false);
    // Skipped obstacles (the kernel's own rule) are left out.
    EXPECT_EQ(truth::disc_first_contact({5, 3}, {5, -1}, 1, std::vector<Wall>{k_floor}, {}, 0).obstacle,
              Obstacle::none);
}

TEST(TruthDiscs, SensorsSeeTheDiscAtItsSize) {
    EXPECT_TRUE(truth::disc_in_circle({0, 0}, 2, {{3, 0}, 1}));
    EXPECT_FALSE(truth::disc_in_circle({0, 0}, 2, {{3.5, 0}, 1}));
    EXPECT_TRUE(truth::disc_in_rect({0, 0}, 2, {2, -1, 4, 1}));
    EXPECT_FALSE(truth::disc_in_rect({0, 0}, 2, {2.5, -1, 4, 1}));
    // A corner: √2 away from (−1, −1).
    EXPECT_TRUE(truth::disc_in_rect({-1, -1}, std::sqrt(2.0) * (1 + 0x1p-52), {0, 0, 1, 1}));
    EXPECT_FALSE(truth::disc_in_rect({-1, -1}, 1.4142135, {0, 0, 1, 1}));
    EXPECT_TRUE(truth::disc_in_rect({0.5, 0.5}, 0, {0, 0, 1, 1}));
}

}  // namespace
}  // namespace ricochet
