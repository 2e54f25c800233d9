// Internal: the two number types a disc decision is evaluated in, and exact signs of a + b·√c.
//
// Every decision of a disc against a wall or a circle is the sign of a polynomial in the input doubles, or of
// p + q·√r with polynomials p, q, r (r ≥ 0): a face's shifted line carries |n| = √(n·n), a cap's entry time
// (−β − √Δ)/a. Each is written once as a template over the number type and evaluated twice at most:
//   Approx  a double with a bound on its distance to the exact value (a running error bound): the filter;
//           its sign is trusted only when |value| exceeds the bound.
//   Z       GMP integers, every input double scaled by one common power of two: exact, always decided. The
//           square roots are never taken: sign(p + q·√r) compares p² with q²·r (sign2 below).
// The polynomials are homogeneous in lengths, so the common scale does not change a sign.
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>

#include "exact/bignum.hpp"
#include "ricochet/vec2.hpp"

namespace ricochet::disc {

// ---------------------------------------------------------------------------------------------------------------
// Approx: value v and bound e with |exact − v| ≤ e.

/// A double with an absolute error bound. Each operation adds its own rounding, |v|·2^−53, and 2^−1022 for
/// a result that underflowed (a subnormal result errs by at most 2^−1075 absolutely); the bound itself is
/// computed in doubles and so may be low by a few ulps, which the decision below covers with a 2^−40 margin.
struct Approx {
    double v = 0.0;
    double e = 0.0;
};

/// Unit roundoff and the absolute term of each operation (see Approx).
inline constexpr double k_u = 0x1p-53;
inline constexpr double k_eta = 0x1p-1022;

inline Approx operator+(Approx a, Approx b) {
    const double v = a.v + b.v;
    return {v, a.e + b.e + std::fabs(v) * k_u + k_eta};
}
inline Approx operator-(Approx a, Approx b) {
    const double v = a.v - b.v;
    return {v, a.e + b.e + std::fabs(v) * k_u + k_eta};
}
inline Approx operator-(Approx a) { return {-a.v, a.e}; }
inline Approx operator*(Approx a, Approx b) {
    // (a.v + δa)(b.v + δb) − a.v·b.v = a.v·δb + b.v·δa + δa·δb
    const double v = a.v * b.v;
    return {v, std::fabs(a.v) * b.e + std::fabs(b.v) * a.e + a.e * b.e + std::fabs(v) * k_u + k_eta};
}
/// √x of a value whose exact value is ≥ 0 (the caller knows it is).
inline Approx sqrt(Approx a) {
    // |√x − √v| = |x − v|/(√x + √v) ≤ e/√v, and ≤ √(v + e) whatever v is.
    const double wide = std::sqrt(std::fmax(a.v + a.e, 0.0)) * (1.0 + 4.0 * k_u);
    if (!(a.v > 0.0)) return {0.0, wide + k_eta};
    const double s = std::sqrt(a.v);
    return {s, std::fmin(a.e / s, wide) * (1.0 + 4.0 * k_u) + s * k_u + k_eta};
}

/// sign(x) if the bound decides it, else nothing (also for a value or bound that overflowed).
inline std::optional<int> sign(Approx a) {
    if (!std::isfinite(a.v) || !std::isfinite(a.e)) return std::nullopt;
    if (std::fabs(a.v) > a.e * (1.0 + 0x1p-40) + k_eta) return a.v > 0.0 ? 1 : -1;
    // Nothing was rounded (an input double itself): its sign is exact, zero included.
    if (a.e == 0.0) return a.v > 0.0 ? 1 : a.v < 0.0 ? -1 : 0;
    return std::nullopt;
}
/// sign(a + b·√c), c's exact value ≥ 0, if the bound decides it.
inline std::optional<int> sign2(Approx a, Approx b, Approx c) { return sign(a + b * sqrt(c)); }
/// sign(a + b·√c + d·√f), c and f exactly ≥ 0, if the bound decides it.
inline std::optional<int> sign3(Approx a, Approx b, Approx c, Approx d, Approx f) {
    return sign(a + b * sqrt(c) + d * sqrt(f));
}
/// An input double, exact.
inline Approx approx(double x) { return {x, 0.0}; }

// ---------------------------------------------------------------------------------------------------------------
// Z: exact integers at a common scale.

/// An exact integer; an input double x is x·2^−k for the decision's common k.
using Z = bignum::Integer;

/// The smallest power of two among the ulps of some doubles: x·2^−k is an integer for each of them.
class Scale {
public:
    /// Counts x in (zero counts for nothing).
    void add(double x) {
        if (x == 0.0) return;
        int ex = 0;
        std::frexp(x, &ex);
        // x = m·2^(ex − 53) with m a 53-bit integer (subnormals included: frexp normalizes them).
        k_ = std::min(k_, ex - 53);
    }
    void add(Vec2 p) {
        add(p.x);
        add(p.y);
    }
    /// k (0 if every number was zero).
    int exponent() const { return k_ == k_none ? 0 : k_; }

private:
    static constexpr int k_none = 1 << 20;
    int k_ = k_none;
};

/// x·2^−k exactly; x must be a multiple of 2^k (Scale).
inline Z exact(double x, int k) {
    if (x == 0.0) return 0;
    int ex = 0;
    const double m = std::ldexp(std::frexp(x, &ex), 53);  // an integer of magnitude below 2^53: exact as int64
    Z z;
    bignum::set_int64(z, static_cast<std::int64_t>(m));
    const int shift = ex - 53 - k;
    bignum::mul_2exp(z, z, static_cast<unsigned long>(shift));
    return z;
}

inline std::optional<int> sign(const Z& a) { return bignum::sign(a); }
/// sign(a + b·√c), c ≥ 0: if a and b·√c have one sign, that sign; else compare a² with b²·c.
inline int sign2_exact(const Z& a, const Z& b, const Z& c) {
    const int sa = bignum::sign(a);
    const int sb = bignum::sign(c) == 0 ? 0 : bignum::sign(b);
    if (sb == 0) return sa;
    if (sa == 0 || sa == sb) return sb;
    // a + b√c has a's sign iff a² > b²c
    const Z diff = a * a - b * b * c;
    return sa * bignum::sign(diff);
}
inline std::optional<int> sign2(const Z& a, const Z& b, const Z& c) { return sign2_exact(a, b, c); }
/// sign(a + b·√c + d·√f), c, f ≥ 0: with L = a + b√c and M = d√f, sign(L + M) is theirs if they agree, else
/// sign(L)·sign(L² − M²), and L² − M² = (a² + b²c − d²f) + 2ab·√c.
inline std::optional<int> sign3(const Z& a, const Z& b, const Z& c, const Z& d, const Z& f) {
    const int sl = sign2_exact(a, b, c);
    const int sm = bignum::sign(f) == 0 ? 0 : bignum::sign(d);
    if (sm == 0) return sl;
    if (sl == 0 || sl == sm) return sm;
    const Z p = a * a + b * b * c - d * d * f;
    const Z q = 2 * a * b;
    return sl * sign2_exact(p, q, c);
}

}  // namespace ricochet::disc
