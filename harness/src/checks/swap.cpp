// swap: the static tests are symmetric in their arguments, and a wall walked the other way gives the
// opposite side and the same hit or miss. A scene with a disc or a bumper, with every wall walked the other way,
// meets the same obstacles first (a wall's capsule has no direction; mapped_run.hpp).
#include <fmt/format.h>

#include "checks/frame_check.hpp"
#include "checks/mapped_run.hpp"
#include "ricochet/format.hpp"

namespace ricochet::checks {
namespace {

class Swap final : public FrameCheck {
public:
    Swap(const Scene& scene, KernelId kernel, const WorldOptions& world) : scene_(scene), kernel_(kernel) {
        if (has_discs_or_bumpers(scene)) reversed_.emplace(scene, k_reversed, kernel, world);
    }

    std::optional<CheckFailure> frame(const Frame& f) override {
        const KernelId k = kernel_;
        if (reversed_)
            if (auto bad = reversed_->frame(Check::swap, f)) return bad;
        if (f.index == 0) {
            for (const Circle& a : scene_.circles)
                for (const Circle& c : scene_.circles)
                    if (circles_overlap(k, a, c) != circles_overlap(k, c, a))
                        return failure(Check::swap, f.index, 0,
                                       fmt::format("circles_overlap({}, {}) = {} but swapped {}", a, c,
                                                   circles_overlap(k, a, c), circles_overlap(k, c, a)));
            for (const Rect& a : scene_.rects)
                for (const Rect& r : scene_.rects)
                    if (rects_overlap(k, a, r) != rects_overlap(k, r, a))
                        return failure(Check::swap, f.index, 0,
                                       fmt::format("rects_overlap({}, {}) = {} but swapped {}", a, r,
                                                   rects_overlap(k, a, r), rects_overlap(k, r, a)));
        }
        // A point ball's decisions from its printed states (a disc's are its run's, compared above).
        for (const Event& e : f.events) {
            if (e.kind != Event::Kind::state || is_disc(scene_.balls[e.ball])) continue;
            const Vec2 p = e.pos, v = e.vel, be = p + v;
            for (std::size_t i = 0; i < scene_.walls.size(); ++i) {
                const Wall& w = scene_.walls[i];
                const Wall back{w.p1, w.p0};
                for (Vec2 q : {p, be})
                    if (classify(k, q, back) != opposite(classify(k, q, w)))
                        return failure(Check::swap, f.index, e.ball,
                                       fmt::format("{} is {} wall {} but {} it walked the other way", q,
                                                   classify(k, q, w), i, classify(k, q, back)));
                if (v == Vec2{}) continue;
                const Sweep a = sweep(k, p, v, w), b = sweep(k, p, v, back);
                if (a.hit() != b.hit())
                    return failure(Check::swap, f.index, e.ball,
                                   fmt::format("from {} moving {} against wall {}: {}, but {} walked the other way", p,
                                               v, i, a.miss, b.miss));
            }
        }
        return std::nullopt;
    }

private:
    static constexpr SceneMap k_reversed{"the run with every wall walked the other way", nullptr, true, false, true};

    const Scene& scene_;
    KernelId kernel_;
    std::optional<MappedRun> reversed_;
};

}  // namespace

std::unique_ptr<FrameCheck> make_swap(const Scene& scene, KernelId kernel, const WorldOptions& world) {
    return std::make_unique<Swap>(scene, kernel, world);
}

}  // namespace ricochet::checks
