// Internal: one ball's frame stepped the lecture's way, written once for the lecture kernels (in float or
// double, lecture/lecture_kernel.hpp) and for a plug-in that gives a sweep but no frame step of its own
// (plugin/plugin_kernel.cpp): the earliest hit over every candidate wall but the one just bounced off, bounce,
// then the rest of the frame from the hit point, traced for the checks when StepScratch asks for it.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "kernels/candidates.hpp"
#include "ricochet/limits.hpp"
#include "ricochet/shapes.hpp"
#include "ricochet/step.hpp"
#include "ricochet/step_trace.hpp"
#include "ricochet/sweep.hpp"
#include "ricochet/vec2.hpp"
#include "ricochet/wall_index.hpp"

namespace ricochet::detail {

/// A leg's answer against one wall in the frame loop's precision Real: the Miss, and t_i and B_i of a hit.
template <class Real>
struct NaiveLeg {
    Miss miss;
    Real t;
    Vec2T<Real> point;
};

/// Steps ball through one frame among walls: for each leg pos → pos + d (d = v·rest), the earliest hit
/// sweep_leg(pos, d, wall) → NaiveLeg<Real> finds over the candidate walls (the index's, or every wall) but
/// the one just bounced off, the lowest index on a tie; at a hit, v′ = reflect(v, wall) and the rest of the
/// frame is the leg from B_i to B_i + (1 − t_i)·v′; at most k_max_bounces bounces, after which the ball stays
/// at its last hit point (bounce_limit). Everything is computed in Real, as the lecture writes it, and widened
/// to double at the end. Memory is not used: the lecture remembers nothing between frames.
template <class Real, class SweepLeg, class Reflect>
FrameStatus step_naive_frame(Ball& ball, std::span<const Wall> walls, std::vector<HitEvent>& hits, StepScratch& scratch,
                             const WallIndex* index, SweepLeg&& sweep_leg, Reflect&& reflect) {
    using V = Vec2T<Real>;
    V pos = vec_cast<Real>(ball.pos), vel = vec_cast<Real>(ball.vel);
    Real rest = 1, now = 0;
    std::uint32_t last = std::numeric_limits<std::uint32_t>::max();
    FrameStatus status = FrameStatus::ok;
    for (int bounce = 0;; ++bounce) {
        const V d = vel * rest;
        const Vec2 a = vec_cast<double>(pos);
        const Vec2 b = vec_cast<double>(pos + d);
        bool found = false;
        std::uint32_t best = 0;
        NaiveLeg<Real> hit{};
        TracedLeg* traced = nullptr;
        if (StepTrace* t = scratch.trace) {
            // The leg as the kernel's own numbers: pos and pos + d in Real, widened to double exactly.
            const auto first = static_cast<std::uint32_t>(t->decisions.size());
            const std::optional<std::uint32_t> skipped = last == std::numeric_limits<std::uint32_t>::max()
                                                             ? std::nullopt
                                                             : std::optional<std::uint32_t>(last);
            traced = &t->legs.emplace_back(TracedLeg{a, b, false, 0, 0, std::nullopt, first, 0, skipped});
            traced->vel = vec_cast<double>(vel);
        }
        for (std::uint32_t i : candidates(walls, index, a, b, scratch.candidates, scratch.all_walls)) {
            if (i == last) continue;
            const NaiveLeg<Real> r = sweep_leg(pos, d, walls[i]);
            if (traced != nullptr) {
                scratch.trace->decisions.push_back({i, r.miss});
                ++traced->decision_count;
            }
            if (r.miss != Miss::none) continue;
            if (!found || r.t < hit.t || (r.t == hit.t && i < best)) {
                found = true;
                best = i;
                hit = r;
            }
        }
        if (!found) {
            pos = pos + d;
            break;
        }
        if (traced != nullptr) {
            traced->hit = best;
            traced->hit_t = static_cast<double>(hit.t);
        }
        if (bounce == k_max_bounces) {
            status = FrameStatus::bounce_limit;
            break;
        }
        if (scratch.trace != nullptr) ++scratch.trace->reflections;
        now = now + rest * hit.t;
        hits.push_back({best, static_cast<double>(now), vec_cast<double>(hit.point)});
        // Spend the rest of the frame, (1 − t_i)·v', moving on from B_i.
        vel = reflect(vel, walls[best]);
        pos = hit.point;
        rest = rest * (Real(1) - hit.t);
        last = best;
    }
    ball = {vec_cast<double>(pos), vec_cast<double>(vel)};
    return status;
}

}  // namespace ricochet::detail
