// What the peer kernels share (peer_trace.hpp).
#include "peer_trace.hpp"

#include <numeric>

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

TracedLeg* begin_leg(StepScratch& scratch, Vec2 a, Vec2 b, Vec2 vel, std::optional<std::uint32_t> skipped) {
    StepTrace* t = scratch.trace;
    if (t == nullptr) return nullptr;
    const auto first = static_cast<std::uint32_t>(t->decisions.size());
    TracedLeg& leg = t->legs.emplace_back(TracedLeg{a, b, false, 0, 0, std::nullopt, first, 0, skipped});
    leg.vel = vel;
    return &leg;
}

void decide(StepScratch& scratch, TracedLeg* leg, std::uint32_t wall, bool hit) {
    if (leg == nullptr) return;
    scratch.trace->decisions.push_back({wall, hit ? Miss::none : Miss::no_reason});
    ++leg->decision_count;
}

}  // namespace ricochet::peers
