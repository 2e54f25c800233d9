// ghost-bounce: no hit where only a tangent is possible, the bounce off a straight chain's joint (checks.hpp),
// decided by truth's exact signs and distances.
#include <fmt/format.h>

#include "checks/frame_check.hpp"
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
            if (e.kind != Event::Kind::hit && e.kind != Event::Kind::bump && e.kind != Event::Kind::meet) continue;
            // Only a ball's first hit or bump in the frame: it arrives with the velocity it had before the frame. A
            // meet before it changed that velocity (the meet point is on the path like a bump's).
            if (seen[e.ball]) continue;
            seen[e.ball] = true;
            if (e.kind != Event::Kind::hit) continue;
            const Ball& b = f.before[e.ball];
            const Wall& w = scene_.walls[e.index];
            const double R = scene_.balls[e.ball].r;
            // The frame's first leg, as every kernel takes it: Bs → Be = Bs + v as C++ rounds it (kernel.hpp).
            const Vec2 be{b.pos.x + b.vel.x, b.pos.y + b.vel.y};
            // A leg parallel to W's line and at least R from it never brings the centre closer than R to any point
            // of the line: the disc can at most touch W, and a tangent is no hit (kernel.hpp).
            if (w.p0 == w.p1 || be == b.pos || !truth::parallel_clear_of_line(b.pos, be, w, R)) continue;
            return failure(Check::ghost_bounce, f.index, e.ball,
                           fmt::format("ball {} (radius {}) moves along the leg {} -> {}, parallel to wall {} ({}) and at "
                                       "least its radius from the wall's line, yet hits it at {}; expected no hit (it "
                                       "can at most touch the wall, and a tangent is no hit)",
                                       e.ball, R, b.pos, be, e.index, w, e.pos));
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
