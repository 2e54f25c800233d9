// Meet times of two balls' paths, exactly (root.hpp; docs/scene-log.md, "Balls that meet", 2 and 3).
#include "kernels/meet/root.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "base/round.hpp"

namespace ricochet::meet {
namespace {

using bignum::Rational;

/// The double nearest to q.
double nearest(const Rational& q) { return bignum::round_quotient(bignum::numerator(q), bignum::denominator(q), 0); }

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

/// The estimate of the entry time c + u, u = (−B − √disc)/A, in the form without cancellation: u·(−B + √disc) =
/// B² − disc = A·qa, so u = qa/(−B + √disc), both terms of the sum positive (B < 0). √disc to 70 bits makes u good
/// to 2^−70 relative (u ≤ 1), whatever the sizes of A, B and qa (a subnormal scene makes them thousands of bits).
double estimate(const Rational& c, const Rational& qa, const Rational& B, const Rational& disc) {
    const Rational u = qa / Rational(-B + bignum::sqrt_below(disc, 70));
    return nearest(Rational(c + u));
}

/// A piece of a path: from p0 at t0 to p1 at t1 > t0 (or a ball at rest at p0 from t0 on, t1 = t0).
struct Piece {
    double t0, t1;
    Vec2 p0, p1;
};

/// The piece of path holding the interval starting at t: the last point at or before t and the next point after
/// it (a path that ends before the interval holds its last point).
Piece piece_at(std::span<const PathPoint> path, double t) {
    std::size_t k = 0;
    while (k + 1 < path.size() && path[k + 1].t <= t) ++k;
    // Skip pieces of zero duration: the later point holds.
    if (k + 1 >= path.size()) return {path[k].t, path[k].t, path[k].p, path[k].p};
    return {path[k].t, path[k + 1].t, path[k].p, path[k + 1].p};
}

/// The piece's point at t in doubles (the filter's estimate).
Vec2 approx_at(const Piece& s, double t) {
    if (s.t1 == s.t0) return s.p0;
    const double f = (t - s.t0) / (s.t1 - s.t0);
    return s.p0 + f * (s.p1 - s.p0);
}

/// True if the filter proves the two pieces stay more than S apart over [c, c2]: the relative motion's segment
/// D(c) → D(c2) in doubles, its nearest point to the origin, and a margin of 2^−40 of the magnitudes involved, far
/// beyond the few roundings of these estimates (each within 8 ulps of the largest magnitude).
bool clearly_apart(const Piece& a, const Piece& b, double S, double c, double c2) {
    const Vec2 d0 = approx_at(a, c) - approx_at(b, c), d1 = approx_at(a, c2) - approx_at(b, c2);
    const double m = std::max({std::fabs(a.p0.x), std::fabs(a.p0.y), std::fabs(a.p1.x), std::fabs(a.p1.y),
                               std::fabs(b.p0.x), std::fabs(b.p0.y), std::fabs(b.p1.x), std::fabs(b.p1.y), S});
    const Vec2 w = d1 - d0;
    const double ww = dot(w, w);
    double u = ww > 0.0 ? -dot(d0, w) / ww : 0.0;
    u = std::clamp(u, 0.0, 1.0);
    const Vec2 near = d0 + u * w;
    const double dist = std::sqrt(dot(near, near));
    if (!std::isfinite(dist) || !std::isfinite(m)) return false;
    return dist > S + 0x1p-40 * m;
}

/// The piece's velocity and its point at c, exactly; a piece of no duration (a ball at the end of its path) moves
/// with `end`.
void exact_motion(const Piece& s, double c, Rational& px, Rational& py, Rational& vx, Rational& vy, Vec2 end = {}) {
    if (s.t1 == s.t0) {
        px = Rational(s.p0.x);
        py = Rational(s.p0.y);
        vx = Rational(end.x);
        vy = Rational(end.y);
        return;
    }
    const Rational dt = Rational(s.t1) - Rational(s.t0);
    vx = (Rational(s.p1.x) - Rational(s.p0.x)) / dt;
    vy = (Rational(s.p1.y) - Rational(s.p0.y)) / dt;
    const Rational from = Rational(c) - Rational(s.t0);
    px = Rational(s.p0.x) + from * vx;
    py = Rational(s.p0.y) + from * vy;
}

}  // namespace

std::optional<Root> first_meet(std::span<const PathPoint> a, std::span<const PathPoint> b, Radii S, double from,
                               Vec2 end_a, Vec2 end_b, double until) {
    // Radii are ≥ 0, so the rounded sum is 0 exactly when the exact one is.
    if (a.empty() || b.empty() || !(S.rounded() > 0.0)) return std::nullopt;
    double lo = std::max({from, a.front().t, b.front().t});
    if (lo > until) return std::nullopt;
    // The common breakpoints after lo: every printed time of either path in (lo, until].
    std::vector<double> cuts;
    for (const PathPoint& p : a)
        if (p.t > lo && p.t <= until) cuts.push_back(p.t);
    for (const PathPoint& p : b)
        if (p.t > lo && p.t <= until) cuts.push_back(p.t);
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    if (cuts.empty() || cuts.back() < until) cuts.push_back(until);
    const Rational sum = Rational(S.a) + Rational(S.b);
    const Rational S2 = sum * sum;
    for (const double c2 : cuts) {
        const double c = lo;
        lo = c2;
        const Piece pa = piece_at(a, c), pb = piece_at(b, c);
        if (clearly_apart(pa, pb, S.rounded(), c, c2)) continue;
        Rational ax, ay, avx, avy, bx, by, bvx, bvy;
        exact_motion(pa, c, ax, ay, avx, avy, end_a);
        exact_motion(pb, c, bx, by, bvx, bvy, end_b);
        // D(u) = D_a + W·u, u = t − c in [0, L].
        const Rational dx = ax - bx, dy = ay - by, wx = avx - bvx, wy = avy - bvy;
        const Rational qa = dx * dx + dy * dy - S2, B = dx * wx + dy * wy, A = wx * wx + wy * wy;
        // Already within S at c (touching, or placed overlapping): a meet at c if they approach.
        if (bignum::sign(qa) <= 0) {
            if (bignum::sign(B) < 0) return Root{Rational(c), Rational(0), Rational(0), c};
            continue;
        }
        // Clear at c: an entry needs approach (B < 0) and two distinct real roots.
        if (bignum::sign(A) == 0 || bignum::sign(B) >= 0) continue;
        const Rational disc = B * B - A * qa;
        if (bignum::sign(disc) <= 0) continue;  // a tangent (or no root) is no meet
        // The smaller root u = (−B − √disc)/A lies in [0, L] iff −B − A·L ≤ √disc.
        const Rational L = Rational(c2) - Rational(c);
        const Rational lhs = -B - A * L;
        if (bignum::sign(lhs) > 0 && lhs * lhs > disc) continue;
        Root root{Rational(c) - B / A, Rational(-1) / A, disc, 0.0};
        root.estimate = std::clamp(estimate(Rational(c), qa, B, disc), c, c2);
        return root;
    }
    return std::nullopt;
}

int compare(const Root& x, const Root& y) {
    // The estimates are within 2^−52 of their exact values (estimate()): farther apart than 2^−48, they decide.
    if (x.estimate < y.estimate - 0x1p-48) return -1;
    if (x.estimate > y.estimate + 0x1p-48) return 1;
    return sign_two_roots(Rational(x.p - y.p), x.q, x.r, Rational(-y.q), y.r);
}

int compare(const Root& x, double t) {
    if (x.estimate < t - 0x1p-48) return -1;
    if (x.estimate > t + 0x1p-48) return 1;
    return sign_root(Rational(x.p - Rational(t)), x.q, x.r);
}

PointOnPath point_at(std::span<const PathPoint> path, double t) {
    std::size_t k = 0;
    while (k + 1 < path.size() && path[k + 1].t <= t) ++k;
    if (path[k].t == t || k + 1 >= path.size()) return {path[k].p, k};
    const Piece s{path[k].t, path[k + 1].t, path[k].p, path[k + 1].p};
    Rational px, py, vx, vy;
    exact_motion(s, t, px, py, vx, vy);
    return {{nearest(px), nearest(py)}, k};
}

bool closer_than(Vec2 a, Vec2 b, Radii S) {
    // The filter: d² = |a − b|² and s² = (R_i + R_j)² in doubles are each within 6 ulps of their exact values, and
    // where d² + s² ≥ 2^−900 an underflow loses at most a few 2^−1074; farther apart than 2^−45·(d² + s²), the doubles
    // decide. Otherwise (close, tiny, or overflowing) the exact comparison does.
    const Vec2 d = a - b;
    const double d2 = dot(d, d), s = S.rounded(), s2 = s * s, scale = d2 + s2;
    if (std::isfinite(scale) && scale >= 0x1p-900) {
        const double margin = 0x1p-45 * scale;
        if (d2 < s2 - margin) return true;
        if (d2 > s2 + margin) return false;
    }
    const Rational dx = Rational(a.x) - Rational(b.x), dy = Rational(a.y) - Rational(b.y);
    const Rational sum = Rational(S.a) + Rational(S.b);
    return dx * dx + dy * dy < sum * sum;
}

bool surely_apart(Vec2 x, std::span<const PathPoint> path, double t, Radii S) {
    // The piece holding t in doubles is within a few ulps of its largest coordinate of the exact point, and point_at
    // rounds the exact point to within one; a margin of 2^−40 of the magnitudes covers both.
    std::size_t k = 0;
    while (k + 1 < path.size() && path[k + 1].t <= t) ++k;
    const Piece s = k + 1 < path.size() ? Piece{path[k].t, path[k + 1].t, path[k].p, path[k + 1].p}
                                        : Piece{path[k].t, path[k].t, path[k].p, path[k].p};
    const Vec2 y = path[k].t == t ? path[k].p : approx_at(s, t);
    const double m = std::max({std::fabs(x.x), std::fabs(x.y), std::fabs(s.p0.x), std::fabs(s.p0.y),
                               std::fabs(s.p1.x), std::fabs(s.p1.y), S.rounded()});
    const Vec2 d = x - y;
    const double dist = std::sqrt(dot(d, d));
    return std::isfinite(dist) && std::isfinite(m) && dist > S.rounded() + 0x1p-40 * m;
}

}  // namespace ricochet::meet
