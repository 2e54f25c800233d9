// Scoring a method's disc answers: hit decisions against an exact truth, the obstacle and the part of it against
// the exact kernel's, ghost bounces, and how far a printed contact point lies inside (bench/README.md, "Disc
// columns"). Apart from the driver so that a test can feed it wrong answers and see the gate fail.
#pragma once

#include <span>
#include <vector>

#include "disc_workloads.hpp"
#include "methods.hpp"

namespace ricochet::bench {

/// Whether the disc of query q enters a wall's capsule (the points within R of it) or the bumper's circle of radius
/// R + r along its leg: the exact hit decision, by contact.hpp's rules but sharing no code with contact.cpp. The leg
/// comes closer than R somewhere (truth.hpp's clear_of_wall / clear_of_circle, exact), or it ends exactly at R
/// moving closer (an entry at t = 1; exact rationals here). A tangent (a least distance of exactly R) is no hit.
bool truth_hit(const DiscQuery& q);

/// One method's disc errors on one workload.
struct DiscScore {
    long fn = 0, fp = 0;  ///< hit decisions that differ from truth_hit: missed, invented
    long part = 0;        ///< hits both agree on whose obstacle (wall, bumper) or part (face, cap) differs from exact's
    long ghosts = -1;     ///< joint workloads: hits on a leg that only slides past the joint (-1: not a joint workload)
    long inside = 0;      ///< hits whose printed contact point is closer than R (R + r) to an obstacle, exactly
    double depth = 0.0;   ///< the largest such distance, R − d (long double), absolute
    double depth_rel = 0.0;  ///< the same over R
};

/// Scores got against the truth (truth_hit per query, in hits) and the exact kernel's answers (for the part).
DiscScore score_discs(std::span<const DiscQuery> qs, std::span<const DiscAnswer> got, std::span<const DiscAnswer> exact,
                      const std::vector<bool>& hits, bool joint);

/// The gate robust and exact are held to (`ricochet bench` exits 1 otherwise): no wrong hit decision, no ghost
/// bounce, no printed contact point inside. The part is not gated: a kernel's part shows only through its printed
/// point, a rounded construction (bench/README.md, "Disc columns").
bool disc_score_clean(const DiscScore& s);

}  // namespace ricochet::bench
