// Internal: one disc's frame stepped the lecture's way, written once for the lecture kernels' discs (in float or
// double, lecture/lecture_disc.hpp) and for a plug-in that sweeps discs (plugin/plugin_disc.cpp): the earliest
// contact over every wall and bumper but the one just bounced off, the bounce about its contact normal at B_i,
// then the rest of the frame from B_i, traced for the checks when StepScratch asks for it. naive_frame.hpp is the
// same loop for point balls among walls.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "ricochet/kernel.hpp"
#include "ricochet/limits.hpp"
#include "ricochet/step_trace.hpp"
#include "ricochet/vec2.hpp"

namespace ricochet::detail {

/// One contact of a disc's leg with an obstacle, in the frame loop's precision Real: t_i, the centre B_i there,
/// and the contact normal from the obstacle to the disc (any non-zero length: the bounce only needs its direction).
template <class Real>
struct NaiveContact {
    Real t;
    Vec2T<Real> point;
    Vec2T<Real> normal;
};

/// Steps ball (a disc, or a point ball in a scene with bumpers) through one frame among obstacles, every wall and
/// bumper tried (no broad phase). For each leg pos → pos + d (d = v·rest), every wall but the one just bounced
/// off: wall_contacts(pos, d, wall, offer) offers the wall's contacts (offer(NaiveContact<Real>) → true if it
/// became the leg's earliest so far) and returns the decision to trace for it (Miss::none: a contact); then every
/// bumper but the one just bounced off: bumper_contacts(pos, d, bumper, offer). An offer is taken only if strictly
/// earlier, so ties go to the first offered: the lowest wall, then bumpers by index. At the earliest contact,
/// v′ = reflect(v, normal) and the rest of the frame is the leg from B_i to B_i + (1 − t_i)·v′; at most
/// k_max_bounces bounces, after which the ball stays at its last contact point (bounce_limit). Everything is
/// computed in Real and widened to double at the end. Memory is not used: nothing is remembered between frames.
template <class Real, class WallContacts, class BumperContacts, class Reflect>
FrameStatus step_naive_disc_frame(Ball& ball, const Obstacles& obstacles, std::vector<HitEvent>& hits,
                                  StepScratch& scratch, WallContacts&& wall_contacts, BumperContacts&& bumper_contacts,
                                  Reflect&& reflect) {
    using V = Vec2T<Real>;
    V pos = vec_cast<Real>(ball.pos), vel = vec_cast<Real>(ball.vel);
    Real rest = 1, now = 0;
    // The obstacle just bounced off, skipped on the next leg as the point stepper skips its wall.
    constexpr std::uint32_t k_none = std::numeric_limits<std::uint32_t>::max();
    std::uint32_t last = k_none;
    bool last_bumper = false;
    FrameStatus status = FrameStatus::ok;

    for (int bounce = 0;; ++bounce) {
        const V d = vel * rest;
        const Vec2 a = vec_cast<double>(pos);
        const Vec2 b = vec_cast<double>(pos + d);
        TracedLeg* traced = nullptr;
        if (StepTrace* t = scratch.trace) {
            const auto first = static_cast<std::uint32_t>(t->decisions.size());
            const std::optional<std::uint32_t> skipped =
                last == k_none || last_bumper ? std::nullopt : std::optional<std::uint32_t>(last);
            traced = &t->legs.emplace_back(TracedLeg{a, b, false, 0, 0, std::nullopt, first, 0, skipped});
            traced->vel = vec_cast<double>(vel);
            if (last != k_none && last_bumper) traced->skipped_bumper = last;
        }
        bool found = false;
        std::uint32_t best = 0;
        bool best_bumper = false;
        NaiveContact<Real> contact{};  // the leg's earliest contact so far
        std::uint32_t index = 0;
        bool bumper = false;
        const auto offer = [&](const NaiveContact<Real>& c) {
            if (found && !(c.t < contact.t)) return false;
            found = true;
            best = index;
            best_bumper = bumper;
            contact = c;
            return true;
        };
        for (index = 0; index < obstacles.walls.size(); ++index) {
            if (index == last && !last_bumper) continue;
            const Miss decision = wall_contacts(pos, d, obstacles.walls[index], offer);
            if (traced != nullptr) {
                scratch.trace->decisions.push_back({index, decision});
                ++traced->decision_count;
            }
        }
        bumper = true;
        for (index = 0; index < obstacles.bumpers.size(); ++index) {
            if (index == last && last_bumper) continue;
            bumper_contacts(pos, d, obstacles.bumpers[index], offer);
        }
        if (!found) {
            pos = pos + d;
            break;
        }
        if (traced != nullptr) {
            (best_bumper ? traced->bumped : traced->hit) = best;
            traced->hit_t = static_cast<double>(contact.t);
        }
        if (bounce == k_max_bounces) {
            status = FrameStatus::bounce_limit;
            break;
        }
        if (scratch.trace != nullptr) ++scratch.trace->reflections;
        now = now + rest * contact.t;
        hits.push_back({best, static_cast<double>(now), vec_cast<double>(contact.point), best_bumper});
        // v′ about the contact normal, then the rest of the frame, (1 − t_i)·v′, from B_i.
        vel = reflect(vel, contact.normal);
        pos = contact.point;
        rest = rest * (Real(1) - contact.t);
        last = best;
        last_bumper = best_bumper;
    }
    ball = {vec_cast<double>(pos), vec_cast<double>(vel)};
    return status;
}

}  // namespace ricochet::detail
