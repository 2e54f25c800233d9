// The exact kernel: a whole frame with its bounces computed exactly, its points then rounded to the
// nearest doubles and each rounded piece checked (printed_path.hpp), so rounding never carries the
// printed path across a wall. This kernel is independent on purpose: it is the oracle the robust kernel
// is checked against, so it shares none of robust's code (N-version); do not merge the two.
//
// Why it is written this way. Every double is an integer times a power of two, so every decision (the
// sign of BC, parallel, tests 4 and 5, touching, which wall first, the corner rules) is the sign of a
// polynomial in the inputs. On doubles a floating-point filter decides almost every sign, exact integers
// the rest (filter.hpp). In a frame all inputs are scaled to integers at one common scale 2^k
// (scaled.hpp); the normal n = (e_y, −e_x) is never normalized, so each hit point, t_i and v' is a
// quotient of integers, carried as numerators over one common positive denominator, reduced only
// once per bounce (one gcd, not one per operation as a rational type does): fractions are compared by
// cross-multiplication. The frame's leg i is the line
// p(t) = A + t·dir through its start (frame time now) and its end Be (t = 1), which keeps denominators
// growing by a sum of sizes per bounce, not a product.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "base/bignum.hpp"
#include "base/round.hpp"
#include "kernels/exact/exact_kernel.hpp"
#include "kernels/exact/filter.hpp"
#include "kernels/exact/int.hpp"
#include "kernels/exact/printed_path.hpp"
#include "kernels/exact/scaled.hpp"
#include "ricochet/step_trace.hpp"

namespace ricochet::exact_kernel {
namespace {

using Z = num::Int;
using ZV = Vec2T<Z>;

/// A point or vector p/d at the frame's scale, d > 0.
struct ZFrac {
    ZV p;
    Z d;
};

/// A wall at the frame's scale: its ends, n = (e_y, −e_x) and n·n.
struct ZWall {
    ZV p0, p1, n;
    Z nn;
};

ZV scaled(Vec2 p, int k) {
    ZV out;
    num::scaled_big(out.x.v, p.x, k);
    num::scaled_big(out.y.v, p.y, k);
    return out;
}
ZWall scaled(const Wall& w, int k) {
    ZWall z{scaled(w.p0, k), scaled(w.p1, k), {}, {}};
    z.n = perp(z.p1 - z.p0);
    z.nn = dot(z.n, z.n);
    return z;
}
bool is_zero(const ZV& a) { return sgn(a.x) == 0 && sgn(a.y) == 0; }
Vec2 round_vec(const ZV& p, const Z& d, int k) {
    return {bignum::round_quotient(p.x.v, d.v, k), bignum::round_quotient(p.y.v, d.v, k)};
}

/// sign of BC(p/d) = n·(p/d − P0), d > 0.
int bc_sign(const ZV& p, const Z& d, const ZWall& w) { return sgn(dot(w.n, p - d * w.p0)); }

/// The decision for the leg q → b against w (doubles): the lecture's tests in order, exact signs.
Miss leg_miss(Vec2 q, Vec2 b, const Wall& w) {
    // Degenerate: a zero-length wall has no normal, a zero-length leg no motion.
    if (w.p0 == w.p1 || q == b) return Miss::degenerate;
    const int sq = printed::side(q, w), sb = printed::side(b, w);
    if (sq < 0 && sb < 0) return Miss::both_inside;
    if (sq > 0 && sb > 0) return Miss::both_outside;
    if (sq == 0 && sb == 0) return Miss::parallel;
    if (sq == 0) return Miss::leaving;
    // X = P0 + u·e with u = −o0/(d × e), 1 − u = o1/(d × e), sign(d × e) = −sq
    if (printed::orient(q, b, w.p0) == -sq) return Miss::before_p0;
    if (printed::orient(q, b, w.p1) == sq) return Miss::past_p1;
    return Miss::none;
}

/// The same decision for a later leg, q = Q/D, b = B/db, the leg's direction dir (b − q = a positive
/// multiple of dir); the leg is never zero-length there (v ≠ 0 and rest > 0).
Miss leg_miss(const ZFrac& q, const ZFrac& b, const ZV& dir, const ZWall& w) {
    // Degenerate: a zero-length wall has no normal.
    if (is_zero(w.n)) return Miss::degenerate;
    const int sq = bc_sign(q.p, q.d, w), sb = bc_sign(b.p, b.d, w);
    if (sq < 0 && sb < 0) return Miss::both_inside;
    if (sq > 0 && sb > 0) return Miss::both_outside;
    if (sq == 0 && sb == 0) return Miss::parallel;
    if (sq == 0) return Miss::leaving;
    // orient(q, b, P) = sign((b − q) × (P − q)) = sign(dir × (P·D − Q))
    if (sgn(cross(dir, q.d * w.p0 - q.p)) == -sq) return Miss::before_p0;
    if (sgn(cross(dir, q.d * w.p1 - q.p)) == sq) return Miss::past_p1;
    return Miss::none;
}

/// A hit on leg p(t) = A + t·dir (A = Ā/dA, dir = Vdir/ddir): n·(A + t·dir − P0) = 0 gives
/// t = n·(P0·dA − Ā)·ddir / (dA·n·Vdir) = nt·ddir/(dA·nd), nd > 0 after fixing signs.
struct Crossing {
    Z nt, nd;
};
Crossing crossing(const ZFrac& a, const ZV& dir, const ZWall& w) {
    Crossing c{dot(w.n, a.d * w.p0 - a.p), dot(w.n, dir)};
    if (sgn(c.nd) < 0) {
        c.nt = -c.nt;
        c.nd = -c.nd;
    }
    return c;
}
/// sign(t1 − t2) for two crossings of one leg: the common factor ddir/dA is positive.
int compare(const Crossing& a, const Crossing& b) { return sgn(a.nt * b.nd - b.nt * a.nd); }

/// v' = v − 2(v·n)/(n·n)·n for v = V/dv: V' = V·(n·n) − 2(V·n)·n over dv·(n·n).
ZFrac reflect(const ZFrac& v, const ZWall& w) {
    // Degenerate: a zero-length wall has no normal; v is unchanged. Not reached by step_ball: such a wall is
    // never hit, never joins the contacts (arrive) and blocks no leg (contact sides are ±1); kept as a guard.
    if (sgn(w.nn) == 0) return v;
    return {v.p * w.nn - (Z(2) * dot(v.p, w.n)) * w.n, v.d * w.nn};
}

/// p/d lies on w's line and within its closed segment (on the line, the segment is its bounding box).
bool on_segment(const ZFrac& p, const ZWall& w) {
    if (bc_sign(p.p, p.d, w) != 0) return false;
    const auto within = [&](const Z& v, const Z& a, const Z& b) {
        const Z sa = p.d * a, sb = p.d * b;
        return (sa <= v && v <= sb) || (sb <= v && v <= sa);
    };
    return within(p.p.x, w.p0.x, w.p1.x) && within(p.p.y, w.p0.y, w.p1.y);
}

/// Divides p/d (and extra, over the same d) by the gcd of all its integers. Values are unchanged; done
/// once per bounce, it keeps sizes from growing with the number of bounces as the products above do.
void reduce(ZFrac& f, Z* extra = nullptr) {
    bignum::Integer g;
    bignum::gcd(g, f.p.x.v, f.p.y.v);
    bignum::gcd(g, g, f.d.v);
    if (extra != nullptr) bignum::gcd(g, g, extra->v);
    if (g == 1) return;
    for (Z* z : {&f.p.x, &f.p.y, &f.d, extra})
        if (z != nullptr) bignum::divexact(z->v, z->v, g);
}

struct ZContact {
    std::uint32_t wall;
    int side;
};

}  // namespace

Side classify(Vec2 p, const Wall& w) { return side_from_sign(printed::side(p, w)); }

bool point_in_circle(Vec2 p, const Circle& c) { return num::circle_sign(p.x, c.c.x, p.y, c.c.y, c.r, 0.0) <= 0; }

bool circles_overlap(const Circle& a, const Circle& b) {
    return num::circle_sign(a.c.x, b.c.x, a.c.y, b.c.y, a.r, b.r) <= 0;
}

namespace {

/// Scratch integers for sweep() and reflect(): one leg needs sixteen, none allocated in the steady state.
struct LegScratch {
    bignum::Integer z[16];
};
LegScratch& leg_scratch() {
    thread_local LegScratch s;
    return s;
}
void set_scaled(bignum::Integer& out, double x, int k) { num::scaled_big(out, x, k); }
/// out = a·b + c·d
void dot2(bignum::Integer& out, const bignum::Integer& a, const bignum::Integer& b, const bignum::Integer& c,
          const bignum::Integer& d) {
    bignum::mul(out, a, b);
    bignum::addmul(out, c, d);
}

}  // namespace

Sweep sweep(Vec2 bs, Vec2 v, const Wall& w) {
    const Vec2 be = bs + v;
    const Miss miss = leg_miss(bs, be, w);
    if (miss != Miss::none) return {miss, 0.0, {}};
    num::Scale sc;
    for (double x : {bs.x, bs.y, be.x, be.y, w.p0.x, w.p0.y, w.p1.x, w.p1.y}) sc.add(x);
    const int k = sc.exponent();
    bignum::Integer* z = leg_scratch().z;
    bignum::Integer &qx = z[0], &qy = z[1], &dx = z[2], &dy = z[3], &p0x = z[4], &p0y = z[5], &nx = z[6], &ny = z[7];
    bignum::Integer &ax = z[8], &ay = z[9], &nt = z[10], &nd = z[11], &bx = z[12], &by = z[13];
    set_scaled(qx, bs.x, k);
    set_scaled(qy, bs.y, k);
    set_scaled(dx, be.x, k);
    set_scaled(dy, be.y, k);
    bignum::sub(dx, dx, qx);  // dir = Be − Bs
    bignum::sub(dy, dy, qy);
    set_scaled(p0x, w.p0.x, k);
    set_scaled(p0y, w.p0.y, k);
    set_scaled(nx, w.p1.y, k);  // n = (e_y, −e_x) = (P1y − P0y, P0x − P1x)
    bignum::sub(nx, nx, p0y);
    set_scaled(ny, w.p1.x, k);
    bignum::sub(ny, p0x, ny);
    // t_i = n·(P0 − Bs)/(n·(Be − Bs)) = nt/nd, nd > 0 after fixing signs
    bignum::sub(ax, p0x, qx);
    bignum::sub(ay, p0y, qy);
    dot2(nt, nx, ax, ny, ay);
    dot2(nd, nx, dx, ny, dy);
    if (bignum::sign(nd) < 0) {
        bignum::neg(nt, nt);
        bignum::neg(nd, nd);
    }
    // B_i = Bs + t_i·(Be − Bs) = (Bs·nd + nt·(Be − Bs))/nd
    dot2(bx, qx, nd, nt, dx);
    dot2(by, qy, nd, nt, dy);
    return {Miss::none, bignum::round_quotient(nt, nd, 0),
            {bignum::round_quotient(bx, nd, k), bignum::round_quotient(by, nd, k)}};
}

Vec2 reflect(Vec2 v, const Wall& w) {
    num::Scale sc;
    for (double x : {v.x, v.y, w.p0.x, w.p0.y, w.p1.x, w.p1.y}) sc.add(x);
    const int k = sc.exponent();
    bignum::Integer* z = leg_scratch().z;
    bignum::Integer &vx = z[0], &vy = z[1], &nx = z[2], &ny = z[3], &t = z[4], &nn = z[5], &vn = z[6], &rx = z[7],
                    &ry = z[8];
    set_scaled(vx, v.x, k);
    set_scaled(vy, v.y, k);
    set_scaled(nx, w.p1.y, k);  // n = (P1y − P0y, P0x − P1x)
    set_scaled(t, w.p0.y, k);
    bignum::sub(nx, nx, t);
    set_scaled(ny, w.p0.x, k);
    set_scaled(t, w.p1.x, k);
    bignum::sub(ny, ny, t);
    dot2(nn, nx, nx, ny, ny);
    // Degenerate: a zero-length wall has no normal; v is unchanged (printed as the exact kernel prints).
    if (bignum::sign(nn) == 0) {
        bignum::set_int64(nn, 1);
        bignum::set_int64(nx, 0);
        bignum::set_int64(ny, 0);
    }
    // v' = v − 2(v·n)/(n·n)·n = (v·(n·n) − 2(v·n)·n)/(n·n)
    dot2(vn, vx, nx, vy, ny);
    bignum::mul_2exp(vn, vn, 1);
    bignum::mul(rx, vx, nn);
    bignum::submul(rx, vn, nx);
    bignum::mul(ry, vy, nn);
    bignum::submul(ry, vn, ny);
    return {bignum::round_quotient(rx, nn, k), bignum::round_quotient(ry, nn, k)};
}

FrameStatus step_ball(Ball& ball, BallMemory& memory, std::span<const Wall> walls, std::vector<HitEvent>& hits,
                      StepScratch& scratch) {
    // The legs are exact fractions, not doubles: a trace gets the reflections only.
    if (scratch.trace != nullptr) scratch.trace->legs_traced = false;
    // The frame's first leg ends at Be = Bs + v as C++ rounds it (kernel.hpp).
    const Vec2 be = ball.pos + ball.vel;
    num::Scale sc;
    for (double x : {ball.pos.x, ball.pos.y, ball.vel.x, ball.vel.y, be.x, be.y}) sc.add(x);
    for (const Wall& w : walls)
        for (double x : {w.p0.x, w.p0.y, w.p1.x, w.p1.y}) sc.add(x);
    const int k = sc.exponent();
    // Walls are scaled when first needed: most legs are decided on doubles.
    std::vector<std::optional<ZWall>> zwalls(walls.size());
    const auto zw = [&](std::uint32_t i) -> const ZWall& {
        if (!zwalls[i]) zwalls[i] = scaled(walls[i], k);
        return *zwalls[i];
    };

    // The exact path: hit points (over their frame times' common denominator) and walls, then the end.
    struct ZHit {
        std::uint32_t wall;
        Z now;
        ZFrac point;
    };
    std::vector<ZHit> path;
    ZFrac q{scaled(ball.pos, k), 1}, v{scaled(ball.vel, k), 1};
    Z now = 0;  // the frame time of q is now/q.d
    int last_from = 0;  // the side the last bounce met its wall from
    std::vector<ZContact> contacts;
    for (std::uint8_t c = 0; c < memory.count; ++c) contacts.push_back({memory.contacts[c].wall, memory.contacts[c].side});
    FrameStatus status = FrameStatus::ok;
    for (int bounce = 0;; ++bounce) {
        // rest = 1 − now = 0: the frame is over.
        if (is_zero(v.p) || now == q.d) break;
        if (bounce == k_max_bounces) {
            status = FrameStatus::bounce_limit;
            break;
        }
        const bool first_leg = bounce == 0;
        // The leg p(t) = A + t·dir: first Bs + t·(Be − Bs); later A = q − now·v, dir = v, so that p(now) = q
        // and its end b = p(1) = A + v = (Q·dv − now·V + D·V)/(D·dv).
        ZFrac a, b;
        ZV dir;
        if (first_leg) {
            a = q;
            b = {scaled(be, k), 1};
            dir = b.p - a.p;
        } else {
            a = {q.p * v.d - now * v.p, q.d * v.d};
            b = {a.p + q.d * v.p, a.d};
            dir = v.p;
        }
        // A leg that would leave a contact wall to its far side bounces off that wall instead.
        const auto blocked = std::find_if(contacts.begin(), contacts.end(), [&](const ZContact& c) {
            const int sb = first_leg ? printed::side(be, walls[c.wall]) : bc_sign(b.p, b.d, zw(c.wall));
            return sb == -c.side;
        });
        if (blocked != contacts.end()) {
            if (scratch.trace != nullptr) ++scratch.trace->reflections;
            v = reflect(v, zw(blocked->wall));
            reduce(v);
            continue;
        }
        std::optional<Crossing> first;
        std::vector<std::uint32_t> at_first;
        for (std::uint32_t i = 0; i < walls.size(); ++i) {
            const Miss miss = first_leg ? leg_miss(ball.pos, be, walls[i]) : leg_miss(q, b, dir, zw(i));
            if (miss != Miss::none) continue;
            Crossing c = crossing(a, dir, zw(i));
            const int order = first ? compare(c, *first) : -1;
            if (order < 0) {
                first = std::move(c);
                at_first.assign(1, i);
            } else if (order == 0) {
                at_first.push_back(i);
            }
        }
        if (!first) {
            // A contact stays while the ball slides along its wall's line on the closed segment.
            std::erase_if(contacts, [&](const ZContact& c) {
                if (first_leg) return printed::side(be, walls[c.wall]) != 0 || !printed::on_closed_segment(be, walls[c.wall]);
                return !on_segment(b, zw(c.wall));
            });
            q = std::move(b);
            break;
        }
        // B_i = A + t·dir = (Ā·nd + nt·Vdir)/(dA·nd); its frame time t = nt·ddir/(dA·nd), ddir = v.d (1 first).
        const ZFrac x{a.p * first->nd + first->nt * dir, a.d * first->nd};
        Z x_now = first_leg ? first->nt : Z(first->nt * v.d);
        path.push_back({at_first.front(), x_now, x});
        // Every wall met at x was met from q's side; bounce off the first, then off the others
        // while v' points through them; if one is still crossed, go straight back.
        std::vector<ZContact> arrived;
        for (std::uint32_t i : at_first)
            arrived.push_back({i, first_leg ? printed::side(ball.pos, walls[i]) : bc_sign(q.p, q.d, zw(i))});
        last_from = arrived.front().side;
        // Contacts the ball slid along to get here are kept, with the side it first came from.
        // (none_of always holds: q lies on a contact's line, so a contact is never among the walls hit.)
        for (const ZContact& c : contacts)
            if (on_segment(x, zw(c.wall)) &&
                std::none_of(arrived.begin(), arrived.end(), [&](const ZContact& r) { return r.wall == c.wall; }))
                arrived.push_back(c);
        ZFrac w = reflect(v, zw(at_first.front()));
        int reflections = 1;
        for (const ZContact& c : arrived)
            if (sgn(dot(w.p, zw(c.wall).n)) == -c.side) {
                w = reflect(w, zw(c.wall));
                ++reflections;
            }
        if (scratch.trace != nullptr) scratch.trace->reflections += reflections;
        for (const ZContact& c : arrived)
            if (sgn(dot(w.p, zw(c.wall).n)) == -c.side) w = {-v.p, v.d};
        v = std::move(w);
        reduce(v);
        q = x;
        now = std::move(x_now);
        reduce(q, &now);
        contacts = std::move(arrived);
    }

    // The printed path: each exact point rounded, each rounded piece checked.
    Vec2 p = ball.pos;
    BallMemory mem = memory;
    // The last wall bounced off, kept on its side until the next bounce (BallMemory).
    std::uint32_t bounced_wall = memory.bounced_wall;
    printed::Kept bounced{memory.bounced_from != 0 ? &walls[memory.bounced_wall] : nullptr, memory.bounced_from};
    const auto visit = [&](const ZFrac& target, const Wall* hit) {
        const printed::Kept met{hit, hit != nullptr ? printed::side(p, *hit) : 0};
        const Vec2 x = printed::make_safe(p, round_vec(target.p, target.d, k), mem, walls, met, bounced);
        if (hit != nullptr) bounced = met;
        BallMemory arrived;
        printed::arrive(p, x, mem, walls, arrived);
        mem = arrived;
        p = x;
    };
    for (const ZHit& h : path) {
        visit(h.point, &walls[h.wall]);
        bounced_wall = h.wall;
        hits.push_back({h.wall, bignum::round_quotient(h.now.v, h.point.d.v, 0), p});
    }
    visit(q, nullptr);
    // v' points strictly back to the side the last bounce came from; rounding a grazing v' can lose that,
    // so the rounded velocity is moved by ulps towards that side until it holds again.
    Vec2 vel = round_vec(v.p, v.d, k);
    // last_from ≠ 0 whenever path is non-empty (a wall hit is met from q's side ±1); the test is a guard.
    // The loop's 64 is a guard too: each pass moves n·vel by an ulp per component, at least their rounding
    // error, so one or two passes hold it.
    if (!path.empty() && last_from != 0) {
        const Wall& w = walls[path.back().wall];
        const Vec2 n = normal(w);
        for (int i = 0; i < 64 && printed::direction_side(vel, w) != last_from; ++i)
            vel = {n.x == 0 ? vel.x : std::nextafter(vel.x, n.x * last_from > 0 ? INFINITY : -INFINITY),
                   n.y == 0 ? vel.y : std::nextafter(vel.y, n.y * last_from > 0 ? INFINITY : -INFINITY)};
    }
    ball = {p, vel};
    memory = mem;
    memory.bounced_from = static_cast<std::int8_t>(bounced.from);
    memory.bounced_wall = bounced_wall;
    return status;
}

}  // namespace ricochet::exact_kernel
