// One frame's meets (meet.hpp's step_meets; docs/scene-log.md, "Balls that meet"): the swept rule of robust and
// exact (swept_frame.hpp), and the lecture's static test at the frame's end; the paths and boxes both read.
#include <algorithm>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "kernels/meet/swept_frame.hpp"
#include "ricochet/meet.hpp"

namespace ricochet {
namespace meet {

/// The heap's order: a comes out after b (later time; on an exact tie the higher pair).
bool later(const MeetCandidate& x, const MeetCandidate& y) {
    const int c = meet::compare(x.root, y.root);
    if (c != 0) return c > 0;
    return std::pair(x.a, x.b) > std::pair(y.a, y.b);
}

bool later(const MeetKey& x, const MeetKey& y, const std::vector<MeetCandidate>& pool) {
    // (compare's first test, on the estimates the keys keep)
    if (const int c = compare_estimates(x.estimate, y.estimate)) return c > 0;
    return later(pool[x.slot], pool[y.slot]);
}

}  // namespace meet

namespace {

/// The lecture's rule: each ball stepped alone, then every pair whose boxes at the frame's end overlap, in index
/// order, through the kernel's static test and push apart (meet_at_end).
void end_of_frame(KernelId k, std::span<const double> masses, std::span<BallFrame> balls,
                  std::vector<MeetRecord>& meets) {
    const std::size_t n = balls.size();
    for (BallFrame& f : balls) meet::build_path(f.path, 0.0, f.before.pos, f.events, f.state.pos);
    std::vector<std::uint32_t> order(n);
    for (std::uint32_t i = 0; i < n; ++i) order[i] = i;
    const auto lo = [&](std::uint32_t i) { return balls[i].state.pos.x - balls[i].state.r; };
    const auto hi = [&](std::uint32_t i) { return balls[i].state.pos.x + balls[i].state.r; };
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return lo(a) < lo(b) || (lo(a) == lo(b) && a < b);
    });
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    for (std::size_t x = 0; x < n; ++x)
        for (std::size_t y = x + 1; y < n && lo(order[y]) <= hi(order[x]); ++y)
            pairs.emplace_back(std::min(order[x], order[y]), std::max(order[x], order[y]));
    std::sort(pairs.begin(), pairs.end());
    const KernelOps& ops = kernel_ops(k);
    for (const auto& [a, b] : pairs) {
        Ball& ba = balls[a].state;
        Ball& bb = balls[b].state;
        if (!(ba.r + bb.r > 0.0)) continue;
        const Vec2 va = ba.vel, vb = bb.vel;
        if (!ops.meet_at_end(ba, bb, masses[a], masses[b])) continue;
        meets.push_back({a, b, 1.0, ba.pos, bb.pos, va, vb, ba.vel, bb.vel, true});
        balls[a].events.push_back({b, 1.0, ba.pos, false, true, ba.vel});
        balls[b].events.push_back({a, 1.0, bb.pos, false, true, bb.vel});
        balls[a].path.push_back({1.0, ba.pos});
        balls[b].path.push_back({1.0, bb.pos});
    }
}

}  // namespace

void step_meets(KernelId k, const Obstacles& obstacles, std::span<const double> masses, std::span<BallFrame> balls,
                std::vector<MeetRecord>& meets, StepScratch& scratch) {
    switch (kernel_ops(k).meet_rule) {
        case MeetRule::none: return;
        case MeetRule::end_of_frame: end_of_frame(k, masses, balls, meets); return;
        case MeetRule::swept:
            if (!scratch.meets) scratch.meets = std::make_shared<MeetFrameScratch>();
            SweptFrame(k, obstacles, masses, balls, meets, scratch, *scratch.meets).run();
            return;
    }
}

}  // namespace ricochet
