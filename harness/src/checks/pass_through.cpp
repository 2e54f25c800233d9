// pass-through: two balls never pass through each other within a frame. On every common time interval of two
// pieces of their paths (printed points with their frame times, uniform motion between), a pair at least S = R_i +
// R_j apart at the interval's start stays at least S apart over it (checks.hpp), decided exactly.
// jump-through, on the same paths: the pieces of no duration that pass-through leaves out (a ball's printed points at
// one time, moving straight from one to the next there), each against the other ball standing at that time.
#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "checks/frame_check.hpp"
#include "checks/near_pairs.hpp"
#include "ricochet/format.hpp"
#include "ricochet/truth.hpp"

namespace ricochet::checks {
namespace {

class PassThrough final : public FrameCheck {
public:
    PassThrough(const Scene& scene, Check which) : scene_(scene), which_(which), active_(scene.balls_collide) {
        for (const Ball& b : scene.balls) radii_.push_back(reach_of(b.r));
    }

    std::optional<CheckFailure> frame(const Frame& f) override {
        // Degenerate: balls that do not collide pass through each other; frame 0 has no paths.
        if (!active_ || f.index == 0) return std::nullopt;
        const std::size_t n = scene_.balls.size();
        paths_.assign(n, {});
        std::vector<PairBox> boxes(n);
        // The lowest ball fails: the first path that is not the printed one, or the first pair (near_pairs sorts
        // them), whichever names the lower ball.
        std::optional<CheckFailure> found;
        for (std::uint32_t i = 0; i < n; ++i) {
            if (auto bad = path_of(f, i); bad && !found) found = std::move(bad);
            for (const PathPoint& p : paths_[i]) boxes[i].add(p.p);
        }
        for (const auto& [i, j] : near_pairs(boxes, radii_)) {
            if (found && found->ball <= i) break;
            if (auto bad = pair(f.index, i, j)) return bad;
        }
        return found;
    }

private:
    /// Ball i's path in frame f: the World's (World::path), which must be its printed path — its state before the
    /// frame at t = 0, its hit, bump and meet points in order, its state at t = 1, the times never decreasing. Where
    /// the World gives none, the straight piece from its state before to its state after if it printed no contact,
    /// else none (not judged: the printed lines do not say when a contact happened).
    std::optional<CheckFailure> path_of(const Frame& f, std::uint32_t i) {
        std::vector<Vec2> printed;
        if (i < f.before.size()) printed.push_back(f.before[i].pos);
        for (const Event& e : f.events)
            if (e.ball == i && e.kind != Event::Kind::overlap) printed.push_back(e.pos);
        const std::span<const PathPoint> given = i < f.paths.size() ? f.paths[i] : std::span<const PathPoint>{};
        if (given.empty()) {
            if (printed.size() == 2) paths_[i] = {{0.0, printed[0]}, {1.0, printed[1]}};
            return std::nullopt;
        }
        // A ball stopped at the frame's meet limit shows when it stopped: its state's point twice, at the stop's time
        // and at t = 1 (docs/scene-log.md, "Balls that meet", 7); it is printed once.
        const std::size_t n = given.size();
        const bool stopped = n == printed.size() + 1 && n >= 2 && given[n - 2].p == given[n - 1].p;
        bool same = (n == printed.size() || stopped) && given.front().t == 0.0 && given.back().t == 1.0;
        for (std::size_t k = 0, j = 0; same && k < n; ++k) {
            if (stopped && k == n - 2) continue;
            same = given[k].p == printed[j++] && (k == 0 || given[k - 1].t <= given[k].t);
        }
        if (!same)
            return failure(which_, f.index, i,
                           fmt::format("the World's path of ball {} in this frame ({} points) is not its printed path "
                                       "({} points: its state before, its hits, bumps and meets, its state) from t = 0 "
                                       "to t = 1",
                                       i, given.size(), printed.size()));
        paths_[i].assign(given.begin(), given.end());
        return std::nullopt;
    }

    /// Balls i < j over the frame: each common time interval of a piece of each (pieces of zero duration left out), or
    /// for jump-through, those pieces.
    std::optional<CheckFailure> pair(std::int64_t frame, std::uint32_t i, std::uint32_t j) const {
        const std::vector<PathPoint>&a = paths_[i], &b = paths_[j];
        if (which_ == Check::jump_through) {
            if (auto bad = jumps(frame, i, j, true)) return bad;
            return jumps(frame, i, j, false);
        }
        std::size_t k = 0, m = 0;
        while (k + 1 < a.size() && m + 1 < b.size()) {
            const PathPoint &a0 = a[k], &a1 = a[k + 1], &b0 = b[m], &b1 = b[m + 1];
            if (!(a0.t < a1.t)) {
                ++k;
                continue;
            }
            if (!(b0.t < b1.t)) {
                ++m;
                continue;
            }
            if (std::max(a0.t, b0.t) < std::min(a1.t, b1.t)) {
                const truth::PairClearance c = truth::pieces_clearance(a0, a1, b0, b1, radii_[i], radii_[j]);
                if (c.start >= 0 && c.least < 0)
                    return failure(Check::pass_through, frame, i,
                                   fmt::format("balls {} and {} come closer than R_i + R_j = {} + {} between frame times "
                                               "{} and {}, at least that far apart at the first: ball {} on {} -> {} "
                                               "(t {} to {}), ball {} on {} -> {} (t {} to {}); expected them to meet "
                                               "first",
                                               i, j, scene_.balls[i].r, scene_.balls[j].r, std::max(a0.t, b0.t),
                                               std::min(a1.t, b1.t), i, a0.p, a1.p, a0.t, a1.t, j, b0.p, b1.p, b0.t,
                                               b1.t));
            }
            // On to the piece that ends first (both where they end together).
            const double end = std::min(a1.t, b1.t);
            if (a1.t == end) ++k;
            if (b1.t == end) ++m;
        }
        return std::nullopt;
    }

    /// The jumps of ball i (i_jumps) or j: each piece of no duration, from p0 to p1 at frame time c, against the
    /// other ball standing at c — its printed point there, else its exact point on its piece across c. One that starts
    /// at least S from it and comes closer passes through it. Where the other ball has points at c that differ, it
    /// moves there too, in an order the log does not print: not judged.
    std::optional<CheckFailure> jumps(std::int64_t frame, std::uint32_t i, std::uint32_t j, bool i_jumps) const {
        const std::uint32_t mover = i_jumps ? i : j, other = i_jumps ? j : i;
        const std::vector<PathPoint>&a = paths_[mover], &b = paths_[other];
        for (std::size_t k = 0; k + 1 < a.size(); ++k) {
            const PathPoint &p0 = a[k], &p1 = a[k + 1];
            if (p0.t != p1.t || p0.p == p1.p) continue;
            const double c = p0.t;
            // The other's first point at or after c (its path runs from t = 0 to t = 1, so there is one).
            const auto at =
                std::lower_bound(b.begin(), b.end(), c, [](const PathPoint& q, double t) { return q.t < t; });
            if (at == b.end()) continue;
            PathPoint s0 = *at, s1 = *at;
            if (at->t == c) {
                const auto moves = [&](const PathPoint& q) { return q.t == c && !(q.p == at->p); };
                if (std::any_of(at, b.end(), moves)) continue;
            } else {
                if (at == b.begin()) continue;
                s0 = *(at - 1);
            }
            const truth::PairClearance cl =
                truth::jump_clearance(p0.p, p1.p, c, s0, s1, radii_[mover], radii_[other]);
            if (cl.start >= 0 && cl.least < 0)
                return failure(which_, frame, i,
                               fmt::format("balls {} and {} come closer than R_i + R_j = {} + {} at frame time {}: "
                                           "ball {} jumps from {} to {} there (two printed points at one time), at "
                                           "least that far from ball {} (on {} -> {}, t {} to {}) where it starts; "
                                           "expected them to meet first",
                                           i, j, scene_.balls[i].r, scene_.balls[j].r, c, mover, p0.p, p1.p, other,
                                           s0.p, s1.p, s0.t, s1.t));
        }
        return std::nullopt;
    }

    const Scene& scene_;
    Check which_;  ///< pass-through or jump-through
    bool active_;
    std::vector<double> radii_;
    std::vector<std::vector<PathPoint>> paths_;  ///< the frame's paths, as judged
};

}  // namespace

std::unique_ptr<FrameCheck> make_pass_through(const Scene& scene, KernelId, const WorldOptions&) {
    return std::make_unique<PassThrough>(scene, Check::pass_through);
}

std::unique_ptr<FrameCheck> make_jump_through(const Scene& scene, KernelId, const WorldOptions&) {
    return std::make_unique<PassThrough>(scene, Check::jump_through);
}

}  // namespace ricochet::checks
