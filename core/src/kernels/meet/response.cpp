// The response at a meet (response.hpp).
#include "kernels/meet/response.hpp"

#include <cmath>

#include "base/bignum.hpp"
#include "base/round.hpp"
#include "kernels/disc/arith.hpp"

namespace ricochet::meet {
namespace {

using bignum::Rational;
using bignum::nearest;

}  // namespace

bool approaching(const Ball& a, const Ball& b) {
    // In bounded double-double first (the differences and products are exact there for coordinates within the
    // splitting range), then with rationals.
    using disc::Approx2;
    const auto fine = [](double x) { return Approx2{x, 0.0, 0.0}; };
    const Approx2 fx = fine(a.pos.x) - fine(b.pos.x), fy = fine(a.pos.y) - fine(b.pos.y);
    const Approx2 gx = fine(a.vel.x) - fine(b.vel.x), gy = fine(a.vel.y) - fine(b.vel.y);
    if (const auto s = disc::sign(gx * fx + gy * fy)) return *s < 0;
    const Rational nx = Rational(a.pos.x) - Rational(b.pos.x), ny = Rational(a.pos.y) - Rational(b.pos.y);
    const Rational wx = Rational(a.vel.x) - Rational(b.vel.x), wy = Rational(a.vel.y) - Rational(b.vel.y);
    return bignum::sign(Rational(wx * nx + wy * ny)) < 0;
}

bool respond_nearest(Ball& a, Ball& b, double ma, double mb) {
    if (!approaching(a, b)) return false;
    const Rational nx = Rational(a.pos.x) - Rational(b.pos.x), ny = Rational(a.pos.y) - Rational(b.pos.y);
    const Rational wx = Rational(a.vel.x) - Rational(b.vel.x), wy = Rational(a.vel.y) - Rational(b.vel.y);
    // u = (v_a − v_b)·n / (n·n); the impulse per unit mass, 2·u/(m_a + m_b), times the other's mass.
    const Rational u = (wx * nx + wy * ny) / (nx * nx + ny * ny);
    const Rational k = Rational(2) * u / (Rational(ma) + Rational(mb));
    const Rational ka = k * Rational(mb), kb = k * Rational(ma);
    a.vel = {nearest(Rational(a.vel.x) - ka * nx), nearest(Rational(a.vel.y) - ka * ny)};
    b.vel = {nearest(Rational(b.vel.x) + kb * nx), nearest(Rational(b.vel.y) + kb * ny)};
    return true;
}

bool respond_rounded(Ball& a, Ball& b, double ma, double mb) {
    if (!approaching(a, b)) return false;
    // n = X_a − X_b: exact where the centres are within a factor 2 of each other (Sterbenz), as meeting balls are
    // unless one is near the origin.
    const Vec2 n = a.pos - b.pos;
    const double nn = dot(n, n);
    const double M = ma + mb;
    if (std::isnormal(nn) && std::isfinite(M)) {
        const Vec2 w = a.vel - b.vel;
        const double wn_x = w.x * n.x, wn_y = w.y * n.y;
        const double u = (wn_x + wn_y) / nn;
        // v_a′ = v_a − (2·m_b/M)·u·n, v_b′ = v_b + (2·m_a/M)·u·n.
        const double ka = 2.0 * (mb / M) * u, kb = 2.0 * (ma / M) * u;
        const Vec2 ka_n = ka * n, kb_n = kb * n;
        const Vec2 va = a.vel - ka_n, vb = b.vel + kb_n;
        // A product or quotient among the subnormals keeps only the bits above 2^−1074, which may be none of them
        // (a subnormal Δv against centres 3e7 apart left u one ulp of 2^−1074): the exact response, rounded.
        const auto lost = [](double x) { return x != 0.0 && !std::isnormal(x); };
        const bool underflow = lost(wn_x) || lost(wn_y) || lost(u) || lost(ka) || lost(kb) || lost(ka_n.x) ||
                               lost(ka_n.y) || lost(kb_n.x) || lost(kb_n.y);
        if (!underflow && std::isfinite(va.x) && std::isfinite(va.y) && std::isfinite(vb.x) && std::isfinite(vb.y)) {
            a.vel = va;
            b.vel = vb;
            return true;
        }
    }
    // Degenerate: n·n under- or overflows in doubles, or the response's terms underflow: the exact response,
    // rounded.
    return respond_nearest(a, b, ma, mb);
}

}  // namespace ricochet::meet
