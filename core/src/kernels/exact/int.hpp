// Int: a big integer (bignum.hpp; never a rational: no gcd), usable as Vec2T's component type. A thin wrapper,
// because Vec2T's defaulted constexpr operator== needs a component whose == is declared constexpr.
#pragma once

#include <utility>

#include "base/bignum.hpp"

namespace ricochet::exact_kernel::num {

/// An arbitrary-precision integer with the arithmetic the exact kernel needs.
template <class M>
struct BasicInt {
    M v;

    BasicInt() = default;
    /// From a machine integer.
    BasicInt(long x) : v(x) {}  // NOLINT: implicit, as for built-in integers
    /// From a big integer.
    explicit BasicInt(M x) : v(std::move(x)) {}

    /// Sum, difference, product and negation, exact.
    friend BasicInt operator+(const BasicInt& a, const BasicInt& b) { return BasicInt(M(a.v + b.v)); }
    friend BasicInt operator-(const BasicInt& a, const BasicInt& b) { return BasicInt(M(a.v - b.v)); }
    friend BasicInt operator*(const BasicInt& a, const BasicInt& b) { return BasicInt(M(a.v * b.v)); }
    friend BasicInt operator-(const BasicInt& a) { return BasicInt(M(-a.v)); }
    /// Comparisons, exact (constexpr only so that Vec2T<BasicInt>'s defaulted == may be).
    friend constexpr bool operator==(const BasicInt& a, const BasicInt& b) { return bignum::compare(a.v, b.v) == 0; }
    friend bool operator<(const BasicInt& a, const BasicInt& b) { return bignum::compare(a.v, b.v) < 0; }
    friend bool operator<=(const BasicInt& a, const BasicInt& b) { return bignum::compare(a.v, b.v) <= 0; }
    /// −1, 0 or +1.
    friend int sgn(const BasicInt& a) { return bignum::sign(a.v); }
};

/// The exact kernel's integer.
using Int = BasicInt<bignum::Integer>;

}  // namespace ricochet::exact_kernel::num
