// Exact predicates: floating-point filter, then the exact path in stages (staged_sign.hpp): when the differences
// are exact, the order of two rounded products; then the leading terms and a bounded tail; then the complete
// exact sum; big rationals (base/bignum.hpp) beyond the expansions' range.
#include "ricochet/predicates.hpp"

#include <cmath>
#include <initializer_list>
#include <optional>

#include "base/bignum.hpp"
#include "predicates/orient_filter.hpp"
#include "predicates/staged_sign.hpp"

namespace ricochet::exact {
namespace {

using staged::Split;
using staged::two_diff;
using staged::two_sum;

// Filter bound for the circle tests, times 4·d2 + r2 (point_circle) or 4·d2 + 3·r2 (circle_circle), derived
// above each use.
constexpr double k_sq = (1.0 + 16.0 * k_eps) * k_eps;
// Stage 3's range (staged_sign.hpp): every non-zero input in [2^-450, 2^450], so that the differences, their tails
// and all their products are multiples of 2^-1004 below 2^903, none underflowing or overflowing.
constexpr double k_exp_min = 0x1p-450;
constexpr double k_exp_max = 0x1p450;
// compare_crossings: the rounding of its two products l, r and of D = l − r, each ≤ ε relative; 4ε leaves room.
constexpr double k_cross_round = 4.0 * k_eps;
// compare_crossings: the error bound is itself a rounded sum of a few terms; inflating it by 1 + 8ε keeps it
// an upper bound, so the filter never vouches for a sign it should not.
constexpr double k_cross_slack = 1.0 + 8.0 * k_eps;

// Per thread: counting costs a plain increment, and threads stepping balls side by side share no cache line.
thread_local FallbackCounts t_counts;

int sign(double v) { return staged::sign_of(v); }
int sign(const bignum::Rational& v) { return bignum::sign(v); }

bool expansion_safe(std::initializer_list<double> xs) {
    for (double x : xs) {
        const double m = std::fabs(x);
        if (m != 0.0 && (m < k_exp_min || m > k_exp_max)) return false;
    }
    return true;
}

/// Counts a sign found without big rationals in the given stage's counter, and returns it.
int counted(int s, unsigned long long FallbackCounts::*stage) {
    ++t_counts.expansion;
    ++(t_counts.*stage);
    return s;
}

/// Counts a sign found by big rationals (FallbackCounts::gmp), and returns it.
int gmp_sign(const bignum::Rational& v) {
    ++t_counts.gmp;
    return sign(v);
}

bignum::Rational q(double x) { return bignum::rational(x); }

/// sign((A + a)(B + b) − (C + c)(D + d)) in stages 1 and 2 (staged_sign.hpp), with l = fl(A·B), r = fl(C·D).
[[gnu::always_inline]] inline std::optional<int> det_sign(Split p, Split q, Split u, Split v, double l, double r) {
    if (const auto s = staged::ordered(p, q, u, v, l, r)) return counted(*s, &FallbackCounts::ordered);
    if (const auto s = staged::bounded_det(p, q, u, v, l, r)) return counted(*s, &FallbackCounts::bounded);
    return std::nullopt;
}

// orient's filter for compare_crossings (the same operations as orient_filter.hpp's): the value, its bound.
struct Filtered {
    double value;
    double bound;
};

Filtered orient_filtered(Vec2 a, Vec2 b, Vec2 c) {
    const double l = (a.x - c.x) * (b.y - c.y);
    const double r = (a.y - c.y) * (b.x - c.x);
    const double sum = std::fabs(l) + std::fabs(r);
    // Too small to rule out underflow, or overflowed: make the filter decline.
    if (!(sum >= k_tiny) || !std::isfinite(sum)) return {l - r, INFINITY};
    return {l - r, k_ccw * sum};
}

// The last stage of direction_side: sign(e × d) as a complete sum, or by GMP. Out of line: rare.
[[gnu::noinline]] int cross_complete(const Wall& w, Vec2 d) {
    if (expansion_safe({w.p0.x, w.p0.y, w.p1.x, w.p1.y, d.x, d.y})) {
        const Split ex = two_diff(w.p1.x, w.p0.x), ey = two_diff(w.p1.y, w.p0.y);
        return counted(staged::complete_det(ex, {d.y, 0.0}, ey, {d.x, 0.0}), &FallbackCounts::complete);
    }
    return gmp_sign((q(w.p1.x) - q(w.p0.x)) * q(d.y) - (q(w.p1.y) - q(w.p0.y)) * q(d.x));
}

// The exact path of direction_side: sign(e × d) with e = P1 − P0, stages 1 and 2, then the last stage.
[[gnu::noinline]] int cross_exact(const Wall& w, Vec2 d, double l, double r) {
    // e × d = (x1 − x0)·dy − (y1 − y0)·dx; d's components are inputs, exact
    const Split ex = two_diff(w.p1.x, w.p0.x), ey = two_diff(w.p1.y, w.p0.y);
    if (const auto s = det_sign(ex, {d.y, 0.0}, ey, {d.x, 0.0}, l, r)) return *s;
    return cross_complete(w, d);
}

// The last stage of point_circle: sign(|p − c|² − r²) as a complete sum, or by GMP. Out of line: rare.
[[gnu::noinline]] int point_circle_complete(Vec2 p, const Circle& c) {
    if (expansion_safe({p.x, p.y, c.c.x, c.c.y, c.r}))
        return counted(staged::complete_squares(two_diff(p.x, c.c.x), two_diff(p.y, c.c.y), {c.r, 0.0}),
                       &FallbackCounts::complete);
    const bignum::Rational ex = q(p.x) - q(c.c.x), ey = q(p.y) - q(c.c.y), r = q(c.r);
    return gmp_sign(ex * ex + ey * ey - r * r);
}

// The exact path of point_circle: stage 2, then the last stage. Out of line, so that the filter's call stays small,
// and apart from the last stage, so that its own frame does too.
[[gnu::noinline]] int point_circle_exact(Vec2 p, const Circle& c) {
    if (const auto s = staged::bounded_squares(two_diff(p.x, c.c.x), two_diff(p.y, c.c.y), {c.r, 0.0}))
        return counted(*s, &FallbackCounts::bounded);
    return point_circle_complete(p, c);
}

// The last stage of circle_circle: sign(|cA − cB|² − (rA + rB)²) as a complete sum, or by GMP. Out of line: rare.
[[gnu::noinline]] int circle_circle_complete(const Circle& a, const Circle& b) {
    if (expansion_safe({a.c.x, a.c.y, b.c.x, b.c.y, a.r, b.r}))
        return counted(staged::complete_squares(two_diff(a.c.x, b.c.x), two_diff(a.c.y, b.c.y), two_sum(a.r, b.r)),
                       &FallbackCounts::complete);
    const bignum::Rational ex = q(a.c.x) - q(b.c.x), ey = q(a.c.y) - q(b.c.y), r = q(a.r) + q(b.r);
    return gmp_sign(ex * ex + ey * ey - r * r);
}

// The exact path of circle_circle, as point_circle's.
[[gnu::noinline]] int circle_circle_exact(const Circle& a, const Circle& b) {
    if (const auto s = staged::bounded_squares(two_diff(a.c.x, b.c.x), two_diff(a.c.y, b.c.y), two_sum(a.r, b.r)))
        return counted(*s, &FallbackCounts::bounded);
    return circle_circle_complete(a, b);
}

// The last stage of orient: sign((a − c) × (b − c)) as a complete sum, or by GMP. Out of line: rare.
[[gnu::noinline]] int orient_complete(Vec2 a, Vec2 b, Vec2 c) {
    if (expansion_safe({a.x, a.y, b.x, b.y, c.x, c.y})) {
        const Split d1 = two_diff(a.x, c.x), d2 = two_diff(b.y, c.y), d3 = two_diff(a.y, c.y), d4 = two_diff(b.x, c.x);
        return counted(staged::complete_det(d1, d2, d3, d4), &FallbackCounts::complete);
    }
    return gmp_sign((q(a.x) - q(c.x)) * (q(b.y) - q(c.y)) - (q(a.y) - q(c.y)) * (q(b.x) - q(c.x)));
}

}  // namespace

// The exact path of orient, out of line so that the filter (orient_filter.hpp) stays small where it is inlined:
// stages 1 and 2, then the last stage, apart so that this frame stays small too.
[[gnu::noinline]] int detail::orient_exact(Vec2 a, Vec2 b, Vec2 c, double l, double r) {
    // (a − c) × (b − c) = (ax − cx)·(by − cy) − (ay − cy)·(bx − cx), each difference as a head and a tail
    const Split d1 = two_diff(a.x, c.x), d2 = two_diff(b.y, c.y), d3 = two_diff(a.y, c.y), d4 = two_diff(b.x, c.x);
    if (const auto s = det_sign(d1, d2, d3, d4, l, r)) return *s;
    return orient_complete(a, b, c);
}

int orient(Vec2 a, Vec2 b, Vec2 c) { return detail::orient(a, b, c); }

int side(Vec2 p, const Wall& w) { return detail::side(p, w); }

int direction_side(Vec2 d, const Wall& w) {
    // n·d = e_y·d_x − e_x·d_y = −(e × d)
    const double ex = w.p1.x - w.p0.x;
    const double ey = w.p1.y - w.p0.y;
    const double l = ex * d.y;
    const double r = ey * d.x;
    const double sum = std::fabs(l) + std::fabs(r);
    if (sum >= k_tiny && std::isfinite(sum) && std::fabs(l - r) > k_ccw * sum) return -sign(l - r);
    return -cross_exact(w, d, l, r);
}

int point_circle(Vec2 p, const Circle& c) {
    // |p − c|² − r², filtered
    const double dx = p.x - c.c.x;
    const double dy = p.y - c.c.y;
    const double d2 = dx * dx + dy * dy;
    const double r2 = c.r * c.r;
    const double sum = d2 + r2;
    // V = D − r² with D = (px − cx)² + (py − cy)². Each term of d2 is its exact square times four factors (1 + δ),
    // |δ| ≤ ε (difference, square twice, sum), so |d2 − D| ≤ ((1 + ε)⁴ − 1)·D ≤ 4ε(1 + 2ε)·d2/(1 − ε)⁴, and
    // |r2 − r²| ≤ ε·r2/(1 − ε): |(d2 − r2) − V| ≤ ε(1 + 8ε)(4·d2 + r2). fl(d2 − r2) keeps the sign of d2 − r2 and
    // errs by ≤ ε of it, and the bound fl(k_sq·fl(4·d2 + r2)) ≥ (1 + 16ε)(1 − ε)²·ε(4·d2 + r2) leaves that (1 + ε)
    // and ≥ 4ε²·sum ≥ 2^-1004 more, far above the few 2^-1075 an underflowed square can add (sum ≥ k_tiny):
    // |fl(d2 − r2)| beyond it gives sign(V). An overflowed 4·d2 makes the bound infinite: the filter declines.
    if (sum >= k_tiny && std::isfinite(sum) && std::fabs(d2 - r2) > k_sq * (4.0 * d2 + r2)) return sign(d2 - r2);
    return point_circle_exact(p, c);
}

int circle_circle(const Circle& a, const Circle& b) {
    // |cA − cB|² − (rA + rB)², filtered
    const double dx = a.c.x - b.c.x;
    const double dy = a.c.y - b.c.y;
    const double rs = a.r + b.r;
    const double d2 = dx * dx + dy * dy;
    const double r2 = rs * rs;
    const double sum = d2 + r2;
    // As in point_circle, with r2 = (rA + rB)² times three factors (sum, square twice): |r2 − (rA + rB)²| ≤
    // 3ε(1 + 2ε)·r2/(1 − ε)³, so |(d2 − r2) − V| ≤ ε(1 + 8ε)(4·d2 + 3·r2); the bound k_sq·fl(4·d2 + fl(3·r2)) rounds
    // three times, ≥ (1 + 16ε)(1 − ε)³·ε(4·d2 + 3·r2), still (1 + ε) and ≥ 3ε²·sum above it.
    if (sum >= k_tiny && std::isfinite(sum) && std::fabs(d2 - r2) > k_sq * (4.0 * d2 + 3.0 * r2)) return sign(d2 - r2);
    return circle_circle_exact(a, b);
}

int compare_crossings(Vec2 a, Vec2 b, const Wall& w1, const Wall& w2) {
    // s1 − s2 = (a2·b1 − a1·b2) / ((a1 − b1)(a2 − b2)), and sign(a_k − b_k) = sign(a_k).
    const int sa1 = orient(w1.p0, w1.p1, a);
    const int sa2 = orient(w2.p0, w2.p1, a);
    const Filtered a1 = orient_filtered(w1.p0, w1.p1, a);
    const Filtered b1 = orient_filtered(w1.p0, w1.p1, b);
    const Filtered a2 = orient_filtered(w2.p0, w2.p1, a);
    const Filtered b2 = orient_filtered(w2.p0, w2.p1, b);
    const double l = a2.value * b1.value;
    const double r = a1.value * b2.value;
    // |x̃ỹ − xy| ≤ ex(|ỹ| + ey) + |x̃|ey for each product, plus the rounding of D itself.
    const double err = a2.bound * (std::fabs(b1.value) + b1.bound) + std::fabs(a2.value) * b1.bound +
                       a1.bound * (std::fabs(b2.value) + b2.bound) + std::fabs(a1.value) * b2.bound +
                       k_cross_round * (std::fabs(l) + std::fabs(r));
    const double d = l - r;
    if (std::isfinite(err) && std::fabs(d) > k_cross_slack * err) return sign(d) * sa1 * sa2;
    auto det = [](const Wall& w, Vec2 p) -> bignum::Rational {
        return (q(w.p0.x) - q(p.x)) * (q(w.p1.y) - q(p.y)) - (q(w.p0.y) - q(p.y)) * (q(w.p1.x) - q(p.x));
    };
    const bignum::Rational ea1 = det(w1, a), eb1 = det(w1, b), ea2 = det(w2, a), eb2 = det(w2, b);
    return gmp_sign(ea2 * eb1 - ea1 * eb2) * sa1 * sa2;
}

FallbackCounts fallback_counts() { return t_counts; }

}  // namespace ricochet::exact
