// The engines `ricochet bench meet` steps side by side on one scene: ricochet's World under a kernel, Box2D 2.4.1 and
// Chipmunk 7 as their users would set them up. Each keeps the balls in its own units; the counter reads them there.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>

#include "meet_count.hpp"
#include "meet_scene.hpp"
#include "ricochet/kernel_id.hpp"

namespace ricochet::meet_bench {

/// One engine stepping one scene.
class Engine {
public:
    virtual ~Engine() = default;
    /// Steps one frame.
    virtual void step() = 0;
    /// The balls' states now, in the engine's units.
    virtual std::span<const Ball> balls() = 0;
    /// The box's side in the engine's units.
    virtual double side() const = 0;
    /// The last frame for the counter (an engine made with record = false leaves met and touched empty).
    virtual FrameRecord frame() = 0;
    /// What the table's notes say of this engine's run so far (its units, what it clamped), or nothing.
    virtual std::string notes() const { return {}; }
};

/// ricochet's World on the scene under kernel k, one thread, the grid broad phase.
std::unique_ptr<Engine> make_ricochet(const MeetScene& s, KernelId k);
/// Box2D 2.4.1, or null where it was not found at build time. record: keep the frame's contacts (a listener).
std::unique_ptr<Engine> make_box2d(const MeetScene& s, bool record);
/// Chipmunk 7, or null where it was not found at build time. record: keep the frame's contacts (a handler).
std::unique_ptr<Engine> make_chipmunk(const MeetScene& s, bool record);

}  // namespace ricochet::meet_bench
