// ball-overlap: two balls that were once at least S = R_i + R_j apart at a common printed time are never closer than
// S at a later one: each frame's end states, and each meet's two centres (checks.hpp), decided exactly.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "checks/frame_check.hpp"
#include "checks/near_pairs.hpp"
#include "ricochet/format.hpp"
#include "ricochet/truth.hpp"

namespace ricochet::checks {
namespace {

using Pair = std::pair<std::uint32_t, std::uint32_t>;

class BallOverlap final : public FrameCheck {
public:
    explicit BallOverlap(const Scene& scene) : scene_(scene), active_(scene.balls_collide) {
        for (const Ball& b : scene.balls) radii_.push_back(reach_of(b.r));
    }

    std::optional<CheckFailure> frame(const Frame& f) override {
        // Degenerate: balls that do not collide pass through each other, and may overlap.
        if (!active_) return std::nullopt;
        found_.reset();
        // A pair's common printed times in order: its meets (in each ball's time order), then the frame's end.
        for (const auto& [pair, centres] : meets(f)) {
            const std::size_t n = std::min(centres.first.size(), centres.second.size());
            for (std::size_t k = 0; k < n; ++k)
                judge(f.index, pair, centres.first[k], centres.second[k], fmt::format("their meet {} in frame {}", k, f.index));
        }
        std::vector<Vec2> at(scene_.balls.size());
        std::vector<PairBox> boxes(scene_.balls.size());
        for (const Event& e : f.events)
            if (e.kind == Event::Kind::state && e.ball < at.size()) {
                at[e.ball] = e.pos;
                boxes[e.ball] = {};
                boxes[e.ball].add(e.pos);
            }
        // Frame 0: the pairs a scene places closer than S are held to S only once they are clear.
        std::vector<Pair> closer;
        for (const Pair& p : near_pairs(boxes, radii_))
            if (truth::circle_reach_side(at[p.first], at[p.second], radii_[p.first], radii_[p.second]) < 0)
                closer.push_back(p);
        if (f.index == 0) {
            unarmed_ = closer;
            return std::nullopt;
        }
        for (const Pair& p : closer)
            if (!std::binary_search(unarmed_.begin(), unarmed_.end(), p))
                judge(f.index, p, at[p.first], at[p.second], fmt::format("the end of frame {}", f.index));
        // A pair placed closer than S that is clear now is held to S from here on.
        std::vector<Pair> still;
        std::set_intersection(unarmed_.begin(), unarmed_.end(), closer.begin(), closer.end(), std::back_inserter(still));
        unarmed_ = std::move(still);
        return found_;
    }

private:
    /// The frame's meets, per pair i < j: the centres ball i printed at its meets with j, and those j printed.
    static std::map<Pair, std::pair<std::vector<Vec2>, std::vector<Vec2>>> meets(const Frame& f) {
        std::map<Pair, std::pair<std::vector<Vec2>, std::vector<Vec2>>> out;
        for (const Event& e : f.events) {
            if (e.kind != Event::Kind::meet || e.index == e.ball) continue;
            auto& centres = out[{std::min(e.ball, e.index), std::max(e.ball, e.index)}];
            (e.ball < e.index ? centres.first : centres.second).push_back(e.pos);
        }
        return out;
    }

    /// The pair at p (ball i) and q (ball j) at a common printed time: closer than S fails if the pair was ever at
    /// least S apart; at least S apart arms it.
    void judge(std::int64_t frame, Pair pair, Vec2 p, Vec2 q, const std::string& when) {
        const auto [i, j] = pair;
        if (!(radii_[i] > 0) && !(radii_[j] > 0)) return;  // two point balls never meet
        const int side = truth::circle_reach_side(p, q, radii_[i], radii_[j]);
        const auto unarmed = std::lower_bound(unarmed_.begin(), unarmed_.end(), pair);
        if (unarmed != unarmed_.end() && *unarmed == pair) {
            if (side >= 0) unarmed_.erase(unarmed);
            return;
        }
        if (side >= 0 || (found_ && std::pair{found_->ball, other_} <= pair)) return;
        found_ = failure(Check::ball_overlap, frame, i,
                         fmt::format("balls {} and {} are {} apart at {} ({} and {}), closer than R_i + R_j = {} + {}; "
                                     "expected balls once that far apart never to come closer",
                                     i, j, std::hypot(p.x - q.x, p.y - q.y), when, p, q, scene_.balls[i].r,
                                     scene_.balls[j].r));
        other_ = j;
    }

    const Scene& scene_;
    bool active_;
    std::vector<double> radii_;
    std::vector<Pair> unarmed_;  ///< sorted: pairs never yet at least S apart at a common printed time
    std::optional<CheckFailure> found_;
    std::uint32_t other_ = 0;  ///< the failing pair's higher ball
};

}  // namespace

std::unique_ptr<FrameCheck> make_ball_overlap(const Scene& scene, KernelId, const WorldOptions&) {
    return std::make_unique<BallOverlap>(scene);
}

}  // namespace ricochet::checks
