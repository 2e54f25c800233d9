// bignum.hpp's operations on GMP (gmpxx): the default backend, and the faster. Each is one GMP call on the
// numbers' own mpz_t/mpq_t, so code written against bignum.hpp compiles to what it did against GMP directly.
#pragma once

#include <cstdint>

#include <gmp.h>
#include <gmpxx.h>

namespace ricochet::bignum::gmp_backend {

/// An integer of any size.
using Integer = mpz_class;
/// A rational of any size, kept in lowest terms.
using Rational = mpq_class;

/// out = v, exactly. Through limbs, on every platform: mpz_set_si takes a long, which has 32 bits on i386 and
/// wasm32 and would cut a 53-bit mantissa.
inline void set_int64(Integer& out, std::int64_t v) {
    // |v| as unsigned: exact even for INT64_MIN.
    const std::uint64_t m = v < 0 ? std::uint64_t{0} - static_cast<std::uint64_t>(v) : static_cast<std::uint64_t>(v);
    // One 64-bit word, least significant first, native byte order.
    mpz_import(out.get_mpz_t(), 1, -1, sizeof m, 0, 0, &m);
    if (v < 0) mpz_neg(out.get_mpz_t(), out.get_mpz_t());
}

/// The low 64 bits of |z| (mpz_get_ui gives a long's worth only).
inline std::uint64_t low_uint64(const Integer& z) {
    std::uint64_t r = 0;
    const auto limbs = static_cast<int>(mpz_size(z.get_mpz_t()));
    for (int i = 0; i < limbs && i * GMP_NUMB_BITS < 64; ++i)
        r |= static_cast<std::uint64_t>(mpz_getlimbn(z.get_mpz_t(), i)) << (i * GMP_NUMB_BITS);
    return r;
}

/// −1, 0 or +1.
inline int sign(const Integer& z) { return mpz_sgn(z.get_mpz_t()); }
/// −1, 0 or +1.
inline int sign(const Rational& q) { return mpq_sgn(q.get_mpq_t()); }
/// Negative, zero or positive as a <, = or > b.
inline int compare(const Integer& a, const Integer& b) { return mpz_cmp(a.get_mpz_t(), b.get_mpz_t()); }
/// The number of bits of |z|, z ≠ 0: 2^(n−1) ≤ |z| < 2^n.
inline long bit_length(const Integer& z) { return static_cast<long>(mpz_sizeinbase(z.get_mpz_t(), 2)); }

/// out = a + b.
inline void add(Integer& out, const Integer& a, const Integer& b) { mpz_add(out.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t()); }
/// out = a − b.
inline void sub(Integer& out, const Integer& a, const Integer& b) { mpz_sub(out.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t()); }
/// out = a·b.
inline void mul(Integer& out, const Integer& a, const Integer& b) { mpz_mul(out.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t()); }
/// out += a·b.
inline void addmul(Integer& out, const Integer& a, const Integer& b) {
    mpz_addmul(out.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
}
/// out −= a·b.
inline void submul(Integer& out, const Integer& a, const Integer& b) {
    mpz_submul(out.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t());
}
/// out = −a.
inline void neg(Integer& out, const Integer& a) { mpz_neg(out.get_mpz_t(), a.get_mpz_t()); }
/// out = |a|.
inline void abs(Integer& out, const Integer& a) { mpz_abs(out.get_mpz_t(), a.get_mpz_t()); }
/// out = a·2^n.
inline void mul_2exp(Integer& out, const Integer& a, unsigned long n) {
    mpz_mul_2exp(out.get_mpz_t(), a.get_mpz_t(), static_cast<mp_bitcnt_t>(n));
}
/// q = a/d truncated towards zero, r = a − q·d (d ≠ 0).
inline void tdiv_qr(Integer& q, Integer& r, const Integer& a, const Integer& d) {
    mpz_tdiv_qr(q.get_mpz_t(), r.get_mpz_t(), a.get_mpz_t(), d.get_mpz_t());
}
/// out = gcd(a, b) ≥ 0.
inline void gcd(Integer& out, const Integer& a, const Integer& b) { mpz_gcd(out.get_mpz_t(), a.get_mpz_t(), b.get_mpz_t()); }
/// out = a/d, where d divides a.
inline void divexact(Integer& out, const Integer& a, const Integer& d) {
    mpz_divexact(out.get_mpz_t(), a.get_mpz_t(), d.get_mpz_t());
}
/// ⌊√a⌋, a ≥ 0.
inline Integer isqrt(const Integer& a) {
    Integer r;
    mpz_sqrt(r.get_mpz_t(), a.get_mpz_t());
    return r;
}

/// x exactly (x finite: every finite double is a rational).
inline Rational rational(double x) { return Rational(x); }
/// num/den in lowest terms, den ≠ 0.
inline Rational rational(const Integer& num, const Integer& den) {
    Rational q(num, den);
    q.canonicalize();
    return q;
}
/// 2^e exactly.
inline Rational pow2(long e) {
    Rational q(1);
    if (e >= 0) mpq_mul_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(e));
    else mpq_div_2exp(q.get_mpq_t(), q.get_mpq_t(), static_cast<mp_bitcnt_t>(-e));
    return q;
}
/// The numerator, with q's sign.
inline const Integer& numerator(const Rational& q) { return q.get_num(); }
/// The denominator, > 0.
inline const Integer& denominator(const Rational& q) { return q.get_den(); }
/// q as a double, truncated towards zero (mpq_get_d): +0 for what truncates to zero, ±infinity from 2^1024.
inline double to_double(const Rational& q) { return q.get_d(); }

}  // namespace ricochet::bignum::gmp_backend
