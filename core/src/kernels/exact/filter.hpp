// Signs of the exact kernel's polynomials in doubles: a floating-point filter decides when the rounded
// value is farther from zero than its error bound (derived below); otherwise the doubles are scaled to
// integers (scaled.hpp) and the polynomial is evaluated exactly, in 128-bit integers when the scaled inputs are
// below 2^60, else in big integers (bignum.hpp; no rationals, no gcd). Valid for every finite double.
#pragma once

#include <cmath>

#include "kernels/exact/scaled.hpp"

namespace ricochet::exact_kernel::num {

#if defined(__SIZEOF_INT128__)
/// 128-bit integers (a GCC/Clang extension) for the integer path. 32-bit targets (i386) have none:
/// there every sign the filter declines goes to big integers, which gives the same exact sign, only slower.
#define RICOCHET_EXACT_HAVE_I128 1
__extension__ typedef __int128 I128;
#endif

/// Unit roundoff: a basic operation whose result is normal is exact up to a factor (1 + δ), |δ| ≤ ε.
inline constexpr double k_unit = 0x1p-53;
/// Filter bound of D = a·b − c·d with a, b, c, d each one rounded difference: each difference errs by ε
/// (or is exact), each product by ε more, so |fl(a·b) − AB| ≤ ((1+ε)³ − 1)/(1−ε)³·|fl(a·b)| ≤ 3.01ε·|fl(a·b)|;
/// the final subtraction adds ε(|fl(a·b)| + |fl(c·d)|). In all ≤ 4.02ε·S, S = |fl(a·b)| + |fl(c·d)|;
/// 5ε also covers rounding S and the bound itself, and the absolute 2^-1075 of an underflowed product
/// once S ≥ k_filter_tiny.
inline constexpr double k_det_bound = 5.0 * k_unit;
/// Filter bound of |P − C|² − R² with R = r1 + r2: dx² + dy² errs by ≤ 4.02ε of itself (difference,
/// square, sum), R² by ≤ 3.01ε (sum, square), the subtraction by ε of the sum: ≤ 5.03ε of the sum; 6ε
/// covers the rest as above.
inline constexpr double k_circle_bound = 6.0 * k_unit;
/// Below this sum of magnitudes a product may have underflowed by more than the margin: decline.
inline constexpr double k_filter_tiny = 0x1p-960;

inline int sign_of(double v) { return (v > 0.0) - (v < 0.0); }
#if RICOCHET_EXACT_HAVE_I128
inline int sign_of(I128 v) { return (v > 0) - (v < 0); }
#endif

/// sign((a1 − a0)(b1 − b0) − (c1 − c0)(d1 − d0)), exactly.
inline int det_sign(double a1, double a0, double b1, double b0, double c1, double c0, double d1, double d0) {
    const double l = (a1 - a0) * (b1 - b0);
    const double r = (c1 - c0) * (d1 - d0);
    const double s = std::fabs(l) + std::fabs(r);
    // S infinite or NaN (an overflow) or too small fails the test and falls through.
    if (s >= k_filter_tiny && s <= 0x1p1023 && std::fabs(l - r) > k_det_bound * s) return sign_of(l - r);
    Scale sc;
    for (double x : {a1, a0, b1, b0, c1, c0, d1, d0}) sc.add(x);
    const int k = sc.exponent();
#if RICOCHET_EXACT_HAVE_I128
    if (sc.fits(k_small_bits)) {
        const auto i = [k](double x) { return scaled_small(x, k); };
        const I128 lp = static_cast<I128>(i(a1) - i(a0)) * (i(b1) - i(b0));
        const I128 rp = static_cast<I128>(i(c1) - i(c0)) * (i(d1) - i(d0));
        return sign_of(lp - rp);
    }
#endif
    bignum::Integer z[8];
    const double xs[8] = {a1, a0, b1, b0, c1, c0, d1, d0};
    for (int j = 0; j < 8; ++j) scaled_big(z[j], xs[j], k);
    const bignum::Integer v = (z[0] - z[1]) * (z[2] - z[3]) - (z[4] - z[5]) * (z[6] - z[7]);
    return bignum::sign(v);
}

/// sign((x1 − x0)² + (y1 − y0)² − (r1 + r2)²), exactly.
inline int circle_sign(double x1, double x0, double y1, double y0, double r1, double r2) {
    const double dx = x1 - x0, dy = y1 - y0, rs = r1 + r2;
    const double d2 = dx * dx + dy * dy;
    const double r2s = rs * rs;
    const double s = d2 + r2s;
    if (s >= k_filter_tiny && s <= 0x1p1023 && std::fabs(d2 - r2s) > k_circle_bound * s) return sign_of(d2 - r2s);
    Scale sc;
    for (double x : {x1, x0, y1, y0, r1, r2}) sc.add(x);
    const int k = sc.exponent();
#if RICOCHET_EXACT_HAVE_I128
    if (sc.fits(k_small_bits)) {
        const auto i = [k](double x) { return static_cast<I128>(scaled_small(x, k)); };
        const I128 ex = i(x1) - i(x0), ey = i(y1) - i(y0), er = i(r1) + i(r2);
        return sign_of(ex * ex + ey * ey - er * er);
    }
#endif
    bignum::Integer z[6];
    const double xs[6] = {x1, x0, y1, y0, r1, r2};
    for (int j = 0; j < 6; ++j) scaled_big(z[j], xs[j], k);
    const bignum::Integer ex = z[0] - z[1], ey = z[2] - z[3], er = z[4] + z[5];
    return bignum::sign(bignum::Integer(ex * ex + ey * ey - er * er));
}

}  // namespace ricochet::exact_kernel::num
