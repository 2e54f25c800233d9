// speed: per ball per frame, |v| changes by no more than the kernel's bound per reflection allows.
#include <fmt/format.h>

#include <cmath>

#include "checks/frame_check.hpp"
#include "ricochet/format.hpp"
#include "ricochet/truth.hpp"

namespace ricochet {

SpeedBound speed_bound(KernelId kernel) {
    const KernelOps& ops = kernel_ops(kernel);
    return {ops.speed_rel_bound, ops.speed_abs_bound};
}

}  // namespace ricochet

namespace ricochet::checks {
namespace {

class Speed final : public FrameCheck {
public:
    bool needs_traces() const override { return true; }

    Speed(const Scene& scene, KernelId kernel) : scene_(scene), kernel_(kernel), bound_(speed_bound(kernel)) {}

    std::optional<CheckFailure> frame(const Frame& f) override {
        if (f.index == 0) return std::nullopt;
        // One reflection of the velocity the frame starts with about every wall keeps to one reflection's bound.
        for (std::size_t b = 0; b < f.before.size(); ++b) {
            const Vec2 v = f.before[b].vel;
            for (std::size_t i = 0; i < scene_.walls.size(); ++i) {
                const Wall& w = scene_.walls[i];
                if (w.p0 == w.p1) continue;  // no normal: never hit, never reflects
                const Vec2 r = reflect(kernel_, v, w);
                if (!truth::speed_within(v, r, 1, bound_.rel, bound_.abs))
                    return failure(Check::speed, f.index, static_cast<std::uint32_t>(b),
                                   fmt::format("reflect({}, wall {}) = {}: |v'| differs from |v| by more than one "
                                               "reflection allows",
                                               v, i, r));
            }
        }
        // A ball that met another: its velocity is the meet's (momentum judges it), not its reflections'.
        const std::vector<bool> met = met_in_frame(f, f.before.size());
        for (const Event& e : f.events) {
            if (e.kind != Event::Kind::state || met[e.ball]) continue;
            const Vec2 v0 = f.before[e.ball].vel, v1 = e.vel;
            // Nothing changed: nothing to bound (the common frame, decided without arithmetic).
            if (v0 == v1) continue;
            const int m = f.traces[e.ball].reflections;
            if (!truth::speed_within(v0, v1, m, bound_.rel, bound_.abs)) {
                const double n0 = std::hypot(v0.x, v0.y), n1 = std::hypot(v1.x, v1.y);
                return failure(Check::speed, f.index, e.ball,
                               fmt::format("|v| went from {} to {} ({} -> {}) over {} reflection(s): relative change "
                                           "{:.3g}, allowed ((1 + {:.3g})^{} - 1) + {} * {:.3g} / |v|",
                                           n0, n1, v0, v1, m, std::fabs(n1 - n0) / n0, bound_.rel, m, m, bound_.abs));
            }
        }
        return std::nullopt;
    }

private:
    const Scene& scene_;
    KernelId kernel_;
    SpeedBound bound_;
};

}  // namespace

std::unique_ptr<FrameCheck> make_speed(const Scene& scene, KernelId kernel, const WorldOptions&) {
    return std::make_unique<Speed>(scene, kernel);
}

}  // namespace ricochet::checks
