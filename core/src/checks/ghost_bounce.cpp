// ghost-bounce: no hit where only a tangent is possible, the bounce off a straight chain's joint (checks.hpp),
// decided by truth's exact signs and distances.
#include <fmt/format.h>

#include "frame_check.hpp"
#include "ricochet/format.hpp"
#include "ricochet/truth.hpp"

namespace ricochet::checks {
namespace {

class GhostBounce final : public FrameCheck {
public:
    explicit GhostBounce(const Scene& scene) : scene_(scene) {}

    std::optional<CheckFailure> frame(const Frame& f) override {
        if (f.index == 0) return std::nullopt;
        std::vector<bool> seen(scene_.balls.size());
        for (const Event& e : f.events) {
            if (e.kind != Event::Kind::hit && e.kind != Event::Kind::bump) continue;
            // Only a ball's first hit or bump in the frame: it arrives with the velocity it had before the frame.
            if (seen[e.ball]) continue;
            seen[e.ball] = true;
            if (e.kind != Event::Kind::hit) continue;
            const Ball& b = f.before[e.ball];
            const Wall& w = scene_.walls[e.index];
            const double R = scene_.balls[e.ball].r;
            // Moving parallel to W's line (n·v = 0, v ≠ 0) at least R from it, the centre never comes closer than
            // R to any point of the line: the disc can at most touch W, and a tangent is no hit (kernel.hpp).
            if (w.p0 == w.p1 || (b.vel.x == 0.0 && b.vel.y == 0.0) || truth::direction_side(b.vel, w) != 0 ||
                !truth::clear_of_line(b.pos, w, R))
                continue;
            return failure(Check::ghost_bounce, f.index, e.ball,
                           fmt::format("ball {} (radius {}) moves from {} with velocity {}, parallel to wall {} ({}) and "
                                       "at least its radius from the wall's line, yet hits it at {}; expected no hit "
                                       "(it can at most touch the wall, and a tangent is no hit)",
                                       e.ball, R, b.pos, b.vel, e.index, w, e.pos));
        }
        return std::nullopt;
    }

private:
    const Scene& scene_;
};

}  // namespace

std::unique_ptr<FrameCheck> make_ghost_bounce(const Scene& scene, KernelId, const WorldOptions&) {
    return std::make_unique<GhostBounce>(scene);
}

}  // namespace ricochet::checks
