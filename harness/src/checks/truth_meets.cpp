// Ground truth for the first meet of a frame (truth.hpp's first_meet, the `oracle` check): the swept rule of
// docs/scene-log.md "Balls that meet" (1–3) written from the spec in rationals, apart from core/src/kernels/meet/
// (root.cpp decides the same question with filters and its own exact stage): a bug there cannot hide itself here.
// Do not deduplicate it into the kernel's code.
#include <algorithm>
#include <cmath>
#include <optional>

#include "checks/truth_detail.hpp"
#include "ricochet/bits.hpp"
#include "ricochet/truth.hpp"

namespace ricochet::truth {
namespace {

/// A piece of a path: from p0 at frame time t0 to p1 at t1 > t0.
struct Piece {
    PathPoint p0, p1;
    /// (p1 − p0)/(t1 − t0), per coordinate.
    Rational velocity(double Vec2::*c) const { return (Q(p1.p.*c) - Q(p0.p.*c)) / (Q(p1.t) - Q(p0.t)); }
    /// p0 + (t − t0)·velocity, per coordinate.
    Rational at(const Rational& t, double Vec2::*c) const { return Q(p0.p.*c) + (t - Q(p0.t)) * velocity(c); }
};

struct Entry {
    Root t;
    bool at_start = false;
};

/// The pair's meet on the common interval [lo, hi] (lo < hi) of pieces a and b, S² = s2: with D = P_a(lo) − P_b(lo)
/// and W = v_a − v_b, |D + W·u|² − S² = A·u² + 2B·u + c, A = W·W, B = D·W, c = |D|² − S².
std::optional<Entry> entry(const Piece& a, const Piece& b, double lo_d, double hi_d, const Rational& s2) {
    const Rational lo = Q(lo_d);
    const Rational dx = a.at(lo, &Vec2::x) - b.at(lo, &Vec2::x), dy = a.at(lo, &Vec2::y) - b.at(lo, &Vec2::y);
    const Rational wx = a.velocity(&Vec2::x) - b.velocity(&Vec2::x), wy = a.velocity(&Vec2::y) - b.velocity(&Vec2::y);
    const Rational B = dx * wx + dy * wy, c = dx * dx + dy * dy - s2;
    // Within S at lo (touching included): a meet at lo if they approach, else none on this interval (the distance
    // is convex in u, so it rises from lo on, or stays).
    if (sgn(c) <= 0) {
        if (sgn(B) >= 0) return std::nullopt;
        return Entry{{lo, Rational(0), Rational(1)}, true};
    }
    // Outside S: an entry needs the distance to fall (B < 0, so A > 0) through a secant (Δ = B² − A·c > 0; Δ = 0 is
    // a tangent, no meet).
    if (sgn(B) >= 0) return std::nullopt;
    const Rational A = wx * wx + wy * wy;
    const Rational delta = B * B - A * c;
    if (sgn(delta) <= 0) return std::nullopt;
    // The smaller root u = (−B − √Δ)/A > 0 (c > 0), within the interval: −B − A·(hi − lo) − √Δ ≤ 0.
    if (sign2(-B - A * (Q(hi_d) - lo), Rational(-1), delta) > 0) return std::nullopt;
    // t = lo + u = (lo·A − B − √Δ)/A.
    return Entry{{lo * A - B, delta, A}, false};
}

/// Balls a and b's first meet over their paths: the first common interval that holds one (intervals in time
/// order, so its meet is the pair's earliest).
std::optional<Entry> pair_meet(std::span<const PathPoint> a, std::span<const PathPoint> b, double Ra, double Rb) {
    const Rational s = Q(Ra) + Q(Rb), s2 = s * s;
    // (Ra + Rb)·(1 + 2^−52) is above S however the sum rounds.
    const double reach = (Ra + Rb) * (1.0 + 0x1p-52);
    std::size_t k = 0, m = 0;
    while (k + 1 < a.size() && m + 1 < b.size()) {
        const Piece pa{a[k], a[k + 1]}, pb{b[m], b[m + 1]};
        // Degenerate: a piece of zero duration is left out (rule 1).
        if (!(pa.p0.t < pa.p1.t)) {
            ++k;
            continue;
        }
        if (!(pb.p0.t < pb.p1.t)) {
            ++m;
            continue;
        }
        const double lo = std::max(pa.p0.t, pb.p0.t), hi = std::min(pa.p1.t, pb.p1.t);
        // Pieces whose boxes lie farther apart than S never come within S: no rationals.
        if (lo < hi && !boxes_apart(pa.p0.p, pa.p1.p, pb.p0.p, pb.p1.p, reach))
            if (auto e = entry(pa, pb, lo, hi, s2)) return e;
        // On to the piece that ends first (both where they end together).
        if (pa.p1.t == hi) ++k;
        if (pb.p1.t == hi) ++m;
    }
    return std::nullopt;
}

/// p ≤ t°, the double nearest t* = (A − √C)/D (ties to even), for a double p > 0: t° ≥ p exactly when t* lies above
/// the midpoint m of p and the double below it, or on m where p is the even one of the two.
bool not_after_nearest(double p, const Root& t) {
    const double below = std::nextafter(p, 0.0);
    const Rational m = (Q(below) + Q(p)) / Rational(2);
    // sign(t* − m) = sign(A − m·D − √C), D > 0.
    const int s = sign2(t.A - m * t.D, Rational(-1), t.C);
    return s > 0 || (s == 0 && (bits_of(p) & 1) == 0);
}

}  // namespace

FirstMeet first_meet(std::span<const std::vector<PathPoint>> paths, std::span<const double> radii,
                     std::span<const std::pair<std::uint32_t, std::uint32_t>> pairs, double printed) {
    FirstMeet out;
    std::optional<Root> best;
    for (const auto& [i, j] : pairs) {
        // Degenerate: two point balls never meet.
        if (!(radii[i] > 0) && !(radii[j] > 0)) continue;
        const std::optional<Entry> e = pair_meet(paths[i], paths[j], radii[i], radii[j]);
        if (!e) continue;
        // The pairs come sorted: a later one at the same exact time loses the tie.
        const int order = best ? compare(e->t, *best) : -1;
        if (order == 0) out.tied = true;
        if (order >= 0) continue;
        best = e->t;
        out = {true, i, j, e->at_start, false, 0.0, false};
    }
    if (!best) return out;
    out.approx = bignum::to_double(Rational((best->A - bignum::sqrt_below(best->C, 64)) / best->D));
    // t* ≥ 0 rounds to a double ≥ 0: p = 0 is never after it; a negative or NaN p is outside [0, t°].
    out.printed_in_time = printed == 0.0 || (printed > 0.0 && not_after_nearest(printed, *best));
    return out;
}

int approach_sign(Vec2 pa, Vec2 va, Vec2 pb, Vec2 vb) {
    const Rational nx = Q(pa.x) - Q(pb.x), ny = Q(pa.y) - Q(pb.y);
    return sgn((Q(va.x) - Q(vb.x)) * nx + (Q(va.y) - Q(vb.y)) * ny);
}

}  // namespace ricochet::truth
