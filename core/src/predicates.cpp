// Exact predicates: floating-point filter, then expansion arithmetic (first on the differences, when they
// are exact), then GMP.
#include "ricochet/predicates.hpp"

#include <atomic>
#include <cmath>
#include <initializer_list>

#include <gmpxx.h>

namespace ricochet::exact {
namespace {

// Generous bound for a sum of squares of differences (each square off by ≤ 3ε, sums ≤ 2ε more).
constexpr double k_sq = 8.0 * k_eps;
// Expansion arithmetic is exact when no product underflows or overflows: every non-zero input lies
// in [2^-450, 2^450], so products lie in [2^-900, 2^900] with all 106 bits representable.
constexpr double k_exp_min = 0x1p-450;
constexpr double k_exp_max = 0x1p450;
// compare_crossings: the rounding of its two products l, r and of D = l − r, each ≤ ε relative; 4ε leaves room.
constexpr double k_cross_round = 4.0 * k_eps;
// compare_crossings: the error bound is itself a rounded sum of a few terms; inflating it by 1 + 8ε keeps it
// an upper bound, so the filter never vouches for a sign it should not.
constexpr double k_cross_slack = 1.0 + 8.0 * k_eps;

std::atomic<unsigned long long> g_expansion{0};
std::atomic<unsigned long long> g_gmp{0};

int sign(double v) { return (v > 0.0) - (v < 0.0); }
int sign(const mpq_class& v) { return sgn(v); }

bool expansion_safe(std::initializer_list<double> xs) {
    for (double x : xs) {
        const double m = std::fabs(x);
        if (m != 0.0 && (m < k_exp_min || m > k_exp_max)) return false;
    }
    return true;
}

// An exact sum of doubles, kept as a non-overlapping expansion in increasing magnitude.
struct Expansion {
    double c[40];
    int n = 0;

    // Knuth's two-sum: a + b = x + y exactly.
    static void two_sum(double a, double b, double& x, double& y) {
        x = a + b;
        const double bv = x - a;
        const double av = x - bv;
        y = (a - av) + (b - bv);
    }
    // Shewchuk's grow-expansion with zero elimination: adds b exactly.
    void add(double b) {
        double q = b;
        int h = 0;
        for (int i = 0; i < n; ++i) {
            double qn, err;
            two_sum(q, c[i], qn, err);
            q = qn;
            if (err != 0.0) c[h++] = err;
        }
        if (q != 0.0 || h == 0) c[h++] = q;
        n = h;
    }
    // Adds k·a·b exactly (k = ±1 or ±2): an exact product is a·b = p + fma(a, b, −p).
    void add_product(double a, double b, double k = 1.0) {
        const double p = a * b;
        const double e = std::fma(a, b, -p);
        add(k * p);
        add(k * e);
    }
    // The largest component carries the sign of the whole sum.
    int sign() const { return exact::sign(c[n - 1]); }
};

mpq_class q(double x) { return mpq_class(x); }

// The first stage of every expansion path: when the differences a predicate is made of are exact, its
// polynomial has two or three products instead of six to nine, and the exact sign costs a fraction.

/// a − b rounded, and whether that is exact (Shewchuk's two-diff: its rounding error is zero).
struct Diff {
    double d;
    bool exact;
};
Diff diff(double a, double b) {
    const double x = a - b;
    const double bv = a - x;
    const double av = x + bv;
    return {x, (a - av) + (bv - b) == 0.0};
}

/// sign(a·b − c·d) exactly, for factors in the expansion range or exact differences of such numbers
/// (multiples of 2^−502 of magnitude at most 2^451: every product and its rounding error is a double).
/// Rounding is monotonic, so fl(a·b) ≠ fl(c·d) already orders the exact products; when they are equal,
/// a·b − c·d is the difference of the two rounding errors (each exact by fma), and a rounded difference
/// of two doubles keeps its sign.
int sign_of_product_difference(double a, double b, double c, double d) {
    const double l = a * b;
    const double r = c * d;
    if (l != r) return l > r ? 1 : -1;
    return sign(std::fma(a, b, -l) - std::fma(c, d, -r));
}

/// sign(dx² + dy² − r²) exactly, for exact differences dx, dy and r of the same kind.
int sign_of_squares(double dx, double dy, double r) {
    Expansion s;
    s.add_product(dx, dx);
    s.add_product(dy, dy);
    s.add_product(r, r, -1.0);
    return s.sign();
}

int orient_exact(Vec2 a, Vec2 b, Vec2 c) {
    if (expansion_safe({a.x, a.y, b.x, b.y, c.x, c.y})) {
        g_expansion.fetch_add(1, std::memory_order_relaxed);
        // (a − c) × (b − c) = (ax − cx)·(by − cy) − (ay − cy)·(bx − cx), when the four differences are exact
        const Diff d1 = diff(a.x, c.x), d2 = diff(b.y, c.y), d3 = diff(a.y, c.y), d4 = diff(b.x, c.x);
        if (d1.exact && d2.exact && d3.exact && d4.exact) return sign_of_product_difference(d1.d, d2.d, d3.d, d4.d);
        // = ax·by − ax·cy − cx·by − ay·bx + ay·cx + cy·bx  (the cx·cy terms cancel)
        Expansion s;
        s.add_product(a.x, b.y);
        s.add_product(a.x, c.y, -1.0);
        s.add_product(c.x, b.y, -1.0);
        s.add_product(a.y, b.x, -1.0);
        s.add_product(a.y, c.x);
        s.add_product(c.y, b.x);
        return s.sign();
    }
    g_gmp.fetch_add(1, std::memory_order_relaxed);
    return sign((q(a.x) - q(c.x)) * (q(b.y) - q(c.y)) - (q(a.y) - q(c.y)) * (q(b.x) - q(c.x)));
}

// Filtered orient: the value, and whether its sign is certain.
struct Filtered {
    double value;
    double bound;
    bool certain() const { return std::fabs(value) > bound; }
};

Filtered orient_filtered(Vec2 a, Vec2 b, Vec2 c) {
    const double l = (a.x - c.x) * (b.y - c.y);
    const double r = (a.y - c.y) * (b.x - c.x);
    const double sum = std::fabs(l) + std::fabs(r);
    // Too small to rule out underflow, or overflowed: make the filter decline.
    if (!(sum >= k_tiny) || !std::isfinite(sum)) return {l - r, INFINITY};
    return {l - r, k_ccw * sum};
}

}  // namespace

int orient(Vec2 a, Vec2 b, Vec2 c) {
    // (a − c) × (b − c) equals (b − a) × (c − a): the same signed double area.
    const Filtered f = orient_filtered(a, b, c);
    if (f.certain()) return sign(f.value);
    // Both products have an exactly-zero factor (x − y = 0 exactly iff x = y): the area is exactly 0.
    if ((a.x == c.x || b.y == c.y) && (a.y == c.y || b.x == c.x)) return 0;
    return orient_exact(a, b, c);
}

int side(Vec2 p, const Wall& w) {
    // BC = n·(p − P0) with n = (e_y, −e_x) is −e × (p − P0) = −orient(P0, P1, p).
    return -orient(w.p0, w.p1, p);
}

int direction_side(Vec2 d, const Wall& w) {
    // n·d = e_y·d_x − e_x·d_y = −(e × d)
    const double ex = w.p1.x - w.p0.x;
    const double ey = w.p1.y - w.p0.y;
    const double l = ex * d.y;
    const double r = ey * d.x;
    const double sum = std::fabs(l) + std::fabs(r);
    if (sum >= k_tiny && std::isfinite(sum) && std::fabs(l - r) > k_ccw * sum) return -sign(l - r);
    if (expansion_safe({w.p0.x, w.p0.y, w.p1.x, w.p1.y, d.x, d.y})) {
        g_expansion.fetch_add(1, std::memory_order_relaxed);
        // e × d = (x1 − x0)·dy − (y1 − y0)·dx, when e's two differences are exact
        const Diff ex_ = diff(w.p1.x, w.p0.x), ey_ = diff(w.p1.y, w.p0.y);
        if (ex_.exact && ey_.exact) return -sign_of_product_difference(ex_.d, d.y, ey_.d, d.x);
        // = x1·dy − x0·dy − y1·dx + y0·dx
        Expansion s;
        s.add_product(w.p1.x, d.y);
        s.add_product(w.p0.x, d.y, -1.0);
        s.add_product(w.p1.y, d.x, -1.0);
        s.add_product(w.p0.y, d.x);
        return -s.sign();
    }
    g_gmp.fetch_add(1, std::memory_order_relaxed);
    return -sign((q(w.p1.x) - q(w.p0.x)) * q(d.y) - (q(w.p1.y) - q(w.p0.y)) * q(d.x));
}

int point_circle(Vec2 p, const Circle& c) {
    // |p − c|² − r², filtered
    const double dx = p.x - c.c.x;
    const double dy = p.y - c.c.y;
    const double d2 = dx * dx + dy * dy;
    const double r2 = c.r * c.r;
    const double sum = d2 + r2;
    if (sum >= k_tiny && std::isfinite(sum) && std::fabs(d2 - r2) > k_sq * sum) return sign(d2 - r2);
    if (expansion_safe({p.x, p.y, c.c.x, c.c.y, c.r})) {
        g_expansion.fetch_add(1, std::memory_order_relaxed);
        // (px − cx)² + (py − cy)² − r², when the two differences are exact
        const Diff ddx = diff(p.x, c.c.x), ddy = diff(p.y, c.c.y);
        if (ddx.exact && ddy.exact) return sign_of_squares(ddx.d, ddy.d, c.r);
        // = px² − 2·px·cx + cx² + py² − 2·py·cy + cy² − r²
        Expansion s;
        s.add_product(p.x, p.x);
        s.add_product(p.x, c.c.x, -2.0);
        s.add_product(c.c.x, c.c.x);
        s.add_product(p.y, p.y);
        s.add_product(p.y, c.c.y, -2.0);
        s.add_product(c.c.y, c.c.y);
        s.add_product(c.r, c.r, -1.0);
        return s.sign();
    }
    g_gmp.fetch_add(1, std::memory_order_relaxed);
    const mpq_class ex = q(p.x) - q(c.c.x), ey = q(p.y) - q(c.c.y), r = q(c.r);
    return sign(ex * ex + ey * ey - r * r);
}

int circle_circle(const Circle& a, const Circle& b) {
    // |cA − cB|² − (rA + rB)², filtered
    const double dx = a.c.x - b.c.x;
    const double dy = a.c.y - b.c.y;
    const double rs = a.r + b.r;
    const double d2 = dx * dx + dy * dy;
    const double r2 = rs * rs;
    const double sum = d2 + r2;
    if (sum >= k_tiny && std::isfinite(sum) && std::fabs(d2 - r2) > k_sq * sum) return sign(d2 - r2);
    if (expansion_safe({a.c.x, a.c.y, b.c.x, b.c.y, a.r, b.r})) {
        g_expansion.fetch_add(1, std::memory_order_relaxed);
        // (ax − bx)² + (ay − by)² − (rA + rB)², when the two differences and the sum are exact
        const Diff ddx = diff(a.c.x, b.c.x), ddy = diff(a.c.y, b.c.y), rsum = diff(a.r, -b.r);
        if (ddx.exact && ddy.exact && rsum.exact) return sign_of_squares(ddx.d, ddy.d, rsum.d);
        // = ax² − 2·ax·bx + bx² + ay² − 2·ay·by + by² − rA² − 2·rA·rB − rB²
        Expansion s;
        s.add_product(a.c.x, a.c.x);
        s.add_product(a.c.x, b.c.x, -2.0);
        s.add_product(b.c.x, b.c.x);
        s.add_product(a.c.y, a.c.y);
        s.add_product(a.c.y, b.c.y, -2.0);
        s.add_product(b.c.y, b.c.y);
        s.add_product(a.r, a.r, -1.0);
        s.add_product(a.r, b.r, -2.0);
        s.add_product(b.r, b.r, -1.0);
        return s.sign();
    }
    g_gmp.fetch_add(1, std::memory_order_relaxed);
    const mpq_class ex = q(a.c.x) - q(b.c.x), ey = q(a.c.y) - q(b.c.y), r = q(a.r) + q(b.r);
    return sign(ex * ex + ey * ey - r * r);
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
    g_gmp.fetch_add(1, std::memory_order_relaxed);
    auto det = [](const Wall& w, Vec2 p) -> mpq_class {
        return (q(w.p0.x) - q(p.x)) * (q(w.p1.y) - q(p.y)) - (q(w.p0.y) - q(p.y)) * (q(w.p1.x) - q(p.x));
    };
    const mpq_class ea1 = det(w1, a), eb1 = det(w1, b), ea2 = det(w2, a), eb2 = det(w2, b);
    return sign(ea2 * eb1 - ea1 * eb2) * sa1 * sa2;
}

FallbackCounts fallback_counts() {
    return {g_expansion.load(std::memory_order_relaxed), g_gmp.load(std::memory_order_relaxed)};
}

}  // namespace ricochet::exact
