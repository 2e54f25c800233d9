// Internal: the rules that keep a printed path from tunnelling, shared by the robust and exact
// kernels. Every decision here is an exact predicate on doubles.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "ricochet/ball_memory.hpp"
#include "ricochet/shapes.hpp"
#include "ricochet/step.hpp"
#include "ricochet/wall_index.hpp"

namespace ricochet::detail {

/// Is the printed piece q → r allowed? It may not pass strictly from one side of a wall to the
/// other through the wall's closed segment, nor leave a contact wall to the side it did not come
/// from, nor arrive where more walls meet than BallMemory can remember. If it is, arrived holds the
/// contacts after it: each wall whose closed segment holds r and whose line q is off, with q's side,
/// and each contact of memory whose closed segment still holds r (the ball slid along it); memory,
/// unchanged, if r = q. The sides of q and r decide both, so each is computed once per wall.
bool piece_allowed(Vec2 q, Vec2 r, const BallMemory& memory, std::span<const Wall> walls, const WallIndex* index,
                   StepScratch& scratch, BallMemory& arrived);

/// A wall the ball bounced off and the side it met it from: until the next bounce the ball moves straight
/// into that side's half-plane, so no printed point may lie on the far side.
struct Keep {
    const Wall* wall = nullptr;
    int from = 0;
};

/// A piece q → r for make_safe to check, with what it is checked against: the ball's memory, the walls (and
/// their index and scratch space), and up to two walls the ball bounced off, whose far side it may not reach.
struct SafePiece {
    Vec2 q;
    Vec2 r;
    const BallMemory& memory;
    std::span<const Wall> walls;
    const WallIndex* index = nullptr;
    StepScratch& scratch;
    std::array<Keep, 2> keep{};
};

/// A point make_safe accepted and the contacts the ball has there (piece_allowed's arrived).
struct SafePoint {
    Vec2 x;
    BallMemory arrived;
};

/// piece.r, or the first point on the way back towards piece.q whose piece q → r is allowed (q itself at
/// worst) and which lies on no kept wall's far side; with the ball's contacts there.
SafePoint make_safe(const SafePiece& piece);

/// The contact on wall w in memory, or nullptr.
const Contact* find_contact(const BallMemory& memory, std::uint32_t w);

}  // namespace ricochet::detail
