// Kernels: four numeric implementations of the lecture's collision tests behind one interface,
// chosen by name at run time.
//
//   lecture-float, lecture-double  the lecture's formulas as written (unit normal n̂, BC, the five
//                                  tests, t_i), in float or double. The baseline; not fixed.
//   robust (default)               double precision. Every decision (side, parallel, before P0, past
//                                  P1, touching, which wall first) is exact: a floating-point filter
//                                  with an exact fallback (predicates.hpp). Constructions (t_i, B_i,
//                                  v') are rounded; a rounded point is never accepted if it would put
//                                  the ball across a wall (see "no tunnelling" below).
//   exact                          GMP rationals for a whole frame with its bounces (the normal is
//                                  not normalized, so nothing is irrational); the frame's points are
//                                  then rounded to doubles, each checked as robust checks its own.
//
// Conventions shared by every kernel
// - Touching is a collision: a point on a circle, on a rectangle's edge or corner, rectangles sharing
//   an edge or a corner, and a leg ending exactly on a wall all collide. A radius-0 circle and a
//   zero-size rectangle behave as the point they are.
// - A frame's leg is the straight segment between two doubles: Bs and Be = Bs + v as C++ computes it
//   (the double nearest to Bs + v). After a bounce at B_i the rest of the frame is the leg from B_i
//   to B_i + (1 − t_i)·v'.
// - A zero-length wall has no normal and is never hit. A zero velocity does no sweep.
// - A ball lying on a wall's line and moving off it does not hit that wall ("leaving").
// - Corners: when several walls are met at the same point, the lowest-indexed one is reported as the
//   hit; v is reflected about it and then about each other wall met there whose outside the new
//   velocity would still cross into; if some wall is still crossed, v' = −v (straight back).
// - At most k_max_bounces bounces a frame; past that the ball stays where it is, a safe point.
//
// No tunnelling (robust and exact guarantee it; tunnel.hpp checks it exactly). A ball's path is the
// polyline of its printed points: start, hit points, end, frame after frame. It tunnels through a
// wall if a piece of the path goes from one open side of the wall's line to the other through the
// closed segment, or if the path arrives on the closed segment from one side and its next piece
// leaves it to the other side, even after sliding along the wall's line on the segment in between.
// A ball that starts on a wall, or reached the segment by sliding along its line from beyond an end,
// may leave it to either side.
//
// Accepted range: every coordinate, radius and velocity component finite with magnitude at most
// k_coordinate_limit (2^256 ≈ 1.2e77), and every ball position staying in that range. Predicates are
// exact for every finite double; the range keeps constructions (t_i, B_i, v') free of overflow.
// Robust error bounds, inside the range: t_i and B_i are within a few ulps of the exact crossing of
// the leg for well-conditioned hits (|n̂·d| not tiny against |d|); v' satisfies
// | |v'| − |v| | ≤ k_speed_rel_bound·|v| + k_speed_abs_bound (2^-48 and 2^-1068) per bounce.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "ricochet/line.hpp"
#include "ricochet/shapes.hpp"

namespace ricochet {

/// The four kernels.
enum class KernelId : std::uint8_t { lecture_float, lecture_double, robust, exact };
/// Every kernel, in a fixed order.
inline constexpr std::array<KernelId, 4> k_all_kernels = {KernelId::lecture_float, KernelId::lecture_double,
                                                           KernelId::robust, KernelId::exact};
/// The kernel's name as scene logs and --kernel spell it ("lecture-float", …, "robust", "exact").
std::string_view kernel_name(KernelId k);
/// The kernel called name, or nothing if there is none.
std::optional<KernelId> parse_kernel(std::string_view name);

/// Largest accepted magnitude of any coordinate, radius or velocity component.
inline constexpr double k_coordinate_limit = 0x1p256;
/// Most bounces one ball makes in one frame.
inline constexpr int k_max_bounces = 16;
/// Robust and exact: bound on the relative change of |v| per bounce (the rounded reflection).
/// Robust computes v' = v − 2(v·n̂)n̂ with n̂ = m/|m|, m = n scaled by a power of two (exact): |m| is off by
/// ≤ 2ε, n̂ by ≤ 2ε per component, so |n̂|² = 1 ± 6ε; v·n̂ is off by ≤ 4ε|v|, 2(v·n̂)n̂ by ≤ 7ε|v|, the
/// subtraction adds ε per component. Reflecting about n̂ itself changes |v|² by 4(v·n̂)²(|n̂|² − 1).
/// In all ≤ 20ε < 32ε = 2^-48 (ε = 2^-53). Exact rounds each component once (ε). Measured worst over
/// 2·10^6 random reflections at scales 2^±60: see core/tests/frame_test.cpp (SpeedBoundHolds).
inline constexpr double k_speed_rel_bound = 0x1p-48;
/// Robust and exact: absolute part of that bound per bounce, for velocities so small that the rounding
/// is subnormal (each operation then errs by up to 2^-1075 absolutely, not relatively): 2^-1068.
inline constexpr double k_speed_abs_bound = 0x1p-1068;

/// True if x is finite and |x| ≤ k_coordinate_limit.
bool in_range(double x);

/// Why a leg does not hit a wall: the lecture's five tests in order, then the degenerate cases.
enum class Miss : std::uint8_t {
    none,           ///< it hits
    both_inside,    ///< test 1: BC(Bs) < 0 and BC(Be) < 0
    both_outside,   ///< test 2: BC(Bs) > 0 and BC(Be) > 0
    parallel,       ///< test 3: n̂·v = 0
    before_p0,      ///< test 4: the hit point lies before P0
    past_p1,        ///< test 5: the hit point lies past P1
    degenerate,     ///< zero-length wall or zero velocity
    leaving,        ///< Bs is on the wall's line and the ball moves off it
};
/// A short name for a Miss ("hit", "both-inside", …).
std::string_view miss_name(Miss m);

/// The answer to one leg against one wall.
struct Sweep {
    Miss miss = Miss::degenerate;
    double t = 0.0;  ///< t_i in [0, 1] when it hits
    Vec2 point;      ///< B_i when it hits
    bool hit() const { return miss == Miss::none; }
};

/// Classifies p against w's line: Outside, Inside or On (the sign of BC).
Side classify(KernelId k, Vec2 p, const Wall& w);
/// Point/circle: |CP| ≤ R.
bool point_in_circle(KernelId k, Vec2 p, const Circle& c);
/// Circle/circle: |cA − cB|² ≤ (rA + rB)², no square root.
bool circles_overlap(KernelId k, const Circle& a, const Circle& b);
/// Point/rectangle: left ≤ x ≤ right and bottom ≤ y ≤ top.
bool point_in_rect(KernelId k, Vec2 p, const Rect& r);
/// Rectangle/rectangle: neither lies wholly left, right, below or above the other.
bool rects_overlap(KernelId k, const Rect& a, const Rect& b);
/// One ball B(t) = Bs + v·t, t in [0, 1], against one wall: the five tests, t_i and B_i.
Sweep sweep(KernelId k, Vec2 bs, Vec2 v, const Wall& w);
/// The lecture's bounce: v' = v − 2(v·n̂)n̂ (kernel precision; exact rounds the rational result).
Vec2 reflect(KernelId k, Vec2 v, const Wall& w);

/// A wall the ball is lying on, and the side it arrived from (±1).
struct Contact {
    std::uint32_t wall = 0;
    std::int8_t side = 0;
};
/// What a kernel remembers of a ball between frames: the walls it lies on and where it came from.
struct BallMemory {
    std::array<Contact, 4> contacts{};
    std::uint8_t count = 0;
    /// The last wall bounced off and the side (±1) it was met from; 0: none yet. Moving straight on
    /// from a bounce the ball stays in that side's half-plane, so until its next bounce no printed point
    /// may lie on that wall's far side, even beyond the wall's ends.
    std::int8_t bounced_from = 0;
    std::uint32_t bounced_wall = 0;
};

/// A bounce during a frame: the wall, the frame time t_i and the point B_i.
struct HitEvent {
    std::uint32_t wall = 0;
    double t = 0.0;
    Vec2 point;
};

/// Answers "which walls may touch the segment a → b?" faster than trying them all.
class WallIndex {
public:
    virtual ~WallIndex() = default;
    /// Appends to out every wall whose closed segment may meet the closed segment a → b (a superset
    /// is fine, each wall at most once, any order).
    virtual void query(Vec2 a, Vec2 b, std::vector<std::uint32_t>& out) const = 0;
};

/// How a frame ended for one ball.
enum class FrameStatus : std::uint8_t {
    ok,            ///< the ball finished its frame
    bounce_limit,  ///< k_max_bounces reached: the ball stays at its last safe point
    out_of_range,  ///< a position or velocity left the accepted range: the ball did not move
};

struct StepTrace;  // step_trace.hpp

/// Scratch space reused across calls to step_ball (keeps the hot loop free of allocation).
struct StepScratch {
    std::vector<std::uint32_t> candidates;
    std::vector<std::uint32_t> touching;
    std::vector<std::uint32_t> all_walls;  ///< 0, 1, …, n − 1: every wall, when there is no index
    /// If set, step_ball fills it with the frame's legs, decisions and reflections (appending; the caller
    /// clears it). Unset, a step pays one null test per leg and per reflection.
    StepTrace* trace = nullptr;
};

/// Steps one ball through one frame among walls: earliest hit, bounce, search again from the hit
/// point for the rest of the frame. Appends the frame's hits to hits. With an index, only the walls it
/// returns are tried (the exact kernel always tries every wall).
FrameStatus step_ball(KernelId k, Ball& ball, BallMemory& memory, std::span<const Wall> walls,
                      std::vector<HitEvent>& hits, StepScratch& scratch, const WallIndex* index = nullptr);

}  // namespace ricochet
