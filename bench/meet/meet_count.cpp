// Counting what an engine missed (meet_count.hpp). Each decision is a double filter with a margin far wider than
// its rounding error, then GMP rationals where the filter cannot tell: the counts are exact on the given doubles.
#include "meet_count.hpp"

#include <algorithm>
#include <cmath>
#include <unordered_set>

#include <gmpxx.h>

namespace ricochet::meet_bench {
namespace {

/// The filter's margin, relative to the sum of the squares a decision involves. The double evaluations below err by
/// a few dozen units of 2^-53 of that sum (differences and interpolations of coordinates no larger than it, a
/// product or two, the one subtraction that may cancel); 1e-9 leaves a factor of 10^5 and more.
constexpr double k_filter_rel = 1e-9;

/// The filter's three answers.
enum class Filter { no, yes, unsure };

/// value < bound, decided by doubles where value is farther than margin from bound.
Filter below(double value, double bound, double margin) {
    if (value < bound - margin) return Filter::yes;
    if (value > bound + margin) return Filter::no;
    return Filter::unsure;
}

mpq_class q(double x) { return mpq_class(x); }

/// A point or vector in rationals: the house's one vector type.
using Q2 = Vec2T<mpq_class>;

/// The piece of path p that covers the interval [a, b] of positive duration: the last k with p[k].t ≤ a and
/// p[k + 1].t ≥ b, p[k].t < p[k + 1].t (a zero-duration piece, a jump, covers no interval).
std::size_t piece(std::span<const PathPoint> p, double a, double b) {
    for (std::size_t k = 0; k + 1 < p.size(); ++k)
        if (p[k].t <= a && b <= p[k + 1].t && p[k].t < p[k + 1].t) return k;
    return p.size();
}

/// The point of piece k of p at time t, in doubles.
Vec2 at(std::span<const PathPoint> p, std::size_t k, double t) {
    const double f = (t - p[k].t) / (p[k + 1].t - p[k].t);
    return p[k].p + (p[k + 1].p - p[k].p) * f;
}

/// The same, exactly: p_k + (p_{k+1} − p_k)·(t − t_k)/(t_{k+1} − t_k).
Q2 at_exact(std::span<const PathPoint> p, std::size_t k, double t) {
    const mpq_class f = (q(t) - q(p[k].t)) / (q(p[k + 1].t) - q(p[k].t));
    return {q(p[k].p.x) + (q(p[k + 1].p.x) - q(p[k].p.x)) * f, q(p[k].p.y) + (q(p[k + 1].p.y) - q(p[k].p.y)) * f};
}

/// min over u in [0, 1] of |A + B·u|²: |A|² where the closest point is at u ≤ 0, |A + B|² where at u ≥ 1, else
/// |A|² − (A·B)²/|B|² (u* = −A·B/|B|²).
template <class N>
N min_sq(const N& aa, const N& ab, const N& bb) {
    if (bb == 0 || ab >= 0) return aa;
    if (-ab >= bb) return N(aa + 2 * ab + bb);
    return N(aa - ab * ab / bb);
}

double sq(Vec2 v) { return v.x * v.x + v.y * v.y; }
double largest(Vec2 v) { return std::max(std::fabs(v.x), std::fabs(v.y)); }

}  // namespace

bool closer_than(Vec2 a, Vec2 b, double ra, double rb, std::int64_t* exact) {
    // |a − b|² < (ra + rb)²
    const double d2 = sq(a - b), s = ra + rb;
    const Filter f = below(d2, s * s, k_filter_rel * (d2 + s * s));
    if (f != Filter::unsure) return f == Filter::yes;
    if (exact != nullptr) ++*exact;
    const mpq_class dx = q(a.x) - q(b.x), dy = q(a.y) - q(b.y), se = q(ra) + q(rb);
    return dx * dx + dy * dy < se * se;
}

bool came_within(std::span<const PathPoint> a, std::span<const PathPoint> b, double ra, double rb,
                 std::int64_t* exact) {
    // Every interval [t0, t1] between consecutive times of either path on which both move along one piece:
    // D(t0 + (t1 − t0)·u) = A + B·u, A = D(t0), B = D(t1) − D(t0); the pair comes within S there if
    // min over u in [0, 1] of |A + B·u|² < S².
    std::vector<double> times;
    for (const PathPoint& p : a) times.push_back(p.t);
    for (const PathPoint& p : b) times.push_back(p.t);
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    const double s = ra + rb, s2 = s * s;
    std::vector<std::pair<double, double>> undecided;
    for (std::size_t i = 0; i + 1 < times.size(); ++i) {
        const double t0 = times[i], t1 = times[i + 1];
        const std::size_t ka = piece(a, t0, t1), kb = piece(b, t0, t1);
        // Degenerate: a time outside one path's span (a path that does not run from 0 to 1): no common piece.
        if (ka == a.size() || kb == b.size()) continue;
        const Vec2 pa0 = at(a, ka, t0), pa1 = at(a, ka, t1), pb0 = at(b, kb, t0), pb1 = at(b, kb, t1);
        const Vec2 da = pa0 - pb0, db = (pa1 - pb1) - da;
        const double m = min_sq(sq(da), dot(da, db), sq(db));
        const double p = std::max({largest(pa0), largest(pa1), largest(pb0), largest(pb1)});
        const Filter f = below(m, s2, k_filter_rel * (sq(da) + sq(db) + s2 + p * p));
        if (f == Filter::yes) return true;
        if (f == Filter::unsure) undecided.emplace_back(t0, t1);
    }
    if (undecided.empty()) return false;
    const mpq_class se = q(ra) + q(rb), se2 = se * se;
    for (const auto& [t0, t1] : undecided) {
        if (exact != nullptr) ++*exact;
        const std::size_t ka = piece(a, t0, t1), kb = piece(b, t0, t1);
        const Q2 da = at_exact(a, ka, t0) - at_exact(b, kb, t0);
        const Q2 db = (at_exact(a, ka, t1) - at_exact(b, kb, t1)) - da;
        if (min_sq<mpq_class>(dot(da, da), dot(da, db), dot(db, db)) < se2) return true;
    }
    return false;
}

double least_distance(std::span<const PathPoint> a, std::span<const PathPoint> b) {
    std::vector<double> times;
    for (const PathPoint& p : a) times.push_back(p.t);
    for (const PathPoint& p : b) times.push_back(p.t);
    std::sort(times.begin(), times.end());
    double least = INFINITY;
    for (std::size_t i = 0; i + 1 < times.size(); ++i) {
        const double t0 = times[i], t1 = times[i + 1];
        const std::size_t ka = piece(a, t0, t1), kb = piece(b, t0, t1);
        if (t0 == t1 || ka == a.size() || kb == b.size()) continue;
        const Vec2 da = at(a, ka, t0) - at(b, kb, t0), db = (at(a, ka, t1) - at(b, kb, t1)) - da;
        least = std::min(least, std::sqrt(std::max(0.0, min_sq(sq(da), dot(da, db), sq(db)))));
    }
    return least;
}

bool pass_through(std::span<const PathPoint> a, std::span<const PathPoint> b, double ra, double rb,
                  std::int64_t* exact) {
    // Degenerate: a path with no points has no start or end to be clear at.
    if (a.empty() || b.empty()) return false;
    if (!came_within(a, b, ra, rb, exact)) return false;
    return !closer_than(a.front().p, b.front().p, ra, rb, exact) && !closer_than(a.back().p, b.back().p, ra, rb, exact);
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> box_pairs(std::span<const Vec2> lo, std::span<const Vec2> hi) {
    const std::size_t n = lo.size();
    std::vector<std::uint32_t> order(n);
    for (std::uint32_t i = 0; i < n; ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return lo[a].x < lo[b].x || (lo[a].x == lo[b].x && a < b);
    });
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    for (std::size_t x = 0; x < n; ++x) {
        const std::uint32_t i = order[x];
        for (std::size_t y = x + 1; y < n && lo[order[y]].x <= hi[i].x; ++y) {
            const std::uint32_t j = order[y];
            if (lo[j].y > hi[i].y || lo[i].y > hi[j].y) continue;
            pairs.emplace_back(std::min(i, j), std::max(i, j));
        }
    }
    return pairs;
}

MeetCounter::MeetCounter(double side, std::span<const Ball> start)
    : side_(side), before_(start.begin(), start.end()), escaped_(start.size(), 0) {
    for (const Ball& b : start) e0_ += sq(b.vel);
}

void MeetCounter::add(const FrameRecord& frame) {
    const std::span<const Ball> end = frame.end;
    const std::size_t n = end.size();
    std::vector<Vec2> lo(n), hi(n);

    // Overlaps at the frame's end.
    for (std::size_t i = 0; i < n; ++i) {
        lo[i] = end[i].pos - Vec2{end[i].r, end[i].r};
        hi[i] = end[i].pos + Vec2{end[i].r, end[i].r};
    }
    for (const auto& [i, j] : box_pairs(lo, hi))
        if (closer_than(end[i].pos, end[j].pos, end[i].r, end[j].r, &counts_.exact)) ++counts_.overlaps;

    // Escapes: a centre outside the closed box [0, side]² (a comparison of doubles is exact).
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 p = end[i].pos;
        if (!escaped_[i] && (p.x < 0.0 || p.x > side_ || p.y < 0.0 || p.y > side_)) {
            escaped_[i] = 1;
            ++counts_.escaped;
        }
    }

    // Pass-throughs: pairs whose paths' boxes, grown by their radii, overlap; those that met are left out.
    const auto path_of = [&](std::size_t i, std::vector<PathPoint>& chord) -> std::span<const PathPoint> {
        if (!frame.paths.empty()) return frame.paths[i];
        chord = {{0.0, before_[i].pos}, {1.0, end[i].pos}};
        return chord;
    };
    for (std::size_t i = 0; i < n; ++i) {
        const std::span<const PathPoint> p = path_of(i, chord_a_);
        lo[i] = hi[i] = p.empty() ? end[i].pos : p.front().p;
        for (const PathPoint& pp : p) {
            lo[i] = {std::min(lo[i].x, pp.p.x), std::min(lo[i].y, pp.p.y)};
            hi[i] = {std::max(hi[i].x, pp.p.x), std::max(hi[i].y, pp.p.y)};
        }
        lo[i] = lo[i] - Vec2{end[i].r, end[i].r};
        hi[i] = hi[i] + Vec2{end[i].r, end[i].r};
    }
    std::unordered_set<std::uint64_t> met;
    for (const auto& [i, j] : frame.met) met.insert(std::uint64_t{std::min(i, j)} << 32 | std::max(i, j));
    for (const auto& [i, j] : box_pairs(lo, hi)) {
        if (met.count(std::uint64_t{i} << 32 | j) != 0) continue;
        if (!pass_through(path_of(i, chord_a_), path_of(j, chord_b_), end[i].r, end[j].r, &counts_.exact)) continue;
        // A chord is the path of a ball that touched nothing; one that did may have turned on the way.
        if (!frame.touched.empty() && (frame.touched[i] || frame.touched[j])) {
            ++counts_.unsure;
            continue;
        }
        ++counts_.pass_throughs;
        const double d = least_distance(path_of(i, chord_a_), path_of(j, chord_b_));
        counts_.deepest = std::max(counts_.deepest, 1.0 - d / (end[i].r + end[j].r));
    }

    double e = 0.0;
    for (const Ball& b : end) e += sq(b.vel);
    counts_.energy_drift = e0_ > 0.0 ? e / e0_ - 1.0 : 0.0;
    counts_.energy_drift_max = std::max(counts_.energy_drift_max, std::fabs(counts_.energy_drift));
    before_.assign(end.begin(), end.end());
}

}  // namespace ricochet::meet_bench
