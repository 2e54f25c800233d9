// Truth: ground truth for the checks, computed apart from every kernel. Kept independent on purpose
// (N-version): its own floating-point filter and GMP fallback, sharing no code with predicates.hpp,
// path.hpp or any kernel, so a bug there cannot hide itself here. Do not deduplicate it into them.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "ricochet/kernel.hpp"
#include "ricochet/meet.hpp"

namespace ricochet::truth {

/// sign((b − a) × (c − a)), exact for every finite double (own filter, GMP when it cannot decide).
int orient(Vec2 a, Vec2 b, Vec2 c);
/// sign of BC = n·(p − P0), n = (e_y, −e_x): +1 outside, −1 inside, 0 on; equals −orient(P0, P1, p).
int side(Vec2 p, const Wall& w);
/// sign(n·d) for a direction d: the side d points to.
int direction_side(Vec2 d, const Wall& w);
/// True if p lies on w's closed segment (on its line and within its bounding box), exactly.
bool on_closed_segment(Vec2 p, const Wall& w);
/// Where p lies against the region the walls enclose (even-odd rule, exact): +1 strictly inside, 0 on a
/// wall, −1 strictly outside. Wall directions do not matter.
int locate(Vec2 p, std::span<const Wall> walls);
/// True if every wall end point is the end point of an even number of wall ends (counting each
/// non-zero-length wall's two ends): the walls form closed chains, so locate's region is bounded by them.
bool walls_closed(std::span<const Wall> walls);

/// sign(|p − c|² − r²), exactly (GMP): −1 inside, 0 on, +1 outside.
int circle_side(Vec2 p, const Circle& c);
/// |p − c|² ≤ r², exactly (GMP).
bool point_in_circle(Vec2 p, const Circle& c);
/// |cA − cB|² ≤ (rA + rB)², exactly (GMP).
bool circles_overlap(const Circle& a, const Circle& b);
/// left ≤ x ≤ right and bottom ≤ y ≤ top (comparisons of doubles are exact).
bool point_in_rect(Vec2 p, const Rect& r);
/// Closed rectangles intersect.
bool rects_overlap(const Rect& a, const Rect& b);

/// | |w| − |v| | ≤ ((1 + b)^m − 1)·|v| + m·a, decided exactly except for |v| itself, which is irrational in
/// general: it is bracketed by a 256-bit square root widened by 2^−200 relative (the only rounding).
/// False when any of v, w, b, a has a non-finite component. The other functions take finite doubles only.
bool speed_within(Vec2 v, Vec2 w, int m, double b, double a);
/// The closed segment a → b (a point if a = b) stays at least R from wall w's closed segment (a point if w has
/// no length): the least distance between the two, exactly, against R (the `penetration` check). R = 0 holds
/// whatever the segments do.
bool clear_of_wall(Vec2 a, Vec2 b, const Wall& w, double R);
/// The closed segment a → b stays at least R + r from c (a bumper of radius r met by a ball of radius R),
/// exactly, with R + r not rounded.
bool clear_of_circle(Vec2 a, Vec2 b, Vec2 c, double R, double r);

/// sign(|p − X|² − R²) for X the point of wall w's closed segment (a point if w has no length) nearest to p,
/// exactly: −1 within reach of a disc of radius R centred at p, 0 touching, +1 clear (the `boundary` check).
int wall_reach_side(Vec2 p, const Wall& w, double R);
/// sign((b − a)·(a − X)), X the point of w's segment nearest to a: −1 if the leg a → b starts by taking a closer
/// to the segment (the derivative of |a − X|² along the leg), exactly; 0 if a lies on the segment (no normal), the
/// leg has no length or runs parallel to the segment there.
int wall_approach_sign(Vec2 a, Vec2 b, const Wall& w);
/// sign(|p − c|² − (R + r)²), exactly, with R + r not rounded: a disc of radius R at p against a bumper (c, r).
int circle_reach_side(Vec2 p, Vec2 c, double R, double r);
/// sign((b − a)·(a − c)), exactly: −1 if the leg a → b starts by taking a closer to c; 0 at c itself.
int circle_approach_sign(Vec2 a, Vec2 b, Vec2 c);
/// True if the foot of p on w's line lies on the closed segment, 0 ≤ (p − P0)·e ≤ e·e, exactly; false for a wall
/// of no length. A disc touching w there touches its face (or the face's end, where face and cap share a normal).
bool projects_onto_segment(Vec2 p, const Wall& w);

/// The leg a → b runs parallel to the line through w's end points (w of non-zero length), at least R from it,
/// exactly: n·(b − a) = 0 and (n·(a − P0))² ≥ R²·(n·n), n = (e_y, −e_x), e = P1 − P0 (the `ghost-bounce` check).
bool parallel_clear_of_line(Vec2 a, Vec2 b, const Wall& w, double R);

/// sign(a × b) of two directions, exactly.
int cross_sign(Vec2 a, Vec2 b);
/// sign(a · b), exactly.
int dot_sign(Vec2 a, Vec2 b);
/// True if a + b is computed exactly in double.
bool sum_exact(double a, double b);

/// The exact decision for the leg a → b against w, by kernel.hpp's conventions: degenerate (zero-length
/// wall or a = b), both inside, both outside, parallel (both on the line), leaving (a on the line),
/// before P0 / past P1 (the leg's line meets the wall's line outside the closed segment), else a hit.
Miss leg_miss(Vec2 a, Vec2 b, const Wall& w);
/// The first wall the leg a → b hits (the earliest exact crossing, the lowest index on a tie), or −1.
long first_hit(Vec2 a, Vec2 b, std::span<const Wall> walls);

/// A disc's contact on a leg (the disc `oracle` check), by the rules of docs/scene-log.md "Discs and bumpers": a
/// contact is an entry (the centre's distance to the obstacle reaches ρ = R, or R + r for a bumper, while
/// decreasing; a tangent is none); a leg starting within ρ meets the obstacle at t = 0 if it starts by moving
/// closer, else not at all; a start on the wall's segment or at the bumper's centre has no normal and meets
/// nothing. A wall's reach is its capsule: the face (the band within R of its line, the foot on the segment) and
/// the caps (|X − P_k| = R); a zero-length wall has its cap only. Computed apart from the kernels (truth_discs.cpp).
struct DiscContact {
    enum class Obstacle : std::uint8_t { none, wall, bumper };
    enum class Part : std::uint8_t { face, cap0, cap1, circle };
    Obstacle obstacle = Obstacle::none;
    std::uint32_t index = 0;   ///< the wall or the bumper
    Part part = Part::face;    ///< where the entry is (at t = 0: the part of the segment nearest the start)
    bool at_start = false;     ///< t = 0 by the start-in-reach rule
};
/// True if the leg a → b of a ball of radius R ≥ 0 has a contact with wall w, exactly.
bool disc_meets_wall(Vec2 a, Vec2 b, double R, const Wall& w);
/// The first contact of the leg a → b of a ball of radius R ≥ 0 among the walls and bumpers: the earliest exact
/// entry time (contact times compared exactly, as numbers (A − √C)/D, no square root rounded); ties to the lowest
/// wall, then the lowest bumper; on one wall the face, then cap P0, then cap P1. skip_wall, skip_bumper: one
/// obstacle the kernel's own rule leaves out (lecture: the one just bounced off), or −1.
DiscContact disc_first_contact(Vec2 a, Vec2 b, double R, std::span<const Wall> walls, std::span<const Bumper> bumpers,
                               long skip_wall = -1, long skip_bumper = -1);
/// True if a disc of radius R centred at p overlaps (or touches) the sensor circle c: |p − c| ≤ R + r, exactly.
bool disc_in_circle(Vec2 p, double R, const Circle& c);
/// True if a disc of radius R centred at p overlaps (or touches) the closed rect r, exactly.
bool disc_in_rect(Vec2 p, double R, const Rect& r);

/// How close a hit point is to the exact crossing (the `accuracy` check, checks.hpp).
struct HitAccuracy {
    /// |e × d| ≥ |e|∞·|d|∞ / 4 (e = P1 − P0, d = b − a: the leg crosses the line at an angle that is not
    /// grazing) and |e|∞, |d|∞ ≥ 2^−400 (no product of the construction underflows), all exactly.
    bool conditioned = false;
    /// |p − X| ≤ ulps·ε·M in each coordinate, exactly, where X = a + s·d with s = BC(a) / (BC(a) − BC(b))
    /// is the exact crossing of the leg's line with the wall's, ε = 2^−53 and M the largest magnitude of the
    /// coordinates of a, b, P0 and P1. Only meaningful when conditioned.
    bool within = false;
    /// max |p − X| per coordinate in units of ε·M, rounded (for messages).
    double error = 0.0;
};
/// The hit point p of the leg a → b on w against the exact crossing, with the bound ulps·ε·M. kept, if not
/// null, is the wall the ball last bounced off, met from side kept_from (BallMemory): the bounce-side rule
/// keeps every printed point off that line's side −kept_from, so a crossing that does not lie strictly on
/// side kept_from may be out of the ball's reach, and the hit is not conditioned.
HitAccuracy hit_accuracy(Vec2 a, Vec2 b, const Wall& w, Vec2 p, double ulps, const Wall* kept = nullptr,
                         int kept_from = 0);
/// The hit time t (the leg fraction a kernel put the crossing at) of the leg a → b on w: conditioned as
/// above, and within when |t − s|·|d|∞ ≤ ulps·ε·M (the error of t_i measured as the distance it moves the
/// point along the leg). No bounce-side exemption: t_i is the crossing's, whatever point is printed.
HitAccuracy hit_time_accuracy(Vec2 a, Vec2 b, const Wall& w, double t, double ulps);
/// The bounce off w of a ball moving v that leaves with v_out, against the exact reflection
/// R = v − 2(v·n)n/(n·n), n = (e_y, −e_x): conditioned when |v·n| ≥ |v|∞·|n|∞ / 4 (not grazing, so the
/// reflection points back clearly) and w has a length; within when every component of v_out − R is at most
/// 2·(rel·|v| + abs) (the speed bound of one reflection, per component as the kernel's error terms carry
/// over), decided exactly. error: max |v_out − R| per component over |v|, for messages.
HitAccuracy bounce_accuracy(Vec2 v, const Wall& w, Vec2 v_out, double rel, double abs);
/// The corner rule (kernel.hpp) for a ball moving v that hits wall `hit`, met from side hit_from, at a point
/// on the closed segments of the walls `others` too (index order), each met from the non-zero side in
/// others_from: R is the exact reflection of v about `hit`, then about each other wall whose outside R would
/// still cross into (n_c·R of sign −from_c), in order; if some wall (`hit` included) is still crossed, or R
/// does not point strictly back to hit_from's side, the rule goes straight back, −v. conditioned when every
/// wall has a length and each of those decisions is clear: |R·n_c| ≥ |R|∞·|n_c|∞ / 4 for every wall c at
/// every step, and |v·n| ≥ |v|∞·|n|∞ / 4 for the hit; within when v_out = −v exactly where the rule goes
/// straight back, else every component of v_out − R is at most 3m·(2·rel·|v| + abs), m the reflections
/// (each rounded reflection errs by at most 2·(rel·|w| + abs) per component, √2 more in length, carried
/// unchanged by the next reflection, an isometry; |w| ≤ 2|v| along the way). error: max |v_out − R| / |v|.
HitAccuracy corner_accuracy(Vec2 v, const Wall& hit, int hit_from, std::span<const Wall> others,
                            std::span<const int> others_from, Vec2 v_out, double rel, double abs);
/// What a kernel took as a disc leg's first contact (from its trace and the frame's events): the obstacle, the leg
/// fraction t_i it put the contact at and the printed contact point p.
struct DiscTaken {
    bool bumper = false;      ///< a bumper, else a wall
    std::uint32_t index = 0;  ///< its index among the scene's walls or bumpers
    double t = 0.0;
    Vec2 p;
};
/// How close a disc's contact is to the exact one (the `accuracy` check for discs, checks.hpp).
struct DiscAccuracy {
    /// The obstacle taken is the leg's exact first contact (else that is `oracle`'s failure, and nothing here is
    /// measured).
    bool taken_first = false;
    /// Another obstacle is met at the same exact time (the corner rule's case).
    bool tied = false;
    /// |t_i − t*|·|d|∞ against ulps·ε·M, t* the exact entry time (A − √C)/D, ε = 2^−53, M the largest magnitude of
    /// the coordinates of a and b, R, and the obstacle's coordinates (and radius). conditioned: a contact at the
    /// leg's start (t* = 0, exactly); a face entered at a sine of at least 1/4 (|n·d| ≥ |e|∞·|d|∞/4); a cap or a
    /// bumper entered at a cosine to its normal of at least 1/4 (16·Δ ≥ (d·d)·ρ²); and |d|∞, |e|∞, ρ ≥ 2^−400.
    HitAccuracy time;
    /// |p − X*| per coordinate against ulps·ε·M, X* = a + t*·d, all exactly. conditioned as time, and unless the
    /// printed piece a → p comes within ρ + 2·ulps·ε·M of another obstacle (ρ = R, or R + r for a bumper): the walk
    /// back that keeps every printed piece clear (frame.cpp) may take the point further than rounding there.
    HitAccuracy point;
};
/// A disc's contact taken on the leg a → b (radius R ≥ 0) against the exact first contact, with the bound
/// ulps·ε·M. skip_wall, skip_bumper: as for disc_first_contact.
DiscAccuracy disc_accuracy(Vec2 a, Vec2 b, double R, std::span<const Wall> walls, std::span<const Bumper> bumpers,
                           long skip_wall, long skip_bumper, const DiscTaken& taken, double ulps);
/// The bounce at the printed contact point x of a disc moving v off wall w or bumper u (one of them set) that leaves
/// with v_out, against the exact reflection about the outward normal at x, N = x − X (X the segment's point
/// nearest x, or the bumper's centre): as bounce_accuracy with n = N, conditioned where v goes into the obstacle at
/// x clearly, v·N ≤ −|v|∞·|N|∞/4 (not where x lies on the segment or at the centre: no normal; nor where a point
/// rounded past a small cap has v leaving it already).
HitAccuracy disc_bounce_accuracy(Vec2 v, Vec2 x, const Wall* w, const Bumper* u, Vec2 v_out, double rel, double abs);
/// The end `to` of a leg that starts at `from` and spends the rest of the frame moving v, after hits at the
/// leg fractions ts (kernel.hpp: after a bounce at B_i the rest of the frame is the leg from B_i to
/// B_i + (1 − t_i)·v′), against from + R·v with R = Π(1 − t_k), exactly. Always conditioned; within when
/// every component of to − (from + R·v) is at most (2k + 3)·ε·M + 2^−1072, k = ts.size(), ε = 2^−53 and
/// M = max(|from|∞, |to|∞, |R·v|∞): R rounded twice per hit (1 − t, then the product), R·v and the sum once
/// each, and the underflow of those roundings. error: max |to − (from + R·v)| per component in units of ε·M.
HitAccuracy leg_end_accuracy(Vec2 from, Vec2 v, std::span<const double> ts, Vec2 to);

/// Two balls over a common time interval of their paths (`pass-through`): ball a on the piece a0 → a1, ball b on
/// b0 → b1 (printed points with their frame times, each piece of positive duration, moving uniformly), over
/// [lo, hi] = [max(a0.t, b0.t), min(a1.t, b1.t)] (lo < hi). There D(lo + u) = D + W·u, D = P_a(lo) − P_b(lo) and W the
/// difference of the pieces' velocities, and with S = Ra + Rb (not rounded), exactly:
struct PairClearance {
    int start = 1;  ///< sign(|D|² − S²): the distance at lo against S
    /// sign(min |D + W·u|² − S²) over u in [0, hi − lo]: at u* = −D·W/(W·W) where it lies inside, the minimum is
    /// (D × W)²/(W·W); else at an end.
    int least = 1;
};
PairClearance pieces_clearance(PathPoint a0, PathPoint a1, PathPoint b0, PathPoint b1, double Ra, double Rb);

/// A jump against a ball standing (`jump-through`): ball a moves from p0 to p1 at one frame time c (a piece of no
/// duration, its printed points at one time), ball b at c on its piece b0 → b1 (b0.t ≤ c ≤ b1.t; its exact point
/// there, or b0.p where b0.t = b1.t). With D = p0 − P_b(c) and W = p1 − p0, D + W·u over u in [0, 1], as above.
PairClearance jump_clearance(Vec2 p0, Vec2 p1, double c, PathPoint b0, PathPoint b1, double Ra, double Rb);

/// The frame's first meet by the swept rule (`oracle`; docs/scene-log.md "Balls that meet", 1–3), decided exactly
/// apart from core/src/kernels/meet/ (truth_meets.cpp). paths: each ball's path as stepped alone through the frame
/// (its printed points with their frame times, from t = 0 to t = 1, uniform motion between; pieces of zero duration
/// left out); radii: each ball's reach (R, or 0 for a point ball); pairs: the pairs i < j, sorted, whose paths may
/// come within S = R_i + R_j (every other pair never does). On each common interval [a, b] of two pieces, with
/// D_a = P_i(a) − P_j(a) and W the difference of the pieces' velocities, a meet is the smaller root a + u of
/// |D_a + W·u|² = S² with u in [0, b − a] while the distance decreases (a double root, a tangent, is none), or a
/// itself where the pair is within S there and D_a·W < 0; S is not rounded. The first meet is the earliest over the
/// pairs (times compared exactly as numbers (A − √C)/D), ties to the lowest pair.
struct FirstMeet {
    bool found = false;
    std::uint32_t i = 0, j = 0;  ///< the pair, i < j
    bool at_start = false;       ///< within S at an interval's start, approaching: t* is that start
    bool tied = false;           ///< a higher pair meets at the same exact time
    double approx = 0.0;         ///< t*, to about double precision (for messages)
    /// The time asked about (first_meet's `printed`) lies in [0, t°], t° the double nearest t* (ties to even; rule 4
    /// rounds t* so, then may only take it earlier), decided exactly: no square root rounded.
    bool printed_in_time = false;
};
FirstMeet first_meet(std::span<const std::vector<PathPoint>> paths, std::span<const double> radii,
                     std::span<const std::pair<std::uint32_t, std::uint32_t>> pairs, double printed);
/// sign((va − vb)·(pa − pb)), exactly: −1 where two balls at pa and pb moving va and vb approach (the lecture's
/// end-of-frame test, "Balls that meet").
int approach_sign(Vec2 pa, Vec2 va, Vec2 pb, Vec2 vb);

/// A meet's response against the laws it keeps (`momentum`): masses ma, mb arriving with va, vb, leaving with oa, ob;
/// p = ma·v_a + mb·v_b and E = ma·|v_a|² + mb·|v_b|² (twice the kinetic energy) before and after, exactly.
struct MeetConservation {
    /// |p′ − p| ≤ momentum_rel·(ma·|va|∞ + mb·|vb|∞ + ma·|oa|∞ + mb·|ob|∞) + momentum_abs·(ma + mb) in each
    /// component.
    bool momentum_within = false;
    /// |E′ − E| ≤ energy_rel·E + energy_abs·(ma + mb)·(|va|∞ + |vb|∞ + |oa|∞ + |ob|∞).
    bool energy_within = false;
    double momentum_error = 0.0;  ///< max |p′ − p| per component over the sum of the bound, rounded (for messages)
    double energy_error = 0.0;    ///< |E′ − E| / E, rounded (for messages)
};
/// False for both laws when a velocity or a mass is not finite.
MeetConservation meet_conservation(double ma, double mb, Vec2 va, Vec2 vb, Vec2 oa, Vec2 ob, double momentum_rel,
                                   double energy_rel, double momentum_abs = 0.0, double energy_abs = 0.0);

/// kernel.hpp's no-tunnelling definition, followed independently of ricochet::TunnelChecker: a piece
/// from one open side to the other through the closed segment, or arriving on the closed segment from
/// one side and leaving to the other, tunnels; after moving along the line either side is fine.
class PathFollower {
public:
    /// Starts every ball at its initial position.
    PathFollower(std::span<const Wall> walls, std::span<const Ball> balls);
    /// Ball i moves on to next; returns the lowest wall the piece tunnels through, or −1.
    long advance(std::size_t i, Vec2 next);

private:
    struct State {
        int last = 0;          // side of the last point off the line, 0 after moving along it
        bool touched = false;  // arrived on the closed segment since
    };
    std::vector<Wall> walls_;
    std::vector<Vec2> at_;
    std::vector<State> st_;
};

}  // namespace ricochet::truth
