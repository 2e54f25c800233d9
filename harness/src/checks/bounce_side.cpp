// bounce-side: a ball that hit a wall from one side prints no later point strictly on that wall's other
// side until its next hit (BallMemory's rule, kernel.hpp), the next hit point included. A ball the disc frame
// steps (a disc, or any ball among bumpers) is held to it after meeting a wall's face (the hit point's foot on
// the segment: the bounce about ±n leaves the line behind), for its points whose foot is on the segment too
// (beyond an end the path may pass around it); a cap or a bumper has no side, and a bump, like a hit, ends it; so
// does a meet with another ball (no side either).
#include <fmt/format.h>

#include "checks/frame_check.hpp"
#include "ricochet/format.hpp"
#include "ricochet/truth.hpp"

namespace ricochet::checks {
namespace {

class BounceSide final : public FrameCheck {
public:
    explicit BounceSide(const Scene& scene)
        : scene_(scene), at_(scene.balls.size()), kept_(scene.balls.size()),
          bumpers_(!scene.bumpers.empty() || scene.balls_collide) {
        for (std::size_t i = 0; i < scene.balls.size(); ++i) at_[i] = scene.balls[i].pos;
    }

    std::optional<CheckFailure> frame(const Frame& f) override {
        if (f.index == 0) return std::nullopt;
        std::optional<CheckFailure> found;
        for (const Event& e : f.events) {
            if (e.kind == Event::Kind::overlap) continue;
            Kept& k = kept_[e.ball];
            const bool disc_frame = bumpers_ || is_disc(scene_.balls[e.ball]);
            if (k.from != 0 && truth::side(e.pos, scene_.walls[k.wall]) == -k.from && !found &&
                (!disc_frame || truth::projects_onto_segment(e.pos, scene_.walls[k.wall])))
                found = failure(Check::bounce_side, f.index, e.ball,
                                fmt::format("the ball hit wall {} from side {}, but its {} {} lies on the other side "
                                            "before its next hit",
                                            k.wall, k.from,
                                            e.kind == Event::Kind::hit    ? "hit point"
                                            : e.kind == Event::Kind::bump ? "bump point"
                                            : e.kind == Event::Kind::meet ? "meet point"
                                                                          : "end of frame",
                                            e.pos));
            if (e.kind == Event::Kind::bump || e.kind == Event::Kind::meet) k = {};
            if (e.kind == Event::Kind::hit) {
                const Wall& w = scene_.walls[e.index];
                // The side it met the wall from: that of the point it came from; coming along the line, the side
                // it last met that wall from still holds. The disc frame's: that of its hit point, off the line
                // by R or walked back (a leg almost along the wall may cross the line beyond an end, then meet
                // the face from the other side), else the point it came from.
                int from = disc_frame ? truth::side(e.pos, w) : 0;
                if (from == 0) from = truth::side(at_[e.ball], w);
                if (disc_frame && !truth::projects_onto_segment(e.pos, w)) k = {};
                else if (from != 0 || k.wall != e.index) k = {e.index, from};
            }
            at_[e.ball] = e.pos;
        }
        return found;
    }

private:
    struct Kept {
        std::uint32_t wall = 0;
        int from = 0;
    };
    const Scene& scene_;
    std::vector<Vec2> at_;
    std::vector<Kept> kept_;
    bool bumpers_;  ///< every ball is stepped by the disc frame (bumpers, or balls that collide)
};

}  // namespace

std::unique_ptr<FrameCheck> make_bounce_side(const Scene& scene, KernelId, const WorldOptions&) {
    return std::make_unique<BounceSide>(scene);
}

}  // namespace ricochet::checks
