// Ground truth for discs (truth.hpp's DiscContact): contact times as exact algebraic numbers t = (A − √C)/D,
// compared by the signs of sums of square roots, in rationals; and for discs that meet each other, how close two come
// over a common time interval of their paths and what a meet does to momentum and energy. Written from the rules of
// docs/scene-log.md, apart from core/src/kernels/disc/ and core/src/kernels/meet/ (which decide the same questions
// with filters and their own exact stages): a bug there cannot hide itself here.
#include "ricochet/truth.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <tuple>
#include <utility>

#include "checks/truth_detail.hpp"

namespace ricochet::truth {
namespace {

/// t ≤ 1: A − √C ≤ D.
bool at_most_one(const Root& r) { return sign2(r.A - r.D, Rational(-1), r.C) <= 0; }

using Part = DiscContact::Part;

struct Met {
    Root t;
    Part part = Part::face;
    bool at_start = false;
    Rational rho2 = 0;  ///< a cap's or a bumper's ρ² (the circle entered)
};

const Root k_zero{Rational(0), Rational(0), Rational(1)};

/// The leg's entry into the circle of radius ρ (ρ² = rho2) around P, from outside it (|f|² > ρ², f = a − P):
/// the smaller root of |f + t·d|² = ρ², t = (−β − √Δ)/(d·d) with β = d·f, Δ = β² − (d·d)(|f|² − ρ²), if the leg
/// moves closer (β < 0), the line is a secant (Δ > 0: Δ = 0 is a tangent, no contact) and t ≤ 1.
std::optional<Root> circle_entry(const Rational& dx, const Rational& dy, const Rational& fx, const Rational& fy,
                                 const Rational& rho2) {
    const Rational beta = dx * fx + dy * fy;
    if (sgn(beta) >= 0) return std::nullopt;
    const Rational dd = dx * dx + dy * dy;
    const Rational delta = beta * beta - dd * (fx * fx + fy * fy - rho2);
    if (sgn(delta) <= 0) return std::nullopt;
    const Root r{-beta, delta, dd};
    if (!at_most_one(r)) return std::nullopt;
    return r;
}

/// Keeps m if it is earlier than best (a tie keeps best: the earlier candidate in the rules' order).
void keep_earliest(std::optional<Met>& best, const Met& m) {
    if (!best || compare(m.t, best->t) < 0) best = m;
}

std::optional<Met> wall_contact(Vec2 a, Vec2 b, double R, const Wall& w) {
    if (a == b || boxes_apart(a, b, w.p0, w.p1, R)) return std::nullopt;
    const Rational ax = Q(a.x), ay = Q(a.y), dx = Q(b.x) - ax, dy = Q(b.y) - ay;
    const Rational R2 = Q(R) * Q(R);
    const Rational ex = Q(w.p1.x) - Q(w.p0.x), ey = Q(w.p1.y) - Q(w.p0.y), ee = ex * ex + ey * ey;
    const Rational wx = ax - Q(w.p0.x), wy = ay - Q(w.p0.y);
    // The segment's point nearest to a: P0 + u·e, u = (a − P0)·e/(e·e) clamped to [0, 1]; its part: u ≤ 0 the
    // cap at P0 (a zero-length wall too), u ≥ 1 the cap at P1, else the face.
    Rational u = 0;
    Part nearest = Part::cap0;
    if (sgn(ee) != 0) {
        u = (wx * ex + wy * ey) / ee;
        if (sgn(u) <= 0) u = 0;
        else if (u >= 1) u = 1, nearest = Part::cap1;
        else nearest = Part::face;
    }
    const Rational fx = wx - u * ex, fy = wy - u * ey;  // a − X
    const Rational dist2 = fx * fx + fy * fy;
    // On the segment: no normal. Not moving closer (d·(a − X) ≥ 0, the slope of |X(t) − segment|² at t = 0): the
    // distance to a convex set is convex along the leg, so it never decreases and nothing is entered.
    if (sgn(dist2) == 0 || sgn(dx * fx + dy * fy) >= 0) return std::nullopt;
    // Within reach (touching included) and moving closer: a contact at t = 0.
    if (sgn(dist2 - R2) <= 0) return Met{k_zero, nearest, true};
    std::optional<Met> best;
    if (sgn(ee) != 0) {
        // The face on a's side s = sign(n·w), n = (e_y, −e_x), w = a − P0, entered if the leg moves toward the line
        // (s·n·d < 0): n·(a + t·d − P0) = s·R·|n|  ⇒  t_f = (s·n·w − √(R²·n·n)) / (−s·n·d).
        const Rational nw = ey * wx - ex * wy, nd = ey * dx - ex * dy;
        const int s = sgn(nw);
        if (s != 0 && s * sgn(nd) < 0) {
            const Rational S(s);
            const Root r{S * nw, R2 * ee, -(S * nd)};
            // 0 ≤ t_f ≤ 1, and the foot of X(t_f) on the closed segment: 0 ≤ (w + t_f·d)·e ≤ e·e, times D:
            // w·e·D + A·(d·e) − (d·e)·√C in [0, e·e·D].
            const Rational we = wx * ex + wy * ey, de = dx * ex + dy * ey, base = we * r.D + r.A * de;
            if (sign2(r.A, Rational(-1), r.C) >= 0 && at_most_one(r) && sign2(base, -de, r.C) >= 0 &&
                sign2(base - ee * r.D, -de, r.C) <= 0)
                keep_earliest(best, {r, Part::face, false});
        }
    }
    // The caps: circles of radius R around P0 and (a wall with a length) P1.
    for (const Part cap : {Part::cap0, Part::cap1}) {
        if (cap == Part::cap1 && sgn(ee) == 0) break;
        const Vec2 P = cap == Part::cap0 ? w.p0 : w.p1;
        if (const auto r = circle_entry(dx, dy, ax - Q(P.x), ay - Q(P.y), R2)) keep_earliest(best, {*r, cap, false, R2});
    }
    return best;
}

std::optional<Met> bumper_contact(Vec2 a, Vec2 b, double R, const Bumper& u) {
    // (R + r)·(1 + 2^−52) is above R + r however the sum rounds.
    if (a == b || boxes_apart(a, b, u.c, u.c, (R + u.r) * (1.0 + 0x1p-52))) return std::nullopt;
    const Rational dx = Q(b.x) - Q(a.x), dy = Q(b.y) - Q(a.y);
    const Rational fx = Q(a.x) - Q(u.c.x), fy = Q(a.y) - Q(u.c.y);
    const Rational rho = Q(R) + Q(u.r), rho2 = rho * rho;
    const Rational dist2 = fx * fx + fy * fy;
    // At the centre: no normal. Not moving closer: never closer.
    if (sgn(dist2) == 0 || sgn(dx * fx + dy * fy) >= 0) return std::nullopt;
    if (sgn(dist2 - rho2) <= 0) return Met{k_zero, Part::circle, true, rho2};
    if (const auto r = circle_entry(dx, dy, fx, fy, rho2)) return Met{*r, Part::circle, false, rho2};
    return std::nullopt;
}

/// The exact first contact of a leg, its entry time, and whether another obstacle is met at that same time.
struct First {
    DiscContact contact;
    std::optional<Met> met;
    bool tied = false;
};

First first_met(Vec2 a, Vec2 b, double R, std::span<const Wall> walls, std::span<const Bumper> bumpers,
                long skip_wall, long skip_bumper) {
    First out;
    const auto take = [&](const std::optional<Met>& m, DiscContact::Obstacle o, std::size_t i) {
        if (!m) return;
        // Strictly earlier only: a tie keeps the lower wall, then walls before bumpers.
        const int order = out.met ? compare(m->t, out.met->t) : -1;
        if (order == 0) out.tied = true;
        if (order >= 0) return;
        out.met = m;
        out.tied = false;
        out.contact = {o, static_cast<std::uint32_t>(i), m->part, m->at_start};
    };
    for (std::size_t i = 0; i < walls.size(); ++i)
        if (static_cast<long>(i) != skip_wall) take(wall_contact(a, b, R, walls[i]), DiscContact::Obstacle::wall, i);
    for (std::size_t k = 0; k < bumpers.size(); ++k)
        if (static_cast<long>(k) != skip_bumper)
            take(bumper_contact(a, b, R, bumpers[k]), DiscContact::Obstacle::bumper, k);
    return out;
}

Rational qabs(const Rational& q) { return abs(q); }

/// |x + y·√u| ≤ k (k ≥ 0), exactly.
bool within(const Rational& x, const Rational& y, const Rational& u, const Rational& k) {
    return sign2(x - k, y, u) <= 0 && sign2(x + k, y, u) >= 0;
}

}  // namespace

bool disc_meets_wall(Vec2 a, Vec2 b, double R, const Wall& w) { return wall_contact(a, b, R, w).has_value(); }

DiscContact disc_first_contact(Vec2 a, Vec2 b, double R, std::span<const Wall> walls, std::span<const Bumper> bumpers,
                               long skip_wall, long skip_bumper) {
    return first_met(a, b, R, walls, bumpers, skip_wall, skip_bumper).contact;
}

DiscAccuracy disc_accuracy(Vec2 a, Vec2 b, double R, std::span<const Wall> walls, std::span<const Bumper> bumpers,
                           long skip_wall, long skip_bumper, const DiscTaken& taken, double ulps) {
    DiscAccuracy out;
    const First first = first_met(a, b, R, walls, bumpers, skip_wall, skip_bumper);
    const DiscContact::Obstacle kind = taken.bumper ? DiscContact::Obstacle::bumper : DiscContact::Obstacle::wall;
    // Another first contact, or none: oracle's failure, with no exact contact on this obstacle to measure against.
    if (!first.met || first.contact.obstacle != kind || first.contact.index != taken.index) return out;
    out.taken_first = true;
    out.tied = first.tied;
    const Met& m = *first.met;
    const Rational ax = Q(a.x), ay = Q(a.y), dx = Q(b.x) - ax, dy = Q(b.y) - ay;
    const Rational d_inf = std::max(qabs(dx), qabs(dy)), tiny = bignum::pow2(-400);
    // M: the largest magnitude of the numbers the contact is built from.
    double M = std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(b.x), std::fabs(b.y), R});
    const Wall* w = taken.bumper ? nullptr : &walls[taken.index];
    const Bumper* u = taken.bumper ? &bumpers[taken.index] : nullptr;
    if (w != nullptr) M = std::max({M, std::fabs(w->p0.x), std::fabs(w->p0.y), std::fabs(w->p1.x), std::fabs(w->p1.y)});
    else M = std::max({M, std::fabs(u->c.x), std::fabs(u->c.y), u->r});
    // Conditioned: a contact at the start (t = 0 and X = a, exactly); a face entered at an angle whose sine is at
    // least 1/4 (|n·d| ≥ |e|∞·|d|∞/4, as a point's crossing; D = |n·d| there); a circle (cap, bumper) entered at an
    // angle whose cosine to the normal is at least 1/4 (at the entry d·(X − P) = −√Δ, so √Δ ≥ |d|·ρ/4, squared:
    // 16·Δ ≥ (d·d)·ρ²; C = Δ and D = d·d there). No product of the construction underflows: |d|∞, |e|∞, ρ ≥ 2^−400.
    bool conditioned = true;
    if (!m.at_start) {
        if (m.part == Part::face) {
            const Rational e_inf = std::max(qabs(Q(w->p1.x) - Q(w->p0.x)), qabs(Q(w->p1.y) - Q(w->p0.y)));
            conditioned = d_inf >= tiny && e_inf >= tiny && 4 * m.t.D >= e_inf * d_inf;
        } else {
            conditioned = d_inf >= tiny && m.rho2 >= tiny * tiny && 16 * m.t.C >= m.t.D * m.rho2;
        }
    }
    if (!conditioned) return out;
    const Rational unit = Q(M) * bignum::pow2(-53), bound = Q(ulps) * unit;
    // t* = (A − √C)/D, D > 0. |t − t*|·|d|∞ ≤ bound  ⇔  |t·D − A + √C| ≤ bound·D/|d|∞.
    const Rational& A = m.t.A;
    const Rational& C = m.t.C;
    const Rational& D = m.t.D;
    const double t_star = bignum::to_double(Rational(A / D)) - std::sqrt(bignum::to_double(Rational(C / (D * D))));
    out.time.conditioned = true;
    out.time.within = within(Q(taken.t) * D - A, Rational(1), C, Rational(bound * D / d_inf));
    out.time.error = std::fabs(taken.t - t_star) * bignum::to_double(Rational(d_inf / unit));
    // X* = a + t*·d; per coordinate |p − a − t*·d| ≤ bound  ⇔  |(p − a)·D − A·d + d·√C| ≤ bound·D.
    const Rational px = Q(taken.p.x) - ax, py = Q(taken.p.y) - ay, k = bound * D;
    out.point.within = within(px * D - A * dx, dx, C, k) && within(py * D - A * dy, dy, C, k);
    out.point.error = std::max(std::fabs(taken.p.x - (a.x + t_star * bignum::to_double(dx))),
                               std::fabs(taken.p.y - (a.y + t_star * bignum::to_double(dy)))) /
                      bignum::to_double(unit);
    // The printed point is walked back until the piece a → p keeps the disc clear of every obstacle: one whose reach
    // the piece comes within 2·bound of (the one just bounced off, one grazed, one met at the same time) may send it
    // further than rounding does, and the point is then not judged. Reach widened by 2·bound, rounded up.
    const double margin = 2.0 * ulps * M * 0x1p-53;
    const double reach = std::nextafter(R + margin, HUGE_VAL);
    bool crowded = false;
    for (std::size_t i = 0; i < walls.size() && !crowded; ++i)
        crowded = (taken.bumper || i != taken.index) && !clear_of_wall(a, taken.p, walls[i], reach);
    for (std::size_t i = 0; i < bumpers.size() && !crowded; ++i)
        crowded = (!taken.bumper || i != taken.index) &&
                  !clear_of_circle(a, taken.p, bumpers[i].c, reach, bumpers[i].r);
    out.point.conditioned = !crowded;
    return out;
}

HitAccuracy disc_bounce_accuracy(Vec2 v, Vec2 x, const Wall* w, const Bumper* u, Vec2 v_out, double rel,
                                 double abs_bound) {
    // The outward normal at x: x − X, X the segment's point nearest x (on the face: parallel to n), or the centre.
    Rational nx, ny;
    if (w != nullptr) {
        std::tie(nx, ny) = from_segment(x, w->p0, w->p1);
    } else {
        nx = Q(x.x) - Q(u->c.x);
        ny = Q(x.y) - Q(u->c.y);
    }
    // Judged where v goes into the obstacle at x clearly, v·N ≤ −|v|∞·|N|∞/4: a printed point rounded or walked
    // back past a small cap may have v leaving it there already (the frame then goes straight back, kernel.hpp).
    const Rational vn = Q(v.x) * nx + Q(v.y) * ny;
    const Rational n_inf = std::max(qabs(nx), qabs(ny)), v_inf = std::max(qabs(Q(v.x)), qabs(Q(v.y)));
    if (!(-4 * vn >= n_inf * v_inf) || sgn(vn) == 0) return {};
    return reflection_accuracy(v, nx, ny, v_out, rel, abs_bound);
}

bool disc_in_circle(Vec2 p, double R, const Circle& c) {
    const Rational dx = Q(p.x) - Q(c.c.x), dy = Q(p.y) - Q(c.c.y), rho = Q(R) + Q(c.r);
    return dx * dx + dy * dy <= rho * rho;
}

bool disc_in_rect(Vec2 p, double R, const Rect& r) {
    // The distance from p to the closed rect, per axis: how far p lies outside [left, right], [bottom, top].
    const auto outside = [](const Rational& x, const Rational& lo, const Rational& hi) {
        return x < lo ? lo - x : x > hi ? x - hi : Rational(0);
    };
    const Rational dx = outside(Q(p.x), Q(r.left), Q(r.right)), dy = outside(Q(p.y), Q(r.bottom), Q(r.top));
    return dx * dx + dy * dy <= Q(R) * Q(R);
}

// Balls that meet (`pass-through`, `momentum`).

namespace {

/// |v|∞, exactly: fabs and max round nothing.
Rational max_norm(Vec2 v) { return Q(std::max(std::fabs(v.x), std::fabs(v.y))); }

/// P(t) = p0 + (t − t0)/(t1 − t0)·(p1 − p0): the piece's point at frame time t.
std::pair<Rational, Rational> point_at(PathPoint p0, PathPoint p1, const Rational& t) {
    const Rational f = (t - Q(p0.t)) / (Q(p1.t) - Q(p0.t));
    return {Q(p0.p.x) + f * (Q(p1.p.x) - Q(p0.p.x)), Q(p0.p.y) + f * (Q(p1.p.y) - Q(p0.p.y))};
}

/// D + W·u over u in [0, length] against S (pieces_clearance, jump_clearance), exactly.
PairClearance clearance(const Rational& dx, const Rational& dy, const Rational& wx, const Rational& wy,
                        const Rational& length, const Rational& s) {
    const Rational s2 = s * s;
    PairClearance c;
    c.start = sgn(dx * dx + dy * dy - s2);
    const Rational dw = dx * wx + dy * wy, ww = wx * wx + wy * wy;
    // Moving apart, or not at all (W = 0): the least distance is the one at the start.
    if (sgn(dw) >= 0) {
        c.least = c.start;
        return c;
    }
    // u* = −D·W/(W·W) ≥ length: still approaching at the end, the least distance is there.
    if (-dw >= length * ww) {
        const Rational ex = dx + wx * length, ey = dy + wy * length;
        c.least = sgn(ex * ex + ey * ey - s2);
        return c;
    }
    // Inside: min |D + W·u|² = |D|² − (D·W)²/(W·W) = (D × W)²/(W·W); compare with S², times W·W > 0.
    const Rational cross = dx * wy - dy * wx;
    c.least = sgn(cross * cross - s2 * ww);
    return c;
}

/// (p1 − p0)/(t1 − t0): the piece's velocity in frame time.
std::pair<Rational, Rational> velocity_of(PathPoint p0, PathPoint p1) {
    const Rational dt = Q(p1.t) - Q(p0.t);
    return {Rational((Q(p1.p.x) - Q(p0.p.x)) / dt), Rational((Q(p1.p.y) - Q(p0.p.y)) / dt)};
}

}  // namespace

PairClearance pieces_clearance(PathPoint a0, PathPoint a1, PathPoint b0, PathPoint b1, double Ra, double Rb) {
    // Pieces whose boxes lie farther apart than S never come within S ((Ra + Rb)·(1 + 2^−52) is above S however the
    // sum rounds).
    if (boxes_apart(a0.p, a1.p, b0.p, b1.p, (Ra + Rb) * (1.0 + 0x1p-52))) return {1, 1};
    const Rational lo = Q(std::max(a0.t, b0.t)), hi = Q(std::min(a1.t, b1.t));
    const auto [ax, ay] = point_at(a0, a1, lo);
    const auto [bx, by] = point_at(b0, b1, lo);
    const auto [vax, vay] = velocity_of(a0, a1);
    const auto [vbx, vby] = velocity_of(b0, b1);
    // D(lo + u) = D + W·u.
    return clearance(ax - bx, ay - by, vax - vbx, vay - vby, hi - lo, Q(Ra) + Q(Rb));
}

PairClearance jump_clearance(Vec2 p0, Vec2 p1, double c, PathPoint b0, PathPoint b1, double Ra, double Rb) {
    if (boxes_apart(p0, p1, b0.p, b1.p, (Ra + Rb) * (1.0 + 0x1p-52))) return {1, 1};
    const auto [bx, by] = b0.t < b1.t ? point_at(b0, b1, Q(c)) : std::pair{Q(b0.p.x), Q(b0.p.y)};
    // D + W·u, u in [0, 1]: the jump's straight line, ball b standing.
    return clearance(Q(p0.x) - bx, Q(p0.y) - by, Q(p1.x) - Q(p0.x), Q(p1.y) - Q(p0.y), Rational(1), Q(Ra) + Q(Rb));
}

MeetConservation meet_conservation(double ma, double mb, Vec2 va, Vec2 vb, Vec2 oa, Vec2 ob, double momentum_rel,
                                   double energy_rel, double momentum_abs, double energy_abs) {
    MeetConservation r;
    // Degenerate: an infinite or NaN number has no rational value, and keeps no law.
    for (double x : {ma, mb, va.x, va.y, vb.x, vb.y, oa.x, oa.y, ob.x, ob.y, momentum_rel, energy_rel, momentum_abs,
                     energy_abs})
        if (!std::isfinite(x)) return r;
    const Rational Ma = Q(ma), Mb = Q(mb);
    // p′ − p = ma·(oa − va) + mb·(ob − vb), per component.
    const Rational px = qabs(Ma * (Q(oa.x) - Q(va.x)) + Mb * (Q(ob.x) - Q(vb.x)));
    const Rational py = qabs(Ma * (Q(oa.y) - Q(va.y)) + Mb * (Q(ob.y) - Q(vb.y)));
    const Rational scale = Ma * max_norm(va) + Mb * max_norm(vb) + Ma * max_norm(oa) + Mb * max_norm(ob);
    const Rational bound = Q(momentum_rel) * scale + Q(momentum_abs) * (Ma + Mb);
    r.momentum_within = px <= bound && py <= bound;
    r.momentum_error = sgn(scale) == 0 ? 0.0 : bignum::to_double(Rational(std::max(px, py) / scale));
    // E = ma·|va|² + mb·|vb|², E′ likewise.
    const auto energy = [&](Vec2 a, Vec2 b) {
        return Rational(Ma * (Q(a.x) * Q(a.x) + Q(a.y) * Q(a.y)) + Mb * (Q(b.x) * Q(b.x) + Q(b.y) * Q(b.y)));
    };
    const Rational before = energy(va, vb), after = energy(oa, ob);
    const Rational change = qabs(after - before);
    const Rational speeds = max_norm(va) + max_norm(vb) + max_norm(oa) + max_norm(ob);
    r.energy_within = change <= Q(energy_rel) * before + Q(energy_abs) * (Ma + Mb) * speeds;
    r.energy_error = sgn(before) == 0 ? (sgn(change) == 0 ? 0.0 : HUGE_VAL) : bignum::to_double(Rational(change / before));
    return r;
}

}  // namespace ricochet::truth
