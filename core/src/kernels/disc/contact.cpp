// A disc's first contact with a wall or a circle, decided exactly (contact.hpp), and the exact clearance
// tests the robust kernel walks its rounded points back with.
#include "kernels/disc/contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "kernels/disc/arith.hpp"
#include "kernels/disc/contact_root.hpp"
#include "ricochet/line.hpp"
#include "ricochet/predicates.hpp"

// A decision answers std::optional<Answer> (nothing: undecided in this frame), Answer itself an optional contact.
// GCC 12 at -O2 takes the copy of an empty Answer's payload into the outer optional for a read of uninitialized
// memory (GCC bug 80635, 35 warnings in this file); the payload is never read while empty.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

namespace ricochet::disc {
namespace {

// ---------------------------------------------------------------------------------------------------------------
// The frames that turn doubles into numbers: vectors over a number type are Vec2T<T> (vec2.hpp).

/// Doubles as Approx numbers, relative to an origin o (the decision's own point: the leg's start) and scaled
/// by 2^−k so that the largest length is near 1: no product overflows or underflows for ordinary inputs, and
/// a far translation costs no precision beyond the subtraction's own rounding.
struct ApproxFrame {
    using T = Approx;
    Vec2 o;
    double s = 1.0;
    /// Chooses the scale from the lengths the decision involves (their magnitudes, roughly).
    ApproxFrame(Vec2 origin, std::initializer_list<double> lengths) : o(origin) {
        double m = 0.0;
        for (double x : lengths) m = std::fmax(m, std::fabs(x));
        if (m > 0.0 && std::isfinite(m)) s = std::ldexp(1.0, -std::ilogb(m));
    }
    Approx scaled(Approx a) const { return {a.v * s, a.e * s + k_eta}; }
    /// p − o
    Vec2T<Approx> point(Vec2 p) const {
        return {scaled(approx(p.x) - approx(o.x)), scaled(approx(p.y) - approx(o.y))};
    }
    /// a − b
    Vec2T<Approx> vector(Vec2 a, Vec2 b) const {
        return {scaled(approx(a.x) - approx(b.x)), scaled(approx(a.y) - approx(b.y))};
    }
    Approx length(double x) const { return scaled(approx(x)); }
    static Approx constant(double x) { return approx(x); }
};

/// Doubles as Approx2 numbers (the second stage) in the filter's frame: p − o is two-sum's exact pair, the scale a
/// power of two, so every input is exact (e = 0) unless the scaling underflowed.
struct FineFrame {
    using T = Approx2;
    Vec2 o;
    double s = 1.0;
    explicit FineFrame(const ApproxFrame& f) : o(f.o), s(f.s) {}
    /// x·s, exact unless it falls below 2^−1000 (then, 0 included, within 2^−1000 of x·s).
    static double scale(double x, double k, double& e) {
        const double y = x * k;
        if (x != 0.0 && std::fabs(y) < 0x1p-1000) e += 0x1p-1000;
        return y;
    }
    /// (a − b)·s
    Approx2 difference(double a, double b) const {
        double h, t;
        fine::two_sum(a, -b, h, t);
        Approx2 out;
        const double hs = scale(h, s, out.e), ts = scale(t, s, out.e);
        fine::two_sum(hs, ts, out.hi, out.lo);
        return out;
    }
    Vec2T<Approx2> point(Vec2 p) const { return {difference(p.x, o.x), difference(p.y, o.y)}; }
    Vec2T<Approx2> vector(Vec2 a, Vec2 b) const { return {difference(a.x, b.x), difference(a.y, b.y)}; }
    Approx2 length(double x) const {
        Approx2 out;
        out.hi = scale(x, s, out.e);
        return out;
    }
    static Approx2 constant(double x) { return {x, 0.0, 0.0}; }
};

/// Doubles as exact integers at the common scale 2^k of every double the decision reads.
struct ZFrame {
    using T = Z;
    Vec2 o;
    int k = 0;
    ZFrame(Vec2 origin, const Scale& scale) : o(origin), k(scale.exponent()) {}
    Vec2T<Z> point(Vec2 p) const { return {exact(p.x, k) - exact(o.x, k), exact(p.y, k) - exact(o.y, k)}; }
    Vec2T<Z> vector(Vec2 a, Vec2 b) const { return {exact(a.x, k) - exact(b.x, k), exact(a.y, k) - exact(b.y, k)}; }
    Z length(double x) const { return exact(x, k); }
    /// A small integer constant (0, ±1, a side), exact.
    static Z constant(double x) {
        Z z;
        bignum::set_int64(z, static_cast<std::int64_t>(x));
        return z;
    }
};

/// Evaluates decision(frame) on the filter's frame, then, only if it could not tell, on the second stage's, and
/// only if that could not either, on the exact one.
template <class Decision>
auto decide(Vec2 origin, std::initializer_list<double> lengths, std::initializer_list<Vec2> points,
            std::initializer_list<double> numbers, Decision&& decision) {
    const ApproxFrame filter(origin, lengths);
    if (auto r = decision(filter)) return *r;
    if (auto r = decision(FineFrame(filter))) return *r;
    Scale scale;
    for (Vec2 p : points) scale.add(p);
    for (double x : numbers) scale.add(x);
    return *decision(ZFrame(origin, scale));
}

/// |a|∞
double inf_norm(Vec2 a) { return std::fmax(std::fabs(a.x), std::fabs(a.y)); }

// ---------------------------------------------------------------------------------------------------------------
// Entry times.

/// t = (a + b·√c)/d with d > 0 and c ≥ 0.
template <class T>
struct Root {
    T a, b, c, d;
};

/// The leg and the obstacle in a frame: d = b − q, R, and the obstacle's numbers relative to q.
template <class F>
struct Setup {
    using T = typename F::T;
    Vec2T<T> d;
    T R;
    // a wall: its ends, e = P1 − P0, n, n·n, n·(q − P0), n·d
    Vec2T<T> p0, p1, e, n;
    T nn, nw, nd;
    // a circle: its centre and ρ = R + r
    Vec2T<T> c;
    T rho;

    Setup(const F& f, const Leg& leg, const Obstacle& o) : d(f.point(leg.b)), R(f.length(leg.R)) {
        if (o.wall != nullptr) {
            p0 = f.point(o.wall->p0);
            p1 = f.point(o.wall->p1);
            e = f.vector(o.wall->p1, o.wall->p0);
            n = perp(e);
            nn = dot(n, n);
            nw = -dot(n, p0);  // n·(q − P0), q the origin
            nd = dot(n, d);
        } else {
            c = f.point(o.c);
            rho = R + f.length(o.r);
        }
    }
    /// The centre of a circle part (a cap's end point) relative to q, and its radius.
    const Vec2T<T>& centre(Part part) const { return part == Part::cap0 ? p0 : part == Part::cap1 ? p1 : c; }
    const T& radius(Part part) const { return part == Part::circle ? rho : R; }
};

/// The entry time of contact ct as a Root (contact.hpp's t_f and t_c).
template <class F>
Root<typename F::T> root(const Setup<F>& s, const Contact& ct) {
    using T = typename F::T;
    if (ct.at_start) return {F::constant(0), F::constant(0), F::constant(0), F::constant(1)};
    if (ct.part == Part::face) {
        // t_f = (s·n·w − R·√(n·n)) / (−s·n·d)
        const T side = F::constant(ct.side);
        return {side * s.nw, -s.R, s.nn, -(side * s.nd)};
    }
    // t_c = (−β − √Δ)/a, β = d·(q − P), γ = |q − P|² − ρ², Δ = β² − a·γ
    const Vec2T<T>& p = s.centre(ct.part);
    const T& rho = s.radius(ct.part);
    const T beta = -dot(s.d, p);
    const T a = dot(s.d, s.d);
    const T gamma = dot(p, p) - rho * rho;
    return {-beta, F::constant(-1), beta * beta - a * gamma, a};
}

/// sign(t1 − t2) = sign(d2·a1 − d1·a2 + d2·b1·√c1 − d1·b2·√c2), d1, d2 > 0.
template <class T>
std::optional<int> compare_roots(const Root<T>& r1, const Root<T>& r2) {
    return sign3(r2.d * r1.a - r1.d * r2.a, r2.d * r1.b, r1.c, -(r1.d * r2.b), r2.c);
}

// ---------------------------------------------------------------------------------------------------------------
// First contacts.

/// Does the leg, starting outside the circle of radius ρ around p (relative to q), enter it? The roots of
/// a·t² + 2β·t + γ, γ > 0: an entry needs β < 0 (approaching), Δ = β² − aγ > 0 (a secant, not a tangent) and
/// the smaller root ≤ 1: g(1) = |b − P|² − ρ² ≤ 0, or, g(1) > 0 with both roots on one side of 1, the vertex
/// −β/a < 1.
template <class T>
std::optional<bool> circle_entered(const Vec2T<T>& d, const Vec2T<T>& p, const T& rho) {
    const T beta = -dot(d, p);
    const auto sb = disc::sign(beta);
    if (!sb) return std::nullopt;
    if (*sb >= 0) return false;
    const T a = dot(d, d);
    const T rho2 = rho * rho;
    const auto sdelta = disc::sign(beta * beta - a * (dot(p, p) - rho2));
    if (!sdelta) return std::nullopt;
    if (*sdelta <= 0) return false;
    const Vec2T<T> bp = d - p;
    const auto g1 = disc::sign(dot(bp, bp) - rho2);
    if (!g1) return std::nullopt;
    if (*g1 <= 0) return true;
    const auto vertex = disc::sign(a + beta);
    if (!vertex) return std::nullopt;
    return *vertex > 0;
}

/// A decided answer that may be "no contact".
using Answer = std::optional<Contact>;

/// The circle of radius ρ around c (relative to q) against the leg: contact.hpp's rules. at_centre: q is c.
template <class F>
std::optional<Answer> circle_contact(const Setup<F>& s, Part part, bool at_centre) {
    using T = typename F::T;
    const Vec2T<T>& p = s.centre(part);
    const T& rho = s.radius(part);
    // Not moving closer, d·(q − P) ≥ 0 (at the centre too, which has no normal): |X(t) − P| never decreases along
    // the leg (its square is convex in t with a slope ≥ 0 at 0), so the leg neither enters the circle nor, within
    // reach, hits at t = 0. Decided first: the reach of a leg that starts at its last contact is a near-tie.
    const auto closer = disc::sign(-dot(s.d, p));
    if (!closer) return std::nullopt;
    if (*closer >= 0 || at_centre) return Answer{};
    const auto reach = disc::sign(dot(p, p) - rho * rho);
    if (!reach) return std::nullopt;
    // Within reach and moving closer: a hit at t = 0.
    if (*reach <= 0) return Answer{Contact{part, 0, true}};
    const auto in = circle_entered(s.d, p, rho);
    if (!in) return std::nullopt;
    if (*in) return Answer{Contact{part, 0, false}};
    return Answer{};
}

template <class F>
std::optional<Answer> wall_contact(const F& f, const Leg& leg, const Wall& w) {
    using T = typename F::T;
    const Setup<F> s(f, leg, Obstacle{&w, {}, 0.0});
    // Degenerate: a zero-length wall is a point, met by its cap.
    if (w.p0 == w.p1) return circle_contact(s, Part::cap0, leg.q == w.p0);
    // q's nearest part of the segment: (q − P0)·e ≤ 0 the cap at P0, (q − P1)·e ≥ 0 the cap at P1, else the face.
    Part nearest = Part::face;
    const auto u0 = disc::sign(-dot(s.p0, s.e));
    if (!u0) return std::nullopt;
    if (*u0 <= 0) {
        nearest = Part::cap0;
    } else {
        const auto u1 = disc::sign(-dot(s.p1, s.e));
        if (!u1) return std::nullopt;
        if (*u1 >= 0) nearest = Part::cap1;
    }
    const auto side = disc::sign(s.nw);
    if (!side) return std::nullopt;
    // Not moving closer to the segment (its distance's slope at t = 0: s·(n·d) on the face, d·(q − P_k) at a cap),
    // or q on the segment (no normal): the distance to the segment is convex along the leg, so it never decreases,
    // and the leg neither enters the capsule nor, within reach, hits at t = 0: no contact, whatever the reach (a
    // near-tie for a leg that starts at its last contact).
    if (nearest == Part::face) {
        if (*side == 0) return Answer{};
        const auto away = disc::sign(F::constant(*side) * s.nd);
        if (!away) return std::nullopt;
        if (*away >= 0) return Answer{};
    } else {
        const auto away = disc::sign(-dot(s.d, s.centre(nearest)));
        if (!away) return std::nullopt;
        if (*away >= 0) return Answer{};
    }
    const T R2nn = s.R * s.R * s.nn;
    if (nearest != Part::face) {
        // Within reach of that cap: its rules (a centre at the end point has no normal).
        const auto reach = disc::sign(dot(s.centre(nearest), s.centre(nearest)) - s.R * s.R);
        if (!reach) return std::nullopt;
        if (*reach <= 0) return circle_contact(s, nearest, leg.q == (nearest == Part::cap0 ? w.p0 : w.p1));
    } else {
        // Within reach of the face: distance² = (n·w)²/(n·n) ≤ R².
        const auto reach = disc::sign(s.nw * s.nw - R2nn);
        if (!reach) return std::nullopt;
        // Within reach and moving closer (above): a hit at t = 0.
        if (*reach <= 0) return Answer{Contact{Part::face, static_cast<std::int8_t>(*side), true}};
    }
    // q is outside the capsule: the earliest of the face entry and the cap entries.
    std::optional<Contact> best;
    std::optional<Root<T>> best_root;
    const auto consider = [&](const Contact& c) -> bool {
        const Root<T> r = root(s, c);
        if (best) {
            const auto order = compare_roots(r, *best_root);
            if (!order) return false;
            // Ties keep the earlier part: face, cap P0, cap P1.
            if (*order >= 0) return true;
        }
        best = c;
        best_root = r;
        return true;
    };
    if (*side != 0) {
        const T sd = F::constant(*side);
        // Outside the band's slab (on a cap's side of an end, q may lie inside it): (n·w)² > R²(n·n).
        std::optional<int> outside = 1;
        if (nearest != Part::face) outside = disc::sign(s.nw * s.nw - R2nn);
        if (!outside) return std::nullopt;
        // Approaching the face: s·(n·d) < 0.
        std::optional<int> closer = 1;
        if (*outside > 0) closer = disc::sign(sd * s.nd);
        if (!closer) return std::nullopt;
        if (*outside > 0 && *closer < 0) {
            // Reaching it within the leg: s·n·(b − P0) ≤ R·|n|, n·(b − P0) = n·d + n·w.
            const auto reach = sign2(sd * (s.nd + s.nw), -s.R, s.nn);
            if (!reach) return std::nullopt;
            if (*reach <= 0) {
                // Inside the ends: 0 ≤ (X(t_f) − P0)·e and (X(t_f) − P1)·e ≤ 0; times −s·n·d > 0 and with
                // (w·e)(n·d) − (n·w)(d·e) = −(e·e)(w × d): s(e·e)(w × d) − R|n|(d·e) against 0, w = q − P_k.
                const T ee = dot(s.e, s.e);
                const T de = dot(s.d, s.e);
                const Vec2T<T> w0{-s.p0.x, -s.p0.y}, w1{-s.p1.x, -s.p1.y};
                const auto lower = sign2(sd * ee * cross(w0, s.d), -(s.R * de), s.nn);
                if (!lower) return std::nullopt;
                if (*lower >= 0) {
                    const auto upper = sign2(sd * ee * cross(w1, s.d), -(s.R * de), s.nn);
                    if (!upper) return std::nullopt;
                    if (*upper <= 0 && !consider(Contact{Part::face, static_cast<std::int8_t>(*side), false}))
                        return std::nullopt;
                }
            }
        }
    }
    for (const Part cap : {Part::cap0, Part::cap1}) {
        // q is outside both cap discs (outside the capsule).
        const auto in = circle_entered(s.d, s.centre(cap), s.R);
        if (!in) return std::nullopt;
        if (*in && !consider(Contact{cap, 0, false})) return std::nullopt;
    }
    return Answer{best};
}

/// A wall and the leg are apart by more than R in x or in y: no contact, decided on doubles with margin (a
/// computed gap of g > 0 means an exact gap ≥ g/(1 + ε)).
bool apart(const Leg& leg, Vec2 lo, Vec2 hi, double reach) {
    const double limit = reach * (1.0 + 0x1p-50);
    const Vec2 llo{std::fmin(leg.q.x, leg.b.x), std::fmin(leg.q.y, leg.b.y)};
    const Vec2 lhi{std::fmax(leg.q.x, leg.b.x), std::fmax(leg.q.y, leg.b.y)};
    return lo.x - lhi.x > limit || llo.x - hi.x > limit || lo.y - lhi.y > limit || llo.y - hi.y > limit;
}

}  // namespace

std::optional<Contact> first_contact(const Leg& leg, const Wall& w) {
    // Degenerate: a leg with no length does not move.
    if (leg.q == leg.b) return std::nullopt;
    if (apart(leg, {std::fmin(w.p0.x, w.p1.x), std::fmin(w.p0.y, w.p1.y)},
              {std::fmax(w.p0.x, w.p1.x), std::fmax(w.p0.y, w.p1.y)}, leg.R))
        return std::nullopt;
    const Vec2 d = leg.b - leg.q;
    return decide(leg.q, {inf_norm(d), inf_norm(w.p0 - leg.q), inf_norm(w.p1 - leg.q), leg.R},
                  {leg.q, leg.b, w.p0, w.p1}, {leg.R}, [&](const auto& f) { return wall_contact(f, leg, w); });
}

std::optional<Contact> first_contact(const Leg& leg, Vec2 c, double r) {
    // Degenerate: a leg with no length does not move.
    if (leg.q == leg.b) return std::nullopt;
    // |R + r| as rounded up a little: a margin for the sum's rounding.
    if (apart(leg, c, c, (leg.R + r) * (1.0 + 0x1p-50))) return std::nullopt;
    const Vec2 d = leg.b - leg.q;
    const Obstacle o{nullptr, c, r};
    return decide(leg.q, {inf_norm(d), inf_norm(c - leg.q), leg.R, r}, {leg.q, leg.b, c}, {leg.R, r},
                  [&](const auto& f) {
                      using F = std::decay_t<decltype(f)>;
                      return circle_contact(Setup<F>(f, leg, o), Part::circle, leg.q == c);
                  });
}

int compare(const Leg& leg, const Obstacle& a, const Contact& ca, const Obstacle& b, const Contact& cb) {
    if (ca.at_start || cb.at_start) return (ca.at_start ? 0 : 1) - (cb.at_start ? 0 : 1);
    // One circle met twice (walls sharing an end point, or a bumper of radius 0 there): the same quadratic.
    const auto centre = [](const Obstacle& o, const Contact& c) {
        return c.part == Part::cap0 ? o.wall->p0 : c.part == Part::cap1 ? o.wall->p1 : o.c;
    };
    const auto radius = [](const Obstacle& o, const Contact& c) { return c.part == Part::circle ? o.r : 0.0; };
    if (ca.part != Part::face && cb.part != Part::face && centre(a, ca) == centre(b, cb) && radius(a, ca) == radius(b, cb))
        return 0;
    const Vec2 d = leg.b - leg.q;
    double m = std::fmax(inf_norm(d), leg.R);
    Scale scale;
    scale.add(leg.q);
    scale.add(leg.b);
    scale.add(leg.R);
    for (const Obstacle* o : {&a, &b}) {
        if (o->wall != nullptr) {
            m = std::fmax(m, std::fmax(inf_norm(o->wall->p0 - leg.q), inf_norm(o->wall->p1 - leg.q)));
            scale.add(o->wall->p0);
            scale.add(o->wall->p1);
        } else {
            m = std::fmax(m, std::fmax(inf_norm(o->c - leg.q), o->r));
            scale.add(o->c);
            scale.add(o->r);
        }
    }
    const auto decision = [&](const auto& f) {
        using F = std::decay_t<decltype(f)>;
        return compare_roots(root(Setup<F>(f, leg, a), ca), root(Setup<F>(f, leg, b), cb));
    };
    const ApproxFrame filter(leg.q, {m});
    if (auto r = decision(filter)) return *r;
    if (auto r = decision(FineFrame(filter))) return *r;
    return *decision(ZFrame(leg.q, scale));
}

TimeEstimate contact_time_estimate(const Leg& leg, const Obstacle& o, const Contact& c) {
    if (c.at_start) return {0.0, 0.0};
    const Vec2 d = leg.b - leg.q;
    double m = std::fmax(inf_norm(d), leg.R);
    if (o.wall != nullptr)
        m = std::fmax(m, std::fmax(inf_norm(o.wall->p0 - leg.q), inf_norm(o.wall->p1 - leg.q)));
    else
        m = std::fmax(m, std::fmax(inf_norm(o.c - leg.q), o.r));
    const ApproxFrame f(leg.q, {m});
    const Setup<ApproxFrame> s(f, leg, o);
    // t = num/den; each Approx operation rounds its value exactly as the plain double expression would.
    Approx num, den;
    if (c.part == Part::face) {
        // t_f = (s·n·w − R·|n|)/(−s·n·d)
        const Approx side = approx(c.side);
        num = side * s.nw - s.R * sqrt(s.nn);
        den = -(side * s.nd);
    } else {
        // t_c = (−β − √Δ)/a = γ/(−β + √Δ): the second form has no cancellation (−β > 0). Δ may round below 0
        // (a grazing entry): √ then takes 0, as √(max(Δ, 0)).
        const Vec2T<Approx>& p = s.centre(c.part);
        const Approx& rho = s.radius(c.part);
        const Approx beta = -dot(s.d, p);
        const Approx a = dot(s.d, s.d);
        num = dot(p, p) - rho * rho;
        den = -beta + sqrt(beta * beta - a * num);
    }
    const double t = num.v / den.v;
    // |N/D − n/d| ≤ (|N − n| + |t|·|D − d|)/(|d| − |D − d|) for |d| > |D − d|, and the quotient's own rounding;
    // the factor covers the bound's own roundings.
    const double room = std::fabs(den.v) - den.e;
    if (!std::isfinite(t) || !(room > 0.0)) return {t, std::numeric_limits<double>::infinity()};
    const double error = ((num.e + std::fabs(t) * den.e) / room + std::fabs(t) * k_u) * (1.0 + 0x1p-40);
    return {t, std::isfinite(error) ? error : std::numeric_limits<double>::infinity()};
}

double contact_time(const Leg& leg, const Obstacle& o, const Contact& c) {
    const double t = contact_time_estimate(leg, o, c).t;
    return std::isfinite(t) ? std::clamp(t, 0.0, 1.0) : 0.0;
}

namespace {

/// A contact's t = (a + b·√c)/d in double-double (it does not depend on the frame's scale).
Approx2 fine_time(const Leg& leg, const Obstacle& o, const Contact& c) {
    const Vec2 d = leg.b - leg.q;
    double m = std::fmax(inf_norm(d), leg.R);
    if (o.wall != nullptr)
        m = std::fmax(m, std::fmax(inf_norm(o.wall->p0 - leg.q), inf_norm(o.wall->p1 - leg.q)));
    else
        m = std::fmax(m, std::fmax(inf_norm(o.c - leg.q), o.r));
    const FineFrame f{ApproxFrame(leg.q, {m})};
    const Root<Approx2> r = root(Setup<FineFrame>(f, leg, o), c);
    return (r.a + r.b * sqrt(r.c)) / r.d;
}

/// from + t·(to − from) in double-double, the difference exact as two-sum's pair (unscaled).
Approx2 along(const Approx2& t, double from, double to) {
    Approx2 diff;
    fine::two_sum(to, -from, diff.hi, diff.lo);
    return Approx2{from, 0.0, 0.0} + t * diff;
}

}  // namespace

FineContact contact_fine(const Leg& leg, const Obstacle& o, const Contact& c) {
    if (c.at_start) return {0.0, leg.q, 0.0};
    const Approx2 t = fine_time(leg, o, c);
    const double v = t.hi + t.lo;
    // hi + lo rounds by at most half an ulp of v.
    const double error = (t.e + std::fabs(v) * 0x1p-53) * (1.0 + 0x1p-40);
    if (!std::isfinite(v) || !std::isfinite(error)) return {0.0, leg.q, std::numeric_limits<double>::infinity()};
    const Approx2 x = along(t, leg.q.x, leg.b.x), y = along(t, leg.q.y, leg.b.y);
    return {v, {x.hi + x.lo, y.hi + y.lo}, error};
}

std::optional<RoundedContact> nearest_contact_fine(const Leg& leg, const Obstacle& o, const Contact& c) {
    if (c.at_start) return RoundedContact{0.0, leg.q};
    const Approx2 t = fine_time(leg, o, c);
    const auto tn = nearest_double(t);
    if (!tn) return std::nullopt;
    const auto x = nearest_double(along(t, leg.q.x, leg.b.x));
    if (!x) return std::nullopt;
    const auto y = nearest_double(along(t, leg.q.y, leg.b.y));
    if (!y) return std::nullopt;
    return RoundedContact{std::clamp(*tn, 0.0, 1.0), {*x, *y}};
}

TimeRoot contact_root(const Leg& leg, const Obstacle& o, const Contact& c) {
    Scale scale;
    scale.add(leg.q);
    scale.add(leg.b);
    scale.add(leg.R);
    if (o.wall != nullptr) {
        scale.add(o.wall->p0);
        scale.add(o.wall->p1);
    } else {
        scale.add(o.c);
        scale.add(o.r);
    }
    const ZFrame f(leg.q, scale);
    const Root<Z> r = root(Setup<ZFrame>(f, leg, o), c);
    return {r.a, r.b, r.c, r.d};
}

Part nearest_part(Vec2 p, const Wall& w) {
    if (w.p0 == w.p1) return Part::cap0;
    const auto u = [&](Vec2 end) {
        return decide(p, {inf_norm(end - p), inf_norm(w.p1 - w.p0)}, {p, w.p0, w.p1}, {}, [&](const auto& f) {
            return disc::sign(-dot(f.point(end), f.vector(w.p1, w.p0)));  // (p − P_k)·e
        });
    };
    if (u(w.p0) <= 0) return Part::cap0;
    if (u(w.p1) >= 0) return Part::cap1;
    return Part::face;
}

namespace {

/// disc::sign(v·(p − c)), exactly.
int dot_sign(Vec2 v, Vec2 p, Vec2 c) {
    return decide(p, {inf_norm(c - p), inf_norm(v)}, {p, c, v}, {}, [&](const auto& f) {
        using F = std::decay_t<decltype(f)>;
        const Vec2T<typename F::T> vv{f.length(v.x), f.length(v.y)};
        return disc::sign(-dot(vv, f.point(c)));  // v·(p − c), p the origin
    });
}

/// Distance from p to the segment a → b at least ρ = R + r, exactly: the cap at the nearer end, or the face:
/// (e × (p − a))² ≥ ρ²·(e·e).
bool point_segment_clear(Vec2 p, Vec2 a, Vec2 b, double R, double r) {
    if (R == 0.0 && r == 0.0) return true;
    return decide(p, {inf_norm(a - p), inf_norm(b - p), R, r}, {p, a, b}, {R, r}, [&](const auto& f) -> std::optional<bool> {
        using T = typename std::decay_t<decltype(f)>::T;
        const Vec2T<T> A = f.point(a), B = f.point(b), e = f.vector(b, a);
        const T rho = f.length(R) + f.length(r);
        const T rho2 = rho * rho;
        // (p − a)·e ≤ 0 ⇔ A·e ≥ 0: the cap at a (a zero-length segment too)
        const auto ua = disc::sign(dot(A, e));
        if (!ua) return std::nullopt;
        if (*ua >= 0) {
            const auto c = disc::sign(dot(A, A) - rho2);
            if (!c) return std::nullopt;
            return *c >= 0;
        }
        const auto ub = disc::sign(dot(B, e));
        if (!ub) return std::nullopt;
        if (*ub <= 0) {
            const auto c = disc::sign(dot(B, B) - rho2);
            if (!c) return std::nullopt;
            return *c >= 0;
        }
        const T x = cross(e, Vec2T<T>{-A.x, -A.y});
        const auto c = disc::sign(x * x - rho2 * dot(e, e));
        if (!c) return std::nullopt;
        return *c >= 0;
    });
}

}  // namespace

int normal_sign(Vec2 p, Vec2 v, const Obstacle& o) {
    if (o.wall == nullptr) return dot_sign(v, p, o.c);
    const Part part = nearest_part(p, *o.wall);
    if (part == Part::face) return exact::side(p, *o.wall) * exact::direction_side(v, *o.wall);
    return dot_sign(v, p, part == Part::cap0 ? o.wall->p0 : o.wall->p1);
}

Vec2 normal_at(Vec2 p, const Obstacle& o) {
    if (o.wall == nullptr) return p - o.c;
    const Part part = nearest_part(p, *o.wall);
    if (part == Part::face) return static_cast<double>(exact::side(p, *o.wall)) * normal(*o.wall);
    return p - (part == Part::cap0 ? o.wall->p0 : o.wall->p1);
}

bool crosses(Vec2 q, Vec2 x, const Wall& w) {
    // Strictly opposite sides of the line, and the closed segment meets the line q x.
    if (q == x || w.p0 == w.p1) return false;
    if (exact::side(q, w) * exact::side(x, w) >= 0) return false;
    return exact::orient(q, x, w.p0) * exact::orient(q, x, w.p1) <= 0;
}

bool touches(Vec2 q, Vec2 x, const Wall& w) {
    // Each segment's line has the other's ends on one closed side each or both: o1·o2 ≤ 0 and o3·o4 ≤ 0; when all
    // four are 0 the two lie on one line (or are points) and meet iff their boxes do.
    const int o1 = exact::orient(q, x, w.p0), o2 = exact::orient(q, x, w.p1);
    const int o3 = exact::orient(w.p0, w.p1, q), o4 = exact::orient(w.p0, w.p1, x);
    if (o1 * o2 > 0 || o3 * o4 > 0) return false;
    if (o1 != 0 || o2 != 0 || o3 != 0 || o4 != 0) return true;
    const auto overlap = [](double a0, double a1, double b0, double b1) {
        return std::max(std::min(a0, a1), std::min(b0, b1)) <= std::min(std::max(a0, a1), std::max(b0, b1));
    };
    return overlap(q.x, x.x, w.p0.x, w.p1.x) && overlap(q.y, x.y, w.p0.y, w.p1.y);
}

bool point_clear(Vec2 p, double R, const Obstacle& o) {
    if (o.wall != nullptr) return point_segment_clear(p, o.wall->p0, o.wall->p1, R, 0.0);
    return point_segment_clear(o.c, p, p, R, o.r);
}

namespace {

/// True if the boxes of the segments a0 → a1 and b0 → b1 lie more than reach apart along x or y: then every point of
/// one is that far from every point of the other. A difference of doubles is within 2^−53 of its value (exact where
/// it is subnormal) and a sum of radii in reach within 2^−53 of its own, which the factor 1 + 2^−50 covers; an
/// overflow or a NaN decides nothing.
bool boxes_apart(Vec2 a0, Vec2 a1, Vec2 b0, Vec2 b1, double reach) {
    const double r = reach * (1.0 + 0x1p-50);
    const auto apart = [r](double u0, double u1, double w0, double w1) {
        return std::min(w0, w1) - std::max(u0, u1) > r || std::min(u0, u1) - std::max(w0, w1) > r;
    };
    return apart(a0.x, a1.x, b0.x, b1.x) || apart(a0.y, a1.y, b0.y, b1.y);
}

}  // namespace

bool piece_clear(Vec2 q, Vec2 x, double R, const Obstacle& o) {
    // Far apart along an axis: clear, without a decision's filters (a circle as the point segment at its centre).
    if (o.wall ? boxes_apart(q, x, o.wall->p0, o.wall->p1, R) : boxes_apart(q, x, o.c, o.c, R + o.r)) return true;
    // A circle: its centre's distance to the piece.
    if (o.wall == nullptr) return point_segment_clear(o.c, q, x, R, o.r);
    // Degenerate: no reach (a point ball) keeps every distance.
    if (R == 0.0) return true;
    const Wall& w = *o.wall;
    if (q == x) return point_segment_clear(q, w.p0, w.p1, R, 0.0);
    if (w.p0 == w.p1) return point_segment_clear(w.p0, q, x, R, 0.0);
    // Two segments are at least R > 0 apart iff they do not cross and each end point is R from the other
    // segment (touching or overlapping segments have an end point at distance 0).
    if (crosses(q, x, w)) return false;
    return point_segment_clear(q, w.p0, w.p1, R, 0.0) && point_segment_clear(x, w.p0, w.p1, R, 0.0) &&
           point_segment_clear(w.p0, q, x, R, 0.0) && point_segment_clear(w.p1, q, x, R, 0.0);
}

}  // namespace ricochet::disc
