// How many random cases an exact-arithmetic test whose reference is computed in big rationals runs: all of them on
// GMP; a tenth on Boost.Multiprecision (bignum_boost_tests), whose rationals of a thousand bits and more are about
// ten times slower. The seed is the same, so the Boost run takes the first tenth of the same cases.
#pragma once

namespace ricochet::test {

/// n on GMP, n/10 on Boost.Multiprecision.
constexpr int bignum_cases(int n) {
#if defined(RICOCHET_BIGNUM_BOOST)
    return n / 10;
#else
    return n;
#endif
}

}  // namespace ricochet::test
