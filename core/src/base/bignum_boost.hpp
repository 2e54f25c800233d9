// bignum.hpp's operations on Boost.Multiprecision's cpp_int and cpp_rational (Debian's libboost-dev, header
// only): the backend for targets with no GMP, wasm32 among them. Slower than GMP, the same values: every
// operation is exact, and to_double truncates as GMP's mpq_get_d does (derived below, not left to Boost's
// convert_to, which rounds).
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include <boost/multiprecision/cpp_int.hpp>

namespace ricochet::bignum::boost_backend {

/// An integer of any size.
using Integer = boost::multiprecision::cpp_int;
/// A rational of any size, kept in lowest terms.
using Rational = boost::multiprecision::cpp_rational;

/// out = v, exactly.
inline void set_int64(Integer& out, std::int64_t v) { out = v; }

/// −1, 0 or +1.
inline int sign(const Integer& z) { return z.sign(); }
/// −1, 0 or +1.
inline int sign(const Rational& q) { return q.sign(); }
/// Negative, zero or positive as a <, = or > b.
inline int compare(const Integer& a, const Integer& b) { return a.compare(b); }
/// The number of bits of |z|, z ≠ 0: 2^(n−1) ≤ |z| < 2^n.
inline long bit_length(const Integer& z) {
    return static_cast<long>(boost::multiprecision::msb(z.sign() < 0 ? Integer(-z) : z)) + 1;
}
/// The low 64 bits of |z|.
inline std::uint64_t low_uint64(const Integer& z) {
    const Integer low = (z.sign() < 0 ? Integer(-z) : z) & Integer(std::numeric_limits<std::uint64_t>::max());
    return low.convert_to<std::uint64_t>();
}

/// out = a + b.
inline void add(Integer& out, const Integer& a, const Integer& b) { out = a + b; }
/// out = a − b.
inline void sub(Integer& out, const Integer& a, const Integer& b) { out = a - b; }
/// out = a·b.
inline void mul(Integer& out, const Integer& a, const Integer& b) { out = a * b; }
/// out += a·b.
inline void addmul(Integer& out, const Integer& a, const Integer& b) { out += a * b; }
/// out −= a·b.
inline void submul(Integer& out, const Integer& a, const Integer& b) { out -= a * b; }
/// out = −a.
inline void neg(Integer& out, const Integer& a) { out = -a; }
/// out = |a|.
inline void abs(Integer& out, const Integer& a) { out = a.sign() < 0 ? Integer(-a) : a; }
/// out = a·2^n.
inline void mul_2exp(Integer& out, const Integer& a, unsigned long n) { out = a << n; }
/// q = a/d truncated towards zero, r = a − q·d (d ≠ 0).
inline void tdiv_qr(Integer& q, Integer& r, const Integer& a, const Integer& d) {
    boost::multiprecision::divide_qr(a, d, q, r);
}
/// out = gcd(a, b) ≥ 0.
inline void gcd(Integer& out, const Integer& a, const Integer& b) { out = boost::multiprecision::gcd(a, b); }
/// out = a/d, where d divides a.
inline void divexact(Integer& out, const Integer& a, const Integer& d) { out = a / d; }
/// ⌊√a⌋, a ≥ 0.
inline Integer isqrt(const Integer& a) { return boost::multiprecision::sqrt(a); }

/// x exactly (x finite). cpp_rational's own conversion is exact too (frexp, then the mantissa as an integer over a
/// power of two); this says so where it is used.
inline Rational rational(double x) { return Rational(x); }
/// num/den in lowest terms, den ≠ 0. The sign goes to the numerator first: Boost 1.74's rational over an unbounded
/// cpp_int throws on a negative denominator ("non-zero singular denominator": it compares it with −max(), which an
/// unbounded type gives as 0).
inline Rational rational(const Integer& num, const Integer& den) {
    return den.sign() < 0 ? Rational(Integer(-num), Integer(-den)) : Rational(num, den);
}
/// 2^e exactly.
inline Rational pow2(long e) {
    const Integer p = Integer(1) << static_cast<unsigned long>(e >= 0 ? e : -e);
    return e >= 0 ? Rational(p) : Rational(Integer(1), p);
}
/// The numerator, with q's sign.
inline Integer numerator(const Rational& q) { return boost::multiprecision::numerator(q); }
/// The denominator, > 0.
inline Integer denominator(const Rational& q) { return boost::multiprecision::denominator(q); }

/// q as a double, truncated towards zero as GMP's mpq_get_d: +0 for what truncates to zero, ±infinity from 2^1024.
inline double to_double(const Rational& q) {
    const Integer n = numerator(q), d = denominator(q);
    const int sg = n.sign();
    if (sg == 0) return 0.0;
    const Integer a = sg < 0 ? Integer(-n) : n;
    const long la = bit_length(a), ld = bit_length(d);
    // 2^(la−1) ≤ a < 2^la and 2^(ld−1) ≤ d < 2^ld, so a·2^sh/d lies in (2^(la−ld+sh−1), 2^(la−ld+sh+1)):
    // sh = 54 − la + ld gives ⌊a·2^sh/d⌋ in [2^53, 2^55), every bit a double can hold and no more than two below.
    const long sh = 54 - la + ld;
    const Integer qt = sh >= 0 ? Integer((a << static_cast<unsigned long>(sh)) / d)
                               : Integer(a / (d << static_cast<unsigned long>(-sh)));
    const auto qi = qt.convert_to<std::uint64_t>();
    // |q| = (qi + f)·2^−sh with 0 ≤ f < 1, and 2^top ≤ |q| < 2^(top+1).
    const long top = static_cast<long>(std::bit_width(qi)) - 1 - sh;
    if (top >= 1024) return sg > 0 ? INFINITY : -INFINITY;
    // The double's ulp at that magnitude: 2^(top−52) for normals, 2^−1074 for subnormals; truncating |q| to a
    // multiple of it is dropping the bits of qi below it (⌊⌊x⌋/2^j⌋ = ⌊x/2^j⌋).
    const long ulp = std::max(top - 52, -1074L);
    const long drop = ulp + sh;  // ≥ 0
    if (drop >= 64) return 0.0;
    const std::uint64_t m = qi >> drop;
    if (m == 0) return 0.0;
    // m < 2^53 and m·2^ulp ≤ DBL_MAX: exact.
    const double mag = std::ldexp(static_cast<double>(m), static_cast<int>(ulp));
    return sg > 0 ? mag : -mag;
}

}  // namespace ricochet::bignum::boost_backend
