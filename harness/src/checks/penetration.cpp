// penetration: every printed piece of a ball's path keeps it clear of the walls and bumpers it was clear of
// (checks.hpp), decided by truth's own exact distances.
#include <fmt/format.h>

#include "checks/frame_check.hpp"
#include "ricochet/format.hpp"
#include "ricochet/truth.hpp"

namespace ricochet::checks {
namespace {

class Penetration final : public FrameCheck {
public:
    explicit Penetration(const Scene& scene)
        : scene_(scene), active_(has_discs_or_bumpers(scene)), obstacles_(scene.walls.size() + scene.bumpers.size()) {
        for (const Ball& b : scene.balls) at_.push_back(b.pos);
        // A ball is held to an obstacle from the first printed point of its path clear of it: its start, if so.
        if (active_)
            for (std::size_t i = 0; i < scene.balls.size(); ++i)
                for (std::size_t k = 0; k < obstacles_; ++k) armed_.push_back(clear(i, k, at_[i], at_[i]));
    }

    std::optional<CheckFailure> frame(const Frame& f) override {
        // Degenerate: point balls among walls alone keep every distance (R = 0).
        if (!active_) return std::nullopt;
        std::optional<CheckFailure> found;
        for (const Event& e : f.events) {
            if (e.kind == Event::Kind::overlap || (e.kind == Event::Kind::state && f.index == 0)) continue;
            const Vec2 from = at_[e.ball];
            at_[e.ball] = e.pos;
            for (std::size_t k = 0; k < obstacles_; ++k) {
                const std::size_t slot = e.ball * obstacles_ + k;
                if (!armed_[slot]) {
                    armed_[slot] = clear(e.ball, k, e.pos, e.pos);
                    continue;
                }
                if (found || clear(e.ball, k, from, e.pos)) continue;
                const bool wall = k < scene_.walls.size();
                const double R = scene_.balls[e.ball].r;
                found = failure(Check::penetration, f.index, e.ball,
                                wall ? fmt::format("the path piece {} -> {} comes closer than the radius {} to wall {} "
                                                   "({}); expected every piece at least R from every wall it was clear of",
                                                   from, e.pos, R, k, scene_.walls[k])
                                     : fmt::format("the path piece {} -> {} comes closer than {} + {} to bumper {} ({}); "
                                                   "expected every piece at least R + r from every bumper it was clear of",
                                                   from, e.pos, R, scene_.bumpers[k - scene_.walls.size()].r,
                                                   k - scene_.walls.size(), scene_.bumpers[k - scene_.walls.size()]));
                found->against =
                    FailureObstacle{!wall, static_cast<std::uint32_t>(wall ? k : k - scene_.walls.size()), from, e.pos};
            }
        }
        return found;
    }

private:
    /// The piece a → b of ball i clear of obstacle k (walls first, then bumpers).
    bool clear(std::size_t i, std::size_t k, Vec2 a, Vec2 b) const {
        const double R = scene_.balls[i].r;
        if (k < scene_.walls.size()) return truth::clear_of_wall(a, b, scene_.walls[k], R);
        const Bumper& c = scene_.bumpers[k - scene_.walls.size()];
        return truth::clear_of_circle(a, b, c.c, R, c.r);
    }

    const Scene& scene_;
    bool active_;
    std::size_t obstacles_;
    std::vector<Vec2> at_;
    std::vector<bool> armed_;  // ball-major: armed_[ball · obstacles + k]
};

}  // namespace

std::unique_ptr<FrameCheck> make_penetration(const Scene& scene, KernelId, const WorldOptions&) {
    return std::make_unique<Penetration>(scene);
}

}  // namespace ricochet::checks
