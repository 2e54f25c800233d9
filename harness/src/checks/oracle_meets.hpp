// Internal: the oracle check for the first meet of a frame whose balls collide (checks.hpp, `oracle`): each ball
// stepped again alone through the frame, its path built from that step, and the frame's first meet against the exact
// one (truth.hpp's first_meet; the lecture kernels by their own end-of-frame rule, decided exactly).
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "checks/frame_check.hpp"

namespace ricochet::checks {

class MeetOracle {
public:
    MeetOracle(const Scene& scene, KernelId kernel);
    /// Frame f's first meet (World::meets()'s first record, the first taken) against the exact first meet of the
    /// balls' paths as each is stepped alone: the same pair, at a time in [0, t°] (t° the double nearest t*), and a
    /// meet printed exactly where there is one. Nothing for frame 0 or a scene whose balls do not collide.
    std::optional<CheckFailure> first_meet(const Frame& f);

private:
    /// Every ball stepped alone from its state before the frame: paths_ and ends_.
    void step_alone(const Frame& f);
    std::optional<CheckFailure> swept(const Frame& f, const MeetRecord* first, bool printed);
    std::optional<CheckFailure> end_of_frame(const Frame& f, const MeetRecord* first, bool printed);

    const Scene& scene_;
    KernelId kernel_;
    MeetRule rule_;
    Obstacles obstacles_;
    std::vector<double> radii_;               ///< each ball's reach (R, or 0 for a point ball)
    std::vector<std::vector<PathPoint>> paths_;  ///< each ball's path as stepped alone this frame
    std::vector<Ball> ends_;                  ///< each ball's state at the end of that step
    std::vector<HitEvent> hits_;
    StepScratch scratch_;
};

}  // namespace ricochet::checks
