// `ricochet bench scale`: per-frame cost as walls and balls grow, brute force against the broad
// phase (grid and BVH), side by side with the way a Box2D 2.4.1 user would do it (walls in a
// b2DynamicTree, one RayCast per ball per leg), with each method's tunnelling count; CSV and chart.
#pragma once

#include <string>

namespace ricochet {

/// Runs the scale benchmark: prints the table, writes OUT_DIR/scale.csv, scale.gp and scale.png.
/// quick: smaller sizes (about a minute); threads: the most threads for the thread sweep (0: all
/// cores). Returns 0, or 1 if the robust kernel tunnelled (never expected).
int run_scale_bench(bool quick, unsigned threads = 0, const std::string& out_dir = "bench-results");

}  // namespace ricochet
