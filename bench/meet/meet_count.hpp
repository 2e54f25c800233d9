// What an engine missed when balls meet, counted on each frame's end state and decided exactly: overlaps, balls out
// of the box, pass-throughs (docs/bench-meet.md). Every decision is exact on the doubles given (a double filter with a
// wide margin first, GMP rationals where it cannot tell); energy drift is informative, in doubles.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "ricochet/meet.hpp"
#include "ricochet/shapes.hpp"

namespace ricochet::meet_bench {

/// One engine's frame as the counter reads it; the spans stay valid until the engine's next step.
struct FrameRecord {
    std::span<const Ball> end;  ///< the balls' states at the frame's end, in the engine's units
    /// Per ball its path through the frame (frame times 0 to 1), or empty for every ball: then each ball's path is
    /// taken as the chord from its state at the frame's start to its end state.
    std::span<const std::vector<PathPoint>> paths;
    /// The pairs (i < j) that met, or that the engine reported in contact, during the frame.
    std::span<const std::pair<std::uint32_t, std::uint32_t>> met;
    /// Per ball, nonzero if it touched anything (a wall or a ball) during the frame, so that its path is not known
    /// to be the chord; empty where the paths are known (ricochet).
    std::span<const std::uint8_t> touched;
};

/// The counts over a run.
struct Counts {
    std::int64_t overlaps = 0;       ///< pairs with |c_i − c_j| < R_i + R_j at a frame's end, summed over frames
    std::int64_t pass_throughs = 0;  ///< pairs that passed through each other within a frame (pass_through below)
    std::int64_t unsure = 0;         ///< pass_through on the chords where a ball touched something else that frame
    /// The deepest pass-through (not unsure): max of 1 − d/S, d the pair's least distance in the frame (in doubles,
    /// informative): near 0 a graze, 1 a centre through a centre.
    double deepest = 0.0;
    std::int64_t escaped = 0;        ///< balls whose centre was outside the box at some frame's end
    double energy_drift = 0.0;       ///< E_F/E_0 − 1 (masses 1)
    double energy_drift_max = 0.0;   ///< max over frames of |E_f/E_0 − 1|
    std::int64_t exact = 0;          ///< decisions the double filter left to rationals
};

/// Exactly: |a − b| < s, s = ra + rb (the sum exact, not rounded).
bool closer_than(Vec2 a, Vec2 b, double ra, double rb, std::int64_t* exact = nullptr);

/// Exactly: the two paths (each its points with frame times from 0 to 1, the centre moving uniformly between
/// consecutive ones) come closer than s = ra + rb at some time of a piece both move on.
bool came_within(std::span<const PathPoint> a, std::span<const PathPoint> b, double ra, double rb,
                 std::int64_t* exact = nullptr);

/// The least distance of the two paths over the pieces both move on, in doubles (informative; came_within decides).
double least_distance(std::span<const PathPoint> a, std::span<const PathPoint> b);

/// A pass-through in a frame: a pair that did not meet, clear (≥ S) at the frame's start and at its end, whose paths
/// came within S between: they crossed each other's line of centres without a meet.
bool pass_through(std::span<const PathPoint> a, std::span<const PathPoint> b, double ra, double rb,
                  std::int64_t* exact = nullptr);

/// Counts a run frame by frame.
class MeetCounter {
public:
    /// The box [0, side]² and the balls' initial states, in the engine's units.
    MeetCounter(double side, std::span<const Ball> start);
    /// Counts one frame (the frame after the last one added).
    void add(const FrameRecord& frame);
    /// The counts so far.
    const Counts& counts() const { return counts_; }

private:
    double side_;
    std::vector<Ball> before_;  // the states at the frame's start
    std::vector<std::uint8_t> escaped_;
    double e0_ = 0.0;
    Counts counts_;
    std::vector<PathPoint> chord_a_, chord_b_;
};

/// The pairs (i < j) whose boxes overlap, boxes given as lo/hi corners: a sort and sweep on x.
std::vector<std::pair<std::uint32_t, std::uint32_t>> box_pairs(std::span<const Vec2> lo, std::span<const Vec2> hi);

}  // namespace ricochet::meet_bench
