// The exact kernel as first written (GMP rationals throughout), kept as the reference that the faster
// exact kernel is checked against bit for bit (exact_kernel_test.cpp).
// The exact kernel: GMP rationals for a whole frame with its bounces. The normal n = (e_y, −e_x) is
// never normalized, so every quantity stays rational. The frame's points are rounded to the nearest
// doubles at the end, and each rounded piece is checked as the robust kernel checks its own
// (path.hpp), so that rounding never carries the printed path across a wall.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>

#include <gmpxx.h>

#include "ricochet/kernel.hpp"
#include "path.hpp"
#include "ricochet/predicates.hpp"

namespace ricochet::exact_reference {
namespace {

using Q = mpq_class;

struct QV {
    Q x, y;
};
QV qv(Vec2 p) { return {Q(p.x), Q(p.y)}; }
QV operator+(const QV& a, const QV& b) { return {a.x + b.x, a.y + b.y}; }
QV operator-(const QV& a, const QV& b) { return {a.x - b.x, a.y - b.y}; }
QV operator*(const Q& k, const QV& a) { return {k * a.x, k * a.y}; }
Q dot(const QV& a, const QV& b) { return a.x * b.x + a.y * b.y; }
Q cross(const QV& a, const QV& b) { return a.x * b.y - a.y * b.x; }
bool is_zero(const QV& a) { return sgn(a.x) == 0 && sgn(a.y) == 0; }

struct QWall {
    QV p0, p1;
    QV e() const { return p1 - p0; }
    QV n() const { return {p1.y - p0.y, p0.x - p1.x}; }  // (e_y, −e_x)
};
QWall qw(const Wall& w) { return {qv(w.p0), qv(w.p1)}; }

/// BC up to the positive factor 1/|n|: n·(p − P0).
Q bc(const QV& p, const QWall& w) { return dot(w.n(), p - w.p0); }
/// sign((b − a) × (c − a))
int orient(const QV& a, const QV& b, const QV& c) { return sgn(cross(b - a, c - a)); }

/// The double nearest to x, ties to even (mpq's get_d truncates).
double nearest(const Q& x) {
    const double d = x.get_d();
    const double away = std::nextafter(d, sgn(x) >= 0 ? INFINITY : -INFINITY);
    if (!std::isfinite(away)) return d;
    const Q ed = abs(x - Q(d));
    const Q ea = abs(Q(away) - x);
    if (ea < ed) return away;
    if (ea == ed && (std::bit_cast<std::uint64_t>(away) & 1u) == 0) return away;
    return d;
}
Vec2 nearest(const QV& p) { return {nearest(p.x), nearest(p.y)}; }

/// The decision for the leg q → b against w, and the exact leg fraction s of a hit.
struct Leg {
    Miss miss;
    Q s;
};

Leg test_leg(const QV& q, const QV& b, const QWall& w) {
    // Degenerate: a zero-length wall has no normal, a zero-length leg no motion.
    if (is_zero(w.e()) || is_zero(b - q)) return {Miss::degenerate, 0};
    const Q bq = bc(q, w), bb = bc(b, w);
    const int sq = sgn(bq), sb = sgn(bb);
    if (sq < 0 && sb < 0) return {Miss::both_inside, 0};
    if (sq > 0 && sb > 0) return {Miss::both_outside, 0};
    if (sq == 0 && sb == 0) return {Miss::parallel, 0};
    if (sq == 0) return {Miss::leaving, 0};
    // X = P0 + u·e with u = −o0/(d × e), 1 − u = o1/(d × e), sign(d × e) = −sq
    if (orient(q, b, w.p0) == -sq) return {Miss::before_p0, 0};
    if (orient(q, b, w.p1) == sq) return {Miss::past_p1, 0};
    // n·(q + s(b − q) − P0) = 0  ⇒  s = BC(q)/(BC(q) − BC(b))
    return {Miss::none, bq / (bq - bb)};
}

QV reflect(const QV& v, const QWall& w) {
    // v' = v − 2(v·n)/(n·n)·n, rational because n is not normalized
    const QV n = w.n();
    const Q nn = dot(n, n);
    if (sgn(nn) == 0) return v;
    return v - Q(2 * dot(v, n) / nn) * n;
}

/// p lies on w's line and within its closed segment (on the line, the segment is its bounding box).
bool on_segment(const QV& p, const QWall& w) {
    if (sgn(bc(p, w)) != 0) return false;
    const auto within = [](const Q& v, const Q& a, const Q& b) { return (a <= v && v <= b) || (b <= v && v <= a); };
    return within(p.x, w.p0.x, w.p1.x) && within(p.y, w.p0.y, w.p1.y);
}

struct QContact {
    std::uint32_t wall;
    int side;
};

}  // namespace

Side classify(Vec2 p, const Wall& w) { return side_from_sign(sgn(bc(qv(p), qw(w)))); }

bool point_in_circle(Vec2 p, const Circle& c) {
    const QV d = qv(p) - qv(c.c);
    const Q r(c.r);
    return dot(d, d) <= r * r;
}

bool circles_overlap(const Circle& a, const Circle& b) {
    const QV d = qv(a.c) - qv(b.c);
    const Q r = Q(a.r) + Q(b.r);
    return dot(d, d) <= r * r;
}

Sweep sweep(Vec2 bs, Vec2 v, const Wall& w) {
    const QV q = qv(bs), b = qv(bs + v);
    const Leg leg = test_leg(q, b, qw(w));
    if (leg.miss != Miss::none) return {leg.miss, 0.0, {}};
    return {Miss::none, nearest(leg.s), nearest(q + leg.s * (b - q))};
}

Vec2 reflect(Vec2 v, const Wall& w) { return nearest(reflect(qv(v), qw(w))); }

FrameStatus step_ball(Ball& ball, BallMemory& memory, std::span<const Wall> walls, std::vector<HitEvent>& hits,
                      StepScratch& scratch) {
    std::vector<QWall> qwalls;
    qwalls.reserve(walls.size());
    for (const Wall& w : walls) qwalls.push_back(qw(w));

    // The rational path: hit points and walls, then the end state.
    struct QHit {
        std::uint32_t wall;
        Q t;
        QV point;
    };
    std::vector<QHit> path;
    QV q = qv(ball.pos), v = qv(ball.vel);
    int last_from = 0;  // the side the last bounce met its wall from
    Q rest = 1, now = 0;
    std::vector<QContact> contacts;
    for (std::uint8_t k = 0; k < memory.count; ++k) contacts.push_back({memory.contacts[k].wall, memory.contacts[k].side});
    FrameStatus status = FrameStatus::ok;
    for (int bounce = 0;; ++bounce) {
        if (is_zero(v) || sgn(rest) == 0) break;
        if (bounce == k_max_bounces) {
            status = FrameStatus::bounce_limit;
            break;
        }
        // The frame's first leg ends at Be = Bs + v as C++ rounds it (kernel.hpp), as robust's and sweep()'s do.
        const QV b = bounce == 0 ? qv(ball.pos + ball.vel) : q + rest * v;
        // A leg that would leave a contact wall to its far side bounces off that wall instead.
        const auto blocked = std::find_if(contacts.begin(), contacts.end(),
                                          [&](const QContact& c) { return sgn(bc(b, qwalls[c.wall])) == -c.side; });
        if (blocked != contacts.end()) {
            v = reflect(v, qwalls[blocked->wall]);
            continue;
        }
        std::optional<Q> first;
        std::vector<std::uint32_t> at_first;
        for (std::uint32_t i = 0; i < qwalls.size(); ++i) {
            Leg leg = test_leg(q, b, qwalls[i]);
            if (leg.miss != Miss::none) continue;
            if (!first || leg.s < *first) {
                first = std::move(leg.s);
                at_first.assign(1, i);
            } else if (leg.s == *first) {
                at_first.push_back(i);
            }
        }
        if (!first) {
            // A contact stays while the ball slides along its wall's line on the closed segment.
            std::erase_if(contacts, [&](const QContact& c) { return !on_segment(b, qwalls[c.wall]); });
            q = b;
            break;
        }
        const Q s = *first;
        const QV x = q + s * (b - q);
        now += s * rest;
        path.push_back({at_first.front(), now, x});
        // Every wall met at x was met from q's side; bounce off the first, then off the others
        // while v' points through them; if one is still crossed, go straight back.
        std::vector<QContact> arrived;
        for (std::uint32_t i : at_first) arrived.push_back({i, sgn(bc(q, qwalls[i]))});
        last_from = arrived.front().side;
        // Contacts the ball slid along to get here are kept, with the side it first came from.
        for (const QContact& c : contacts)
            if (on_segment(x, qwalls[c.wall]) &&
                std::none_of(arrived.begin(), arrived.end(), [&](const QContact& a) { return a.wall == c.wall; }))
                arrived.push_back(c);
        QV w = reflect(v, qwalls[at_first.front()]);
        for (const QContact& c : arrived)
            if (sgn(dot(w, qwalls[c.wall].n())) == -c.side) w = reflect(w, qwalls[c.wall]);
        for (const QContact& c : arrived)
            if (sgn(dot(w, qwalls[c.wall].n())) == -c.side) w = {-v.x, -v.y};
        v = w;
        rest *= 1 - s;
        q = x;
        contacts = std::move(arrived);
    }

    // The printed path: each rational point rounded, each rounded piece checked.
    Vec2 p = ball.pos;
    BallMemory mem = memory;
    // The last wall bounced off, kept on its side until the next bounce (BallMemory).
    std::uint32_t bounced_wall = memory.bounced_wall;
    detail::Keep bounced{memory.bounced_from != 0 ? &walls[memory.bounced_wall] : nullptr, memory.bounced_from};
    auto visit = [&](const QV& target, const Wall* hit) {
        const detail::Keep met{hit, hit != nullptr ? exact::side(p, *hit) : 0};
        const Vec2 x = detail::make_safe(p, nearest(target), mem, walls, nullptr, scratch, met, bounced);
        if (hit != nullptr) bounced = met;
        BallMemory arrived;
        detail::arrive(p, x, mem, walls, nullptr, scratch, arrived);
        mem = arrived;
        p = x;
    };
    for (const QHit& h : path) {
        visit(h.point, &walls[h.wall]);
        bounced_wall = h.wall;
        hits.push_back({h.wall, nearest(h.t), p});
    }
    visit(q, nullptr);
    // v' points strictly back to the side the last bounce came from; rounding a grazing v' can lose that,
    // so the rounded velocity is moved by ulps towards that side until it holds again.
    Vec2 vel = nearest(v);
    if (!path.empty() && last_from != 0) {
        const Wall& w = walls[path.back().wall];
        const Vec2 n = normal(w);
        for (int i = 0; i < 64 && exact::direction_side(vel, w) != last_from; ++i)
            vel = {n.x == 0 ? vel.x : std::nextafter(vel.x, n.x * last_from > 0 ? INFINITY : -INFINITY),
                   n.y == 0 ? vel.y : std::nextafter(vel.y, n.y * last_from > 0 ? INFINITY : -INFINITY)};
    }
    ball = {p, vel};
    memory = mem;
    memory.bounced_from = static_cast<std::int8_t>(bounced.from);
    memory.bounced_wall = bounced_wall;
    return status;
}

}  // namespace ricochet::exact_reference
