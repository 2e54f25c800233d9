// Internal: the accuracy check for a ball stepped as a disc (a ball of radius R > 0, or any ball in a scene with
// bumpers): each contact's t_i, printed point and bounce against truth.hpp's exact contact (checks.hpp,
// `accuracy`). The legs' rest-of-the-frame part is accuracy.cpp's, shared with point balls.
#pragma once

#include <optional>
#include <vector>

#include "checks/frame_check.hpp"

namespace ricochet::checks {

class DiscAccuracy {
public:
    DiscAccuracy(const Scene& scene, SpeedBound bound) : scene_(scene), bound_(bound) {}
    /// Ball i's frame f: each leg that took a contact the frame printed (contacts: the ball's hits and bumps of
    /// the frame, in order), judged against the exact first contact of that leg.
    std::optional<CheckFailure> contacts(const Frame& f, std::uint32_t i, const std::vector<const Event*>& printed) const;

private:
    const Scene& scene_;
    SpeedBound bound_;
};

}  // namespace ricochet::checks
