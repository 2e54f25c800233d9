// accuracy: every well-conditioned hit's t_i and B_i lie within k_hit_accuracy_ulps·ε·M of the exact
// crossing of the leg the kernel swept (checks.hpp).
#include <fmt/format.h>

#include <cmath>
#include <vector>

#include "frame_check.hpp"
#include "ricochet/format.hpp"
#include "ricochet/truth.hpp"

namespace ricochet::checks {
namespace {

class Accuracy final : public FrameCheck {
public:
    bool needs_traces() const override { return true; }

    explicit Accuracy(const Scene& scene) : scene_(scene) {}

    std::optional<CheckFailure> frame(const Frame& f) override {
        if (f.index == 0) return std::nullopt;
        for (std::uint32_t i = 0; i < f.traces.size(); ++i)
            if (auto bad = ball(f, i)) return bad;
        return std::nullopt;
    }

private:
    std::optional<CheckFailure> ball(const Frame& f, std::uint32_t i) const {
        const StepTrace& trace = f.traces[i];
        // The exact kernel's legs are rational (not traced): its B_i is the exact crossing, rounded once.
        if (!trace.legs_traced) return std::nullopt;
        std::vector<const Event*> hits;
        for (const Event& e : f.events)
            if (e.kind == Event::Kind::hit && e.ball == i) hits.push_back(&e);
        // The k-th leg that took a hit printed the k-th hit (a hit found at the bounce limit is not taken;
        // oracle checks the order, so a leg whose wall differs from its event's ends the comparison).
        std::size_t k = 0;
        // The wall the ball last bounced off and the side it met it from (the bounce-side rule's line): from
        // the memory before the frame, then each hit's wall, met from the side of that leg's start.
        const BallMemory& memory = f.memory_before[i];
        const Wall* kept = memory.bounced_from != 0 ? &scene_.walls[memory.bounced_wall] : nullptr;
        int kept_from = memory.bounced_from;
        for (std::size_t l = 0; l < trace.legs.size() && k < hits.size(); ++l) {
            const TracedLeg& leg = trace.legs[l];
            if (leg.blocked || !leg.hit) continue;
            const Event& hit = *hits[k++];
            const Wall* keep_now = kept;
            const int keep_now_from = kept_from;
            if (hit.index < scene_.walls.size()) {
                const int from = truth::side(leg.from, scene_.walls[hit.index]);
                if (from != 0) {
                    kept = &scene_.walls[hit.index];
                    kept_from = from;
                }
            }
            if (hit.index != *leg.hit) break;
            // A leg with a non-finite end is oracle's failure; there is no exact crossing to compare with.
            if (!std::isfinite(leg.from.x) || !std::isfinite(leg.from.y) || !std::isfinite(leg.to.x) ||
                !std::isfinite(leg.to.y))
                break;
            // t_i: the fraction of the leg the kernel put the crossing at (the trace's, since a log does not
            // print it), against the exact s.
            const truth::HitAccuracy rt =
                truth::hit_time_accuracy(leg.from, leg.to, scene_.walls[hit.index], leg.hit_t, k_hit_accuracy_ulps);
            if (rt.conditioned && !rt.within)
                return failure(Check::accuracy, f.index, i,
                               fmt::format("leg {} ({} -> {}) hits wall {} at t_i = {}, {:.4g} eps*M along the leg "
                                           "from the exact crossing (bound {})",
                                           l, leg.from, leg.to, hit.index, leg.hit_t, rt.error, k_hit_accuracy_ulps));
            const truth::HitAccuracy r = truth::hit_accuracy(leg.from, leg.to, scene_.walls[hit.index], hit.pos,
                                                             k_hit_accuracy_ulps, keep_now, keep_now_from);
            if (r.conditioned && !r.within)
                return failure(Check::accuracy, f.index, i,
                               fmt::format("leg {} ({} -> {}) hits wall {} at {}, {:.4g} eps*M from the exact "
                                           "crossing (bound {})",
                                           l, leg.from, leg.to, hit.index, hit.pos, r.error, k_hit_accuracy_ulps));
        }
        return std::nullopt;
    }

    const Scene& scene_;
};

}  // namespace

std::unique_ptr<FrameCheck> make_accuracy(const Scene& scene, KernelId, const WorldOptions&) {
    return std::make_unique<Accuracy>(scene);
}

}  // namespace ricochet::checks
