// Internal: one row of `ricochet bench`'s table (bench.cpp), which the speed targets are judged on
// (bench_targets.hpp).
#pragma once

#include <cmath>
#include <cstddef>
#include <string>

namespace ricochet::bench {

/// One row of the table: a method on a workload.
struct Row {
    std::string kind;  // sweep, static, box, extra
    std::string workload;
    std::string method;
    std::size_t n = 0;
    double ns = NAN;     // median ns per query (or per ball-frame, per pair)
    double ratio = NAN;  // against lecture-double in the same run
    long fn = -1, fp = -1, conv = -1;
    double t_ulps = NAN, t_abs = NAN, p_ulps = NAN, p_abs = NAN;
    long tunnels = -1;
    long escaped = -1;  // balls that ended the run outside the box
    double drift = NAN;
    // Disc rows (disc_score.hpp): wrong obstacle or part, ghost bounces, printed points inside and how deep.
    long part = -1, ghosts = -1, inside = -1;
    double depth = NAN, depth_rel = NAN;
};

}  // namespace ricochet::bench
