// Internal: a scene under an exact map, stepped in lockstep with the run and compared, ball by ball, with the run
// mapped. How the symmetry and swap checks hold a scene with discs or bumpers to its images. Under a mirror or a
// quarter turn every decision of a disc is exact and its constructions round the same numbers up to sign and
// order, so the image of the run is the run of the image (by value: −0 = +0). A wall walked the other way is
// the same capsule, but robust rounds a face contact's t_i from the wall's first end point: there only the
// decisions are the same, each ball's first contact at frames 0 and 1 (as `translation` compares them).
// Balls that meet: a meet's `other ball` is mapped like the ball; the balls in reverse order take their masses along.
// Meets at one time are taken pair by pair, the lowest pair first (docs/scene-log.md, "Balls that meet", 3), so with
// the balls renumbered a frame where a meet was taken while another sharing a ball was due at the same exact time
// (three balls at one point), or one of such a group placed against the balls as they are (MeetRecord::tied), may
// part: from that frame on the image is not compared.
#pragma once

#include <optional>
#include <vector>

#include "checks/frame_check.hpp"
#include "ricochet/world.hpp"

namespace ricochet::checks {

/// An exact map of a scene: a linear map of the plane exact on doubles (negations and swaps of coordinates), every
/// wall walked the other way, the balls in reverse order.
struct SceneMap {
    const char* name = "";          ///< for messages: "the run mirrored across x = 0"
    Vec2 (*point)(Vec2) = nullptr;  ///< points and velocities; nullptr: unchanged
    bool reverse_walls = false;
    bool reverse_balls = false;
    bool first_contacts = false;    ///< compare each ball's first hit or bump at frames 0 and 1 only
};

/// The scene under m: walls, balls, bumpers, circles and rects mapped (a rect's corners re-sorted), radii kept, the
/// masses in the balls' order.
Scene apply(const SceneMap& m, const Scene& s);

/// The image of a scene stepped beside the run.
class MappedRun {
public:
    MappedRun(const Scene& scene, const SceneMap& map, KernelId kernel, const WorldOptions& world);
    /// Steps the image one frame (frame 0: starts it) and compares its events with f's mapped: ball i's events,
    /// mapped, in order, must be its image ball's. The first difference is a failure of c at ball i.
    std::optional<CheckFailure> frame(Check c, const Frame& f);

private:
    /// The balls in reverse order, among balls that meet: the frame is one where a meet was taken whose outcome the
    /// order of meets at one exact time decides (MeetRecord::tied, in the run or the image), and the image is
    /// compared no more.
    bool parts(const Frame& f);

    Event mapped(Event e) const;
    std::uint32_t image_of(std::uint32_t ball) const;

    SceneMap map_;
    Scene image_;
    World world_;
    std::vector<Event> events_;
    std::vector<std::vector<Event>> want_, got_;  // per ball of the image
    bool parted_ = false;                          // the image is compared no more (parts())
};

}  // namespace ricochet::checks
