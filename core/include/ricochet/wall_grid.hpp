// WallGrid: the default broad phase for walls, a uniform grid walked along each leg.
//
// Conservative by construction. Let G(p) = (p − o)·inv be the grid coordinate of a real point p
// (o, inv doubles; the map is exact over the reals) and cell(p) = ⌊G(p)⌋. A wall is registered in,
// and a leg a → b visits, every cell that holds a real point within m cells (∞-norm) of the
// computed segment G̃(a) → G̃(b), where G̃ is G rounded:
//   |G̃(a) − G(a)| ≤ 2.01ε·|G(a)| per coordinate (a subtraction and a product, each rounded),
//   the per-column y range of the segment is off by ≤ 12ε·max|G̃| (a division, a product, a sum),
// and m = k_grid_margin·(1 + (|a|∞ + |b|∞ + |o|∞)·inv) ≥ 2^-40·max|G| ≫ 14ε·max|G| (ε = 2^-53).
// So every real point S on the real segment a → b lies within m of the computed segment and its cell
// is visited; the same holds for every point of a wall, so a wall that meets the leg at S (its end
// points, the hit point and touching included) shares cell(S) with it and is returned.
// query_near(a, b, r) widens the walk by r·inv cells (times 1 + 2^-40 for its rounding): a wall point W within
// r of S has |G(W) − G(S)|∞ ≤ r·inv, so G(W) lies within m + r·inv of the computed segment and cell(W), where
// the wall is registered, is visited.
// The margin, 2^13 ulps of the largest coordinate, also covers the rounding of the lecture-double
// kernel's hit points, so that kernel gives the same bits with and without the index except for
// hits whose t_i is wrong by O(1) (a leg parallel to the wall within an ulp: measure zero, see
// scale_test). lecture-float rounds at 2^-24: give it GridOptions{.margin = k_float_margin}.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "ricochet/kernel.hpp"
#include "ricochet/shapes.hpp"

namespace ricochet {

/// Default relative margin of the wall grid: 2^-40 of the largest coordinate, in cells.
inline constexpr double k_grid_margin = 0x1p-40;
/// A margin that also covers the lecture-float kernel's 2^-24 rounding.
inline constexpr double k_float_margin = 0x1p-18;
/// Most wall references the grid stores per wall, on average: past it the cells grow (a maze's walls take 3 to 6
/// each; walls that all cross the whole scene would otherwise take √n each, n²/√n in all).
inline constexpr std::size_t k_max_references_per_wall = 64;

/// How a WallGrid is laid out.
struct GridOptions {
    /// Side of a cell; 0 chooses one: about four cells per wall, grown where the walls would take more than
    /// k_max_references_per_wall references each on average.
    double cell_size = 0.0;
    double margin = k_grid_margin;  ///< relative margin, see the header comment
    std::size_t max_cells = std::size_t{1} << 24;  ///< cap on nx·ny (memory)
};

/// A uniform grid over a scene's walls, built once; query walks the cells along a segment.
/// Thread-safe: query is const and keeps no state.
class WallGrid final : public WallIndex {
public:
    /// Builds the grid over walls (indices refer to this span's order).
    explicit WallGrid(std::span<const Wall> walls, GridOptions options = {});
    /// Appends every wall registered in a cell the segment a → b visits, each once (see above).
    void query(Vec2 a, Vec2 b, std::vector<std::uint32_t>& out) const override;
    /// Appends every wall registered in a cell within r of the segment a → b, each once (see above).
    void query_near(Vec2 a, Vec2 b, double r, std::vector<std::uint32_t>& out) const override;
    /// Side of a cell.
    double cell_size() const { return 1.0 / inv_; }
    /// Cells along x and y.
    std::uint32_t columns() const { return nx_; }
    std::uint32_t rows() const { return ny_; }
    /// Wall references stored in all cells together (a wall crossing k cells counts k times).
    std::size_t references() const { return items_.size(); }
    /// Bytes of the cell table and wall lists.
    std::size_t bytes() const { return (start_.size() + items_.size()) * sizeof(std::uint32_t); }
    /// Cache hints for a query that will start at p, in three stages issued some balls apart:
    /// stage 0 fetches the cell's entry, 1 its wall list, 2 those walls. Changes no result.
    void prefetch(Vec2 p, int stage, std::span<const Wall> walls) const;

private:
    template <class F>
    void visit(Vec2 a, Vec2 b, double reach, F&& f) const;
    void collect(Vec2 a, Vec2 b, double reach, std::vector<std::uint32_t>& out) const;

    std::uint32_t wall_count_ = 0;
    double ox_ = 0, oy_ = 0, inv_ = 1, margin_ = k_grid_margin, o_mag_ = 0;
    std::uint32_t nx_ = 0, ny_ = 0;
    std::vector<std::uint32_t> start_;  // CSR: cell c holds items_[start_[c] .. start_[c + 1])
    std::vector<std::uint32_t> items_;
};

}  // namespace ricochet
