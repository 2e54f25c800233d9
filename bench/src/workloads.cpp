#include "workloads.hpp"

#include <cmath>
#include <numbers>

namespace ricochet::bench {

std::uint64_t Rng::next() {
    // splitmix64 (Steele, Lea, Flood 2014)
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

bool make_query(Vec2 bs, Vec2 be, const Wall& w, SweepQuery& out) {
    // The kernels' leg ends at fl(Bs + v); keep only pairs for which that is the Be we meant.
    const Vec2 v = be - bs;
    if (!(bs + v == be) || v == Vec2{}) return false;
    out = {bs, v, w};
    return true;
}

Vec2 in_box(Rng& r, double half) { return {r.uniform(-half, half), r.uniform(-half, half)}; }

Wall random_wall(Rng& r, Vec2 offset, double half) {
    Wall w;
    do {
        w = {offset + in_box(r, half), offset + in_box(r, half)};
    } while (w.p0 == w.p1);
    return w;
}

namespace {

// a + b exactly, as a head and a tail (Knuth's two-sum).
void two_sum(double a, double b, double& s, double& e) {
    s = a + b;
    const double bv = s - a;
    e = (a - (s - bv)) + (b - bv);
}

// The double nearest to p0 + u·(p1 − p0), up to a tail of order 2^-100 relative: the head and tail of
// each difference and product are kept (error-free transforms), and rounded once at the end.
double on_segment(double p0, double p1, double u) {
    double d, de;
    two_sum(p1, -p0, d, de);
    const double m = u * d;
    const double me = std::fma(u, d, -m);  // exact product tail: the one place an FMA is meant
    double s, se;
    two_sum(p0, m, s, se);
    return s + (se + (me + u * de));
}

}  // namespace

Vec2 point_on_wall(const Wall& w, double u) { return {on_segment(w.p0.x, w.p1.x, u), on_segment(w.p0.y, w.p1.y, u)}; }

// n̂ for wall w, and a point at signed distance h from w's line at parameter u.
Vec2 off_wall(const Wall& w, double u, double h) {
    const Vec2 n = unit_normal(w);
    return point_on_wall(w, u) + h * n;
}

Vec2 nudge(Vec2 p, Rng& r, int ulps) {
    auto step = [](double x, int k) {
        for (; k > 0; --k) x = std::nextafter(x, INFINITY);
        for (; k < 0; ++k) x = std::nextafter(x, -INFINITY);
        return x;
    };
    return {step(p.x, r.integer(-ulps, ulps)), step(p.y, r.integer(-ulps, ulps))};
}

namespace {

template <class Make>
SweepWorkload generate(std::string name, std::size_t n, Make&& make) {
    SweepWorkload out{std::move(name), {}};
    out.queries.reserve(n);
    SweepQuery q;
    while (out.queries.size() < n)
        if (make(q)) out.queries.push_back(q);
    return out;
}

}  // namespace

SweepWorkload offset_workload(double offset, std::size_t n, std::uint64_t seed) {
    Rng r(seed);
    const Vec2 o{offset, offset * 0.75};
    return generate("offset", n, [&](SweepQuery& q) {
        const Wall w = random_wall(r, o, 1.0);
        return make_query(o + in_box(r, 1.0), o + in_box(r, 1.0), w, q);
    });
}

SweepWorkload angle_workload(double angle, std::size_t n, std::uint64_t seed) {
    Rng r(seed);
    return generate("angle", n, [&](SweepQuery& q) {
        const Wall w = random_wall(r, {}, 1.0);
        const double len = length(edge(w));
        // The leg spans parameters [a, b] along the wall (length ≈ (b − a)·len) and crosses the line
        // halfway; its angle to the wall is about 2h/((b − a)·len), so h = angle·(b − a)·len/2.
        const double a = r.uniform(-0.3, 0.6), b = a + r.uniform(0.3, 0.8);
        const double h = angle * (b - a) * len / 2;
        const double sgn = r.unit() < 0.5 ? -1.0 : 1.0;
        return make_query(off_wall(w, a, sgn * h), off_wall(w, b, -sgn * h), w, q);
    });
}

SweepWorkload one_wall_workload(const std::string& kind, const Wall& w, std::size_t n, std::uint64_t seed) {
    Rng r(seed);
    if (kind == "grazing")
        return generate(kind, n, [&](SweepQuery& q) {
            const double len = length(edge(w));
            const double a = r.uniform(-0.3, 0.9), b = r.uniform(0.1, 1.3);
            const double sgn = r.unit() < 0.5 ? -1.0 : 1.0;
            return make_query(off_wall(w, a, sgn * 1e-12 * len), off_wall(w, b, -sgn * 1e-12 * len), w, q);
        });
    return generate(kind, n, [&](SweepQuery& q) { return make_query(in_box(r, 1.0), point_on_wall(w, r.unit()), w, q); });
}

std::vector<SweepWorkload> sweep_workloads(std::size_t n, std::uint64_t seed) {
    std::vector<SweepWorkload> out;
    Rng r(seed);
    // Uniform: walls, starts and ends uniform in [−1, 1]².
    out.push_back(generate("uniform", n, [&](SweepQuery& q) {
        const Wall w = random_wall(r, {}, 1.0);
        return make_query(in_box(r, 1.0), in_box(r, 1.0), w, q);
    }));
    // Far from the origin: the uniform scene moved by 10^k, k uniform in [3, 15].
    out.push_back(generate("far", n, [&](SweepQuery& q) {
        const double o = std::pow(10.0, r.uniform(3.0, 15.0));
        const Vec2 off{o * (r.unit() < 0.5 ? -1 : 1), o * r.uniform(-1.0, 1.0)};
        const Wall w = random_wall(r, off, 1.0);
        return make_query(off + in_box(r, 1.0), off + in_box(r, 1.0), w, q);
    }));
    // End point on the wall: Be is the double nearest to a point of the segment.
    out.push_back(generate("end-on-wall", n, [&](SweepQuery& q) {
        const Wall w = random_wall(r, {}, 1.0);
        return make_query(in_box(r, 1.0), point_on_wall(w, r.unit()), w, q);
    }));
    // Aimed at an end point ± a few ulps: the leg passes through P0 or P1 moved by up to 3 ulps.
    out.push_back(generate("at-endpoint", n, [&](SweepQuery& q) {
        const Wall w = random_wall(r, {}, 1.0);
        const Vec2 target = nudge(r.unit() < 0.5 ? w.p0 : w.p1, r, 3);
        const Vec2 bs = in_box(r, 1.0);
        return make_query(bs, target + (target - bs), w, q);
    }));
    // Grazing: nearly parallel, crossing the line by 1e-12 of the wall's length at each end.
    out.push_back(generate("grazing", n, [&](SweepQuery& q) {
        const Wall w = random_wall(r, {}, 1.0);
        const double len = length(edge(w));
        const double a = r.uniform(-0.3, 0.9), b = r.uniform(0.1, 1.3);
        const double sgn = r.unit() < 0.5 ? -1.0 : 1.0;
        return make_query(off_wall(w, a, sgn * 1e-12 * len), off_wall(w, b, -sgn * 1e-12 * len), w, q);
    }));
    // Tiny velocities: |v| = 10^k, k in [−15, −5], starting within |v| of the wall's line.
    out.push_back(generate("tiny-v", n, [&](SweepQuery& q) {
        const Wall w = random_wall(r, {}, 1.0);
        const double s = std::pow(10.0, r.uniform(-15.0, -5.0));
        const double ang = r.uniform(0.0, 2 * std::numbers::pi);
        const Vec2 bs = off_wall(w, r.uniform(-0.1, 1.1), r.uniform(-s, s));
        return make_query(bs, bs + Vec2{s * std::cos(ang), s * std::sin(ang)}, w, q);
    }));
    // Huge velocities: |v| = 10^k, k in [5, 15], from the unit box.
    out.push_back(generate("huge-v", n, [&](SweepQuery& q) {
        const Wall w = random_wall(r, {}, 1.0);
        const double s = std::pow(10.0, r.uniform(5.0, 15.0));
        const Vec2 bs = in_box(r, 1.0);
        // Aim through a point of the wall's neighbourhood so that about half of them hit.
        const Vec2 through = point_on_wall(w, r.uniform(-0.5, 1.5));
        const Vec2 d = normalize(through - bs);
        return make_query(bs, bs + s * d, w, q);
    }));
    return out;
}

std::vector<StaticWorkload> static_workloads(std::size_t n, std::uint64_t seed) {
    Rng r(seed);
    std::vector<StaticWorkload> out;
    auto make = [&](std::string name, StaticKind kind, auto&& fill) {
        StaticWorkload wl{std::move(name), kind, {}};
        wl.queries.resize(n);
        for (StaticQuery& q : wl.queries) {
            q.kind = kind;
            fill(q);
        }
        out.push_back(std::move(wl));
    };
    // A point on the circle: c + r(cos θ, sin θ) rounded, then ±2 ulps.
    make("point-circle", StaticKind::point_circle, [&](StaticQuery& q) {
        q.a = {in_box(r, 100.0), r.uniform(0.0, 10.0)};
        const double th = r.uniform(0.0, 2 * std::numbers::pi);
        q.p = nudge(q.a.c + q.a.r * Vec2{std::cos(th), std::sin(th)}, r, 2);
    });
    // Touching circles: centres rA + rB apart along a random direction, rounded, then ±2 ulps.
    make("circle-circle", StaticKind::circle_circle, [&](StaticQuery& q) {
        q.a = {in_box(r, 100.0), r.uniform(0.0, 10.0)};
        const double rb = r.uniform(0.0, 10.0);
        const double th = r.uniform(0.0, 2 * std::numbers::pi);
        q.b = {nudge(q.a.c + (q.a.r + rb) * Vec2{std::cos(th), std::sin(th)}, r, 2), rb};
    });
    // A point on an edge or a corner of the rectangle, ±1 ulp per coordinate.
    make("point-rect", StaticKind::point_rect, [&](StaticQuery& q) {
        const Vec2 a = in_box(r, 100.0), b = in_box(r, 100.0);
        q.ra = {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
        const double x = r.unit() < 0.5 ? (r.unit() < 0.5 ? q.ra.left : q.ra.right) : r.uniform(q.ra.left, q.ra.right);
        const double y = r.unit() < 0.5 ? (r.unit() < 0.5 ? q.ra.bottom : q.ra.top) : r.uniform(q.ra.bottom, q.ra.top);
        q.p = nudge({x, y}, r, 1);
    });
    // Rectangles sharing an edge or a corner, ±1 ulp.
    make("rect-rect", StaticKind::rect_rect, [&](StaticQuery& q) {
        const Vec2 a = in_box(r, 100.0), b = in_box(r, 100.0);
        q.ra = {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
        const double w = r.uniform(0.0, 50.0), h = r.uniform(0.0, 50.0);
        const Vec2 corner = nudge({r.unit() < 0.5 ? q.ra.right : q.ra.left - w, r.unit() < 0.5 ? q.ra.top : q.ra.bottom - h}, r, 1);
        q.rb = {corner.x, corner.y, corner.x + w, corner.y + h};
    });
    return out;
}

const std::vector<BoxWorkload>& box_workloads() {
    static const std::vector<BoxWorkload> b = {{"box", {0, 0}, 0.0},
                                               {"box-turned", {0, 0}, 0.3},
                                               {"box-far-1e6", {1e6, -3e5}, 0.3},
                                               {"box-far-1e12", {1e12, 3e11}, 0.3}};
    return b;
}

std::vector<Wall> make_box(Vec2 offset, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    auto corner = [&](double x, double y) { return offset + Vec2{c * x - s * y, s * x + c * y}; };
    const Vec2 a = corner(-1, -1), b = corner(1, -1), cc = corner(1, 1), d = corner(-1, 1);
    return {{a, b}, {b, cc}, {cc, d}, {d, a}};
}

std::vector<Ball> make_balls(Vec2 offset, double angle, std::size_t n, std::uint64_t seed) {
    Rng r(seed);
    const double c = std::cos(angle), s = std::sin(angle);
    std::vector<Ball> out;
    for (std::size_t i = 0; i < n; ++i) {
        const double x = r.uniform(-0.9, 0.9), y = r.uniform(-0.9, 0.9);
        const double sp = std::pow(10.0, r.uniform(std::log10(0.05), std::log10(3.0)));
        const double th = r.uniform(0.0, 2 * std::numbers::pi);
        out.push_back({offset + Vec2{c * x - s * y, s * x + c * y}, {sp * std::cos(th), sp * std::sin(th)}});
    }
    return out;
}

}  // namespace ricochet::bench
