// round_quotient's two conventions at their edges (round.hpp): a zero denominator has no value (NaN),
// and a negative value that rounds up to 2^1024 in magnitude is −DBL_MAX, as a positive one is DBL_MAX.
#include <cfloat>
#include <cmath>

#include <gtest/gtest.h>

#include "base/bignum.hpp"
#include "base/round.hpp"

namespace ricochet::bignum {
namespace {

TEST(RoundQuotient, AZeroDenominatorGivesNaNAndAZeroNumeratorZero) {
    EXPECT_TRUE(std::isnan(round_quotient(Integer(3), Integer(0), 0)));
    EXPECT_TRUE(std::isnan(round_quotient(Integer(-3), Integer(-1), 0)));  // den < 0: no value either
    EXPECT_EQ(round_quotient(Integer(0), Integer(0), 0), 0.0);              // 0 is checked first
}

TEST(RoundQuotient, JustBelowTwoToThe1024RoundsToTheLargestDoubleEitherSign) {
    // DBL_MAX = 2^1024 − 2^971; 2^1024 − 2^969 lies above DBL_MAX + half its ulp (2^970), so it rounds
    // up to 2^1024, which has no double: the convention gives ±DBL_MAX below 2^1024.
    const Integer v = (Integer(1) << 1024) - (Integer(1) << 969);
    EXPECT_EQ(round_quotient(v, Integer(1), 0), DBL_MAX);
    EXPECT_EQ(round_quotient(Integer(-v), Integer(1), 0), -DBL_MAX);
    // The same value as a quotient at another scale: (2^1024 − 2^969)·2^-10 / 2^-10.
    EXPECT_EQ(round_quotient(Integer(-v), Integer(1) << 10, 10), -DBL_MAX);
    // From 2^1024 on: infinity.
    EXPECT_EQ(round_quotient(Integer(-(Integer(1) << 1024)), Integer(1), 0), -INFINITY);
}

}  // namespace
}  // namespace ricochet::bignum
