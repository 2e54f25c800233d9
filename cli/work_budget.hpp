// A bound on a command's work, checked before stepping: a small valid log (200 balls, `frames 10000000`)
// would otherwise run for hours and print nothing, and 10^5 copies of one wall (a 1.3 MB log) would fill the
// wall index before the first frame. Work is estimated as
//   frames × balls × (walls + circles + rects + bumpers + 1) + k_max_references_per_wall × walls,
// the ball-against-entity tests of one run without a broad phase (checks step the scene again, so a
// replay costs a small multiple of it) and the most references the wall index may hold (wall_grid.hpp),
// built whatever the frames. `--max-work N` raises or lowers the bound; 0 removes it.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

#include "ricochet/scene.hpp"

namespace ricochet::cli {

/// The default bound: 10^8 (pinball.scene, 500 frames × 1 ball × (6 walls + 3 shapes + 1) + 64 × 6 walls,
/// is 5 384). A gcc Debug build replays an exact-kernel log with two checks at
/// about 10^5 a second: the default is then about a quarter of an hour (each further check adds to it),
/// where the 200-ball, 10^7-frame log (10^10) would take more than a day.
inline constexpr std::uint64_t k_default_max_work = 100'000'000;

/// frames × balls × (walls + circles + rects + bumpers + 1) + k_max_references_per_wall × walls, saturating
/// at the largest uint64.
std::uint64_t estimated_work(const Scene& scene, std::int64_t frames);

/// Adds `--max-work N` (default k_default_max_work, 0: no bound) to a command, stored in max_work.
void add_max_work_option(CLI::App& command, std::uint64_t& max_work);

/// Empty if running scene for frames fits max_work (0: no bound); else the error, naming log, the product
/// and how to raise the bound.
std::string work_over_budget(const std::string& log, const Scene& scene, std::int64_t frames, std::uint64_t max_work);

/// As work_over_budget, but prints the error on stderr and throws Exit{2}.
void check_work_or_exit(const std::string& log, const Scene& scene, std::int64_t frames, std::uint64_t max_work);

}  // namespace ricochet::cli
