// no-escape: where the walls form closed chains, a ball that starts strictly inside the region they
// enclose never prints a point strictly outside it, and one that starts strictly outside never one
// strictly inside.
#include <fmt/format.h>

#include "checks/frame_check.hpp"
#include "ricochet/format.hpp"
#include "ricochet/truth.hpp"

namespace ricochet::checks {
namespace {

class NoEscape final : public FrameCheck {
public:
    explicit NoEscape(const Scene& scene) : scene_(scene), closed_(truth::walls_closed(scene.walls)) {
        if (closed_)
            for (const Ball& b : scene.balls) start_.push_back(truth::locate(b.pos, scene.walls));
    }

    std::optional<CheckFailure> frame(const Frame& f) override {
        // Open walls enclose nothing a ball could not walk round: the check says nothing about them.
        if (!closed_ || f.index == 0) return std::nullopt;
        for (const Event& e : f.events) {
            if (e.kind == Event::Kind::overlap) continue;
            const int from = start_[e.ball];
            if (from == 0) continue;  // started on a wall: either side is its own
            if (truth::locate(e.pos, scene_.walls) == -from)
                return failure(Check::no_escape, f.index, e.ball,
                               fmt::format("the ball started strictly {} the closed walls, but its {} {} is strictly {}",
                                           from > 0 ? "inside" : "outside",
                                           e.kind == Event::Kind::hit    ? "hit point"
                                           : e.kind == Event::Kind::bump ? "bump point"
                                           : e.kind == Event::Kind::meet ? "meet point"
                                                                         : "end of frame",
                                           e.pos,
                                           from > 0 ? "outside" : "inside"));
        }
        return std::nullopt;
    }

private:
    const Scene& scene_;
    bool closed_;
    std::vector<int> start_;
};

}  // namespace

std::unique_ptr<FrameCheck> make_no_escape(const Scene& scene, KernelId, const WorldOptions&) { return std::make_unique<NoEscape>(scene); }

}  // namespace ricochet::checks
