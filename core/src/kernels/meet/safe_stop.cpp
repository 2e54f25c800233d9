// The bound of meets reached (swept_frame.hpp; docs/scene-log.md, "Balls that meet", 7): every ball stops at its
// path's point at the last meet's time, and a stop whose piece would enter another ball's printed path is moved to a
// neighbouring double that clears.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "base/bignum.hpp"
#include "kernels/disc/frame.hpp"
#include "kernels/disc/neighbours.hpp"
#include "kernels/meet/swept_frame.hpp"
#include "ricochet/bits.hpp"

namespace ricochet {

void SweptFrame::safe_stop(double t) {
    std::vector<double> when(n_);
    std::vector<meet::PointOnPath> at(n_);
    std::vector<std::vector<PathPoint>> to_stop(n_);
    for (std::uint32_t i = 0; i < n_; ++i) {
        when[i] = std::max(t, seg_t_[i]);
        Placed none;
        at[i] = place(i, when[i], none);
        stop_path(i, at[i], when[i], to_stop[i]);
    }
    std::vector<PathPoint> moved;
    for (std::uint32_t i = 0; i < n_; ++i) {
        const double s = balls_[i].path[at[i].from].t;
        if (!stop_enters(i, s, to_stop)) continue;
        using bignum::Rational;
        const Vec2 x = at[i].x, q = balls_[i].path[at[i].from].p;
        const std::pair<bignum::Rational, bignum::Rational> exact = meet::exact_point(balls_[i].path, when[i]);
        std::optional<Vec2> best;
        Rational best_d2, best_e2;
        bool tie = false;
        // The neighbouring doubles, then those 2 and 3 ulps out where none of a ring is taken (far out, a neighbour
        // across a wall or in a third ball's reach can leave none).
        for (int ring = 1; ring <= meet::k_rings && (!best || tie); ++ring) {
            best.reset();
            tie = false;
            for_each_on_ring(x, ring, [&](Vec2 c) {
                if (c != q && !same_bits(disc::walk_back(q, c, radius(i), obstacles_, scratch_), c)) return;
                stop_path(i, {c, at[i].from}, when[i], moved);
                std::swap(moved, to_stop[i]);
                const bool enters = stop_enters(i, s, to_stop);
                std::swap(moved, to_stop[i]);
                if (enters) return;
                const Rational dx = Rational(c.x) - Rational(x.x), dy = Rational(c.y) - Rational(x.y);
                const Rational fx = Rational(c.x) - exact.first, fy = Rational(c.y) - exact.second;
                const Rational d2 = dx * dx + dy * dy, e2 = fx * fx + fy * fy;
                if (!best || d2 < best_d2 || (d2 == best_d2 && e2 < best_e2)) {
                    best = c;
                    best_d2 = d2;
                    best_e2 = e2;
                    tie = false;
                } else if (d2 == best_d2 && e2 == best_e2) {
                    tie = true;
                }
            });
        }
        if (!best || tie) continue;
        at[i].x = *best;
        stop_path(i, at[i], when[i], to_stop[i]);
    }
    for (std::size_t i = 0; i < n_; ++i) {
        const meet::PointOnPath& p = at[i];
        const Vec2 v = velocity_on(i, p.from);
        cut(i, p.from);
        BallFrame& f = balls_[i];
        f.events.clear();
        f.state = {p.x, v, radius(i)};
        // It stops there at time `when` and stays to the frame's end: the point is printed once, as its state; the
        // path says when it got there (pass-through reads the path with its times).
        f.path = {{when[i], p.x}, {1.0, p.x}};
    }
}

void SweptFrame::stop_path(std::uint32_t i, const meet::PointOnPath& p, double t, std::vector<PathPoint>& out) const {
    const std::vector<PathPoint>& path = balls_[i].path;
    out.assign(committed_[i].begin(), committed_[i].end());
    out.insert(out.end(), path.begin(), path.begin() + static_cast<std::ptrdiff_t>(p.from + 1));
    end_at(i, p, t, out);
    out.push_back({1.0, p.x});
}

bool SweptFrame::stop_enters(std::uint32_t i, double s, const std::vector<std::vector<PathPoint>>& to_stop) {
    bool enters = false;
    neighbours(i, [&](std::uint32_t k) {
        const meet::Radii S{radius(i), radius(k)};
        if (enters || !(S.rounded() > 0.0)) return;
        enters = meet::first_entry(to_stop[i], to_stop[k], S, s).has_value();
    });
    return enters;
}

}  // namespace ricochet
