// Internal: the README's speed targets ("Where each speed target stands") on `ricochet bench`'s own rows (targets.hpp
// says what a verdict is).
#pragma once

#include <span>
#include <vector>

#include "ricochet_bench/targets.hpp"
#include "row.hpp"

namespace ricochet::bench {

/// The verdicts of one run, in the README's order: sweeps (uniform ≤ 1.2×, end on wall and at an end point
/// ≤ 1.5× lecture-double), boundary-heavy static tests (≤ 3×), closed boxes (≤ 1.5×), batched decisions (≤ 1.5 ns
/// per ball-wall pair uniform, ≤ 10 ns end on wall), then from disc_rows (disc_score.hpp) discs (uniform ≤ 2×,
/// grazing, caps and among bumpers ≤ 4×). Ratios are robust's row against lecture-double's in the same interleaved
/// runs; a target whose rows the run lacks is "not measured".
std::vector<Verdict> bench_targets(std::span<const Row> rows, std::span<const Row> disc_rows = {});

}  // namespace ricochet::bench
