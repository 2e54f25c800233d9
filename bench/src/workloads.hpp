// Workload generators: fixed-seed query sets, the same for every method.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ricochet/kernel.hpp"

namespace ricochet::bench {

/// One sweep query: the leg Bs → Be = fl(Bs + v) against one wall. Generators guarantee fl(bs + v) == be.
struct SweepQuery {
    Vec2 bs;
    Vec2 v;
    Wall wall;
};

/// The four static tests.
enum class StaticKind : std::uint8_t { point_circle, circle_circle, point_rect, rect_rect };

/// One static query; which fields matter depends on kind.
struct StaticQuery {
    StaticKind kind;
    Vec2 p;
    Circle a, b;
    Rect ra, rb;
};

/// A named sweep workload.
struct SweepWorkload {
    std::string name;
    std::vector<SweepQuery> queries;
};

/// A named static workload.
struct StaticWorkload {
    std::string name;
    StaticKind kind;
    std::vector<StaticQuery> queries;
};

/// A deterministic generator: splitmix64, so that sequences are the same on every platform.
class Rng {
public:
    explicit Rng(std::uint64_t seed) : state_(seed) {}
    /// Next 64 random bits.
    std::uint64_t next();
    /// Uniform double in [0, 1), 53 random bits.
    double unit() { return static_cast<double>(next() >> 11) * 0x1p-53; }
    /// Uniform double in [lo, hi).
    double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
    /// Uniform integer in [lo, hi].
    int integer(int lo, int hi) { return lo + static_cast<int>(next() % static_cast<std::uint64_t>(hi - lo + 1)); }

private:
    std::uint64_t state_;
};

/// The sweep workloads, n queries each, from seed.
std::vector<SweepWorkload> sweep_workloads(std::size_t n, std::uint64_t seed);
/// The static workloads (boundary-heavy), n queries each, from seed.
std::vector<StaticWorkload> static_workloads(std::size_t n, std::uint64_t seed);

/// Uniform sweeps in a unit box moved by offset (stability sweep over magnitude).
SweepWorkload offset_workload(double offset, std::size_t n, std::uint64_t seed);
/// Grazing sweeps whose leg makes an angle of about angle radians with the wall (stability sweep over angle).
SweepWorkload angle_workload(double angle, std::size_t n, std::uint64_t seed);

/// Many balls against the one wall w (for the batched path): kind "end-on-wall" (every Be the double
/// nearest a point of w) or "grazing" (every leg crossing w's line by 1e-12 of its length).
SweepWorkload one_wall_workload(const std::string& kind, const Wall& w, std::size_t n, std::uint64_t seed);

/// A closed box: the square [−1, 1]² turned by angle and moved to offset, with balls inside.
struct BoxWorkload {
    std::string name;
    Vec2 offset;
    double angle = 0.0;
};
/// The closed boxes `ricochet bench` runs: box, box-turned, box-far-1e6, box-far-1e12.
const std::vector<BoxWorkload>& box_workloads();
/// A box's four walls; consecutive walls share their corner doubles.
std::vector<Wall> make_box(Vec2 offset, double angle);
/// n balls inside the box (a margin of 0.1 from the walls), speeds 0.05..3 per frame, from seed.
std::vector<Ball> make_balls(Vec2 offset, double angle, std::size_t n, std::uint64_t seed);

/// A point uniform in the square [−half, half]².
Vec2 in_box(Rng& r, double half);
/// A wall with both ends uniform in the square [−half, half]² moved to offset, of non-zero length.
Wall random_wall(Rng& r, Vec2 offset, double half);
/// The double nearest to P0 + u·(P1 − P0), to about 2^−100 relative (error-free transforms).
Vec2 point_on_wall(const Wall& w, double u);
/// The point at signed distance h (along n̂) from w's line, at parameter u, rounded.
Vec2 off_wall(const Wall& w, double u, double h);
/// p with each coordinate moved by a random number of ulps in [−ulps, ulps].
Vec2 nudge(Vec2 p, Rng& r, int ulps);

/// A query from a start and an end point: v = Be − Bs; false if fl(Bs + v) ≠ Be (the caller retries).
bool make_query(Vec2 bs, Vec2 be, const Wall& w, SweepQuery& out);

}  // namespace ricochet::bench
