// `ricochet bench meet`: what the peers miss when balls meet. One scene of discs in a closed box stepped by ricochet
// robust (`balls collide`, every meet in exact time order), lecture-double (the static test at the frame's end),
// Box2D 2.4.1 (bullets) and Chipmunk 7 from the same initial state; for each, ns per ball-frame and the overlaps,
// escapes and pass-throughs counted exactly on every frame's end state (meet_count.hpp; docs/bench-meet.md).
#pragma once

#include <cstdint>

namespace ricochet::meet_bench {

/// How big the run is: full (1 000 discs for 200 frames, slow and fast, and 10 000 discs for 50: minutes), quick
/// (a quarter of the frames, 3 repetitions), smoke (25 discs, 5 frames, once: a check that robust misses nothing).
enum class MeetSize { full, quick, smoke };

/// Runs the benchmark and prints its Markdown table. frames: the slow and fast scenes' frames (the cost scene steps a
/// quarter of them), 0 for the size's own. Returns 0, or 1 if robust left an overlap, an escape or a pass-through
/// (never expected).
int run_meet_bench(MeetSize size, std::uint64_t seed = 20261123, std::int64_t frames = 0);

}  // namespace ricochet::meet_bench
