// Internal: the Chipmunk 7 way of moving balls through static walls, as its users write it: every wall a
// radius-0 cpSegmentShape on the space's static body (Chipmunk indexes static shapes in its bounding-box tree),
// one cpSpaceSegmentQuery per leg with the ball's radius (a swept circle; 0 for a point), the earliest hit taken
// but the shape just bounced off and shapes the ball moves away from, v reflected about the query's normal, the
// rest of the frame spent from there. In double (cpFloat), as Chipmunk computes. Chipmunk 7.0.3's space query
// walks its tree with the thin segment, the radius left out of the boxes it tests: a wall within R of the
// centre's path but whose box the path does not reach is never asked, and the disc runs into it (the bench
// counts those as penetrations; a lone shape, a leaf at the tree's root, is always asked).
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "ricochet/shapes.hpp"

namespace ricochet::scale {

/// True if Chipmunk was found at build time.
bool chipmunk_available();

/// The walls in a cpSpace.
class ChipmunkPeer {
public:
    explicit ChipmunkPeer(std::span<const Wall> walls);
    ~ChipmunkPeer();
    ChipmunkPeer(const ChipmunkPeer&) = delete;
    ChipmunkPeer& operator=(const ChipmunkPeer&) = delete;
    /// One frame of one ball (its radius ball.r); appends its centre at each contact to hits if given.
    void step(Ball& ball, std::vector<Vec2>* hits) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace ricochet::scale
