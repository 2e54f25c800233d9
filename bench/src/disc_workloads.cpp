#include "disc_workloads.hpp"

#include <cmath>
#include <utility>

#include "ricochet/truth.hpp"
#include "workloads.hpp"

namespace ricochet::bench {
namespace {

// The exact constructions live on a grid of 2^−8: every coordinate an integer below 2^16 times k_unit, so every
// sum and small multiple below is exact in double.
constexpr double k_unit = 0x1p-8;

// A direction (a, b) of integer length c: a Pythagorean triple, or an axis.
struct Dir {
    double a, b, c;
};

// One of 8 triples (the axis included), swapped and signed at random: 64 exact directions.
Dir random_dir(Rng& r) {
    static constexpr Dir k_triples[] = {{1, 0, 1},    {3, 4, 5},    {5, 12, 13},  {8, 15, 17},
                                        {7, 24, 25}, {20, 21, 29}, {12, 35, 37}, {9, 40, 41}};
    Dir d = k_triples[r.integer(0, 7)];
    if (r.unit() < 0.5) std::swap(d.a, d.b);
    if (r.unit() < 0.5) d.a = -d.a;
    if (r.unit() < 0.5) d.b = -d.b;
    return d;
}

Vec2 grid_point(Rng& r, int half) {
    return {r.integer(-half, half) * k_unit, r.integer(-half, half) * k_unit};
}
// o + s·k_unit·(a, b): s units of length c along d, exactly.
Vec2 along(Vec2 o, Dir d, double s) { return o + Vec2{s * k_unit * d.a, s * k_unit * d.b}; }
// o + k·k_unit·(−b, a): k units of length c across d (to its left), exactly.
Vec2 across(Vec2 o, Dir d, double k) { return o + Vec2{-k * k_unit * d.b, k * k_unit * d.a}; }

double sign(Rng& r) { return r.unit() < 0.5 ? -1.0 : 1.0; }

// Bs and Be, nudged by up to 2 ulps in each coordinate when nudged is set.
void maybe_nudge(Rng& r, bool nudged, Vec2& bs, Vec2& be) {
    if (!nudged) return;
    bs = nudge(bs, r, 2);
    be = nudge(be, r, 2);
}

// The query, if fl(Bs + v) == Be, v ≠ 0 and Bs is clear of every obstacle (exactly: truth.hpp); else false (retry).
bool make_disc(Vec2 bs, Vec2 be, DiscQuery q, DiscQuery& out) {
    const Vec2 v = be - bs;
    if (!(bs + v == be) || v == Vec2{}) return false;
    for (const Wall& w : q.wall_span())
        if (!truth::clear_of_wall(bs, bs, w, q.R)) return false;
    if (q.has_bumper && !truth::clear_of_circle(bs, bs, q.bumper.c, q.R, q.bumper.r)) return false;
    q.bs = bs;
    q.v = v;
    out = q;
    return true;
}

DiscQuery one_wall(Wall w, double R) {
    DiscQuery q;
    q.R = R;
    q.walls[0] = w;
    q.nwalls = 1;
    return q;
}

template <class Make>
DiscWorkload generate(std::string name, std::size_t n, Make&& make) {
    DiscWorkload out{std::move(name), {}, false};
    out.queries.reserve(n);
    DiscQuery q;
    while (out.queries.size() < n)
        if (make(q)) out.queries.push_back(q);
    return out;
}

constexpr std::string_view k_names[] = {"disc-uniform", "disc-grazing", "disc-cap", "disc-joint", "bumper"};

}  // namespace

std::span<const std::string_view> disc_workload_names() { return k_names; }

std::vector<DiscWorkload> disc_workloads(std::size_t n, std::uint64_t seed) {
    std::vector<DiscWorkload> out;
    Rng r(seed);
    // Uniform: a wall, Bs and Be uniform in [−1, 1]², R uniform in [0.01, 0.25].
    out.push_back(generate(std::string(k_names[0]), n, [&](DiscQuery& q) {
        const Wall w = random_wall(r, {}, 1.0);
        const double R = r.uniform(0.01, 0.25);
        return make_disc(in_box(r, 1.0), in_box(r, 1.0), one_wall(w, R), q);
    }));
    // Grazing a face: the centre's path parallel to the wall at exactly R from its line (a Pythagorean direction on
    // the 2^−8 grid: exactly tangent, no hit), the same with Bs and Be nudged by up to 2 ulps (just in or just
    // clear), and a random wall with Bs, Be rounded from R·n̂ off it (within ulps of tangent); a third each.
    out.push_back(generate(std::string(k_names[1]), n, [&](DiscQuery& q) {
        const int kind = r.integer(0, 2);
        if (kind == 2) {
            const Wall w = random_wall(r, {}, 1.0);
            const double R = r.uniform(0.01, 0.25), s = sign(r);
            return make_disc(off_wall(w, r.uniform(-0.1, 1.1), s * R), off_wall(w, r.uniform(-0.1, 1.1), s * R),
                             one_wall(w, R), q);
        }
        const Dir d = random_dir(r);
        const int L = r.integer(4, 24), k = r.integer(1, 3);
        const Vec2 o = grid_point(r, 256);
        Wall w{o, along(o, d, L)};
        if (r.unit() < 0.5) std::swap(w.p0, w.p1);
        const double s = sign(r) * k;
        Vec2 bs = across(along(o, d, r.integer(-2, L + 2)), d, s);
        Vec2 be = across(along(o, d, r.integer(-2, L + 2)), d, s);
        maybe_nudge(r, kind == 1, bs, be);
        return make_disc(bs, be, one_wall(w, k * d.c * k_unit), q);
    }));
    // At an end point's cap: the path tangent to the circle of radius R around P_k at a point beyond the wall's end
    // (the wall runs away from the tangent point, so nothing else of the capsule is within R of the path): exactly
    // tangent, or Bs and Be nudged by up to 2 ulps; half each; the cap at P0 or at P1.
    out.push_back(generate(std::string(k_names[2]), n, [&](DiscQuery& q) {
        const Dir m = random_dir(r);
        Dir e = random_dir(r);
        while (e.a * m.a + e.b * m.b <= 0) e = random_dir(r);
        const int L = r.integer(4, 24), k = r.integer(1, 3);
        const Vec2 end = grid_point(r, 256);
        Wall w{along(end, e, -L), end};
        if (r.unit() < 0.5) std::swap(w.p0, w.p1);
        const Vec2 t = along(end, m, k);  // |t − end| = k·c·k_unit = R
        const double s = sign(r);
        Vec2 bs = across(t, m, -s * r.integer(1, 16)), be = across(t, m, s * r.integer(1, 16));
        maybe_nudge(r, r.unit() < 0.5, bs, be);
        return make_disc(bs, be, one_wall(w, k * m.c * k_unit), q);
    }));
    // A chain's joint: two collinear walls sharing an end point (each either way round, in either order), the disc
    // sliding past the joint at exactly R from their line, or with R one to three ulps smaller (clear by ulps).
    // The exact answer is always no hit: any hit is a ghost bounce.
    {
        DiscWorkload joint = generate(std::string(k_names[3]), n, [&](DiscQuery& q) {
            const Dir d = random_dir(r);
            const int l1 = r.integer(4, 24), l2 = r.integer(4, 24), k = r.integer(1, 3);
            const Vec2 o = grid_point(r, 256);
            const Vec2 p1 = along(o, d, l1), p2 = along(p1, d, l2);
            Wall a{o, p1}, b{p1, p2};
            if (r.unit() < 0.5) std::swap(a.p0, a.p1);
            if (r.unit() < 0.5) std::swap(b.p0, b.p1);
            if (r.unit() < 0.5) std::swap(a, b);
            const double s = sign(r) * k;
            Vec2 bs = across(along(o, d, r.integer(1, l1 - 1)), d, s);
            Vec2 be = across(along(o, d, r.integer(l1 + 1, l1 + l2 - 1)), d, s);
            if (r.unit() < 0.5) std::swap(bs, be);
            double R = k * d.c * k_unit;
            if (r.unit() < 0.5)
                for (int u = r.integer(1, 3); u > 0; --u) R = std::nextafter(R, 0.0);
            DiscQuery c = one_wall(a, R);
            c.walls[1] = b;
            c.nwalls = 2;
            return make_disc(bs, be, c, q);
        });
        joint.joint = true;
        out.push_back(std::move(joint));
    }
    // A bumper: the path tangent to the circle of radius R + r around C (exactly, on the grid), the same nudged by
    // up to 2 ulps, and head-on or off-centre legs through the closest approach (lateral offsets on the grid,
    // tangent when the offset is R + r); a third each.
    out.push_back(generate(std::string(k_names[4]), n, [&](DiscQuery& q) {
        const Dir d = random_dir(r);
        const int k = r.integer(1, 3);
        const Vec2 c = grid_point(r, 256);
        const double rho = k * d.c * k_unit;
        // R and r on a 16 times finer grid, R + r = rho exactly, both > 0.
        const double R = r.integer(1, 16 * k * static_cast<int>(d.c) - 1) * (k_unit / 16);
        DiscQuery b;
        b.R = R;
        b.has_bumper = true;
        b.bumper = {c, rho - R};
        const int kind = r.integer(0, 2);
        Vec2 bs, be;
        if (kind < 2) {
            const Vec2 t = along(c, d, k);
            const double s = sign(r);
            bs = across(t, d, -s * r.integer(1, 16));
            be = across(t, d, s * r.integer(1, 16));
            maybe_nudge(r, kind == 1, bs, be);
        } else {
            const int j = r.integer(-k, k);
            bs = across(along(c, d, k + r.integer(1, 16)), d, j);
            be = across(along(c, d, -r.integer(0, 16)), d, j);
        }
        return make_disc(bs, be, b, q);
    }));
    return out;
}

}  // namespace ricochet::bench
