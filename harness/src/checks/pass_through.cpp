// pass-through: two balls never pass through each other within a frame. On every common time interval of two
// pieces of their paths (printed points with their frame times, uniform motion between), a pair at least S = R_i +
// R_j apart at the interval's start stays at least S apart over it (checks.hpp), decided exactly.
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
    explicit PassThrough(const Scene& scene) : scene_(scene), active_(scene.balls_collide) {
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
            return failure(Check::pass_through, f.index, i,
                           fmt::format("the World's path of ball {} in this frame ({} points) is not its printed path "
                                       "({} points: its state before, its hits, bumps and meets, its state) from t = 0 "
                                       "to t = 1",
                                       i, given.size(), printed.size()));
        paths_[i].assign(given.begin(), given.end());
        return std::nullopt;
    }

    /// Balls i < j over the frame: each common time interval of a piece of each (pieces of zero duration left out).
    std::optional<CheckFailure> pair(std::int64_t frame, std::uint32_t i, std::uint32_t j) const {
        const std::vector<PathPoint>&a = paths_[i], &b = paths_[j];
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

    const Scene& scene_;
    bool active_;
    std::vector<double> radii_;
    std::vector<std::vector<PathPoint>> paths_;  ///< the frame's paths, as judged
};

}  // namespace

std::unique_ptr<FrameCheck> make_pass_through(const Scene& scene, KernelId, const WorldOptions&) {
    return std::make_unique<PassThrough>(scene);
}

}  // namespace ricochet::checks
