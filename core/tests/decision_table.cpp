// The four kernels' acceptance table: for generated near-degenerate sweeps (end point on the wall, aimed at
// a wall's end point ± a few ulps, grazing, far from the origin), how many hit decisions each kernel
// gets wrong against the exact kernel. Exit status 1 if robust gets any wrong.
//
//   decision_table [N]   N sweeps per workload (default 100000), fixed seed
#include <cmath>
#include <cstdlib>
#include <random>
#include <string>

#include <fmt/format.h>

#include "ricochet/kernel.hpp"

using namespace ricochet;

namespace {

struct Query {
    Vec2 bs, v;
    Wall w;
};

struct Gen {
    std::mt19937_64 rng{20261123};
    double u(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
    double ulps(double x, int n) {
        for (int i = 0; i < std::abs(n); ++i) x = std::nextafter(x, n > 0 ? INFINITY : -INFINITY);
        return x;
    }
    Wall wall(double scale, Vec2 off) {
        return {{off.x + scale * u(-1, 1), off.y + scale * u(-1, 1)}, {off.x + scale * u(-1, 1), off.y + scale * u(-1, 1)}};
    }
    // A leg from bs to be whose double end point is exactly be (v = be − bs, retried until bs + v == be).
    Query leg(Vec2 bs, Vec2 be, const Wall& w) {
        Vec2 v = be - bs;
        if (bs + v != be) be = bs + v;
        return {bs, v, w};
    }
    // The end point is the double nearest to a point of the wall (often just off its line).
    Query end_on_wall() {
        const Wall w = wall(10, {0, 0});
        const double t = u(0, 1);
        const Vec2 be{w.p0.x + t * (w.p1.x - w.p0.x), w.p0.y + t * (w.p1.y - w.p0.y)};
        return leg({u(-10, 10), u(-10, 10)}, be, w);
    }
    // Through an end point of the wall, then a few ulps either side.
    Query aimed_at_end() {
        const Wall w = wall(10, {0, 0});
        const Vec2 p = (rng() % 2) ? w.p0 : w.p1;
        const Vec2 bs{u(-10, 10), u(-10, 10)};
        const double k = u(1.0, 3.0);
        Vec2 be{bs.x + k * (p.x - bs.x), bs.y + k * (p.y - bs.y)};
        be = {ulps(be.x, static_cast<int>(rng() % 7) - 3), ulps(be.y, static_cast<int>(rng() % 7) - 3)};
        return leg(bs, be, w);
    }
    // Nearly parallel to the wall, crossing its line by about 1e-12 of its length.
    Query grazing() {
        const Wall w = wall(10, {0, 0});
        const Vec2 e = w.p1 - w.p0, n = perp(e);
        const double len = std::sqrt(dot(e, e));
        const double a = u(-0.2, 0.4), b = u(0.6, 1.2);
        const double da = u(-1, 1) * 1e-12 * len / len, db = u(-1, 1) * 1e-12;
        const Vec2 bs = w.p0 + a * e + da * n;
        const Vec2 be = w.p0 + b * e + db * n;
        return leg(bs, be, w);
    }
    // The uniform case moved far from the origin, 1e3 to 1e15.
    Query far() {
        const double off = std::pow(10.0, u(3, 15));
        const Vec2 o{off * (rng() % 2 ? 1 : -1), off * u(0.5, 1)};
        const Wall w = wall(10, o);
        const double t = u(0, 1);
        const Vec2 be{w.p0.x + t * (w.p1.x - w.p0.x), w.p0.y + t * (w.p1.y - w.p0.y)};
        return leg({o.x + u(-10, 10), o.y + u(-10, 10)}, be, w);
    }
};

}  // namespace

int main(int argc, char** argv) {
    const long n = argc > 1 ? std::strtol(argv[1], nullptr, 10) : 100000;
    if (n <= 0) {
        fmt::print(stderr, "usage: decision_table [N>0]\n");
        return 2;
    }
    Gen g;
    struct Workload {
        const char* name;
        Query (Gen::*make)();
    };
    const Workload workloads[] = {{"end-on-wall", &Gen::end_on_wall},
                                  {"aimed-at-end", &Gen::aimed_at_end},
                                  {"grazing", &Gen::grazing},
                                  {"far-from-origin", &Gen::far}};
    fmt::print("wrong hit decisions against exact, {} sweeps per workload\n", n);
    fmt::print("{:<16} {:>8} {:>15} {:>15} {:>10}\n", "workload", "hits", "lecture-float", "lecture-double", "robust");
    long robust_wrong = 0;
    for (const Workload& wl : workloads) {
        long hits = 0, wrong[3] = {0, 0, 0};
        for (long i = 0; i < n; ++i) {
            const Query q = (g.*wl.make)();
            const bool truth = sweep(KernelId::exact, q.bs, q.v, q.w).hit();
            hits += truth;
            const KernelId ks[3] = {KernelId::lecture_float, KernelId::lecture_double, KernelId::robust};
            for (int k = 0; k < 3; ++k) wrong[k] += sweep(ks[k], q.bs, q.v, q.w).hit() != truth;
        }
        fmt::print("{:<16} {:>8} {:>15} {:>15} {:>10}\n", wl.name, hits, wrong[0], wrong[1], wrong[2]);
        robust_wrong += wrong[2];
    }
    if (robust_wrong != 0) {
        fmt::print(stderr, "FAIL: robust got {} decisions wrong\n", robust_wrong);
        return 1;
    }
    fmt::print("robust: 0 wrong decisions\n");
    return 0;
}
