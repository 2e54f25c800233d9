// The walls' plan (wall_plan.hpp): the comparison path for axis-aligned walls gives the exact side, against big
// rationals, at the bounds of the accepted range, at subnormals and signed zeros; the leg test and a whole run give
// the same answers on both paths; a plan is made once per set of walls.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "base/bignum.hpp"
#include "kernels/robust/robust_leg.hpp"
#include "predicates/orient_filter.hpp"
#include "ricochet/bits.hpp"
#include "ricochet/step.hpp"
#include "ricochet/wall_plan.hpp"
#include "ricochet/world.hpp"

namespace ricochet {
namespace {

/// side(p, w) = sign(n·(p − P0)), n = (e_y, −e_x), in big rationals.
int side_gmp(Vec2 p, const Wall& w) {
    const auto q = [](double x) { return bignum::rational(x); };
    return bignum::sign((q(w.p1.y) - q(w.p0.y)) * (q(p.x) - q(w.p0.x)) - (q(w.p1.x) - q(w.p0.x)) * (q(p.y) - q(w.p0.y)));
}

/// Coordinates where a comparison could go wrong if the derivation did: the range's ends (2^256), huge and tiny
/// magnitudes, subnormals, both zeros, and neighbours an ulp apart.
std::vector<double> hard_numbers() {
    std::vector<double> v = {0.0, -0.0, 1.0, -1.0, 0x1p256, -0x1p256, 1e300, -1e300, 1e-300, 4.9e-324, -4.9e-324,
                             2.2250738585072014e-308, 3.0, 0.1, -7.5, 1e6 + 0.5};
    const std::size_t n = v.size();
    for (std::size_t i = 0; i < n; ++i) {
        v.push_back(std::nextafter(v[i], INFINITY));
        v.push_back(std::nextafter(v[i], -INFINITY));
    }
    return v;
}

TEST(WallPlan, AxisSidesAreTheExactSides) {
    const std::vector<double> xs = hard_numbers();
    std::mt19937_64 rng(20261203);
    std::uniform_int_distribution<std::size_t> pick(0, xs.size() - 1);
    long checked = 0;
    for (int i = 0; i < 200000; ++i) {
        const double c = xs[pick(rng)], a = xs[pick(rng)], b = xs[pick(rng)];
        const Vec2 p{xs[pick(rng)], xs[pick(rng)]};
        // Horizontal (y = c), vertical (x = c), both directions; a = b makes a zero-length wall.
        for (const Wall& w : {Wall{{a, c}, {b, c}}, Wall{{c, a}, {c, b}}}) {
            ASSERT_EQ(exact::detail::side_planned(p, w), side_gmp(p, w))
                << "p (" << p.x << ", " << p.y << ") wall (" << w.p0.x << ", " << w.p0.y << ") (" << w.p1.x << ", "
                << w.p1.y << ")";
            ASSERT_EQ(exact::detail::side_planned(p, w), exact::detail::side(p, w));
            ++checked;
        }
    }
    EXPECT_EQ(checked, 400000);
    // A wall that is neither goes to the filtered orientation.
    const Wall sloped{{0.0, 0.0}, {3.0, 1.0}};
    EXPECT_EQ(exact::detail::side_planned({3.0, 1.0}, sloped), 0);
    EXPECT_EQ(exact::detail::side_planned({0.0, 1.0}, sloped), side_gmp({0.0, 1.0}, sloped));
}

TEST(WallPlan, TheLegTestDecidesTheSameOnBothPaths) {
    const std::vector<double> xs = hard_numbers();
    std::mt19937_64 rng(7);
    std::uniform_int_distribution<std::size_t> pick(0, xs.size() - 1);
    for (int i = 0; i < 100000; ++i) {
        const double c = xs[pick(rng)], a = xs[pick(rng)], b = xs[pick(rng)];
        const Vec2 q{xs[pick(rng)], xs[pick(rng)]}, e{xs[pick(rng)], xs[pick(rng)]};
        for (const Wall& w : {Wall{{a, c}, {b, c}}, Wall{{c, a}, {c, b}}, Wall{{a, b}, {c, a}}}) {
            const robust::Leg axis = robust::test_leg<true>(q, e, w);
            const robust::Leg general = robust::test_leg<false>(q, e, w);
            ASSERT_EQ(axis.miss, general.miss);
            ASSERT_EQ(axis.sq, general.sq);
            ASSERT_EQ(axis.sb, general.sb);
        }
    }
}

TEST(WallPlan, APlanIsMadeOncePerSetOfWalls) {
    const std::vector<Wall> box = {{{0, 0}, {4, 0}}, {{4, 0}, {4, 4}}, {{4, 4}, {0, 4}}, {{0, 4}, {0, 0}}};
    const std::vector<Wall> turned = {{{0, 0}, {4, 1}}, {{4, 1}, {3, 5}}};
    EXPECT_EQ(plan_walls(box).axis_aligned, 4u);
    EXPECT_EQ(plan_walls(turned).axis_aligned, 0u);
    EXPECT_EQ(plan_walls(std::vector<Wall>{{{1, 1}, {1, 1}}}).axis_aligned, 1u);  // zero length: both
    StepScratch scratch;
    EXPECT_EQ(planned(scratch, box).axis_aligned, 4u);
    EXPECT_TRUE(scratch.plan.describes(box));
    // A plan that describes the walls is kept as it is (a caller may hand one, as World does)...
    scratch.plan.axis_aligned = 0;
    EXPECT_EQ(planned(scratch, box).axis_aligned, 0u);
    // ...and other walls get their own.
    EXPECT_EQ(planned(scratch, turned).axis_aligned, 0u);
    EXPECT_TRUE(scratch.plan.describes(turned));
    EXPECT_EQ(planned(scratch, box).axis_aligned, 4u);
}

TEST(WallPlan, AWorldStepsTheSameBitsWithAndWithoutItsPlan) {
    // A box with an inner cross of walls: corners, end points on lines, balls along a wall's line.
    Scene s;
    s.walls = {{{0, 0}, {8, 0}}, {{8, 0}, {8, 8}}, {{8, 8}, {0, 8}}, {{0, 8}, {0, 0}}, {{4, 2}, {4, 6}}, {{2, 4}, {6, 4}}};
    s.balls = {{{1, 1}, {3, 3}}, {{4, 1}, {0, 0.75}}, {{0.5, 4}, {7, 0}}, {{7.5, 0.25}, {-0.3, 0.7}}, {{1, 7}, {1e-9, -2.5}}};
    World planned_world(s, KernelId::robust), general(s, KernelId::robust, {.plan = false});
    std::vector<Event> a, b;
    planned_world.start(a);
    general.start(b);
    for (int f = 0; f < 200; ++f) {
        (void)planned_world.step(a);
        (void)general.step(b);
    }
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) ASSERT_TRUE(same_bits(a[i], b[i])) << "event " << i;
    EXPECT_GT(a.size(), 1000u);
}

}  // namespace
}  // namespace ricochet
