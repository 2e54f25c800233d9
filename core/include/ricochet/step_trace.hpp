// StepTrace: what a kernel did during one ball's frame, for the checks: the legs it swept with its
// per-wall decisions and the wall it took as first hit, and how many times it reflected v. Filled only
// when StepScratch::trace points at one; with no trace a step pays one null test per leg.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "ricochet/sweep.hpp"
#include "ricochet/vec2.hpp"

namespace ricochet {

/// One wall decision a kernel made for a leg.
struct TracedDecision {
    std::uint32_t wall = 0;
    Miss miss = Miss::degenerate;
};

/// One leg a kernel swept: the segment from → to as its doubles (lecture-float: its floats, widened
/// exactly), the decisions it made for it, and the wall it took as the leg's first hit.
struct TracedLeg {
    Vec2 from;
    Vec2 to;
    /// The leg ended on the far side of a contact wall, so the kernel reflected v off that wall without
    /// sweeping (kernel.hpp); blocked_wall and blocked_side (the side the contact was met from) say which.
    bool blocked = false;
    std::uint32_t blocked_wall = 0;
    std::int8_t blocked_side = 0;
    std::optional<std::uint32_t> hit;  ///< the wall taken as the leg's first hit, or none
    std::uint32_t first_decision = 0;  ///< this leg's decisions: StepTrace::decisions[first, first + count)
    std::uint32_t decision_count = 0;
    /// The walls the kernel skipped without a decision because of its own rule (lecture: the wall just
    /// bounced off), or none.
    std::optional<std::uint32_t> skipped;
    /// The kernel's t_i of the hit (or bump) it took: the fraction of this leg at which it put the crossing or the
    /// contact (0 without one).
    double hit_t = 0.0;
    /// The velocity the ball moved with on this leg (the leg is the rest of the frame at this velocity); the
    /// next leg's, or the frame's end state's, is the one it left a hit with.
    Vec2 vel{};
    /// A disc's leg (or a point ball's among bumpers): the bumper taken as the leg's first contact, or none (hit
    /// then names a wall, or nothing).
    std::optional<std::uint32_t> bumped{};
    /// The bumper the kernel skipped without a decision because of its own rule (lecture: the bumper just bounced
    /// off), or none.
    std::optional<std::uint32_t> skipped_bumper{};
};

/// One ball's frame as its kernel stepped it.
struct StepTrace {
    std::vector<TracedLeg> legs;
    std::vector<TracedDecision> decisions;
    /// Every reflect() the kernel made this frame: hits, the extra reflections at a corner, reflections
    /// off contact walls that emit no hit. Going straight back (v' = −v) is exact and not counted.
    int reflections = 0;
    /// False for a kernel whose legs are not doubles (exact: rational legs, rounded once at the end);
    /// then legs and decisions stay empty and only reflections is filled.
    bool legs_traced = true;
    /// The frame stopped at the bounce limit (FrameStatus::bounce_limit). Set by whoever stepped the ball
    /// with this trace (run_checked), from what step_ball returned.
    bool stopped_at_limit = false;
    /// Empties the trace for the next frame.
    void clear() {
        legs.clear();
        decisions.clear();
        reflections = 0;
        legs_traced = true;
        stopped_at_limit = false;
    }
};

}  // namespace ricochet
