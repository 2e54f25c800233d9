// The tunnel checker (tunnel.hpp): exact predicates on the printed doubles.
#include "ricochet/tunnel.hpp"

#include "ricochet/line.hpp"
#include "ricochet/predicates.hpp"

namespace ricochet {

TunnelChecker::TunnelChecker(std::span<const Wall> walls, std::span<const Ball> balls)
    : walls_(walls.begin(), walls.end()), state_(balls.size() * walls.size()) {
    for (std::size_t i = 0; i < balls.size(); ++i) {
        at_.push_back(balls[i].pos);
        for (std::size_t w = 0; w < walls_.size(); ++w)
            state_[i * walls_.size() + w].last_side = static_cast<std::int8_t>(exact::side(balls[i].pos, walls_[w]));
    }
}

std::optional<std::uint32_t> TunnelChecker::advance(std::size_t i, Vec2 next) {
    const Vec2 q = at_[i];
    at_[i] = next;
    if (q == next) return std::nullopt;
    std::optional<std::uint32_t> found;
    for (std::size_t w = 0; w < walls_.size(); ++w) {
        const Wall& wall = walls_[w];
        State& st = state_[i * walls_.size() + w];
        const int sq = exact::side(q, wall);
        const int sr = exact::side(next, wall);
        bool tunnel = false;
        if (sq != 0 && sr != 0) {
            // Strictly from one side to the other, through the closed segment.
            tunnel = sq != sr && exact::orient(q, next, wall.p0) * exact::orient(q, next, wall.p1) <= 0;
            st = {static_cast<std::int8_t>(sr), false};
        } else if (sq != 0) {
            // Arrives on the line: it touches the wall if it lands on the closed segment.
            st = {static_cast<std::int8_t>(sq), in_segment_box(next, wall)};
        } else if (sr != 0) {
            // Leaves the line: through the wall if it had arrived on the segment from the other side.
            tunnel = st.last_side != 0 && st.touched && sr != st.last_side;
            st = {static_cast<std::int8_t>(sr), false};
        } else {
            // Moves along the line: it keeps the side it came from, and stays on the wall while it stays on
            // the closed segment; sliding off the segment's end, it may go round to either side.
            st.touched = st.touched && in_segment_box(next, wall);
        }
        if (tunnel && !found) found = static_cast<std::uint32_t>(w);
    }
    return found;
}

}  // namespace ricochet
