// Ground truth for the checks (truth.hpp).
#include "ricochet/truth.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "checks/truth_detail.hpp"

namespace ricochet::truth {
namespace {

int sgn_q(const Rational& q) { return sgn(q); }

}  // namespace

int orient(Vec2 a, Vec2 b, Vec2 c) {
    // Shewchuk's orient2dfast with its error bound (3 + 16ε)ε·(|l| + |r|), ε = 2^−53, valid while no
    // product under- or overflows; otherwise, or when the rounded value is within the bound, GMP decides.
    const double l = (a.x - c.x) * (b.y - c.y);
    const double r = (a.y - c.y) * (b.x - c.x);
    const double det = l - r;
    const double sum = std::fabs(l) + std::fabs(r);
    constexpr double eps = 0x1p-53;
    const double bound = (3.0 + 16.0 * eps) * eps * sum;
    if (std::isfinite(det) && std::isfinite(sum) && sum >= 0x1p-900 && std::fabs(det) > bound)
        return det > 0 ? 1 : -1;
    // (a − c) × (b − c), which has the sign of (b − a) × (c − a).
    return sgn_q((Q(a.x) - Q(c.x)) * (Q(b.y) - Q(c.y)) - (Q(a.y) - Q(c.y)) * (Q(b.x) - Q(c.x)));
}

int side(Vec2 p, const Wall& w) { return -orient(w.p0, w.p1, p); }

bool on_closed_segment(Vec2 p, const Wall& w) {
    if (orient(w.p0, w.p1, p) != 0) return false;
    return std::min(w.p0.x, w.p1.x) <= p.x && p.x <= std::max(w.p0.x, w.p1.x) && std::min(w.p0.y, w.p1.y) <= p.y &&
           p.y <= std::max(w.p0.y, w.p1.y);
}

int locate(Vec2 p, std::span<const Wall> walls) {
    bool inside = false;
    for (const Wall& w : walls) {
        if (on_closed_segment(p, w)) return 0;
        const Vec2 a = w.p0, b = w.p1;
        // The ray from p to +x crosses the edge if the edge straddles y = p.y (half-open, so a vertex on
        // the ray counts once) and p lies to the left of the upward-directed edge.
        if ((a.y > p.y) != (b.y > p.y)) {
            const int o = orient(a, b, p);
            if (b.y > a.y ? o > 0 : o < 0) inside = !inside;
        }
    }
    return inside ? 1 : -1;
}

int circle_side(Vec2 p, const Circle& c) {
    const Rational dx = Q(p.x) - Q(c.c.x), dy = Q(p.y) - Q(c.c.y), r = Q(c.r);
    return sgn_q(dx * dx + dy * dy - r * r);
}

bool point_in_circle(Vec2 p, const Circle& c) {
    const Rational dx = Q(p.x) - Q(c.c.x), dy = Q(p.y) - Q(c.c.y), r = Q(c.r);
    return dx * dx + dy * dy <= r * r;
}

bool circles_overlap(const Circle& a, const Circle& b) {
    const Rational dx = Q(a.c.x) - Q(b.c.x), dy = Q(a.c.y) - Q(b.c.y), r = Q(a.r) + Q(b.r);
    return dx * dx + dy * dy <= r * r;
}

bool point_in_rect(Vec2 p, const Rect& r) {
    return r.left <= p.x && p.x <= r.right && r.bottom <= p.y && p.y <= r.top;
}

bool rects_overlap(const Rect& a, const Rect& b) {
    // Closed intervals intersect on both axes.
    return std::max(a.left, b.left) <= std::min(a.right, b.right) &&
           std::max(a.bottom, b.bottom) <= std::min(a.top, b.top);
}

bool speed_within(Vec2 v, Vec2 w, int m, double b, double a) {
    // An infinite or NaN component has no rational value: such a speed is outside every bound (a lecture
    // kernel's float arithmetic overflowing a reflection gives one).
    for (double x : {v.x, v.y, w.x, w.y, b, a})
        if (!std::isfinite(x)) return false;
    // | |w| − |v| | ≤ C·|v| + A with C = (1 + b)^m − 1 and A = m·a, i.e. (1 − C)|v| − A ≤ |w| ≤ (1 + C)|v| + A.
    const Rational vv = Q(v.x) * Q(v.x) + Q(v.y) * Q(v.y);
    const Rational ww = Q(w.x) * Q(w.x) + Q(w.y) * Q(w.y);
    Rational grow = 1;
    for (int i = 0; i < m; ++i) grow *= 1 + Q(b);
    const Rational c = grow - 1, abs_part = Q(a) * m;
    const Rational hi = 1 + c, lo = 1 - c;
    // No absolute part: both sides squared, exactly, with no square root at all.
    if (sgn(abs_part) == 0) {
        if (ww > hi * hi * vv) return false;
        return sgn(lo) <= 0 || ww >= lo * lo * vv;
    }
    // |v| bracketed by a 256-bit square root widened by 2^−200 relative, far below any b used.
    const Rational root = bignum::sqrt_below(vv, 256);
    const Rational slack = bignum::pow2(-200);
    const Rational vhi = root * (1 + slack), vlo = root * (1 - slack);
    const Rational upper = hi * vhi + abs_part, lower = lo * vlo - abs_part;
    if (ww > upper * upper) return false;
    return sgn(lower) <= 0 || ww >= lower * lower;
}

namespace {

/// |p − X|², X as in from_segment.
Rational distance2_to_segment(Vec2 p, Vec2 a, Vec2 b) {
    const auto [dx, dy] = from_segment(p, a, b);
    return dx * dx + dy * dy;
}

}  // namespace

std::pair<Rational, Rational> from_segment(Vec2 p, Vec2 a, Vec2 b) {
    const Rational ex = Q(b.x) - Q(a.x), ey = Q(b.y) - Q(a.y);
    const Rational px = Q(p.x) - Q(a.x), py = Q(p.y) - Q(a.y);
    const Rational ee = ex * ex + ey * ey;
    Rational u = 0;
    if (sgn(ee) != 0) {
        u = (px * ex + py * ey) / ee;
        if (u < 0) u = 0;
        if (u > 1) u = 1;
    }
    return {px - u * ex, py - u * ey};
}

bool clear_of_wall(Vec2 a, Vec2 b, const Wall& w, double R) {
    if (R == 0.0 || boxes_apart(a, b, w.p0, w.p1, R)) return true;
    // Two closed segments that intersect are 0 apart: a proper crossing (each strictly splits the other's ends)
    // or an end point on the other segment (the distances below are then 0).
    if (a != b && w.p0 != w.p1 && orient(a, b, w.p0) * orient(a, b, w.p1) < 0 &&
        orient(w.p0, w.p1, a) * orient(w.p0, w.p1, b) < 0)
        return false;
    // Otherwise the least distance is from an end point of one to the other segment.
    const Rational r2 = Q(R) * Q(R);
    return distance2_to_segment(a, w.p0, w.p1) >= r2 && distance2_to_segment(b, w.p0, w.p1) >= r2 &&
           distance2_to_segment(w.p0, a, b) >= r2 && distance2_to_segment(w.p1, a, b) >= r2;
}

bool clear_of_circle(Vec2 a, Vec2 b, Vec2 c, double R, double r) {
    // (R + r)·(1 + 2^−52) is above R + r however the sum rounds.
    if (boxes_apart(a, b, c, c, (R + r) * (1.0 + 0x1p-52))) return true;
    const Rational rho = Q(R) + Q(r);
    return distance2_to_segment(c, a, b) >= rho * rho;
}

int wall_reach_side(Vec2 p, const Wall& w, double R) {
    return sgn(distance2_to_segment(p, w.p0, w.p1) - Q(R) * Q(R));
}

int wall_approach_sign(Vec2 a, Vec2 b, const Wall& w) {
    // d/dt |a + t·d − X(t)|² = 2·d·(a − X) at t = 0, d = b − a: the nearest point of a convex set moves, the
    // distance's derivative does not see it.
    const auto [dx, dy] = from_segment(a, w.p0, w.p1);
    return sgn((Q(b.x) - Q(a.x)) * dx + (Q(b.y) - Q(a.y)) * dy);
}

int circle_reach_side(Vec2 p, Vec2 c, double R, double r) {
    const Rational dx = Q(p.x) - Q(c.x), dy = Q(p.y) - Q(c.y), rho = Q(R) + Q(r);
    return sgn(dx * dx + dy * dy - rho * rho);
}

int circle_approach_sign(Vec2 a, Vec2 b, Vec2 c) {
    return sgn((Q(b.x) - Q(a.x)) * (Q(a.x) - Q(c.x)) + (Q(b.y) - Q(a.y)) * (Q(a.y) - Q(c.y)));
}

bool projects_onto_segment(Vec2 p, const Wall& w) {
    const Rational ex = Q(w.p1.x) - Q(w.p0.x), ey = Q(w.p1.y) - Q(w.p0.y);
    const Rational ee = ex * ex + ey * ey;
    if (sgn(ee) == 0) return false;
    // 0 ≤ (p − P0)·e ≤ e·e: the projection's fraction u in [0, 1].
    const Rational pe = (Q(p.x) - Q(w.p0.x)) * ex + (Q(p.y) - Q(w.p0.y)) * ey;
    return sgn(pe) >= 0 && pe <= ee;
}

bool parallel_clear_of_line(Vec2 a, Vec2 b, const Wall& w, double R) {
    const Rational ex = Q(w.p1.x) - Q(w.p0.x), ey = Q(w.p1.y) - Q(w.p0.y);
    // n·x − n·P0 for x = a and x = b: equal when the leg is parallel to the line.
    const auto bc = [&](Vec2 x) -> Rational { return ey * (Q(x.x) - Q(w.p0.x)) - ex * (Q(x.y) - Q(w.p0.y)); };
    const Rational at_a = bc(a);
    if (at_a != bc(b)) return false;
    // The distance from a to the line is |n·(a − P0)| / |n|: compare its square with R², times n·n.
    return at_a * at_a >= Q(R) * Q(R) * (ex * ex + ey * ey);
}

namespace {

/// A leg a → b and wall w, exactly: whether the crossing is well-conditioned, and then its leg fraction s,
/// |d|∞ and ε·M.
struct ExactCrossing {
    bool conditioned = false;
    Rational s, dx, dy, d_inf, unit;
};

ExactCrossing exact_crossing(Vec2 a, Vec2 b, const Wall& w) {
    ExactCrossing c;
    const Rational ex = Q(w.p1.x) - Q(w.p0.x), ey = Q(w.p1.y) - Q(w.p0.y);
    c.dx = Q(b.x) - Q(a.x);
    c.dy = Q(b.y) - Q(a.y);
    const auto qabs = [](const Rational& q) { return Rational(abs(q)); };
    const Rational e_inf = std::max(qabs(ex), qabs(ey));
    c.d_inf = std::max(qabs(c.dx), qabs(c.dy));
    const Rational tiny = bignum::pow2(-400);
    // e × d; the crossing is well-conditioned when its sine (in ∞-norms) is at least 1/4.
    const Rational cross = ex * c.dy - ey * c.dx;
    c.conditioned = e_inf >= tiny && c.d_inf >= tiny && 4 * qabs(cross) >= e_inf * c.d_inf;
    if (!c.conditioned) return c;
    // BC(x) = n·(x − P0) with the outward normal n = (e_y, −e_x); s = BC(a) / (BC(a) − BC(b)).
    const auto bc = [&](Vec2 x) -> Rational { return ey * (Q(x.x) - Q(w.p0.x)) - ex * (Q(x.y) - Q(w.p0.y)); };
    const Rational bc_a = bc(a), bc_b = bc(b);
    c.s = bc_a / (bc_a - bc_b);  // bc_a − bc_b = e × d ≠ 0 here
    const double m = std::max({std::fabs(a.x), std::fabs(a.y), std::fabs(b.x), std::fabs(b.y), std::fabs(w.p0.x),
                               std::fabs(w.p0.y), std::fabs(w.p1.x), std::fabs(w.p1.y)});
    // ε·M exactly (a power of two times a double).
    c.unit = Q(m) * bignum::pow2(-53);
    return c;
}

/// err ≤ ulps·unit, and err in units of unit (for messages).
HitAccuracy judge(const Rational& err, const Rational& unit, double ulps) {
    HitAccuracy r;
    r.conditioned = true;
    r.within = err <= Q(ulps) * unit;
    // unit > 0: judge is called only for a conditioned crossing, whose wall has |e|∞ ≥ 2^-400, so M ≥ 2^-401.
    r.error = bignum::to_double(Rational(err / unit));
    return r;
}

}  // namespace

HitAccuracy hit_accuracy(Vec2 a, Vec2 b, const Wall& w, Vec2 p, double ulps, const Wall* kept, int kept_from) {
    const ExactCrossing c = exact_crossing(a, b, w);
    if (!c.conditioned) return {};
    // B_i exactly: X = a + s·d.
    const Rational xx = Q(a.x) + c.s * c.dx, xy = Q(a.y) + c.s * c.dy;
    if (kept != nullptr && kept_from != 0) {
        // side(X) of the kept wall's line, exactly: sign of n·(X − P0) with n = (e_y, −e_x).
        const Rational kx = Q(kept->p1.x) - Q(kept->p0.x), ky = Q(kept->p1.y) - Q(kept->p0.y);
        const int side = sgn(Rational(ky * (xx - Q(kept->p0.x)) - kx * (xy - Q(kept->p0.y))));
        if (side != kept_from) return {};
    }
    return judge(std::max(Rational(abs(Q(p.x) - xx)), Rational(abs(Q(p.y) - xy))), c.unit, ulps);
}

HitAccuracy hit_time_accuracy(Vec2 a, Vec2 b, const Wall& w, double t, double ulps) {
    const ExactCrossing c = exact_crossing(a, b, w);
    if (!c.conditioned) return {};
    // |t_i − s|·|d|∞: how far along the leg the error in t_i moves the point.
    return judge(Rational(abs(Q(t) - c.s) * c.d_inf), c.unit, ulps);
}

HitAccuracy reflection_accuracy(Vec2 v, const Rational& nx, const Rational& ny, Vec2 v_out, double rel,
                                double abs_bound) {
    HitAccuracy r;
    const Rational vn = Q(v.x) * nx + Q(v.y) * ny, nn = nx * nx + ny * ny;
    const auto qabs = [](const Rational& q) { return Rational(abs(q)); };
    const Rational n_inf = std::max(qabs(nx), qabs(ny)), v_inf = std::max(qabs(Q(v.x)), qabs(Q(v.y)));
    r.conditioned = sgn(nn) != 0 && 4 * qabs(vn) >= v_inf * n_inf;
    if (!r.conditioned) return r;
    // R = v − 2(v·n)/(n·n)·n, exactly.
    const Rational k = 2 * vn / nn;
    const Rational rx = Q(v.x) - k * nx, ry = Q(v.y) - k * ny;
    const Rational err = std::max(qabs(Q(v_out.x) - rx), qabs(Q(v_out.y) - ry));
    // err ≤ 2·rel·|v| + 2·abs  ⇔  err − 2·abs ≤ 0, or (err − 2·abs)² ≤ 4·rel²·(v·v): no square root needed.
    const Rational over = err - 2 * Q(abs_bound);
    const Rational vv = Q(v.x) * Q(v.x) + Q(v.y) * Q(v.y);
    r.within = sgn(over) <= 0 || over * over <= 4 * Q(rel) * Q(rel) * vv;
    r.error = sgn(vv) == 0 ? 0.0 : bignum::to_double(err) / std::sqrt(bignum::to_double(vv));
    return r;
}

HitAccuracy bounce_accuracy(Vec2 v, const Wall& w, Vec2 v_out, double rel, double abs_bound) {
    // n = (e_y, −e_x), the outward normal.
    const Rational ex = Q(w.p1.x) - Q(w.p0.x), ey = Q(w.p1.y) - Q(w.p0.y);
    return reflection_accuracy(v, ey, -ex, v_out, rel, abs_bound);
}

HitAccuracy corner_accuracy(Vec2 v, const Wall& hit, int hit_from, std::span<const Wall> others,
                            std::span<const int> others_from, Vec2 v_out, double rel, double abs_bound) {
    const auto qabs = [](const Rational& q) { return Rational(abs(q)); };
    struct Normal {
        Rational x, y, nn, inf;  // n = (e_y, −e_x), n·n, |n|∞
    };
    const auto normal = [&](const Wall& w) {
        const Rational ex = Q(w.p1.x) - Q(w.p0.x), ey = Q(w.p1.y) - Q(w.p0.y);
        return Normal{ey, -ex, ey * ey + ex * ex, std::max(qabs(ey), qabs(ex))};
    };
    HitAccuracy r;
    Rational wx = Q(v.x), wy = Q(v.y);
    // n·w, and whether its sign is clear: |n·w| ≥ |w|∞·|n|∞ / 4.
    const auto side_of = [&](const Normal& n, int& s) {
        const Rational d = n.x * wx + n.y * wy;
        s = sgn(d);
        return 4 * qabs(d) >= std::max(qabs(wx), qabs(wy)) * n.inf;
    };
    // w − 2(w·n)/(n·n)·n, exactly.
    const auto reflect_about = [&](const Normal& n) {
        const Rational k = 2 * (n.x * wx + n.y * wy) / n.nn;
        wx -= k * n.x;
        wy -= k * n.y;
    };
    const Normal nh = normal(hit);
    int s = 0;
    if (sgn(nh.nn) == 0 || !side_of(nh, s)) return r;
    std::vector<Normal> ns;
    for (const Wall& c : others) {
        ns.push_back(normal(c));
        if (sgn(ns.back().nn) == 0) return r;
    }
    reflect_about(nh);
    int m = 1;
    for (std::size_t j = 0; j < ns.size(); ++j) {
        if (!side_of(ns[j], s)) return r;
        if (s == -others_from[j]) {
            reflect_about(ns[j]);
            ++m;
        }
    }
    // Still crossing a wall met here, or not strictly back from the wall hit: straight back.
    bool back = false;
    for (std::size_t j = 0; j < ns.size(); ++j) {
        if (!side_of(ns[j], s)) return r;
        back = back || s == -others_from[j];
    }
    if (!side_of(nh, s)) return r;
    back = back || s != hit_from;
    r.conditioned = true;
    const Rational vv = Q(v.x) * Q(v.x) + Q(v.y) * Q(v.y);
    if (back) {
        r.within = v_out == -v;
        r.error = r.within ? 0.0 : 2.0;
        return r;
    }
    const Rational err = std::max(qabs(Q(v_out.x) - wx), qabs(Q(v_out.y) - wy));
    // err ≤ 3m·(2·rel·|v| + abs)  ⇔  over = err − 3m·abs ≤ 0, or over² ≤ 36m²·rel²·(v·v).
    const Rational over = err - 3 * m * Q(abs_bound);
    r.within = sgn(over) <= 0 || over * over <= 36 * m * m * Q(rel) * Q(rel) * vv;
    // vv ≠ 0 here: for v = 0 every side is 0, which is not hit_from (±1), so the rule went straight back above.
    r.error = sgn(vv) == 0 ? 0.0 : bignum::to_double(err) / std::sqrt(bignum::to_double(vv));
    return r;
}

HitAccuracy leg_end_accuracy(Vec2 from, Vec2 v, std::span<const double> ts, Vec2 to) {
    const auto qabs = [](const Rational& q) { return Rational(abs(q)); };
    // R = Π(1 − t_k): the fraction of the frame left after the hits.
    Rational rest = 1;
    for (double t : ts) rest *= 1 - Q(t);
    // The exact end from + R·v, and its distance to the printed one.
    const Rational px = rest * Q(v.x), py = rest * Q(v.y);
    const Rational err = std::max(qabs(Q(to.x) - (Q(from.x) + px)), qabs(Q(to.y) - (Q(from.y) + py)));
    const Rational m = std::max({qabs(Q(from.x)), qabs(Q(from.y)), qabs(Q(to.x)), qabs(Q(to.y)), qabs(px), qabs(py)});
    // Each rounding of a product or a sum errs by at most ε relative to its result, or 2^−1075 when it
    // underflows: 2k roundings for R (relative, so ≤ (2k)ε·|R·v| + …), one for R·v, one for the sum (≤ ε·|to|).
    // (2k + 2)ε·M with the second-order terms, which stay below ε·M while k < 2^50, makes (2k + 3)ε·M.
    const Rational unit = m * bignum::pow2(-53);
    const auto k = static_cast<long>(ts.size());
    HitAccuracy r;
    r.conditioned = true;
    r.within = err <= (2 * k + 3) * unit + bignum::pow2(-1072);
    r.error = sgn(unit) == 0 ? 0.0 : bignum::to_double(Rational(err / unit));
    return r;
}

bool sum_exact(double a, double b) { return Q(a + b) == Q(a) + Q(b); }

int direction_side(Vec2 d, const Wall& w) {
    // n·d = e_y·d_x − e_x·d_y, with e = P1 − P0 taken exactly (its double difference may round).
    return sgn_q(Q(d.x) * (Q(w.p1.y) - Q(w.p0.y)) - Q(d.y) * (Q(w.p1.x) - Q(w.p0.x)));
}

bool walls_closed(std::span<const Wall> walls) {
    std::vector<Vec2> ends;
    for (const Wall& w : walls) {
        if (w.p0 == w.p1) continue;
        ends.push_back(w.p0);
        ends.push_back(w.p1);
    }
    if (ends.empty()) return false;
    std::sort(ends.begin(), ends.end(), [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    for (std::size_t i = 0; i < ends.size();) {
        std::size_t j = i;
        while (j < ends.size() && ends[j] == ends[i]) ++j;
        if ((j - i) % 2 != 0) return false;
        i = j;
    }
    return true;
}

int cross_sign(Vec2 a, Vec2 b) { return orient({0, 0}, a, b); }

int dot_sign(Vec2 a, Vec2 b) {
    const double l = a.x * b.x, r = a.y * b.y;
    const double s = l + r;
    const double sum = std::fabs(l) + std::fabs(r);
    constexpr double eps = 0x1p-53;
    if (std::isfinite(s) && std::isfinite(sum) && sum >= 0x1p-900 && std::fabs(s) > 3.0 * eps * sum)
        return s > 0 ? 1 : -1;
    return sgn_q(Q(a.x) * Q(b.x) + Q(a.y) * Q(b.y));
}

Miss leg_miss(Vec2 bs, Vec2 be, const Wall& w) {
    if (w.p0 == w.p1 || bs == be) return Miss::degenerate;
    const int s0 = side(bs, w), s1 = side(be, w);
    if (s0 < 0 && s1 < 0) return Miss::both_inside;
    if (s0 > 0 && s1 > 0) return Miss::both_outside;
    if (s0 == 0 && s1 == 0) return Miss::parallel;
    if (s0 == 0) return Miss::leaving;
    // The leg crosses (or ends on) the line; it meets the closed segment unless P0 and P1 lie strictly
    // on one side of the leg's line. Which end it misses by: P0 is "behind" when orient(Bs, Be, P0) = −s0.
    const int o0 = orient(bs, be, w.p0), o1 = orient(bs, be, w.p1);
    if (o0 * o1 > 0) return o0 == -s0 ? Miss::before_p0 : Miss::past_p1;
    return Miss::none;
}

long first_hit(Vec2 bs, Vec2 be, std::span<const Wall> walls) {
    long best = -1;
    Rational best_s;
    for (std::size_t i = 0; i < walls.size(); ++i) {
        const Wall& w = walls[i];
        if (leg_miss(bs, be, w) != Miss::none) continue;
        // n·(Bs + s(Be − Bs) − P0) = 0  ⇒  s = BC(Bs)/(BC(Bs) − BC(Be)), BC up to the factor 1/|n|.
        const Rational ex = Q(w.p1.x) - Q(w.p0.x), ey = Q(w.p1.y) - Q(w.p0.y);
        const auto bc = [&](Vec2 p) -> Rational { return ey * (Q(p.x) - Q(w.p0.x)) - ex * (Q(p.y) - Q(w.p0.y)); };
        const Rational a = bc(bs), b = bc(be);
        const Rational s = a / (a - b);
        if (best < 0 || s < best_s) {
            best = long(i);
            best_s = s;
        }
    }
    return best;
}

PathFollower::PathFollower(std::span<const Wall> walls, std::span<const Ball> balls) : walls_(walls.begin(), walls.end()) {
    for (const Ball& b : balls) {
        at_.push_back(b.pos);
        for (const Wall& w : walls_) st_.push_back({side(b.pos, w), false});
    }
}

long PathFollower::advance(std::size_t i, Vec2 next) {
    const Vec2 q = at_[i];
    at_[i] = next;
    if (q == next) return -1;
    long found = -1;
    for (std::size_t k = 0; k < walls_.size(); ++k) {
        const Wall& w = walls_[k];
        State& st = st_[i * walls_.size() + k];
        const int sq = side(q, w), sr = side(next, w);
        bool tunnel = false;
        if (sq != 0 && sr != 0) {
            tunnel = sq == -sr && orient(q, next, w.p0) * orient(q, next, w.p1) <= 0;
            st = {sr, false};
        } else if (sq != 0) {
            st = {sq, on_closed_segment(next, w)};
        } else if (sr != 0) {
            // st.last != 0 always holds when touched: touched is set only together with last = sq ≠ 0 (a guard).
            tunnel = st.touched && st.last != 0 && sr != st.last;
            st = {sr, false};
        } else {
            st = {0, false};
        }
        if (tunnel && found < 0) found = long(k);
    }
    return found;
}

}  // namespace ricochet::truth
