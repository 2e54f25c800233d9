// The checks' exact oracle (truth.hpp) where its floating-point filters give up: products that overflow
// or underflow, speeds decided without and with an absolute part, hits that are not conditioned, and
// dot_sign, which no check calls. Every expectation is worked by hand in the comment beside it.
#include <gtest/gtest.h>

#include <cfloat>
#include <vector>

#include "ricochet/truth.hpp"

namespace ricochet {
namespace {

TEST(TruthOrient, AnOverflowingProductIsDecidedExactly) {
    // (a − c) × (b − c) with c = 0: l = a.x·b.y = 1e400 overflows to +inf, r = a.y·b.x = 0, so det is
    // not finite. Exactly, (b − a) × (c − a) = (−1e200)(0) − (1e200)(−1e200) = 1e400 > 0.
    const Vec2 a{1e200, 0}, b{0, 1e200}, c{0, 0};
    EXPECT_EQ(truth::orient(a, b, c), 1);
    EXPECT_EQ(truth::orient(b, a, c), -1);
}

TEST(TruthOrient, ASumOfProductsThatOverflowsWithAFiniteDifferenceIsDecidedExactly) {
    // c = 0, a = (X, X), b = (X, X + u) with X = 1.5·2^511 and u its ulp: l = X·(X + u) and r = X·X are
    // both finite (about 1.125·2^1023) and so is l − r, but |l| + |r| overflows. Exactly
    // l − r = X·u > 0.
    const double x = 0x1.8p511;
    const Vec2 a{x, x}, b{x, std::nextafter(x, INFINITY)}, c{0, 0};
    EXPECT_EQ(truth::orient(a, b, c), 1);
    EXPECT_EQ(truth::orient(b, a, c), -1);
    EXPECT_EQ(truth::cross_sign(a, b), 1);  // the same determinant with c = 0
}

TEST(TruthSpeed, WithoutAnAbsolutePartBothBoundsAreExact) {
    // a = 0: | |w| − |v| | ≤ ((1 + b)^m − 1)·|v|, |v| = 5.
    const Vec2 v{3, 4};
    // b = 2^-48, m = 1: |w| = 10 is 5 over the bound 5·2^-48.
    EXPECT_FALSE(truth::speed_within(v, {6, 8}, 1, 0x1p-48, 0.0));
    // b = 1, m = 1: C = 1, so the lower bound (1 − C)|v| = 0 holds for any w, and |w| ≤ 2|v| = 10.
    EXPECT_TRUE(truth::speed_within(v, {0, 0}, 1, 1.0, 0.0));
    EXPECT_TRUE(truth::speed_within(v, {6, 8}, 1, 1.0, 0.0));  // |w| = 10 exactly on the bound
    EXPECT_FALSE(truth::speed_within(v, {6, std::nextafter(8.0, 9.0)}, 1, 1.0, 0.0));
}

TEST(TruthSpeed, WithAnAbsolutePartASpeedFarAboveOrBelowIsOutside) {
    // b = 2^-48, a = 1, m = 1: |w| must lie within 5·2^-48 + 1 of |v|.
    EXPECT_FALSE(truth::speed_within({3, 4}, {30, 40}, 1, 0x1p-48, 1.0));  // |w| = 50, 45 above
    EXPECT_FALSE(truth::speed_within({30, 40}, {3, 4}, 1, 0x1p-48, 1.0));  // |w| = 5, 45 below |v| = 50
    EXPECT_TRUE(truth::speed_within({30, 40}, {30, 40.5}, 1, 0x1p-48, 1.0));  // |w| ≈ 50.4, within 1
}

TEST(TruthHitAccuracy, AWallShorterThanTwoToTheMinus400IsNotConditioned) {
    // The leg y = 2^-501 from x = −1 to 1 crosses the wall x = 0 of length 2^-500 at its middle, at a right
    // angle, but |e|∞ = 2^-500 < 2^-400: not conditioned (truth.hpp).
    const Wall tiny{{0, 0}, {0, 0x1p-500}};
    EXPECT_FALSE(truth::hit_accuracy({-1, 0x1p-501}, {1, 0x1p-501}, tiny, {0, 0x1p-501}, 256).conditioned);
    EXPECT_FALSE(truth::hit_time_accuracy({-1, 0x1p-501}, {1, 0x1p-501}, tiny, 0.5, 256).conditioned);
    // So is a leg shorter than 2^-400 across a unit wall, and a grazing one: e = (0, 2), d = (0.1, 2) has
    // 4·|e × d| = 0.8 < |e|∞·|d|∞ = 4.
    const Wall unit{{0, -1}, {0, 1}};
    EXPECT_FALSE(truth::hit_accuracy({-0x1p-500, 0}, {0x1p-500, 0}, unit, {0, 0}, 256).conditioned);
    EXPECT_FALSE(truth::hit_accuracy({-0.05, -1}, {0.05, 1}, unit, {0, 0}, 256).conditioned);
    // At exactly 2^-400 it is: the crossing (0, 2^-401) is at s = 1/2, error 0.
    const Wall small{{0, 0}, {0, 0x1p-400}};
    const truth::HitAccuracy at = truth::hit_accuracy({-1, 0x1p-401}, {1, 0x1p-401}, small, {0, 0x1p-401}, 256);
    EXPECT_TRUE(at.conditioned);
    EXPECT_TRUE(at.within);
    EXPECT_EQ(at.error, 0.0);
}

TEST(TruthHitAccuracy, TheKeptWallExemptsACrossingOnlyOffItsKeptSide) {
    // The leg (−1, 0) → (1, 0) crosses x = 0 at X = (0, 0); p = (2^-52, 0) is 2^-52 off, i.e. 2 units of
    // ε·M with M = 1.
    const Wall w{{0, -1}, {0, 1}};
    const Vec2 a{-1, 0}, b{1, 0}, p{0x1p-52, 0};
    const truth::HitAccuracy plain = truth::hit_accuracy(a, b, w, p, 256);
    ASSERT_TRUE(plain.conditioned);
    EXPECT_TRUE(plain.within);
    EXPECT_EQ(plain.error, 2.0);
    EXPECT_FALSE(truth::hit_accuracy(a, b, w, p, 1).within);  // 2 units > 1
    // Kept wall y = 0.5 from (−1, 0.5) to (1, 0.5): n = (0, −2), BC(X) = −2·(0 − 0.5) = 1, side +1.
    const Wall kept{{-1, 0.5}, {1, 0.5}};
    const truth::HitAccuracy same_side = truth::hit_accuracy(a, b, w, p, 256, &kept, 1);
    EXPECT_TRUE(same_side.conditioned);
    EXPECT_EQ(same_side.error, 2.0);
    // Kept from −1: X lies on the far side, out of the ball's reach: not conditioned.
    EXPECT_FALSE(truth::hit_accuracy(a, b, w, p, 256, &kept, -1).conditioned);
    // Kept wall through X (its line y = x): side 0 is not strictly the kept side either.
    const Wall through{{-1, -1}, {1, 1}};
    EXPECT_FALSE(truth::hit_accuracy(a, b, w, p, 256, &through, 1).conditioned);
    // kept_from = 0 (no bounce yet): the kept wall is ignored.
    EXPECT_TRUE(truth::hit_accuracy(a, b, w, p, 256, &kept, 0).conditioned);
}

TEST(TruthDotSign, FilterAndExactFallbackAgree) {
    EXPECT_EQ(truth::dot_sign({1, 2}, {3, 4}), 1);    // 11
    EXPECT_EQ(truth::dot_sign({1, 0}, {-1, 0}), -1);  // −1
    EXPECT_EQ(truth::dot_sign({1, 1}, {1, -1}), 0);   // 1 − 1 = 0: the filter cannot say, GMP says 0
    // 2^-52 against a bound 3ε·2: too close for the filter, exactly positive.
    EXPECT_EQ(truth::dot_sign({1 + 0x1p-52, 1}, {1, -1}), 1);
    // Products that underflow to 0 (2^-1200): the sum is below 2^-900, GMP says +.
    EXPECT_EQ(truth::dot_sign({0x1p-600, 0}, {0x1p-600, 0}), 1);
    EXPECT_EQ(truth::dot_sign({0x1p-600, 0}, {-0x1p-600, 0}), -1);
    // A product that overflows: s = +inf, exactly 1e400 + 1 > 0.
    EXPECT_EQ(truth::dot_sign({1e200, 1}, {1e200, 1}), 1);
    // Finite products whose |l| + |r| overflows: s = DBL_MAX − DBL_MAX = 0, exactly 0.
    EXPECT_EQ(truth::dot_sign({DBL_MAX, DBL_MAX}, {1, -1}), 0);
    EXPECT_EQ(truth::dot_sign({DBL_MAX, DBL_MAX}, {1, -std::nextafter(1.0, 0.0)}), 1);
}


TEST(TruthBounce, AZeroLengthWallOrABallAtRestIsJudgedWithoutDividing) {
    // A wall of no length has no normal: no bounce to judge. A ball at rest meets any wall at |v·n| = 0 ≥ 0,
    // and its reflection is 0 exactly: within, with error 0 (no division by |v| = 0).
    EXPECT_FALSE(truth::bounce_accuracy({1, -1}, Wall{{2, 2}, {2, 2}}, {1, 1}, 0x1p-48, 0).conditioned);
    const truth::HitAccuracy r = truth::bounce_accuracy({0, 0}, Wall{{0, 0}, {1, 0}}, {0, 0}, 0x1p-48, 0);
    EXPECT_TRUE(r.conditioned);
    EXPECT_TRUE(r.within);
    EXPECT_EQ(r.error, 0.0);
    // v = (1, −1) off the floor y = 0 reflects to (1, 1) exactly; (1, 1 + 2^-40) is far outside 2·2^-48·√2.
    EXPECT_TRUE(truth::bounce_accuracy({1, -1}, Wall{{0, 0}, {1, 0}}, {1, 1}, 0x1p-48, 0).within);
    EXPECT_FALSE(truth::bounce_accuracy({1, -1}, Wall{{0, 0}, {1, 0}}, {1, 1 + 0x1p-40}, 0x1p-48, 0).within);
}

TEST(TruthCorner, AZeroLengthWallOrAnUnclearSideIsNotConditioned) {
    // The hit wall p0 → p1 = (0, 0) → (1, 0) has n = (e_y, −e_x) = (0, −1); v = (0, −1) meets it with
    // n·v = 1, clear (4·1 ≥ |v|∞·|n|∞ = 1), and R = v − 2(n·v)/(n·n)·n = (0, 1).
    const Wall hit{{0, 0}, {1, 0}};
    const Vec2 v{0, -1};
    const std::vector<Wall> none;
    const std::vector<int> no_sides;
    EXPECT_TRUE(truth::corner_accuracy(v, hit, 1, none, no_sides, {0, 1}, 0x1p-52, 0).conditioned);
    // A hit wall of no length has no normal.
    EXPECT_FALSE(truth::corner_accuracy(v, Wall{{0, 0}, {0, 0}}, 1, none, no_sides, {0, 1}, 0x1p-52, 0).conditioned);
    // Nor has another wall of no length at the corner.
    const std::vector<Wall> point = {Wall{{0, 0}, {0, 0}}};
    const std::vector<int> one_side = {1};
    EXPECT_FALSE(truth::corner_accuracy(v, hit, 1, point, one_side, {0, 1}, 0x1p-52, 0).conditioned);
    // A wall (0, 0) → (0, 1), n = (1, 0), that R = (0, 1) runs along: n·R = 0, no clear side.
    const std::vector<Wall> along = {Wall{{0, 0}, {0, 1}}};
    EXPECT_FALSE(truth::corner_accuracy(v, hit, 1, along, one_side, {0, 1}, 0x1p-52, 0).conditioned);
}

TEST(TruthCorner, AWallCrossedAgainAfterALaterReflectionSendsTheBallStraightBack) {
    // Hit: (0, 0) → (1, 0), n = (0, −1), v = (0, −1): R = (0, 1) (the test above).
    // Wall 0: (0, 0) → (−1, −2), n0 = (−2, 1), met from side +1: n0·R = 1 > 0, not crossed (clear: 4 ≥ 1·2).
    // Wall 1: (0, 0) → (−1, −3), n1 = (−3, 1), met from side −1: n1·R = 1 crosses it (clear: 4 ≥ 1·3), so
    //   R = (0, 1) − 2·1/10·(−3, 1) = (3/5, 4/5), the second reflection.
    // Then n0·R = −6/5 + 4/5 = −2/5 crosses wall 0 (clear: 4·2/5 ≥ 4/5·2), n1·R = −9/5 + 4/5 = −1 does not,
    // and n·R = −4/5 is clear: the rule goes straight back, v′ = −v = (0, 1).
    const Wall hit{{0, 0}, {1, 0}};
    const std::vector<Wall> others = {Wall{{0, 0}, {-1, -2}}, Wall{{0, 0}, {-1, -3}}};
    const std::vector<int> from = {1, -1};
    const auto back = truth::corner_accuracy({0, -1}, hit, 1, others, from, {0, 1}, 0x1p-52, 0);
    EXPECT_TRUE(back.conditioned);
    EXPECT_TRUE(back.within);
    EXPECT_EQ(back.error, 0.0);
    // The two reflections' (3/5, 4/5), however close, is not straight back: −v bit for bit or nothing.
    const auto reflected = truth::corner_accuracy({0, -1}, hit, 1, others, from, {0.6, 0.8}, 0x1p-52, 0);
    EXPECT_TRUE(reflected.conditioned);
    EXPECT_FALSE(reflected.within);
    EXPECT_EQ(reflected.error, 2.0);
}

TEST(TruthCorner, AWallThatALaterReflectionRunsAlongIsNotConditioned) {
    // Hit: (0, 0) → (1, 0), n = (0, −1), v = (0, −1): R = (0, 1).
    // Wall 0: (0, 0) → (−1, 0), n0 = (0, 1), met from +1: n0·R = 1, clear, not crossed.
    // Wall 1: (0, 0) → (1, 1), n1 = (1, −1), met from +1: n1·R = −1 crosses it (clear: 4 ≥ 1·1), so
    //   R = (0, 1) − 2·(−1)/2·(1, −1) = (1, 0).
    // Then n0·R = 0: whether R still crosses wall 0 is not clear, and the rule is not judged.
    const Wall hit{{0, 0}, {1, 0}};
    const std::vector<Wall> others = {Wall{{0, 0}, {-1, 0}}, Wall{{0, 0}, {1, 1}}};
    const std::vector<int> from = {1, 1};
    EXPECT_FALSE(truth::corner_accuracy({0, -1}, hit, 1, others, from, {1, 0}, 0x1p-52, 0).conditioned);
}

TEST(TruthLegEnd, ABallAtRestAtTheOriginIsWithinWithErrorZero) {
    // M = 0, so ε·M = 0: the error is reported as 0 rather than 0/0, and to = from + R·v exactly.
    const std::vector<double> ts = {0.5};
    const auto r = truth::leg_end_accuracy({0, 0}, {0, 0}, ts, {0, 0});
    EXPECT_TRUE(r.conditioned);
    EXPECT_TRUE(r.within);
    EXPECT_EQ(r.error, 0.0);
    // The 2^−1072 of underflow allowed, and no more: 2^−1074 is within, 2^−1071 is not (M = |to|∞, so
    // the (2k + 3)·ε·M = 5·2^−53·|to|∞ part is far below 2^−1074).
    EXPECT_TRUE(truth::leg_end_accuracy({0, 0}, {0, 0}, ts, {0x1p-1074, 0}).within);
    EXPECT_FALSE(truth::leg_end_accuracy({0, 0}, {0, 0}, ts, {0x1p-1071, 0}).within);
}

}  // namespace
}  // namespace ricochet
