// Disc workloads: a disc of radius R moving Bs → Be against one wall, a chain of two walls or one bumper;
// fixed-seed query sets, the same for every method (bench/README.md, "Disc workloads").
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ricochet/kernel.hpp"

namespace ricochet::bench {

/// One disc query: the disc of radius R whose centre moves Bs → Be = fl(Bs + v) (generators guarantee
/// fl(bs + v) == be, and that Bs is at least R from every wall and R + r from the bumper) among walls[0, nwalls)
/// and, if has_bumper, the bumper.
struct DiscQuery {
    Vec2 bs;
    Vec2 v;
    double R = 0.0;
    std::array<Wall, 2> walls{};
    std::uint8_t nwalls = 0;
    bool has_bumper = false;
    Bumper bumper;

    /// The query's walls.
    std::span<const Wall> wall_span() const { return {walls.data(), nwalls}; }
    /// The query's bumpers (none or one).
    std::span<const Bumper> bumper_span() const { return {&bumper, has_bumper ? 1u : 0u}; }
};

/// A named disc workload. joint: every query slides at its radius along a chain of two collinear walls, where
/// any hit is a ghost bounce.
struct DiscWorkload {
    std::string name;
    std::vector<DiscQuery> queries;
    bool joint = false;
};

/// The names of the disc workloads, in disc_workloads' order (without generating them).
std::span<const std::string_view> disc_workload_names();

/// The disc workloads, n queries each, from seed: disc-uniform, disc-grazing, disc-cap, disc-joint, bumper.
std::vector<DiscWorkload> disc_workloads(std::size_t n, std::uint64_t seed);

}  // namespace ricochet::bench
