// Events written by hand for the render tests: a ball's state, a hit, an overlap.
#pragma once

#include <cstdint>

#include "ricochet/event.hpp"

namespace ricochet::test {

inline Event state(std::int64_t frame, std::uint32_t ball, Vec2 pos, Vec2 vel = {}) {
    return {Event::Kind::state, frame, ball, Event::Shape::none, 0, pos, vel};
}

inline Event hit(std::int64_t frame, std::uint32_t ball, std::uint32_t wall, Vec2 pos) {
    return {Event::Kind::hit, frame, ball, Event::Shape::none, wall, pos, {}};
}

inline Event overlap(std::int64_t frame, std::uint32_t ball, std::uint32_t circle) {
    return {Event::Kind::overlap, frame, ball, Event::Shape::circle, circle, {}, {}};
}

}  // namespace ricochet::test
