// `ricochet bench scale`: per-frame cost as walls and balls grow, brute force against the broad
// phase (grid and BVH), side by side with the way Box2D 2.4.1 and Chipmunk 7 users would do it (box2d_peer.hpp,
// chipmunk_peer.hpp), with each method's tunnelling count; discs of a tenth of a cell against the same balls as
// points in the walls sweep, the peers' discs beside them with their penetrations; discs in a box with and without
// `balls collide` (the meet sweep); CSV and chart.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "ricochet/shapes.hpp"

namespace ricochet {

namespace scale {
/// The maze of the bench: an n×n lattice of pitch 1, its closed border and each inner lattice edge a wall with
/// probability 1/2 (about n² walls). The bench draws a maze of lattice n from seed 1000 + n.
std::vector<Wall> make_maze(int n, std::uint64_t seed);
/// count balls at random points of a lattice-n maze, random directions, 0.05 to 0.5 cells a frame. The bench draws
/// b balls from seed 2000 + b.
std::vector<Ball> make_balls(std::size_t count, int n, std::uint64_t seed);
/// The disc rows' radius: a tenth of a cell.
inline constexpr double k_disc_radius = 0.1;
/// make_balls' balls as discs of radius r, each moved into the middle of its cell (at least 0.15 from the cell's
/// sides, so clear of every wall of the maze for r ≤ 0.1): x ↦ ⌊x⌋ + 0.15 + 0.7·(x − ⌊x⌋), y likewise.
std::vector<Ball> make_discs(std::size_t count, int n, std::uint64_t seed, double r = k_disc_radius);
/// The meet sweep's box: an m×m lattice of cells 2 units wide (m = ⌈√count⌉), its four walls around [0, 2m]².
std::vector<Wall> make_box(std::size_t count);
/// count discs of radius r, one in each of the first count cells of make_box's lattice, at a random point at least
/// 0.2 from the cell's sides (so no two start within 0.4 of each other, nor within 0.2 of a wall, for r ≤ 0.1), moving
/// as make_balls' balls do (0.05 to 0.5 units a frame). The bench draws them from seed 3000 + count.
std::vector<Ball> make_box_discs(std::size_t count, std::uint64_t seed, double r = k_disc_radius);
}  // namespace scale

/// How big the scenes are: full (to 10^6 walls and balls), quick (to 10^5, about a minute), smoke (to 100
/// walls and 1 000 balls, a second: a correctness check of every column, not a measurement).
enum class ScaleSize { full, quick, smoke };

/// Runs the scale benchmark: prints the table and the maze and thread targets' verdicts, writes OUT_DIR/scale.csv,
/// scale.dat, scale.gp, scale_targets.md and (with gnuplot) scale.png. threads: the most threads for the thread
/// sweep (0: all cores). Returns 0, or 1 if the robust kernel tunnelled (never expected).
int run_scale_bench(ScaleSize size, unsigned threads = 0, const std::string& out_dir = "bench-results");

/// The meet sweep of run_scale_bench alone (`ricochet bench scale --meet`): N discs in a box (make_box_discs), stepped
/// by robust without and with `balls collide`, one thread; prints the rows and the meet targets' verdicts, writes
/// OUT_DIR/meet.csv (scale.csv's columns) and meet_targets.md. Returns 0, or 1 if a checked run failed no-tunnel or
/// penetration (never expected).
int run_meet_bench(ScaleSize size, const std::string& out_dir = "bench-results");

}  // namespace ricochet
