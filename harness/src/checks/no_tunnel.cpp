// no-tunnel: every printed path piece, through TunnelChecker and, independently, truth::PathFollower.
#include <fmt/format.h>

#include "checks/frame_check.hpp"
#include "ricochet/format.hpp"
#include "ricochet/truth.hpp"
#include "ricochet/tunnel.hpp"

namespace ricochet::checks {
namespace {

class NoTunnel final : public FrameCheck {
public:
    NoTunnel(const Scene& scene) : scene_(scene), tunnel_(scene.walls, scene.balls), path_(scene.walls, scene.balls) {
        for (const Ball& b : scene.balls) last_.push_back(b.pos);
    }

    std::optional<CheckFailure> frame(const Frame& f) override {
        std::optional<CheckFailure> found;
        for (const Event& e : f.events) {
            if (e.kind == Event::Kind::overlap || (e.kind == Event::Kind::state && f.index == 0)) continue;
            const Vec2 q = last_[e.ball];
            last_[e.ball] = e.pos;
            // Two implementations of one definition (kernel.hpp), kept apart: either finding counts.
            std::optional<std::uint32_t> w = tunnel_.advance(e.ball, e.pos);
            const long other = path_.advance(e.ball, e.pos);
            // Taken only if the two disagree, a bug in one of them: no test has found such a path.
            if (!w && other >= 0) w = static_cast<std::uint32_t>(other);
            if (w && !found) {
                found = failure(Check::no_tunnel, f.index, e.ball,
                                fmt::format("the path piece {} -> {} goes through wall {} ({}); expected no piece to "
                                            "cross a wall",
                                            q, e.pos, *w, scene_.walls[*w]));
                found->piece = FailurePiece{q, e.pos, *w};
            }
        }
        return found;
    }

private:
    const Scene& scene_;
    TunnelChecker tunnel_;
    truth::PathFollower path_;
    std::vector<Vec2> last_;
};

}  // namespace

std::unique_ptr<FrameCheck> make_no_tunnel(const Scene& scene, KernelId, const WorldOptions&) { return std::make_unique<NoTunnel>(scene); }

}  // namespace ricochet::checks
