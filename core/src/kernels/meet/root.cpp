// Meet times of two balls' paths, exactly (root.hpp; docs/scene-log.md, "Balls that meet", 2 to 4).
//
// Every decision is made in two stages, as the disc frame's are (kernels/disc/arith.hpp): first in double-double
// arithmetic with a running error bound (Approx2: a sign is taken only where the bound decides it, a rounding only
// where every value within the bound rounds alike), then, where that does not decide, with rationals. Both stages
// answer the same exact question, so which one answered never shows in a result.
#include "kernels/meet/root.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "base/round.hpp"
#include "kernels/disc/arith.hpp"

namespace ricochet::meet {
namespace {

using bignum::Rational;
using bignum::nearest;
using disc::Approx2;

/// An input double, exact.
Approx2 fine(double x) { return {x, 0.0, 0.0}; }

/// sign(x + y·√d), d ≥ 0, exactly: where the two terms' signs differ, compare their squares.
int sign_root(const Rational& x, const Rational& y, const Rational& d) {
    const int sx = bignum::sign(x);
    const int sy = bignum::sign(d) == 0 ? 0 : bignum::sign(y);
    if (sy == 0) return sx;
    if (sx == 0 || sx == sy) return sy;
    const int c = bignum::sign(Rational(x * x - y * y * d));
    return c > 0 ? sx : c < 0 ? sy : 0;
}

/// sign(x + y·√d + z·√e), d, e ≥ 0, exactly: the first two terms' sign against the third's; where they differ,
/// (x + y√d)² − z²e = (x² + y²d − z²e) + 2xy·√d decides which is larger.
int sign_two_roots(const Rational& x, const Rational& y, const Rational& d, const Rational& z, const Rational& e) {
    const int s1 = sign_root(x, y, d);
    const int s2 = bignum::sign(e) == 0 ? 0 : bignum::sign(z);
    if (s2 == 0) return s1;
    if (s1 == 0 || s1 == s2) return s2;
    const int c = sign_root(Rational(x * x + y * y * d - z * z * e), Rational(2 * x * y), d);
    return c > 0 ? s1 : c < 0 ? s2 : 0;
}

/// True if the double has an even significand (ties round to it).
bool even(double y) {
    int e = 0;
    const double m = std::frexp(y, &e);
    return std::fmod(std::ldexp(m, 53), 2.0) == 0.0;
}

/// The double nearest to p + q·√r (ties to even), from y within an ulp or so of it: y is moved to a neighbour while
/// the exact value lies beyond the midpoint between them.
double round_root(const Rational& p, const Rational& q, const Rational& r, double y) {
    for (;;) {
        const double up = std::nextafter(y, HUGE_VAL), down = std::nextafter(y, -HUGE_VAL);
        const int above = sign_root(Rational(p - (Rational(y) + Rational(up)) / 2), q, r);
        if (above > 0 || (above == 0 && !even(y))) {
            y = up;
            continue;
        }
        const int below = sign_root(Rational(p - (Rational(y) + Rational(down)) / 2), q, r);
        if (below < 0 || (below == 0 && !even(y))) {
            y = down;
            continue;
        }
        return y;
    }
}

/// The piece of path holding the interval starting at t: the last point at or before t and the next point after
/// it (a path that ends before the interval holds its last point).
Piece piece_at(std::span<const PathPoint> path, double t) {
    std::size_t k = 0;
    while (k + 1 < path.size() && path[k + 1].t <= t) ++k;
    // Skip pieces of zero duration: the later point holds.
    if (k + 1 >= path.size()) return {path[k].t, path[k].t, path[k].p, path[k].p};
    return {path[k].t, path[k + 1].t, path[k].p, path[k + 1].p};
}

/// True if the piece spans the whole frame (t0 = 0, t1 = 1: a ball no contact has cut): its fraction of the frame at
/// t is t itself and its velocity its displacement, exactly, with no quotient by 1 whose double-double bound would
/// have to be carried.
bool whole_frame(const Piece& s) { return s.t0 == 0.0 && s.t1 == 1.0; }

/// The piece's point at t in doubles (the filter's estimate).
Vec2 approx_at(const Piece& s, double t) {
    if (s.t1 == s.t0) return s.p0;
    const double f = (t - s.t0) / (s.t1 - s.t0);
    return s.p0 + f * (s.p1 - s.p0);
}

/// True if the filter proves the interval [c, c2] holds no meet of the two pieces, from the relative motion's segment
/// D(c) → D(c2) in doubles: they stay more than S apart (its nearest point to the origin, with a margin of 2^−40 of the
/// magnitudes involved, far beyond the few roundings of these estimates: each coordinate within 2^7 ulps of the
/// largest magnitude m), or they move apart all through it. A meet needs B = D(c)·W < 0 (fine_verdict), and for c2 > c
/// and pieces that move as their points do, D(c)·(D(c2) − D(c)) is (c2 − c)·B: where its estimate d0·w exceeds the
/// estimate's error bound, 2^−40·m·(|d0|₁ + |w|₁ + 2^−40·m) (the inputs' errors, the products' roundings) and 2^−1000
/// (underflow), B > 0.
bool clearly_nothing(const Piece& a, const Piece& b, double S, double c, double c2) {
    const Vec2 d0 = approx_at(a, c) - approx_at(b, c), d1 = approx_at(a, c2) - approx_at(b, c2);
    const double m = std::max({std::fabs(a.p0.x), std::fabs(a.p0.y), std::fabs(a.p1.x), std::fabs(a.p1.y),
                               std::fabs(b.p0.x), std::fabs(b.p0.y), std::fabs(b.p1.x), std::fabs(b.p1.y), S});
    const Vec2 w = d1 - d0;
    const double ww = dot(w, w), dw = dot(d0, w);
    double u = ww > 0.0 ? -dw / ww : 0.0;
    u = std::clamp(u, 0.0, 1.0);
    const Vec2 near = d0 + u * w;
    const double dist = std::sqrt(dot(near, near));
    if (!std::isfinite(dist) || !std::isfinite(m)) return false;
    if (dist > S + 0x1p-40 * m) return true;
    // (A piece of no duration moves with its ball's end velocity, which its points do not show.)
    if (!(c2 > c && a.t1 > a.t0 && b.t1 > b.t0)) return false;
    const double l1 = std::fabs(d0.x) + std::fabs(d0.y) + std::fabs(w.x) + std::fabs(w.y);
    return dw > 0x1p-40 * m * (l1 + 0x1p-40 * m) + 0x1p-1000;
}

/// An input double in type N (Approx2: exact, no bound; Rational).
template <class N>
N number(double x) {
    if constexpr (std::is_same_v<N, Approx2>) return fine(x);
    else return N(x);
}

/// The relative motion of two pieces over an interval from c: D(u) = D_c + W·u, and the quadratic's coefficients
/// |D(u)|² − S² = qa + 2B·u + A·u², in type N (Approx2 or Rational).
template <class N>
struct Relative {
    N qa, B, A;
};

/// The piece's point at c and velocity, in type N; a piece of no duration moves with `end`. (A coordinate that stays
/// has velocity 0 exactly: Approx2's quotient would carry a bound.)
template <class N>
void motion(const Piece& s, double c, Vec2 end, N& px, N& py, N& vx, N& vy) {
    if (s.t1 == s.t0) {
        px = number<N>(s.p0.x);
        py = number<N>(s.p0.y);
        vx = number<N>(end.x);
        vy = number<N>(end.y);
        return;
    }
    const N dt = number<N>(s.t1) - number<N>(s.t0), from = number<N>(c) - number<N>(s.t0);
    const bool whole = whole_frame(s);
    const auto velocity = [&](double x0, double x1) -> N {
        if (x1 == x0) return number<N>(0.0);
        if (whole) return N(number<N>(x1) - number<N>(x0));
        return N((number<N>(x1) - number<N>(x0)) / dt);
    };
    vx = velocity(s.p0.x, s.p1.x);
    vy = velocity(s.p0.y, s.p1.y);
    px = number<N>(s.p0.x) + from * vx;
    py = number<N>(s.p0.y) + from * vy;
}

/// The root's two pieces relative to each other from its c, in type N.
template <class N>
Relative<N> relative(const Root& r) {
    N ax, ay, avx, avy, bx, by, bvx, bvy;
    motion<N>(r.a, r.c, r.end_a, ax, ay, avx, avy);
    motion<N>(r.b, r.c, r.end_b, bx, by, bvx, bvy);
    const N dx = ax - bx, dy = ay - by, wx = avx - bvx, wy = avy - bvy;
    const N sum = number<N>(r.S.a) + number<N>(r.S.b);
    return {N(dx * dx + dy * dy - sum * sum), N(dx * wx + dy * wy), N(wx * wx + wy * wy)};
}

/// What an interval holds: no meet, a meet at its start, a meet inside it, or (the bounded stage only) a meet inside
/// it whose time the bound could not round.
enum class Holds { nothing, meet_at_start, meet, unsure };

/// The interval's verdict on D(u) = D_c + W·u, u in [0, L] (nothing where the bound decides none of it): within S at c (qa ≤ 0), a meet there if they approach
/// (B < 0); clear at c, an entry needs approach (B < 0, A > 0) and two distinct real roots (disc = B² − A·qa > 0, a
/// tangent is no meet), and the smaller root u = (−B − √disc)/A lies in [0, L] iff −B − A·L ≤ √disc. Its time is
/// c + u in the form without cancellation, u·(−B + √disc) = B² − disc = A·qa: u = qa/(−B + √disc).
std::optional<Holds> fine_verdict(const Relative<Approx2>& m, double c, double c2, double& estimate) {
    const auto sq = disc::sign(m.qa), sb = disc::sign(m.B);
    if (!sq || !sb) return std::nullopt;
    if (*sq <= 0) return *sb < 0 ? Holds::meet_at_start : Holds::nothing;
    const auto sa = disc::sign(m.A);
    if (!sa) return std::nullopt;
    if (*sa == 0 || *sb >= 0) return Holds::nothing;
    const Approx2 disc = m.B * m.B - m.A * m.qa;
    const auto sd = disc::sign(disc);
    if (!sd) return std::nullopt;
    if (*sd <= 0) return Holds::nothing;
    const Approx2 lhs = -m.B - m.A * (fine(c2) - fine(c));
    const auto sl = disc::sign(lhs);
    if (!sl) return std::nullopt;
    if (*sl > 0) {
        const auto beyond = disc::sign(lhs * lhs - disc);
        if (!beyond) return std::nullopt;
        if (*beyond > 0) return Holds::nothing;
    }
    const std::optional<double> t = disc::nearest_double(fine(c) + m.qa / (-m.B + disc::sqrt(disc)));
    if (!t) return Holds::unsure;  // a meet, its time's rounding not decided here
    estimate = *t;
    return Holds::meet;
}

/// The exact time of a meet the interval holds: c itself, or the smaller root c + (−B − √disc)/A.
Root::Exact exact_time(const Relative<Rational>& m, double c, bool at_start) {
    if (at_start) return {Rational(c), Rational(0), Rational(0)};
    return {Rational(c) - m.B / m.A, Rational(-1) / m.A, Rational(m.B * m.B - m.A * m.qa)};
}

/// The same verdict exactly.
Holds exact_verdict(const Relative<Rational>& m, double c, double c2) {
    if (bignum::sign(m.qa) <= 0) return bignum::sign(m.B) < 0 ? Holds::meet_at_start : Holds::nothing;
    if (bignum::sign(m.A) == 0 || bignum::sign(m.B) >= 0) return Holds::nothing;
    const Rational disc = m.B * m.B - m.A * m.qa;
    if (bignum::sign(disc) <= 0) return Holds::nothing;
    const Rational lhs = -m.B - m.A * (Rational(c2) - Rational(c));
    if (bignum::sign(lhs) > 0 && lhs * lhs > disc) return Holds::nothing;
    return Holds::meet;
}

/// The double nearest the exact time: the start itself, or from an estimate of c + qa/(−B + √disc) with √disc to
/// 70 bits (good to 2^−70 relative, u ≤ 1, whatever the sizes of A, B and qa: a subnormal scene makes them
/// thousands of bits), moved to the nearest double exactly.
double exact_estimate(const Relative<Rational>& m, double c, const Root::Exact& exact) {
    if (bignum::sign(exact.q) == 0) return c;
    const Rational disc = m.B * m.B - m.A * m.qa;
    const double y = nearest(Rational(Rational(c) + m.qa / Rational(-m.B + bignum::sqrt_below(disc, 70))));
    return round_root(exact.p, exact.q, exact.r, y);
}

}  // namespace

const Root::Exact& exact_of(const Root& root) {
    if (!root.exact) root.exact = exact_time(relative<Rational>(root), root.c, root.at_start);
    return *root.exact;
}

std::optional<Root> first_meet(std::span<const PathPoint> a, std::span<const PathPoint> b, Radii S, double from,
                               Vec2 end_a, Vec2 end_b, double until) {
    // Radii are ≥ 0, so the rounded sum is 0 exactly when the exact one is.
    if (a.empty() || b.empty() || !(S.rounded() > 0.0)) return std::nullopt;
    double lo = std::max({from, a.front().t, b.front().t});
    if (lo > until) return std::nullopt;
    // The common intervals from lo: cut at every printed time of either path in (lo, until], and at until. (Both
    // paths' times are non-decreasing: the next cut is the smaller of their next times, found without a buffer.)
    std::size_t ia = 0, ib = 0;
    const auto next_cut = [&](double t) {
        while (ia < a.size() && a[ia].t <= t) ++ia;
        while (ib < b.size() && b[ib].t <= t) ++ib;
        double cut = until;
        if (ia < a.size()) cut = std::min(cut, a[ia].t);
        if (ib < b.size()) cut = std::min(cut, b[ib].t);
        return cut;
    };
    do {
        const double c = lo, c2 = next_cut(lo);
        lo = c2;
        Root root;
        root.c = c;
        root.a = piece_at(a, c);
        root.b = piece_at(b, c);
        root.end_a = end_a;
        root.end_b = end_b;
        root.S = S;
        if (clearly_nothing(root.a, root.b, S.rounded(), c, c2)) continue;
        double estimate = c;
        std::optional<Holds> holds = fine_verdict(relative<Approx2>(root), c, c2, estimate);
        if (!holds || *holds == Holds::unsure) {
            // The rationals decide what the bounded stage did not (or round the time it could not).
            const Relative<Rational> m = relative<Rational>(root);
            holds = exact_verdict(m, c, c2);
            if (*holds != Holds::nothing) {
                root.exact = exact_time(m, c, *holds == Holds::meet_at_start);
                estimate = exact_estimate(m, c, *root.exact);
            }
        }
        if (*holds == Holds::nothing) continue;
        root.at_start = *holds == Holds::meet_at_start;
        root.estimate = root.at_start ? c : std::clamp(estimate, c, c2);
        return root;
    } while (lo < until);
    return std::nullopt;
}

bool entered(const Root& m, std::span<const PathPoint> a, std::span<const PathPoint> b, Radii S) {
    return !m.at_start || !closer_on_paths(a, b, m.c, S);
}

std::optional<Root> first_entry(std::span<const PathPoint> a, std::span<const PathPoint> b, Radii S, double from,
                                double until) {
    while (from < until) {
        const std::optional<Root> m = first_meet(a, b, S, from, {}, {}, until);
        if (!m || entered(*m, a, b, S)) return m;
        from = next_point(a, b, m->c);
    }
    return std::nullopt;
}

double next_point(std::span<const PathPoint> a, std::span<const PathPoint> b, double t) {
    double next = 1.0;
    for (const std::span<const PathPoint> path : {a, b})
        for (const PathPoint& q : path)
            if (q.t > t) {
                next = std::min(next, q.t);
                break;
            }
    return next;
}

int compare(const Root& x, const Root& y) {
    if (const int c = compare_estimates(x.estimate, y.estimate)) return c;
    const Root::Exact &ex = exact_of(x), &ey = exact_of(y);
    return sign_two_roots(Rational(ex.p - ey.p), ex.q, ex.r, Rational(-ey.q), ey.r);
}

int compare(const Root& x, double t) {
    if (const int c = compare_estimates(x.estimate, t)) return c;
    const Root::Exact& ex = exact_of(x);
    return sign_root(Rational(ex.p - Rational(t)), ex.q, ex.r);
}

PointOnPath point_at(std::span<const PathPoint> path, double t) {
    std::size_t k = 0;
    while (k + 1 < path.size() && path[k + 1].t <= t) ++k;
    if (path[k].t == t || k + 1 >= path.size()) return {path[k].p, k};
    const Piece s{path[k].t, path[k + 1].t, path[k].p, path[k + 1].p};
    // X = P0 + (t − t0)·(P1 − P0)/(t1 − t0), each coordinate rounded to nearest: bounded first, then exactly.
    const Approx2 f = whole_frame(s) ? fine(t) : (fine(t) - fine(s.t0)) / (fine(s.t1) - fine(s.t0));
    // (A zero is +0, as the rationals round it: + 0.0 turns −0 into +0 and leaves every other value.)
    const auto coordinate = [&](double x0, double x1) -> std::optional<double> {
        if (x1 == x0) return x0 + 0.0;
        const std::optional<double> x = disc::nearest_double(fine(x0) + f * (fine(x1) - fine(x0)));
        if (!x) return std::nullopt;
        return *x + 0.0;
    };
    const std::optional<double> x = coordinate(s.p0.x, s.p1.x), y = coordinate(s.p0.y, s.p1.y);
    if (x && y) return {{*x, *y}, k};
    Rational px, py, vx, vy;
    motion<Rational>(s, t, {}, px, py, vx, vy);
    return {{nearest(px), nearest(py)}, k};
}

std::pair<Rational, Rational> exact_point(std::span<const PathPoint> path, double t) {
    Rational px, py, vx, vy;
    motion<Rational>(piece_at(path, t), t, {}, px, py, vx, vy);
    return {std::move(px), std::move(py)};
}

bool closer_than(Vec2 a, Vec2 b, Radii S) {
    // The filter: d² = |a − b|² and s² = (R_i + R_j)² in doubles are each within 6 ulps of their exact values, and
    // where d² + s² ≥ 2^−900 an underflow loses at most a few 2^−1074; farther apart than 2^−45·(d² + s²), the doubles
    // decide. Then the bounded double-double stage (touching balls: the differences and squares are exact there
    // but for inputs far outside the splitting range), then the rationals.
    const Vec2 d = a - b;
    const double d2 = dot(d, d), s = S.rounded(), s2 = s * s, scale = d2 + s2;
    if (std::isfinite(scale) && scale >= 0x1p-900) {
        const double margin = 0x1p-45 * scale;
        if (d2 < s2 - margin) return true;
        if (d2 > s2 + margin) return false;
    }
    const Approx2 dx = fine(a.x) - fine(b.x), dy = fine(a.y) - fine(b.y), sum = fine(S.a) + fine(S.b);
    if (const auto sign = disc::sign(dx * dx + dy * dy - sum * sum)) return *sign < 0;
    const Rational ex = Rational(a.x) - Rational(b.x), ey = Rational(a.y) - Rational(b.y);
    const Rational sum_exact = Rational(S.a) + Rational(S.b);
    return ex * ex + ey * ey < sum_exact * sum_exact;
}

std::optional<bool> closing_at_end(Vec2 a0, Vec2 b0, Vec2 a1, Vec2 b1) {
    const Approx2 d1x = fine(a1.x) - fine(b1.x), d1y = fine(a1.y) - fine(b1.y);
    const Approx2 wx = d1x - (fine(a0.x) - fine(b0.x)), wy = d1y - (fine(a0.y) - fine(b0.y));
    const std::optional<int> s = disc::sign(d1x * wx + d1y * wy);
    if (!s) return std::nullopt;
    return *s <= 0;
}

bool surely_no_meet_before_end(std::span<const PathPoint> a, std::span<const PathPoint> b, double lo, double t) {
    if (a.size() != 2 || b.size() != 2 || !(lo < t)) return false;
    if (a[0].t != lo || b[0].t != lo || a[1].t != t || b[1].t != t) return false;
    const std::optional<bool> closing = closing_at_end(a[0].p, b[0].p, a[1].p, b[1].p);
    return closing && *closing;
}

bool jump_enters(Vec2 p0, Vec2 p1, const std::pair<Rational, Rational>& k, Radii S) {
    const Rational dx = Rational(p0.x) - k.first, dy = Rational(p0.y) - k.second;
    const Rational wx = Rational(p1.x) - Rational(p0.x), wy = Rational(p1.y) - Rational(p0.y);
    const Rational s = Rational(S.a) + Rational(S.b), s2 = s * s;
    const Rational dd = dx * dx + dy * dy, dw = dx * wx + dy * wy, ww = wx * wx + wy * wy;
    // |D + W·u|² = dd + 2·dw·u + ww·u²: from inside reach, or moving no closer (dw ≥ 0), it enters nothing.
    if (dd < s2 || !(dw < Rational(0))) return false;
    // Its least on [0, 1]: at u* = −dw/ww where that is inside (dd − dw²/ww, times ww), else at u = 1.
    if (-dw < ww) return dd * ww - dw * dw < s2 * ww;
    return dd + dw + dw + ww < s2;
}

bool closer_on_paths(std::span<const PathPoint> a, std::span<const PathPoint> b, double t, Radii S) {
    // |D(t)|² − S², the quadratic's qa at c = t: bounded first, then exactly.
    Root at;
    at.c = t;
    at.a = piece_at(a, t);
    at.b = piece_at(b, t);
    at.S = S;
    if (const auto sign = disc::sign(relative<Approx2>(at).qa)) return *sign < 0;
    return bignum::sign(relative<Rational>(at).qa) < 0;
}

bool surely_apart(Vec2 x, std::span<const PathPoint> path, double t, Radii S) {
    // The piece holding t in doubles is within a few ulps of its largest coordinate of the exact point, and point_at
    // rounds the exact point to within one; a margin of 2^−40 of the magnitudes covers both.
    const Piece s = piece_at(path, t);
    const Vec2 y = s.t0 == t ? s.p0 : approx_at(s, t);
    const double m = std::max({std::fabs(x.x), std::fabs(x.y), std::fabs(s.p0.x), std::fabs(s.p0.y),
                               std::fabs(s.p1.x), std::fabs(s.p1.y), S.rounded()});
    const Vec2 d = x - y;
    const double dist = std::sqrt(dot(d, d));
    return std::isfinite(dist) && std::isfinite(m) && dist > S.rounded() + 0x1p-40 * m;
}

}  // namespace ricochet::meet
