// The core's exact numbers: an integer and a rational of any size and the operations its exact code uses
// (predicates/predicates.cpp, kernels/exact/exact_kernel.cpp, kernels/disc/, harness/src/checks/truth.cpp), on the backend chosen when ricochet is configured
// (RICOCHET_BIGNUM in CMakeLists.txt):
//   gmp    GMP's C++ classes (bignum_gmp.hpp): the default, and the faster;
//   boost  Boost.Multiprecision's cpp_int and cpp_rational (bignum_boost.hpp), header-only: where there is
//          no GMP (wasm32).
// Both give the same bits: every operation is exact, and the one rounding, to_double, is GMP's truncation on
// both (bignum_backends_test compares them operation by operation).
#pragma once

#include <algorithm>

#if defined(RICOCHET_BIGNUM_BOOST)
#include "base/bignum_boost.hpp"
namespace ricochet::bignum {
namespace backend = boost_backend;
}
#elif defined(RICOCHET_BIGNUM_GMP)
#include "base/bignum_gmp.hpp"
namespace ricochet::bignum {
namespace backend = gmp_backend;
}
#else
#error "ricochet: define RICOCHET_BIGNUM_GMP or RICOCHET_BIGNUM_BOOST (the build does, from RICOCHET_BIGNUM)"
#endif

namespace ricochet::bignum {

// The types (GMP's mpz_class and mpq_class, or cpp_int and cpp_rational) with their own +, −, ×, / (rationals),
// comparisons and abs; the rest by name. Each is documented where its backends define it.
using backend::Integer;
using backend::Rational;

using backend::compare;
using backend::sign;

using backend::abs;
using backend::add;
using backend::addmul;
using backend::bit_length;
using backend::divexact;
using backend::gcd;
using backend::isqrt;
using backend::low_uint64;
using backend::mul;
using backend::mul_2exp;
using backend::neg;
using backend::set_int64;
using backend::sub;
using backend::submul;
using backend::tdiv_qr;

using backend::denominator;
using backend::numerator;
using backend::pow2;
using backend::rational;
using backend::to_double;

/// A rational r ≤ √x with √x − r < 2^−bits·√x (x ≥ 0): r = ⌊√(n·d·4^s)⌋/(d·2^s) for x = n/d, with s chosen so
/// that the integer root has at least bits + 1 bits, whence its relative error below 2^−bits. The same integers
/// on every backend.
inline Rational sqrt_below(const Rational& x, long bits) {
    const Integer& n = numerator(x);
    if (sign(n) == 0) return Rational(0);
    const Integer& d = denominator(x);
    Integer nd;
    mul(nd, n, d);
    // n·d·4^s ≥ 4^bits·2 needs bit_length(n·d) + 2s ≥ 2·bits + 2.
    const long s = std::max(0L, (2 * bits + 3 - bit_length(nd)) / 2);
    mul_2exp(nd, nd, static_cast<unsigned long>(2 * s));
    Integer den;
    mul_2exp(den, d, static_cast<unsigned long>(s));
    return rational(isqrt(nd), den);
}

}  // namespace ricochet::bignum
