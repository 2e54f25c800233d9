// Event: one line of `ricochet run`'s output (docs/scene-log.md), and that line's text.
#pragma once

#include <cstdint>
#include <string>

#include "ricochet/vec2.hpp"

namespace ricochet {

/// One line of `ricochet run`'s output.
struct Event {
    /// New kinds join at the end: a kind's value is its hash record's first byte (hash.hpp).
    enum class Kind : std::uint8_t { state, hit, overlap, bump, meet };
    enum class Shape : std::uint8_t { none, circle, rect };
    Kind kind = Kind::state;
    std::int64_t frame = 0;
    std::uint32_t ball = 0;
    Shape shape = Shape::none;   ///< overlap: which kind of static shape
    std::uint32_t index = 0;     ///< hit: the wall; bump: the bumper; overlap: the circle or rect; meet: the other ball
    Vec2 pos;                    ///< state: position; hit, bump, meet: the ball's centre there
    Vec2 vel;                    ///< state: velocity; meet: the velocity the ball leaves the meet with
    friend bool operator==(const Event&, const Event&) = default;
};

/// One event as `ricochet run` prints it (no newline): `state F I X Y VX VY`, `hit F I W X Y`,
/// `bump F I K X Y`, `meet F I J X Y VX VY`, `overlap F I circle|rect K`, numbers in shortest round-trip form (format.hpp's formatter).
std::string format_event(const Event& event);
/// Appends format_event(event) and a newline to out (no temporary string).
void append_event_line(std::string& out, const Event& event);

}  // namespace ricochet
