// Kernels: four numeric implementations of the lecture's collision tests behind one interface,
// chosen by name at run time. Each is a type with the functions of KernelOps, entered once in the
// kernel registry under its name (below); a plug-in kernel joins the same registry.
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
//   velocity would still cross into; if some wall is still crossed, v' = −v (straight back). The lecture
//   kernels have no such rule (the lecture has none): they reflect about the reported wall only.
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
// the leg for well-conditioned hits (|n̂·d| not tiny against |d|; the `accuracy` check of checks.hpp
// makes both precise: 256·ε·M for B_i when |e × d| ≥ |e|∞·|d|∞/4); v' satisfies
// | |v'| − |v| | ≤ k_speed_rel_bound·|v| + k_speed_abs_bound (2^-48 and 2^-1068) per bounce.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "ricochet/ball_memory.hpp"
#include "ricochet/kernel_id.hpp"
#include "ricochet/limits.hpp"
#include "ricochet/line.hpp"
#include "ricochet/shapes.hpp"
#include "ricochet/step.hpp"
#include "ricochet/sweep.hpp"
#include "ricochet/wall_index.hpp"

namespace ricochet {

/// What a ball is stepped among when it has a radius or the scene has bumpers (step_disc below).
struct Obstacles {
    std::span<const Wall> walls;
    std::span<const Bumper> bumpers;
    const WallIndex* index = nullptr;  ///< over the walls, or null: every wall is tried
    /// Over the bumpers' centres, each a zero-length wall (bumper i is wall i), or null: every bumper is tried.
    /// A bumper within R of a leg has its centre within R + bumper_reach of it.
    const WallIndex* bumper_index = nullptr;
    double bumper_reach = 0.0;  ///< the largest bumper radius (with bumper_index)
    /// The scene's balls are solid to each other (`balls collide`): every ball, a point ball among walls alone too,
    /// is stepped by step_disc, whose paths the meets are searched on (meet.hpp).
    bool balls_meet = false;
};

/// How a kernel steps balls that meet (`balls collide`, docs/scene-log.md "Balls that meet").
enum class MeetRule : std::uint8_t {
    none,         ///< it does not: World refuses a scene with `balls collide`
    end_of_frame, ///< the lecture's static circle/circle test at the frame's end, then push apart (meet_at_end)
    swept,        ///< in exact time order on the balls' paths, every decision exact (meet.hpp), v′ from respond
};

/// A scene a kernel cannot step (a disc or a bumper for a kernel that steps point balls among walls only): World
/// and run_checked refuse it with this, before stepping anything. The only exception the core throws on a well-formed scene.
class UnsupportedScene : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

/// One kernel's implementation: the same functions as the free functions below, without the KernelId.
/// The registry holds one of these per kernel; it is the only place a kernel's name or id maps to code.
struct KernelOps {
    std::string_view name;  ///< as scene logs and --kernel spell it
    Side (*classify)(Vec2 p, const Wall& w);
    bool (*point_in_circle)(Vec2 p, const Circle& c);
    bool (*circles_overlap)(const Circle& a, const Circle& b);
    bool (*point_in_rect)(Vec2 p, const Rect& r);
    bool (*rects_overlap)(const Rect& a, const Rect& b);
    Sweep (*sweep)(Vec2 bs, Vec2 v, const Wall& w);
    Vec2 (*reflect)(Vec2 v, const Wall& w);
    FrameStatus (*step_ball)(Ball& ball, BallMemory& memory, std::span<const Wall> walls, std::vector<HitEvent>& hits,
                             StepScratch& scratch, const WallIndex* index);
    /// Steps a disc (a ball of radius > 0) among walls and bumpers, or a point ball in a scene with bumpers; a
    /// hit off a bumper is a HitEvent with bumper set. A point ball among walls alone always goes to step_ball,
    /// so that it keeps its bits. Null for a kernel that steps point balls among walls only (the peers, plug-ins
    /// without plugin.h's sweep_disc): World refuses a scene with discs or bumpers for it. A kernel type gives it
    /// as K::step_disc.
    FrameStatus (*step_disc)(Ball& ball, BallMemory& memory, const Obstacles& obstacles, std::vector<HitEvent>& hits,
                             StepScratch& scratch) = nullptr;
    /// True if step_disc also handles bumpers (K::k_steps_bumpers); false: discs among walls only.
    bool steps_bumpers = false;
    /// The kernel's stated bound on | |v′| − |v| | per reflection: speed_rel_bound·|v| + speed_abs_bound
    /// (the `speed` check, checks.hpp). A kernel type states it as K::k_speed_rel_bound and
    /// K::k_speed_abs_bound; one that states none is held to robust's (limits.hpp).
    double speed_rel_bound = k_speed_rel_bound;
    double speed_abs_bound = k_speed_abs_bound;
    /// True for a kernel whose failures are documented weaknesses rather than bugs to fix: the lecture
    /// baselines and the peers (Box2D, Chipmunk: shown, not fixed, here). Their failure logs carry `expect
    /// failure` (failure_log.hpp), so replay passes while the failure reproduces, and a campaign that meets a
    /// saved one again exits 0. A kernel type says so with K::k_failures_documented = true; the default,
    /// false, is for kernels held to the guarantees: robust, exact and the user's own (plug-ins), whose saved
    /// failures are regressions that fail until fixed.
    bool failures_documented = false;
    /// How the kernel steps balls that meet; K::k_meet_rule, with K::respond (swept) or K::meet_at_end (end_of_frame).
    MeetRule meet_rule = MeetRule::none;
    /// swept: the elastic response at the printed centres a.pos, b.pos, masses ma, mb (docs/scene-log.md, "Balls
    /// that meet", 5): sets a.vel and b.vel and returns true, or returns false and changes nothing where the
    /// centres do not approach.
    bool (*respond)(Ball& a, Ball& b, double ma, double mb) = nullptr;
    /// end_of_frame: the lecture's static test |B_a − B_b|² ≤ (R_a + R_b)² in the kernel's precision; where the
    /// balls overlap and approach, pushes them apart to R_a + R_b along the line of centres, sets the response's
    /// velocities and returns true; else returns false and changes nothing.
    bool (*meet_at_end)(Ball& a, Ball& b, double ma, double mb) = nullptr;
};

/// A kernel type: static member functions with exactly KernelOps's signatures (one of each, no overloads).
template <class K>
concept Kernel = requires {
    KernelOps{std::string_view{}, &K::classify,      &K::point_in_circle, &K::circles_overlap, &K::point_in_rect,
              &K::rects_overlap,  &K::sweep,         &K::reflect,         &K::step_ball};
};

/// The registry entry of kernel type K, called name.
template <Kernel K>
constexpr KernelOps make_kernel_ops(std::string_view name) {
    KernelOps ops{name, &K::classify, &K::point_in_circle, &K::circles_overlap, &K::point_in_rect,
                  &K::rects_overlap, &K::sweep, &K::reflect, &K::step_ball};
    if constexpr (requires { K::k_speed_rel_bound; K::k_speed_abs_bound; }) {
        ops.speed_rel_bound = K::k_speed_rel_bound;
        ops.speed_abs_bound = K::k_speed_abs_bound;
    }
    if constexpr (requires { K::k_failures_documented; }) ops.failures_documented = K::k_failures_documented;
    if constexpr (requires { &K::step_disc; }) ops.step_disc = &K::step_disc;
    if constexpr (requires { K::k_steps_bumpers; }) ops.steps_bumpers = K::k_steps_bumpers;
    if constexpr (requires { K::k_meet_rule; }) ops.meet_rule = K::k_meet_rule;
    if constexpr (requires { &K::respond; }) ops.respond = &K::respond;
    if constexpr (requires { &K::meet_at_end; }) ops.meet_at_end = &K::meet_at_end;
    return ops;
}

/// Room in the registry: the four built-in kernels and up to twelve registered ones. A fixed table keeps
/// every entry where it is, so a KernelOps reference stays valid while kernels join.
inline constexpr std::size_t k_max_kernels = 16;

/// A plug-in kernel joins the registry here, by name, without editing any dispatch: write a type with
/// KernelOps's static functions (the Kernel concept checks them), then at start-up, before any thread
/// steps a scene (registration is not synchronized), call
///     register_kernel(make_kernel_ops<MyKernel>("my-kernel"));
/// From then on parse_kernel("my-kernel") finds it, kernel_name and kernel_names() spell it, every free
/// function below dispatches to it, and scene logs may name it. Returns its id, or nothing if the name is
/// taken or the registry is full. The name must outlive every use of the registry (a literal is fine).
std::optional<KernelId> register_kernel(const KernelOps& ops);
/// A kernel this build knows by name but was built without (a peer whose library was not found at build
/// time): parse_kernel still finds nothing, and absent_kernel_message (kernel_id.hpp) says why wherever the
/// name is refused. Returns false if the name is registered or noted already, or the table is full. Both
/// strings must outlive every use of the registry (literals are fine).
bool note_absent_kernel(std::string_view name, std::string_view why);
/// The implementation of kernel k. k must be registered (every KernelId parse_kernel returns is).
const KernelOps& kernel_ops(KernelId k);
/// Every registered kernel, in id order: k_all_kernels first, then the plug-ins in the order they joined.
std::span<const KernelId> registered_kernels();

/// Classifies p against w's line: outside, inside or on (the sign of BC).
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

/// Why kernel k cannot step these balls among walls and `bumpers` bumpers ("kernel 'box2d' steps point balls
/// only: ball 0 has radius 0.5"), or nothing if it can.
std::optional<std::string> unsupported_scene(KernelId k, std::span<const Ball> balls, std::size_t bumpers);
/// The same, for a scene whose balls meet (`balls collide`): also "kernel 'box2d' does not step balls that meet
/// ('balls collide')" when the kernel has no MeetRule.
std::optional<std::string> unsupported_scene(KernelId k, std::span<const Ball> balls, std::size_t bumpers,
                                             bool balls_meet);

/// Steps one ball through one frame among walls and bumpers: a point ball with no bumpers exactly as step_ball
/// below (the same bits), anything else with the kernel's step_disc. Throws UnsupportedScene if the kernel
/// cannot (unsupported_scene). The ball keeps its radius; out of range as step_ball below.
FrameStatus step_ball(KernelId k, Ball& ball, BallMemory& memory, const Obstacles& obstacles,
                      std::vector<HitEvent>& hits, StepScratch& scratch);

/// Steps one ball through one frame among walls: earliest hit, bounce, search again from the hit
/// point for the rest of the frame. Appends the frame's hits to hits. With an index, only the walls it
/// returns are tried (the exact kernel always tries every wall). A frame that would leave the accepted
/// range changes nothing (ball, memory and hits stay as they were) and returns out_of_range.
FrameStatus step_ball(KernelId k, Ball& ball, BallMemory& memory, std::span<const Wall> walls,
                      std::vector<HitEvent>& hits, StepScratch& scratch, const WallIndex* index = nullptr);

}  // namespace ricochet
