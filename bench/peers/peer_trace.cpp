// What the peer kernels share (peer_trace.hpp).
#include "peer_trace.hpp"

#include <cmath>
#include <numeric>

#include "ricochet/truth.hpp"

namespace ricochet::peers {

std::span<const std::uint32_t> candidates(std::span<const Wall> walls, const WallIndex* index, Vec2 a, Vec2 b,
                                          StepScratch& scratch) {
    if (index != nullptr) {
        scratch.candidates.clear();
        index->query(a, b, scratch.candidates);
        return scratch.candidates;
    }
    // Every wall: the list 0..n−1 is built once per scratch, not once per leg.
    if (scratch.all_walls.size() != walls.size()) {
        scratch.all_walls.resize(walls.size());
        std::iota(scratch.all_walls.begin(), scratch.all_walls.end(), std::uint32_t{0});
    }
    return scratch.all_walls;
}

Miss no_hit_miss(Vec2 a, Vec2 b, const Wall& w) {
    // Degenerate: a leg with an infinite or NaN end (float overflowed) is not a segment and has no exact
    // answer; `oracle` fails such a leg before it reads any decision.
    if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(b.x) || !std::isfinite(b.y))
        return Miss::degenerate;
    const Miss exact = truth::leg_miss(a, b, w);
    if (exact != Miss::none) return exact;
    return truth::side(a, w) > 0 ? Miss::both_outside : Miss::both_inside;
}

TracedLeg* begin_leg(StepScratch& scratch, Vec2 a, Vec2 b, Vec2 vel, std::optional<std::uint32_t> skipped) {
    StepTrace* t = scratch.trace;
    if (t == nullptr) return nullptr;
    const auto first = static_cast<std::uint32_t>(t->decisions.size());
    TracedLeg& leg = t->legs.emplace_back(TracedLeg{a, b, false, 0, 0, std::nullopt, first, 0, skipped});
    leg.vel = vel;
    return &leg;
}

void decide(StepScratch& scratch, TracedLeg* leg, std::uint32_t wall, const Wall& w, bool hit) {
    if (leg == nullptr) return;
    scratch.trace->decisions.push_back({wall, hit ? Miss::none : no_hit_miss(leg->from, leg->to, w)});
    ++leg->decision_count;
}

}  // namespace ricochet::peers
