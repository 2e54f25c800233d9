// Internal: the stages of the predicates' exact path (Shewchuk 1997, "adaptive"), for the two polynomials every
// predicate is made of: a 2×2 determinant and a sum of three squares, of differences each given as a head (the
// rounded difference) and a tail (its exact rounding error, 0 when the difference is exact). Each stage answers
// only when it is certain; the caller (predicates.cpp) tries them in order:
//   1. ordered  (determinants of exact differences): the order of the two rounded products, or on a tie of
//               their rounding errors;
//   2. bounded  the leading terms of the exact expansion plus a rounded tail, farther from zero than a derived
//               bound on everything rounded or dropped;
//   3. complete the whole exact sum in expansion arithmetic.
// Stages 1 and 2 hold for every finite input (their guards decline where they could not); stage 3 needs inputs
// in the expansions' range, and GMP decides beyond it.
#pragma once

#include <cmath>
#include <optional>

#include "ricochet/predicates.hpp"

namespace ricochet::exact::staged {

/// A real number as a double and an exact correction: value = head + tail.
struct Split {
    double head;
    double tail;
};

/// a + b = s.head + s.tail exactly, s.head = fl(a + b) (Knuth's two-sum: exact for all finite a, b whose sum
/// does not overflow, subnormals included).
inline Split two_sum(double a, double b) {
    const double s = a + b;
    const double bv = s - a;
    const double av = s - bv;
    return {s, (a - av) + (b - bv)};
}

/// a − b exactly: fl(a − b) and its rounding error, which is 0 exactly when the difference is exact. Either way
/// |tail| ≤ ε|head|: the error of a rounding to nearest is at most half an ulp, and 0 below the normal range.
inline Split two_diff(double a, double b) { return two_sum(a, -b); }

/// −1, 0 or +1: the sign of v.
inline int sign_of(double v) { return (v > 0.0) - (v < 0.0); }

/// Veltkamp's splitting constant for doubles, 2^27 + 1: x = hi + lo with hi and lo of at most 26 bits each.
inline constexpr double k_split = 134217729.0;
/// Below this magnitude a square's partial products may underflow. Dekker's square error is exact for x = 0 and for
/// 2^-485 ≤ |x| ≤ 2^995: no split overflows (2^27·|x| < 2^1023), and hi and lo are multiples of ulp(x) ≥ 2^-537 of
/// at most 26 bits, so every partial product is a representable multiple of 2^-1074, and Dekker's argument holds
/// as without underflow (Boldo 2006: exponents summing to at least e_min + p − 1 = −970 suffice).
inline constexpr double k_square_min = 0x1p-485;
/// Above this, a sum of two or three squares or products leaves its terms too close to overflow for stage 2.
inline constexpr double k_stage_huge = 0x1p900;
/// Stage 2's bound for a determinant, times L = |l| + |r| (derived in bounded_det).
inline constexpr double k_det_tail = 18.0 * k_eps * k_eps;
/// Stage 2's bound for a sum of squares, times M = X² + Y² + R² rounded (derived in bounded_squares).
inline constexpr double k_squares_tail = 32.0 * k_eps * k_eps;

/// x² − fl(x²) exactly, for x = 0 or 2^-485 ≤ |x| ≤ 2^995, given p = fl(x²): Dekker's product of x by itself
/// (the two cross terms hi·lo as one exact 2hi·lo), with no call to fma, which x86-64 without FMA makes in libm.
[[gnu::always_inline]] inline double square_error(double x, double p) {
    const double t = k_split * x;
    const double hi = t - (t - x);
    const double lo = x - hi;
    return ((hi * hi - p) + (hi + hi) * lo) + lo * lo;
}

/// Stage 1: sign(A·B − C·D) for exact differences A, B, C, D (every tail 0) from l = fl(A·B) and r = fl(C·D).
/// No answer when a tail is not 0, or when l = r and |l| is below k_tiny or infinite.
[[gnu::always_inline]] inline std::optional<int> ordered(Split p, Split q, Split u, Split v, double l,
                                                         double r) {
    if (p.tail != 0.0 || q.tail != 0.0 || u.tail != 0.0 || v.tail != 0.0) return std::nullopt;
    // Rounding is monotonic (A·B ≤ C·D ⇒ fl(A·B) ≤ fl(C·D)), overflow and underflow included: l ≠ r orders the
    // exact products.
    if (l != r) return l > r ? 1 : -1;
    // A tie: A·B − C·D = (A·B − l) − (C·D − r), two fma's. A finite product of magnitude ≥ 2^-968 has an exactly
    // representable rounding error, and the rounded difference of two doubles keeps the sign of the exact one.
    if (!(std::fabs(l) >= k_tiny && std::isfinite(l))) return std::nullopt;
    return sign_of(std::fma(p.head, q.head, -l) - std::fma(u.head, v.head, -r));
}

/// Stage 2: sign((A + a)(B + b) − (C + c)(D + d)) given l = fl(A·B) and r = fl(C·D), each tail at most ε of its
/// head; no answer when the estimate is within its bound, or L = |l| + |r| is outside [k_tiny, k_stage_huge].
[[gnu::always_inline]] inline std::optional<int> bounded_det(Split p, Split q, Split u, Split v, double l,
                                                             double r) {
    const double A = p.head, a = p.tail, B = q.head, b = q.tail, C = u.head, c = u.tail, D = v.head, d = v.tail;
    // det = (l + le) − (r + re) + (A·b + a·B − C·d − c·D) + (a·b − c·d), with A·B = l + le and C·D = r + re, and
    // l − r = s + t exactly (two-sum). est = s + (((t + le) − re) + ((A·b + a·B) − (C·d + c·D))) drops a·b − c·d.
    // With L = |l| + |r|: |t| ≤ ε|s| ≤ ε(1 + ε)L; |le| + |re| ≤ εL; |A·b| ≤ ε|A·B| ≤ ε|l|/(1 − ε) and likewise
    // the other first-order terms, ≤ 2εL/(1 − ε) in all; |a·b − c·d| ≤ ε²L/(1 − ε). le and re are fma's, rounded
    // once (≤ ε); t, le, re then pass through three rounded additions (≤ γ3 = 3ε/(1 − 3ε)), the first-order
    // terms through a product and three additions (≤ γ4): |det − (s + rest)| ≤ (γ3(2 + ε) + ε)εL +
    // γ4·2εL/(1 − ε) + ε²L/(1 − ε) ≤ 16ε²L(1 + 5ε). An underflow adds ≤ 2^-1075 to each of the eight rounded
    // products and fma's, ≤ 2^-1071 in all. fl(s + rest) keeps the sign of s + rest and errs by ≤ ε of it;
    // fl(L) ≥ (1 − ε)L, and fl(L) ≥ k_tiny makes the bound k_det_tail·fl(L) = 18ε²·fl(L) normal, so it rounds by
    // ≤ ε: |fl(est)| beyond it gives |s + rest| > 18ε²L(1 − ε)²/(1 + ε), which exceeds 16ε²L(1 + 5ε) + 2^-1071.
    // fl(L) ≤ k_stage_huge keeps |A·B|, |C·D| ≤ 2^901 and every term finite.
    const double big = std::fabs(l) + std::fabs(r);
    if (!(big >= k_tiny && big <= k_stage_huge)) return std::nullopt;
    const double le = std::fma(A, B, -l);
    const double re = std::fma(C, D, -r);
    const Split st = two_sum(l, -r);
    const double rest = ((st.tail + le) - re) + ((A * b + a * B) - (C * d + c * D));
    const double est = st.head + rest;
    if (std::fabs(est) > k_det_tail * big) return sign_of(est);
    return std::nullopt;
}

/// Stage 2: sign((X + x)² + (Y + y)² − (R + ρ)²), each tail at most ε of its head; no answer when the estimate is
/// within its bound, a non-zero head is below k_square_min, or M = X² + Y² + R² (rounded) is outside
/// [k_tiny, k_stage_huge].
[[gnu::always_inline]] inline std::optional<int> bounded_squares(Split dx, Split dy, Split rr) {
    const double X = dx.head, x = dx.tail, Y = dy.head, y = dy.tail, R = rr.head, rho = rr.tail;
    // V = (P1 + E1) + (P2 + E2) − (P3 + E3) + 2(X·x + Y·y − R·ρ) + (x² + y² − ρ²), with P1 = fl(X²), E1 = X² − P1
    // exactly (square_error), and so on, P1 + P2 = S + s and S − P3 = H + h exactly (two-sum).
    // est = H + (((((s + h) + E1) + E2) − E3) + 2((X·x + Y·y) − R·ρ)) drops x² + y² − ρ². With M = P1 + P2 + P3:
    // |s| ≤ ε|S| ≤ ε(1 + ε)M; |H| ≤ (1 + ε)max(S, P3) ≤ (1 + ε)²M, so |h| ≤ ε(1 + ε)²M; |E1| + |E2| + |E3| ≤ εM
    // (the squares are normal): the five sum to ≤ 3ε(1 + ε)²M. |X·x| ≤ εX² ≤ εP1/(1 − ε) and likewise, so the
    // first-order terms sum to ≤ 2εM/(1 − ε), and |x² + y² − ρ²| ≤ ε²M/(1 − ε). The five pass through at most five
    // rounded additions (≤ γ5 = 5ε/(1 − 5ε)), the first-order terms through a product and three additions (≤ γ4;
    // the factor 2 is exact): |V − (H + rest)| ≤ γ5·3ε(1 + ε)²M + γ4·2εM/(1 − ε) + ε²M/(1 − ε) ≤ 24ε²M(1 + 8ε).
    // An underflowed product X·x, Y·y or R·ρ adds ≤ 2^-1075, ≤ 2^-1071 in all. fl(H + rest) keeps the sign of
    // H + rest; fl(M) ≥ (1 − ε)²M, and fl(M) ≥ k_tiny makes the bound k_squares_tail·fl(M) = 32ε²·fl(M) normal:
    // |fl(est)| beyond it gives |H + rest| > 32ε²M(1 − ε)³/(1 + ε), which exceeds 24ε²M(1 + 8ε) + 2^-1071.
    // fl(M) ≤ k_stage_huge keeps |X|, |Y|, |R| ≤ 2^451 and every term finite.
    const double p1 = X * X, p2 = Y * Y, p3 = R * R;
    const Split s = two_sum(p1, p2);
    const double m = s.head + p3;
    const auto splits = [](double v) { return v == 0.0 || std::fabs(v) >= k_square_min; };
    if (!(m >= k_tiny && m <= k_stage_huge && splits(X) && splits(Y) && splits(R))) return std::nullopt;
    const double e1 = square_error(X, p1), e2 = square_error(Y, p2), e3 = square_error(R, p3);
    const Split h = two_sum(s.head, -p3);
    const double rest = ((((s.tail + h.tail) + e1) + e2) - e3) + 2.0 * ((X * x + Y * y) - R * rho);
    const double est = h.head + rest;
    if (std::fabs(est) > k_squares_tail * m) return sign_of(est);
    return std::nullopt;
}

/// An exact sum of doubles, kept as a non-overlapping expansion in increasing magnitude; zero components are
/// never stored, so an empty expansion is exactly zero. Stage 3's precondition holds for every value added.
class Expansion {
public:
    /// Adds b exactly (Shewchuk's grow-expansion with zero elimination).
    void add(double b) {
        if (b == 0.0) return;
        double q = b;
        int h = 0;
        for (int i = 0; i < n_; ++i) {
            const Split s = two_sum(q, c_[i]);
            q = s.head;
            if (s.tail != 0.0) c_[h++] = s.tail;
        }
        if (q != 0.0) c_[h++] = q;
        n_ = h;
    }
    /// Adds k·a·b exactly, for k = ±1 or ±2: a·b = p + fma(a, b, −p) exactly.
    void add_product(double a, double b, double k = 1.0) {
        const double p = a * b;
        if (p == 0.0) return;  // a factor is 0: under the precondition no product underflows
        add(k * p);
        add(k * std::fma(a, b, -p));
    }
    /// The largest component carries the sign of the whole sum.
    int sign() const { return n_ == 0 ? 0 : sign_of(c_[n_ - 1]); }

private:
    // Stage 3 adds at most 18 doubles, and each add grows the expansion by at most one component.
    double c_[18];
    int n_ = 0;
};

// Stage 3's precondition: every head and tail is a multiple of 2^-502 of magnitude at most 2^451, as are the
// differences (and their tails) of doubles whose non-zero magnitudes lie in [2^-450, 2^450]. Then every product
// is 0 or a multiple of 2^-1004 ≥ 2^-1022 below 2^903: nothing underflows or overflows, and each fma gives a
// product's rounding error exactly.

/// Stage 3: sign((A + a)(B + b) − (C + c)(D + d)) exactly, as the sum of the eight products. Out of line: rare.
[[gnu::noinline]] inline int complete_det(Split p, Split q, Split u, Split v) {
    Expansion e;
    e.add_product(p.tail, q.tail);
    e.add_product(u.tail, v.tail, -1.0);
    e.add_product(p.head, q.tail);
    e.add_product(p.tail, q.head);
    e.add_product(u.head, v.tail, -1.0);
    e.add_product(u.tail, v.head, -1.0);
    e.add_product(p.head, q.head);
    e.add_product(u.head, v.head, -1.0);
    return e.sign();
}

/// Stage 3: sign((X + x)² + (Y + y)² − (R + ρ)²) exactly, as X² + 2X·x + x² + … . Out of line: rare.
[[gnu::noinline]] inline int complete_squares(Split dx, Split dy, Split rr) {
    Expansion e;
    e.add_product(dx.tail, dx.tail);
    e.add_product(dy.tail, dy.tail);
    e.add_product(rr.tail, rr.tail, -1.0);
    e.add_product(dx.head, dx.tail, 2.0);
    e.add_product(dy.head, dy.tail, 2.0);
    e.add_product(rr.head, rr.tail, -2.0);
    e.add_product(dx.head, dx.head);
    e.add_product(dy.head, dy.head);
    e.add_product(rr.head, rr.head, -1.0);
    return e.sign();
}

}  // namespace ricochet::exact::staged
