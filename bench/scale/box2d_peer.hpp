// Internal: the Box2D 2.4.1 way of moving point balls through static walls, as its users write it:
// every wall a b2EdgeShape (two-sided) in a b2DynamicTree, one b2DynamicTree::RayCast per leg, the
// nearest b2EdgeShape::RayCast hit taken, v reflected about its normal, the rest of the frame spent
// from the hit point; a disc the same way with b2TimeOfImpact (a circle swept against each candidate edge of the
// tree, the earliest touching one taken, v reflected about the normal b2Distance gives there). Everything in float
// (b2Vec2), as Box2D stores it.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "ricochet/shapes.hpp"

namespace ricochet::scale {

/// A ball as a Box2D user keeps it: b2Vec2 position and velocity per frame.
struct FloatBall {
    float x, y, vx, vy;
};

/// True if Box2D was found at build time.
bool box2d_available();

/// The walls in a b2DynamicTree.
class Box2dPeer {
public:
    /// Builds the tree (one proxy per wall).
    explicit Box2dPeer(std::span<const Wall> walls);
    ~Box2dPeer();
    /// One frame of one ball; appends its hit points to hits if given.
    void step(FloatBall& ball, std::vector<Vec2>* hits) const;
    /// One frame of one disc of radius r (a b2CircleShape bullet); appends its centre at each contact to hits.
    void step_disc(FloatBall& ball, float r, std::vector<Vec2>* hits) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace ricochet::scale
