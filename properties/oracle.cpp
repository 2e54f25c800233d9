// Ground truth for the properties (oracle.hpp).
#include "oracle.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>

namespace ricochet::props {
namespace {

int sgn_q(const mpq_class& q) { return sgn(q); }
mpq_class Q(double x) { return mpq_class(x); }  // exact: every finite double is a rational

}  // namespace

int orient_oracle(Vec2 a, Vec2 b, Vec2 c) {
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

int side_oracle(Vec2 p, const Wall& w) { return -orient_oracle(w.p0, w.p1, p); }

bool on_closed_segment_oracle(Vec2 p, const Wall& w) {
    if (orient_oracle(w.p0, w.p1, p) != 0) return false;
    return std::min(w.p0.x, w.p1.x) <= p.x && p.x <= std::max(w.p0.x, w.p1.x) && std::min(w.p0.y, w.p1.y) <= p.y &&
           p.y <= std::max(w.p0.y, w.p1.y);
}

int locate(Vec2 p, std::span<const Wall> walls) {
    bool inside = false;
    for (const Wall& w : walls) {
        if (on_closed_segment_oracle(p, w)) return 0;
        const Vec2 a = w.p0, b = w.p1;
        // The ray from p to +x crosses the edge if the edge straddles y = p.y (half-open, so a vertex on
        // the ray counts once) and p lies to the left of the upward-directed edge.
        if ((a.y > p.y) != (b.y > p.y)) {
            const int o = orient_oracle(a, b, p);
            if (b.y > a.y ? o > 0 : o < 0) inside = !inside;
        }
    }
    return inside ? 1 : -1;
}

int circle_side_oracle(Vec2 p, const Circle& c) {
    const mpq_class dx = Q(p.x) - Q(c.c.x), dy = Q(p.y) - Q(c.c.y), r = Q(c.r);
    return sgn_q(dx * dx + dy * dy - r * r);
}

bool point_in_circle_oracle(Vec2 p, const Circle& c) {
    const mpq_class dx = Q(p.x) - Q(c.c.x), dy = Q(p.y) - Q(c.c.y), r = Q(c.r);
    return dx * dx + dy * dy <= r * r;
}

bool circles_overlap_oracle(const Circle& a, const Circle& b) {
    const mpq_class dx = Q(a.c.x) - Q(b.c.x), dy = Q(a.c.y) - Q(b.c.y), r = Q(a.r) + Q(b.r);
    return dx * dx + dy * dy <= r * r;
}

bool point_in_rect_oracle(Vec2 p, const Rect& r) {
    return r.left <= p.x && p.x <= r.right && r.bottom <= p.y && p.y <= r.top;
}

bool rects_overlap_oracle(const Rect& a, const Rect& b) {
    // Closed intervals intersect on both axes.
    return std::max(a.left, b.left) <= std::min(a.right, b.right) &&
           std::max(a.bottom, b.bottom) <= std::min(a.top, b.top);
}

bool speed_within(Vec2 v, Vec2 w, int m, double b, double a) {
    // (1 − b)^m·|v| − m·a ≤ |w| ≤ (1 + b)^m·|v| + m·a. |v| is irrational in general: it is bracketed by a
    // 256-bit square root widened by 2^−200 relative, far below b; everything else is exact (GMP).
    const mpq_class vv = Q(v.x) * Q(v.x) + Q(v.y) * Q(v.y);
    const mpq_class ww = Q(w.x) * Q(w.x) + Q(w.y) * Q(w.y);
    mpq_class lo = 1, hi = 1;
    for (int i = 0; i < m; ++i) {
        lo *= 1 - Q(b);
        hi *= 1 + Q(b);
    }
    const mpq_class abs_part = Q(a) * m;
    if (sgn(abs_part) == 0) return lo * lo * vv <= ww && ww <= hi * hi * vv;
    mpf_class root(vv, 256);
    root = sqrt(root);
    const mpq_class slack = mpq_class(1, 1) / (mpq_class(1) << 200);
    const mpq_class vhi = mpq_class(root) * (1 + slack), vlo = mpq_class(root) * (1 - slack);
    const mpq_class upper = hi * vhi + abs_part, lower = lo * vlo - abs_part;
    if (ww > upper * upper) return false;
    return sgn(lower) <= 0 || ww >= lower * lower;
}

bool sum_exact(double a, double b) { return Q(a + b) == Q(a) + Q(b); }

int cross_sign(Vec2 a, Vec2 b) { return orient_oracle({0, 0}, a, b); }

int dot_sign(Vec2 a, Vec2 b) {
    const double l = a.x * b.x, r = a.y * b.y;
    const double s = l + r;
    const double sum = std::fabs(l) + std::fabs(r);
    constexpr double eps = 0x1p-53;
    if (std::isfinite(s) && std::isfinite(sum) && sum >= 0x1p-900 && std::fabs(s) > 3.0 * eps * sum)
        return s > 0 ? 1 : -1;
    return sgn_q(Q(a.x) * Q(b.x) + Q(a.y) * Q(b.y));
}

Miss expected_miss(Vec2 bs, Vec2 be, const Wall& w) {
    if (w.p0 == w.p1 || bs == be) return Miss::degenerate;
    const int s0 = side_oracle(bs, w), s1 = side_oracle(be, w);
    if (s0 < 0 && s1 < 0) return Miss::both_inside;
    if (s0 > 0 && s1 > 0) return Miss::both_outside;
    if (s0 == 0 && s1 == 0) return Miss::parallel;
    if (s0 == 0) return Miss::leaving;
    // The leg crosses (or ends on) the line; it meets the closed segment unless P0 and P1 lie strictly
    // on one side of the leg's line. Which end it misses by: P0 is "behind" when orient(Bs, Be, P0) = −s0.
    const int o0 = orient_oracle(bs, be, w.p0), o1 = orient_oracle(bs, be, w.p1);
    if (o0 * o1 > 0) return o0 == -s0 ? Miss::before_p0 : Miss::past_p1;
    return Miss::none;
}

long first_hit_oracle(Vec2 bs, Vec2 be, std::span<const Wall> walls) {
    long best = -1;
    mpq_class best_s;
    for (std::size_t i = 0; i < walls.size(); ++i) {
        const Wall& w = walls[i];
        if (expected_miss(bs, be, w) != Miss::none) continue;
        // n·(Bs + s(Be − Bs) − P0) = 0  ⇒  s = BC(Bs)/(BC(Bs) − BC(Be)), BC up to the factor 1/|n|.
        const mpq_class ex = Q(w.p1.x) - Q(w.p0.x), ey = Q(w.p1.y) - Q(w.p0.y);
        const auto bc = [&](Vec2 p) -> mpq_class { return ey * (Q(p.x) - Q(w.p0.x)) - ex * (Q(p.y) - Q(w.p0.y)); };
        const mpq_class a = bc(bs), b = bc(be);
        const mpq_class s = a / (a - b);
        if (best < 0 || s < best_s) {
            best = long(i);
            best_s = s;
        }
    }
    return best;
}

PathOracle::PathOracle(std::span<const Wall> walls, std::span<const Ball> balls) : walls_(walls.begin(), walls.end()) {
    for (const Ball& b : balls) {
        at_.push_back(b.pos);
        for (const Wall& w : walls_) st_.push_back({side_oracle(b.pos, w), false});
    }
}

long PathOracle::advance(std::size_t i, Vec2 next) {
    const Vec2 q = at_[i];
    at_[i] = next;
    if (q == next) return -1;
    long found = -1;
    for (std::size_t k = 0; k < walls_.size(); ++k) {
        const Wall& w = walls_[k];
        State& st = st_[i * walls_.size() + k];
        const int sq = side_oracle(q, w), sr = side_oracle(next, w);
        bool tunnel = false;
        if (sq != 0 && sr != 0) {
            tunnel = sq == -sr && orient_oracle(q, next, w.p0) * orient_oracle(q, next, w.p1) <= 0;
            st = {sr, false};
        } else if (sq != 0) {
            st = {sq, on_closed_segment_oracle(next, w)};
        } else if (sr != 0) {
            tunnel = st.touched && st.last != 0 && sr != st.last;
            st = {sr, false};
        } else {
            st = {0, false};
        }
        if (tunnel && found < 0) found = long(k);
    }
    return found;
}

Vec2 mirror(Vec2 p) { return {-p.x, p.y}; }
Vec2 rotate90(Vec2 p) { return {-p.y, p.x}; }

Scene transform(const Scene& s, Vec2 (*f)(Vec2)) {
    Scene out = s;
    for (Wall& w : out.walls) w = {f(w.p0), f(w.p1)};
    for (Ball& b : out.balls) b = {f(b.pos), f(b.vel)};
    for (Circle& c : out.circles) c.c = f(c.c);
    for (Rect& r : out.rects) {
        const Vec2 a = f({r.left, r.bottom}), b = f({r.right, r.top});
        r = {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
    }
    out.expect_hash.reset();
    out.expect_states.clear();
    return out;
}

Scene translate(const Scene& s, Vec2 t) {
    Scene out = s;
    for (Wall& w : out.walls) w = {w.p0 + t, w.p1 + t};
    for (Ball& b : out.balls) b.pos = b.pos + t;
    for (Circle& c : out.circles) c.c = c.c + t;
    for (Rect& r : out.rects) r = {r.left + t.x, r.bottom + t.y, r.right + t.x, r.top + t.y};
    out.expect_hash.reset();
    out.expect_states.clear();
    return out;
}

bool translation_exact(const Scene& s, Vec2 t) {
    const auto ok = [&](Vec2 p) { return sum_exact(p.x, t.x) && sum_exact(p.y, t.y); };
    for (const Wall& w : s.walls)
        if (!ok(w.p0) || !ok(w.p1)) return false;
    for (const Ball& b : s.balls) {
        // Be = Bs + v must be the same point, moved, before and after.
        const Vec2 be = b.pos + b.vel;
        if (!ok(b.pos) || !ok(be) || !(same_value((b.pos + t) + b.vel, be + t))) return false;
    }
    for (const Circle& c : s.circles)
        if (!ok(c.c)) return false;
    for (const Rect& r : s.rects)
        if (!ok({r.left, r.bottom}) || !ok({r.right, r.top})) return false;
    return true;
}

}  // namespace ricochet::props
