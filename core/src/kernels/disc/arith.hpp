// Internal: the two number types a disc decision is evaluated in, and exact signs of a + b·√c.
//
// Every decision of a disc against a wall or a circle is the sign of a polynomial in the input doubles, or of
// p + q·√r with polynomials p, q, r (r ≥ 0): a face's shifted line carries |n| = √(n·n), a cap's entry time
// (−β − √Δ)/a. Each is written once as a template over the number type and evaluated three times at most:
//   Approx  a double with a bound on its distance to the exact value (a running error bound): the filter;
//           its sign is trusted only when |value| exceeds the bound.
//   Approx2 a double-double with such a bound, every rounding computed exactly, so that a bound of 0 means an
//           exact value: the near-ties and the exact ties of inputs with few significant bits (the point
//           kernels' expansion stage, staged_sign.hpp, in the same place). No square root: sign(p + q·√r) as Z.
//   Z       GMP integers, every input double scaled by one common power of two: exact, always decided. The
//           square roots are never taken: sign(p + q·√r) compares p² with q²·r (sign2 below).
// The polynomials are homogeneous in lengths, so the common scale does not change a sign.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

#include "base/bignum.hpp"
#include "ricochet/bits.hpp"
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
// Approx2: the second stage, a double-double hi + lo with a bound e on its distance to the exact value.
//
// Every rounding an operation makes is computed exactly (two-sum; Dekker's product by Veltkamp's split, exact for
// factors in [2^−450, 2^450]) and either kept (the leading terms) or added to e (the dropped ones), so e = 0 means
// the value is exact: a true tie (a tangent, a contact exactly at an end) of inputs with few significant bits is
// decided here, as is a near-tie within 2^−100 or so of its size; only the rest reaches GMP. Magnitudes outside the
// split's range, and underflow, add an absolute 2^−1000 or a relative 2^−52 instead. The bound is summed in
// doubles and so may be low by a few ulps, which the decision covers with a 2^−40 margin as Approx's does.
// The sum and the product are always inlined: a call passes three doubles in memory each way, and inlined, the
// branches on inputs that are doubles (lo = 0) fold away.

/// A double-double with an error bound: the exact value is within e of hi + lo.
struct Approx2 {
    double hi = 0.0;
    double lo = 0.0;
    double e = 0.0;
};

namespace fine {

/// a + b = s + t exactly (Knuth's two-sum).
inline void two_sum(double a, double b, double& s, double& t) {
    s = a + b;
    const double bv = s - a;
    t = (a - (s - bv)) + (b - bv);
}
/// Veltkamp's split of x into two halves of at most 26 bits.
inline void split(double x, double& hi, double& lo) {
    const double c = 134217729.0 * x;  // 2^27 + 1
    hi = c - (c - x);
    lo = x - hi;
}
/// Within this range a factor's split and Dekker's product are exact (no overflow, no partial product underflows).
inline bool splittable(double x) {
    const double m = std::fabs(x);
    return m == 0.0 || (m >= 0x1p-450 && m <= 0x1p450);
}
/// a·b = p + err: exactly for splittable factors; otherwise err = 0 and slop grows by a bound on the error.
inline void two_prod(double a, double b, double& p, double& err, double& slop) {
    p = a * b;
    if (splittable(a) && splittable(b)) {
        double ah, al, bh, bl;
        split(a, ah, al);
        split(b, bh, bl);
        err = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
    } else {
        err = 0.0;
        slop += std::fabs(p) * 0x1p-52 + 0x1p-1000;
    }
}
/// An error bound that is 0 only when every term is: a term that underflowed to 0 counts 2^−1000.
inline double term(double x, double y) {
    if (x == 0.0 || y == 0.0) return 0.0;
    return x * y + 0x1p-1000;
}

}  // namespace fine

[[gnu::always_inline]] inline Approx2 operator+(Approx2 a, Approx2 b) {
    // Two doubles (an input, a product of two): their sum is exactly two-sum's pair.
    if (a.lo == 0.0 && b.lo == 0.0) {
        Approx2 out;
        fine::two_sum(a.hi, b.hi, out.hi, out.lo);
        out.e = a.e + b.e;
        return out;
    }
    double s, t, l1, r1, l2, r2;
    fine::two_sum(a.hi, b.hi, s, t);
    fine::two_sum(a.lo, b.lo, l1, r1);
    fine::two_sum(t, l1, l2, r2);
    Approx2 out;
    fine::two_sum(s, l2, out.hi, out.lo);
    // dropped: r1 + r2, each exact
    out.e = a.e + b.e + std::fabs(r1) + std::fabs(r2);
    return out;
}
inline Approx2 operator-(Approx2 a) { return {-a.hi, -a.lo, a.e}; }
inline Approx2 operator-(Approx2 a, Approx2 b) { return a + (-b); }
[[gnu::always_inline]] inline Approx2 operator*(Approx2 a, Approx2 b) {
    // (a.hi + a.lo)(b.hi + b.lo) = p + pe + (c1 + f1) + (c2 + f2) + (c3 + f3); kept: p + pe + c1 + c2 + c3 (their
    // sums' roundings g1..g3 dropped), dropped: f1..f3, g1..g3; and the inputs' errors, propagated.
    double slop = 0.0, p, pe;
    fine::two_prod(a.hi, b.hi, p, pe, slop);
    Approx2 out;
    if (a.lo == 0.0 && b.lo == 0.0) {
        // Two doubles: the product is exactly Dekker's pair, already normalized.
        out.hi = p;
        out.lo = pe;
    } else {
        double c1, f1, c2, f2, c3, f3;
        fine::two_prod(a.hi, b.lo, c1, f1, slop);
        fine::two_prod(a.lo, b.hi, c2, f2, slop);
        fine::two_prod(a.lo, b.lo, c3, f3, slop);
        double m1, g1, m2, g2, l, g3;
        fine::two_sum(c1, c2, m1, g1);
        fine::two_sum(m1, c3, m2, g2);
        fine::two_sum(pe, m2, l, g3);
        fine::two_sum(p, l, out.hi, out.lo);
        slop += std::fabs(f1) + std::fabs(f2) + std::fabs(f3) + std::fabs(g1) + std::fabs(g2) + std::fabs(g3);
    }
    out.e = slop;
    if (a.e != 0.0 || b.e != 0.0) {
        const double ma = std::fabs(a.hi) + std::fabs(a.lo), mb = std::fabs(b.hi) + std::fabs(b.lo);
        out.e += (fine::term(ma, b.e) + fine::term(mb, a.e) + fine::term(a.e, b.e)) * (1.0 + 0x1p-50);
    }
    return out;
}

/// √x of a value whose exact value is ≥ 0 (the caller knows it is), for constructions: s0 = √(hi) and one Newton
/// step, s0 + (x − s0²)/(2·s0), whose truncation, ≤ (x − s0²)²/(8·s0³) ≤ 2^−104·√x, and roundings are within 2^−98
/// of √x; exact (no step) when s0² = x. The input's error e adds ≤ min(e/√v, √e) (as Approx's sqrt).
inline Approx2 sqrt(Approx2 a) {
    const double v = a.hi + a.lo;
    if (!(v > 0.0)) return {0.0, 0.0, a.e == 0.0 && v == 0.0 ? 0.0 : std::sqrt(std::fmax(v, 0.0) + a.e) * 1.001 + 0x1p-1000};
    const double s0 = std::sqrt(v);
    double slop = 0.0, p, pe;
    fine::two_prod(s0, s0, p, pe, slop);
    // x − s0² = (hi − p) − pe + lo: hi − p is exact (p is within a few ulps of hi), the rest rounds by ≤ 2^−104·x.
    const double r = ((a.hi - p) - pe) + a.lo;
    Approx2 out;
    if (r == 0.0 && slop == 0.0 && a.lo == 0.0 && pe == 0.0 && a.hi == p) {
        out = {s0, 0.0, 0.0};
    } else {
        fine::two_sum(s0, r / (2.0 * s0), out.hi, out.lo);
        out.e = s0 * 0x1p-98 + slop / s0;
    }
    if (a.e != 0.0) out.e += std::fmin(a.e / (s0 * (1.0 - 0x1p-50)), std::sqrt(a.e) * (1.0 + 0x1p-50)) + 0x1p-1000;
    return out;
}
/// a/b for constructions: q1 = hi/hi, then the remainder ρ = a − q1·b (Approx2, with its bound) over b: the
/// quotient's error is ρ's over |b|, ρ/b's rounding and b's own low part and error, each bounded; nothing useful
/// (an infinite bound) when b's bound reaches its value.
inline Approx2 operator/(Approx2 a, Approx2 b) {
    const double bmin = std::fabs(b.hi) - std::fabs(b.lo) - b.e;
    if (!(bmin > 0.0)) return {0.0, 0.0, HUGE_VAL};
    const double q1 = a.hi / b.hi;
    const Approx2 rho = a - Approx2{q1, 0.0, 0.0} * b;
    const double q2 = rho.hi / b.hi;
    Approx2 out;
    fine::two_sum(q1, q2, out.hi, out.lo);
    const double mr = std::fabs(rho.hi) + std::fabs(rho.lo);
    out.e = ((rho.e + mr * (0x1p-51 + b.e / bmin)) / bmin) * (1.0 + 0x1p-40) + std::fabs(q2) * 0x1p-52 + 0x1p-1000;
    return out;
}
/// The smaller of the gaps between finite x and its two neighbouring doubles, as std::nextafter's would give them:
/// |x|'s bits one step down and one up (0's neighbours are ±2^−1074; the largest double's upper one is infinity,
/// whose gap fmin passes over). Each difference of neighbours is exact.
inline double smaller_gap(double x) {
    const double a = std::fabs(x);
    const std::uint64_t bits = bits_of(a);
    if (bits == 0) return std::numeric_limits<double>::denorm_min();
    return std::fmin(double_of_bits(bits + 1) - a, a - double_of_bits(bits - 1));
}

/// The double nearest to the exact value, if the bound decides it: hi + lo rounds to x, and every value within e of
/// hi + lo lies closer to x than half the gap to x's nearer neighbour.
inline std::optional<double> nearest_double(Approx2 a) {
    if (!std::isfinite(a.hi) || !std::isfinite(a.lo) || !std::isfinite(a.e)) return std::nullopt;
    const double x = a.hi + a.lo;
    // hi − x is 0 or one of hi's ulps (exact); r is the distance from hi + lo to x, rounded by ≤ 2^−53·|r|.
    const double r = (a.hi - x) + a.lo;
    const double gap = smaller_gap(x);
    if (0.5 * gap - std::fabs(r) * (1.0 + 0x1p-50) > a.e * (1.0 + 0x1p-40) + 0x1p-1070) return x;
    return std::nullopt;
}

/// sign(x) if the bound decides it (e = 0: the exact sign, zero included), else nothing.
inline std::optional<int> sign(Approx2 a) {
    if (!std::isfinite(a.hi) || !std::isfinite(a.lo) || !std::isfinite(a.e)) return std::nullopt;
    // hi + lo is normalized (two-sum): |lo| ≤ ulp(hi)/2, and hi + lo has hi's sign unless hi = 0.
    if (a.e == 0.0) return a.hi != 0.0 ? (a.hi > 0.0 ? 1 : -1) : (a.lo > 0.0 ? 1 : a.lo < 0.0 ? -1 : 0);
    const double m = std::fabs(a.hi) - std::fabs(a.lo);
    if (m * (1.0 - 0x1p-50) > a.e * (1.0 + 0x1p-40) + 0x1p-1000) return a.hi > 0.0 ? 1 : -1;
    return std::nullopt;
}
/// sign(a + b·√c), c's exact value ≥ 0, without a square root: Z's rule (sign2_exact below) on bounded values.
inline std::optional<int> sign2(Approx2 a, Approx2 b, Approx2 c) {
    const auto sa = sign(a);
    const auto sc = sign(c);
    if (!sa || !sc) return std::nullopt;
    if (*sc == 0) return sa;
    const auto sb = sign(b);
    if (!sb) return std::nullopt;
    if (*sb == 0) return sa;
    if (*sa == 0 || *sa == *sb) return sb;
    const auto diff = sign(a * a - b * b * c);
    if (!diff) return std::nullopt;
    return *sa * *diff;
}
/// sign(a + b·√c + d·√f), c and f exactly ≥ 0: Z's rule (sign3 below) on bounded values.
inline std::optional<int> sign3(Approx2 a, Approx2 b, Approx2 c, Approx2 d, Approx2 f) {
    const auto sl = sign2(a, b, c);
    const auto sf = sign(f);
    if (!sl || !sf) return std::nullopt;
    if (*sf == 0) return sl;
    const auto sd = sign(d);
    if (!sd) return std::nullopt;
    if (*sd == 0) return sl;
    if (*sl == 0 || *sl == *sd) return sd;
    const auto r = sign2(a * a + b * b * c - d * d * f, Approx2{2.0, 0.0, 0.0} * a * b, c);
    if (!r) return std::nullopt;
    return *sl * *r;
}

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
