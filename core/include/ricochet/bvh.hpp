// WallBvh: a bounding-volume tree over the walls, the wall grid's alternative for the broad phase.
// Conservative by the same margin argument as the grid (wall_grid.hpp): every box is inflated by
// margin·(1 + |a|∞ + |b|∞) before a leg a → b is tested against it.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "ricochet/kernel.hpp"
#include "ricochet/shapes.hpp"
#include "ricochet/wall_grid.hpp"  // k_grid_margin

namespace ricochet {

/// A bounding-volume tree (AABB tree, median split, 4 walls a leaf) over a scene's walls: the
/// alternative to WallGrid, measured against it by `ricochet bench scale`. Same conservative margin.
class WallBvh final : public WallIndex {
public:
    /// Builds the tree over walls.
    explicit WallBvh(std::span<const Wall> walls, double margin = k_grid_margin);
    /// Appends every wall in a leaf whose box (inflated) the segment a → b may touch.
    void query(Vec2 a, Vec2 b, std::vector<std::uint32_t>& out) const override;
    /// Appends every wall in a leaf whose box, inflated by r too, the segment a → b may touch.
    void query_near(Vec2 a, Vec2 b, double r, std::vector<std::uint32_t>& out) const override;
    /// Nodes in the tree.
    std::size_t nodes() const { return nodes_.size(); }

private:
    struct Node {
        double lo_x, lo_y, hi_x, hi_y;
        std::uint32_t first;  // leaf: first item; inner: index of the left child (right = first + 1)
        std::uint32_t count;  // leaf: item count; inner: 0
    };
    void build(std::span<const Wall> walls, std::uint32_t slot, std::uint32_t first, std::uint32_t count);
    std::vector<Node> nodes_;
    std::vector<std::uint32_t> items_;
    double margin_;
};

}  // namespace ricochet
