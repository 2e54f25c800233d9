// The `check` invariants of scene logs, asserted frame by frame while a scene runs (run_checked).
// This is the one definition of each: replay, record, the property tests and the fuzz targets assert
// exactly these. "Printed state" is a `state` event (frame 0: the initial state); "exactly" and
// "truth" mean the independent exact oracle of truth.hpp; "the frame's legs" are the legs its kernel
// swept, as StepTrace reports them.
//
//   no-tunnel      Every ball's printed path (start, hit points, ends of frames), piece by piece, tunnels
//                  through no wall by kernel.hpp's definition, as TunnelChecker (tunnel.hpp) and,
//                  independently, truth::PathFollower follow it; either one finding a tunnel fails, at the
//                  frame of the piece, naming the lowest such wall.
//   symmetry       (a) The scene mirrored across x = 0 (mirror_x), stepped in lockstep by the same kernel,
//                  prints the same events with every x and vx negated, compared by value (−0 = +0).
//                  (b) Under M (x, y) ↦ (−x, y) and under R (x, y) ↦ (−y, x), applied to the ball, the shapes
//                  and the walls (walls keep their direction): for each printed state p, v and every wall,
//                  classify keeps its side (M: the opposite side); sweep(p, v) keeps its Miss (M: both-inside
//                  and both-outside exchanged), and a hit keeps t by value and maps its point; point_in_circle
//                  and point_in_rect of p keep their answers; at frame 0 circles_overlap and rects_overlap of
//                  every ordered pair of static shapes keep theirs.
//                  In a scene with a disc or a bumper, (a) becomes four images stepped in lockstep (mapped_run):
//                  the scene mirrored across x = 0, mirrored across y = 0, turned by R, and with its balls in
//                  reverse order (radii kept) each print, ball by ball, the run's events mapped (positions and
//                  velocities; ball i as its image), by value; (b) is asked of point balls only.
//   boundary       At each printed state p, v: the radius-0 circle and the zero-size rect at p hold exactly
//                  the frame's printed positions equal to p; for every circle C, point_in_circle(p, C) =
//                  circles_overlap({p, 0}, C) = point_in_circle(C.c, {p, C.r}); for every rect R,
//                  point_in_rect(p, R) = rects_overlap({p, p, p, p}, R); and if v ≠ 0, for every wall w with
//                  s = classify(p, w) and the sweep from p moving v: s = On gives neither test 1 nor test 2 and
//                  no hit, Inside never both-outside, Outside never both-inside, and a hit whose Be = p + v
//                  classifies On has t = 1 and point Be. For discs and among bumpers (the touching rule): a
//                  ball of radius R whose state before a frame, p, is at most R from a wall's closed segment
//                  (R > 0) or at most R + r from a bumper's centre (exactly: touching, or within reach) while
//                  its leg p → Be = p + v (as rounded) starts by moving closer (d·(p − X) < 0, X the nearest
//                  point of the segment or the centre, exactly; p on the segment or at the centre has no
//                  normal), makes a hit or a bump at p its first event of that frame. The state parts above
//                  are asked of point balls only.
//   speed          Per ball per frame, with m the reflections its kernel made in the frame (StepTrace:
//                  every reflect() call, hits, corner re-reflections and contact reflections without a hit;
//                  v′ = −v is exact and counts 0): | |v_end| − |v_start| | ≤ ((1 + b)^m − 1)·|v_start| + m·a,
//                  b and a the kernel's speed_bound. Decided exactly (truth::speed_within): the only rounding
//                  is |v_start| itself, a 256-bit square root widened by 2^−200 relative. And reflect(v_start, w)
//                  about every wall of non-zero length keeps to the bound with m = 1. A non-finite velocity
//                  (or v′) is outside every bound.
//   deterministic  A second World stepped in lockstep prints the same events, bit for bit, and so the same
//                  running hash; and that hash is XXH64 (seed 0) over the 56-byte records of the spec's table
//                  (docs/scene-log.md, hash.hpp), encoded by the check itself, independently of hash.cpp.
//   oracle         Every decision equals the exact one. At frame 0, circles_overlap and rects_overlap of
//                  every ordered pair of static shapes. At each printed state p: classify(p, w) for every
//                  wall, and the overlap events the frame printed for the ball are exactly the circles and
//                  rects holding p. For each frame's legs a → b, as the kernel swept them from its own
//                  (rounded) points and velocities (a leg with a non-finite end fails: it is not a
//                  segment): each per-wall Miss it decided equals truth's for a → b (a miss it gives no reason
//                  for, a plug-in's RICOCHET_MISS, only needs truth to miss too); every wall it did not
//                  try is exactly missed; the wall it took as the leg's first hit equals truth's first hit
//                  (the earliest exact crossing, the lowest index on a tie; a wall the kernel's own rule
//                  skips, lecture's wall just bounced off, left out); a leg it ended at a contact wall ends
//                  exactly on that wall's far side; the hits it took, in order, are the frame's hit events.
//                  The bounce limit as the spec states it: a frame makes at most 16 bounces (hits taken and
//                  reflections off contact walls); one that stops at the limit made exactly 16 and prints the
//                  ball at the last point of its path.
//                  And the frame's first hit equals the exact kernel's from the same state and memory (unless
//                  the exact kernel's frame leaves the accepted range). The exact kernel's legs are rational,
//                  so it has only the static parts; a kernel that steps whole frames itself and traces no legs
//                  (a plug-in's frame step, plugin.h) has the static parts and the frame's first hit.
//                  A ball the disc frame steps (radius R > 0, or any ball in a scene with bumpers): its printed
//                  states' overlaps are the sensors its disc touches (|p − c| ≤ R + r; the rect within R), and
//                  for each leg a → b it swept: its contact decision for each wall it tried equals
//                  truth::disc_meets_wall(a, b, R) (docs/scene-log.md's rules: an entry, tangents none, the
//                  start-in-reach rule, no normal on the segment); every wall it did not try has no contact; the
//                  obstacle it met first (a wall, or a bumper) is truth::disc_first_contact's (contact times
//                  compared exactly as (A − √C)/D; ties to the lowest wall, then bumpers; the obstacle the
//                  kernel's own rule skips left out); the contacts it took are the frame's hits and bumps in
//                  order; at most 16 a frame, as above; and the frame's first contact equals the exact kernel's
//                  from the same state. The exact kernel's disc legs are doubles (its contact points are
//                  rounded), so it is judged leg by leg too.
//                  In a scene whose balls collide, the frame's first meet (World::meets()'s first record) is
//                  judged against the exact one, the meet limit reached or not: under the swept rule (robust,
//                  exact) it is, on the paths the balls make alone (each stepped again from its state before the
//                  frame: its start at t = 0, each contact at its t_i, its end at t = 1), the earliest entry over
//                  every pair with S = R_i + R_j > 0 by rule 2 of "Balls that meet" (the smaller root of
//                  |D_a + W·u|² = S² on a common interval of pieces, a tangent none, a pair within S at the
//                  interval's start meeting there if D_a·W < 0; S not rounded; times compared exactly as
//                  (A − √C)/D), ties to the lowest (i, j); the printed meet is that pair at a time in [0, t°], t°
//                  the double nearest t*; and a frame prints a meet exactly where there is one
//                  (truth::first_meet). The lecture kernels' first meet is their own rule decided exactly: the
//                  lowest pair whose centres, each stepped alone to the frame's end, are within S at two points
//                  and approach ((v_i − v_j)·(B_i − B_j) < 0).
//   swap           circles_overlap(a, b) = circles_overlap(b, a) and rects_overlap likewise for every pair of
//                  static shapes (frame 0); for each printed state p, v and every wall w, the wall walked the
//                  other way gives p and Be = p + v the opposite side and the sweep from p the same hit or miss.
//                  In a scene with a disc or a bumper, also: the scene with every wall walked the other way,
//                  stepped in lockstep, meets per ball the same first obstacle (hit wall or bumped bumper) at
//                  frames 0 and 1 (a capsule has no direction; a contact point is a rounded construction that
//                  may round from either end); the per-state part is asked of point balls only.
//   translation    For each offset t of a fixed list ((1, −2), (1024, 4096), (−3·2^30, 2^31), (2^40, −5·2^40),
//                  (0.5, 0.25)) that moves every coordinate of the scene and every ball's Bs and Be = Bs + v
//                  without rounding (and (Bs + t) + v = Be + t), the moved scene stepped in lockstep prints
//                  the same overlaps (at frame 1 those of the balls that met nothing in it: a state after a
//                  contact is a rounded construction) and, per ball, the same first hit wall (the exact kernel:
//                  every hit wall) at frames 0 and 1; and at every frame, for each printed state p, v that t moves exactly,
//                  classify, the sweep's Miss, point_in_circle and point_in_rect are unchanged by moving p and
//                  the scene by t. In a scene with a disc or a bumper, bumpers move too, a bump counts as a
//                  contact (per ball, the first hit wall or bumped bumper, every kernel: the exact kernel rounds
//                  a disc's contact points), and the per-state part is asked of point balls only.
//   broad-phase    The scene stepped with no broad phase on one thread, and with the wall grid and static
//                  index on two threads, print the checked run's events bit for bit.
//   round-trip     At frame 0: the scene written as a log (write_scene_log) reads back (parse_scene_log) as
//                  the same scene bit for bit, and writing that again gives the same text.
//   no-escape      Where the walls form closed chains (every end point the end of an even number of walls,
//                  zero-length walls left out), a ball whose start is strictly inside the region they enclose
//                  (even-odd rule, exactly) prints no hit point or state strictly outside it, and one starting
//                  strictly outside none strictly inside. Other scenes pass.
//   bounce-side    After a ball hits a wall from side s (the side of its previous printed point; along the
//                  line, the side it last met that wall from), none of its printed points lies strictly on the
//                  wall's side −s until its next hit, that hit's point included (BallMemory, kernel.hpp).
//                  A ball the disc frame steps (a disc, or any ball in a scene with bumpers) is held to it
//                  after a face contact only, a hit whose point's foot on the wall's line lies on the closed
//                  segment (truth::projects_onto_segment), s the side of that hit point (else of the point it
//                  came from), and for its printed points whose foot lies on the segment too (beyond an end its
//                  path may pass around the wall); a cap has no side, so a hit elsewhere ends the rule, and so
//                  does a bump (a bumper has no side either).
//   accuracy       kernel.hpp's "t_i and B_i within a few ulps of the exact crossing for well-conditioned
//                  hits", made precise: for each leg a → b of the frame's legs that took a hit, with
//                  e = P1 − P0 of its wall and d = b − a, if |e × d| ≥ |e|∞·|d|∞ / 4 and |e|∞, |d|∞ ≥ 2^−400
//                  (exactly), then with s = BC(a) / (BC(a) − BC(b)) the exact crossing's leg fraction and
//                  the bound k_hit_accuracy_ulps·ε·M (256 · 2^−53 · M, M the largest magnitude of the
//                  coordinates of a, b, P0, P1): the kernel's t_i for the leg (the trace's; logs do not print
//                  it) has |t_i − s|·|d|∞ within the bound, and the printed hit point is within the bound of
//                  a + s·d in each coordinate, unless a + s·d does not lie strictly on the side the ball keeps
//                  of the wall it last bounced off (bounce-side puts it out of reach; t_i is still checked).
//                  And the bounce: for each such hit whose printed point lies on no other wall's closed
//                  segment (no corner rule applies) and whose velocity v meets the wall at |v·n| ≥
//                  |v|∞·|n|∞ / 4 (n = (e_y, −e_x), exactly), the velocity it leaves with (the next leg's, else
//                  the frame's end state's) is within 2·(b·|v| + a) of v − 2(v·n)n/(n·n) in each component,
//                  b and a the kernel's speed_bound, decided exactly.
//                  At a corner (the printed point on other walls' closed segments too, each met from a side):
//                  the velocity it leaves with follows kernel.hpp's corner rule, computed exactly (reflect
//                  about the wall hit, then about each other wall there, in index order, whose outside the
//                  new velocity would cross into; straight back if one is still crossed): −v exactly where
//                  the rule goes straight back, else within 3m·(2b·|v| + a) per component after m
//                  reflections, when each of the rule's decisions is clear (|w·n| ≥ |w|∞·|n|∞ / 4).
//                  And the rest of the frame: the frame's first leg starts at the ball's state before it, a
//                  leg after a hit at that hit's printed point, a leg after a reflection off a contact wall
//                  where that one started; each leg a → b moving v after hits at t_1 … t_k earlier in the
//                  frame ends within (2k + 3)·ε·M + 2^−1072 of a + R·v, R = Π(1 − t_j), in each coordinate
//                  (M the largest magnitude of a, b and R·v; truth::leg_end_accuracy), exactly.
//                  The same bound for every kernel: robust keeps it (its derivation is in promise_test.cpp),
//                  lecture-float does not (2^−24 rounding). The exact kernel's legs are rational, so it has
//                  none to check (its B_i is its exact crossing, rounded once); nor has a plug-in's frame step
//                  (plugin.h), which shows no legs.
//                  A ball the disc frame steps (a disc, or any ball among bumpers) is judged per contact, with the
//                  bound k_disc_accuracy_ulps·ε·M (M also counts R and a bumper's radius): for each leg that took
//                  a printed hit or bump on the leg's exact first contact, entered at t* = (A − √C)/D, if the
//                  contact is well-conditioned (a start in reach; a face at |n·d| ≥ |e|∞·|d|∞ / 4; a cap or bumper
//                  at 16·Δ ≥ (d·d)·ρ²; |d|∞, |e|∞, ρ ≥ 2^−400), |t_i − t*|·|d|∞ and the printed point's distance
//                  to a + t*·d in each coordinate are within the bound (the point not judged where the printed
//                  piece a → B_i comes within ρ + 2·bound of another obstacle: the walk back may go further);
//                  and where no other obstacle is met at the same time, with N = B_i − X the outward normal at
//                  the printed point (X the segment's point nearest it, or the bumper's centre) and v·N ≤
//                  −|v|∞·|N|∞ / 4, the velocity it leaves with is within 2·(b·|v| + a) of v − 2(v·N)N/(N·N) per
//                  component (truth::disc_accuracy, truth::disc_bounce_accuracy). The rest of the frame as above,
//                  a bump counting as a hit.
//   event-order    Every frame's events come in the order docs/scene-log.md gives: per ball in index order its
//                  hits and bumps (none at frame 0), then its state, then every overlap, ball-major, circles before
//                  rects, each by index and once; each event carries its frame's number and names a ball,
//                  wall, bumper, circle or rect of the scene (a state index 0 and no shape, a hit or bump no shape).
//   penetration    Bounded penetration, with δ = 0: for each ball of radius R and each wall (reach ρ = R) and
//                  bumper of radius r (reach ρ = R + r, the exact sum), once a printed point of the ball's path
//                  (its start, a hit or bump point, a state) is at least ρ from it, every later piece of the path
//                  (closed segment between consecutive printed points) is at least ρ from it: the wall's closed
//                  segment, the bumper's centre. Decided exactly on the printed doubles (truth::clear_of_wall,
//                  truth::clear_of_circle). A ball that starts closer is held to an obstacle only from its first
//                  printed point that is clear of it. Point balls among walls alone (ρ = 0) always hold.
//   ghost-bounce   No hit where only a tangent is possible (a disc sliding along a straight chain at its radius does
//                  not bounce off a joint): a ball's first hit or bump in a frame, if it is a hit off wall W (of
//                  non-zero length) while the frame's first leg Bs → Be = Bs + v (as rounded; non-zero length) runs
//                  parallel to W (n·(Be − Bs) = 0) at least R from W's line ((n·(Bs − P0))² ≥ R²·(n·n)), fails:
//                  the disc can at most touch W, and a tangent is no hit. Exactly on the printed doubles
//                  (truth::parallel_clear_of_line). Later hits in a frame are not judged: the velocity a ball
//                  leaves a hit with is not printed.
//   plan           The scene stepped with every decision on the general exact path (WorldOptions::plan off, the
//                  run's other options) prints the checked run's events bit for bit: the path a scene's plan picks
//                  (wall_plan.hpp) changes the time a decision takes, never its answer.
//   ball-overlap   In a scene whose balls collide: for each pair of balls i < j with S = R_i + R_j > 0, once the pair
//                  has been at least S apart at a common printed time — the frame's end states (frame 0: the initial
//                  ones), or the two centres of one of their meets (the k-th `meet F i j` line with the k-th `meet F
//                  j i`) — it is at no later common printed time closer than S: |p_i − p_j|² ≥ S², exactly on the
//                  printed doubles, S not rounded (truth::circle_reach_side). A pair the scene places closer than S is
//                  held to it from its first common printed time at least S apart. Other scenes pass.
//   pass-through   In a scene whose balls collide: for each frame and each pair i < j with S > 0, over each common
//                  time interval [lo, hi] of a piece of each path (World::path: the ball's printed points — its state
//                  before the frame at t = 0, its hit, bump and meet points in order, its state at t = 1 — at their
//                  frame times, moving uniformly between; pieces of zero duration left out), a pair at least S apart
//                  at lo stays at least S apart: with D(lo + u) = D + W·u (W the difference of the pieces'
//                  velocities), |D + W·u|² ≥ S² for u in [0, hi − lo], its least at u* = −D·W/(W·W) where that lies
//                  inside ((D × W)² ≥ S²·(W·W)), exactly in rationals (truth::pieces_clearance). The World's path
//                  must be the ball's printed path, else the check fails for that ball; where the World gives none,
//                  a ball that printed no contact in the frame moves along the straight piece from its state before to
//                  its state after, and one that did is not judged. Other scenes pass. The lecture kernels fail it:
//                  two balls that cross each other within a frame never overlap at its end.
//   momentum       In a scene whose balls collide: for each meet the World took (World::meets(); masses m_a, m_b the
//                  scene's, mass_of): the record is what the frame printed (its centres and the velocities it leaves
//                  with are the two `meet` lines', the k-th record of a pair the k-th meet each ball printed with the
//                  other; every printed meet is recorded), and so are its arriving velocities where the frame printed
//                  them (a ball's state before the frame at its first contact, the velocity it left a meet with just
//                  before). A meet with a response keeps momentum, each component of m_a·v_a′ + m_b·v_b′ − (m_a·v_a
//                  + m_b·v_b) at most k_meet_momentum_rel (2^−40) times m_a·|v_a|∞ + m_b·|v_b|∞ + m_a·|v_a′|∞ +
//                  m_b·|v_b′|∞, plus k_meet_momentum_abs (2^−1068) times m_a + m_b, and kinetic energy, |E′ − E| ≤
//                  k·E + k_meet_energy_abs·(m_a + m_b)·(|v_a|∞ + |v_b|∞ + |v_a′|∞ + |v_b′|∞) with E = m_a·|v_a|² +
//                  m_b·|v_b|², k = k_meet_energy_rel (2^−40), exactly (truth::meet_conservation); one without (the printed centres
//                  did not approach) leaves both velocities as they were, exactly. Other scenes pass.
//   relabel        In a scene whose balls collide: the scene with its balls, and their masses, in reverse order,
//                  stepped in lockstep, prints per ball the run's events with ball i as ball N − 1 − i (a meet's
//                  other ball too), by value (−0 = +0). Meets at the same time are taken pair by pair in index
//                  order, so from a frame where a meet was taken while another sharing a ball was due at the same
//                  exact time (MeetRecord::tied, the World's own exact decision), in either run, the two may part:
//                  that frame and every later one are not compared. Other scenes pass.
//   jump-through   In a scene whose balls collide: for each frame, each pair i < j with S > 0 and each jump of one of
//                  them — a piece of zero duration of its path as pass-through reads it, from p0 to p1 at frame
//                  time c (two printed points at one time that differ) — against the other ball at c (its printed
//                  point at c, else its exact point on its piece across c): a jump that starts at least S from it
//                  stays at least S from it along the straight line p0 → p1: |D + W·u|² ≥ S² for u in [0, 1], D =
//                  p0 − P(c), W = p1 − p0, exactly in rationals (truth::jump_clearance). Where the other ball also has
//                  points at c that differ, the log does not print the order of the two moves: not judged. The
//                  World's path must be the printed path, as for pass-through. Other scenes pass.
//
// Discs and bumpers: every check is defined in a scene with a disc or a bumper: no-tunnel, speed, no-escape (each
// as written above, read for the disc's centre: its printed path, its velocity; m counts the bounces off bumpers
// and the corner reflections too), deterministic, broad-phase, round-trip, event-order (a bump names a bumper of
// the scene and no shape), penetration, ghost-bounce, plan, and symmetry, swap, translation, boundary, bounce-side,
// oracle and accuracy as read for discs above.
//
// Balls that meet: every check is defined in a scene whose balls collide (`balls collide`). A meet is a printed point
// of the ball's path, as a bump is (no-tunnel, penetration and no-escape read it; bounce-side judges it and ends its
// rule there, a ball having no side; ghost-bounce judges no hit a meet came before). event-order puts a ball's meets
// among its hits and bumps (in the order they happened, which the lines cannot show), from frame 1 on, each naming
// another ball of the scene, not two point balls, in a scene whose balls collide, and ball I printing as many meets
// with J as J with I. Every ball is stepped by the disc frame (a point ball as a disc of radius 0): the disc readings
// of oracle, accuracy, bounce-side and translation apply. A ball that met another in a frame (every ball, in a frame
// whose meets reached the limit of 16·N) is not stepped again alone: its frame is not the one it makes alone, so it
// has no trace, and speed, oracle (its legs and first contact) and accuracy do not judge it (oracle judges the
// frame's first meet instead); ball-overlap, pass-through and momentum do. The images of symmetry and swap and
// translation's moved scenes carry `balls collide` and the masses (the balls in reverse order take theirs along, and
// relabel's exception holds for that image); a meet's other ball maps like its ball; where first contacts are compared (swap, translation), a ball whose first
// contact is a meet, in either run, is not, a meet being decided on paths of rounded contact points; and translation
// counts a meet as a contact.
//
// speed, oracle and accuracy read the frame's StepTrace: each ball is stepped again from its state and memory before
// the frame with a trace (the same wall index); that step must end in the run's state bit for bit, else
// the first of them in the scene's order fails for that ball.
//
// The first failure is the earliest frame; within a frame the first check in the scene's order, then the
// lowest ball.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "ricochet/check.hpp"
#include "ricochet/scene.hpp"
#include "ricochet/world.hpp"

namespace ricochet {

/// The bound `speed` allows per reflection: | |v′| − |v| | ≤ rel·|v| + abs.
struct SpeedBound {
    double rel = 0.0;  ///< b, relative
    double abs = 0.0;  ///< a, absolute (subnormal rounding)
};
/// The kernel's stated speed bound, from the kernel table (KernelOps): k_speed_rel_bound and
/// k_speed_abs_bound for robust and exact; the lecture kernels' own (core/src/kernels/lecture/).
SpeedBound speed_bound(KernelId kernel);

/// The `accuracy` check's bound on a well-conditioned hit point's error, in units of ε·M (ε = 2^−53, M the
/// largest coordinate of the leg and the wall): robust's construction errs by at most 130 (derivation in
/// core/tests/promise_test.cpp), so 256 leaves a factor of 2.
inline constexpr double k_hit_accuracy_ulps = 256.0;

/// The same bound for a disc's contact (t_i and the printed contact point), in units of ε·M (M the largest magnitude
/// of the leg's ends, R, and the obstacle's coordinates and radius). Robust takes a contact's t_i from doubles only
/// where its running error bound is at most 2^−40 (robust_disc.cpp), else a finer construction: along a leg with
/// |d|∞ ≤ 2M that is 2^14·ε·M; B_i = q + t_i·d adds a few ε·M, and the walk back that keeps the piece clear moves
/// the point back along the leg by at most about as much again (it doubles its step); 2^16 leaves a factor of 2.
inline constexpr double k_disc_accuracy_ulps = 65536.0;

/// The `momentum` check's bound on a meet's momentum, relative: each component of m_a·v_a′ + m_b·v_b′ − (m_a·v_a +
/// m_b·v_b) at most this times m_a·|v_a|∞ + m_b·|v_b|∞ + m_a·|v_a′|∞ + m_b·|v_b′|∞. Robust computes the response in
/// doubles, u = (Δv·n)/(n·n) and v′ = v − 2·m_b/(m_a + m_b)·u·n: a handful of roundings of ε = 2^−53 each, on terms no
/// larger than those of the sum (m_a·2·m_b/(m_a + m_b) ≤ 2·min(m_a, m_b), |u·n| ≤ |Δv|); 2^−40 leaves a factor of
/// 2^13 over ε.
inline constexpr double k_meet_momentum_rel = 0x1p-40;
/// The same for a meet's kinetic energy: (1 − this)·E ≤ E′ ≤ (1 + this)·E, E = m_a·|v_a|² + m_b·|v_b|² (the elastic
/// response keeps it exactly; the rounded one errs by a few ε of E, as |v′|·|v| ≤ E/m).
inline constexpr double k_meet_energy_rel = 0x1p-40;
/// The absolute part of both bounds, per unit of m_a + m_b (momentum) and of (m_a + m_b)·(|v_a|∞ + |v_b|∞ + |v_a′|∞ +
/// |v_b′|∞) (energy): where the response's products fall among the subnormals each rounding errs by up to 2^−1075
/// absolutely, not relatively; 2^−1068 covers a handful of them (the `speed` check's absolute term is alike).
inline constexpr double k_meet_momentum_abs = 0x1p-1068;
inline constexpr double k_meet_energy_abs = 0x1p-1068;

/// Where a path broke: the printed piece from → to and the wall it went through (no-tunnel).
struct FailurePiece {
    Vec2 from;               ///< the piece's start
    Vec2 to;                 ///< its end
    std::uint32_t wall = 0;  ///< the wall it went through
};

/// What a disc's failing piece reached into (`penetration`): a wall or a bumper, by its index in the scene.
struct FailureObstacle {
    bool bumper = false;      ///< a bumper, else a wall
    std::uint32_t index = 0;  ///< its index among the scene's walls or bumpers
    Vec2 from{}, to{};        ///< the piece of the path that came too close to it
};

/// The first broken invariant of a run.
struct CheckFailure {
    Check check = Check::no_tunnel;  ///< the invariant that broke
    std::int64_t frame = 0;          ///< the first frame it broke in
    std::uint32_t ball = 0;          ///< the ball it broke for
    std::string message;  ///< expected against actual, for people
    std::optional<FailurePiece> piece{};  ///< no-tunnel: the piece and its wall, for pictures (message unchanged)
    std::optional<FailureObstacle> against{};  ///< penetration: what the piece reached into (message unchanged)
    /// "CHECK broke at frame F ball I: MESSAGE".
    std::string str() const;
};

/// What running a scene with its checks produced.
struct CheckedRun {
    std::vector<Event> events;              ///< every event (empty if not kept)
    std::uint64_t hash = 0;                 ///< run hash (hash.hpp) of every event stepped
    std::int64_t frames_run = 0;            ///< frames stepped (< frames only after an error)
    std::optional<CheckFailure> failure;    ///< the first broken invariant
    std::optional<StepError> error;         ///< the run stopped: a ball left the accepted range
};

/// Options for run_checked.
struct CheckOptions {
    bool keep_events = true;                                   ///< store events in CheckedRun::events
    std::function<void(std::span<const Event>)> on_frame;      ///< called with each frame's events, in order
    /// Asked after each frame stepped without error (0 included) once its checks are done, with the run
    /// so far (its hash not yet set): true ends the run after that frame, its hash covering the frames
    /// run. Checks and events up to it are as without it.
    std::function<bool(const CheckedRun&)> stop_after;
    /// How the run's World and the checks' own worlds step (broad-phase's excepted). Options change no
    /// event's bits (world.hpp; broad-phase checks it), so no check's answer depends on them.
    WorldOptions world{};
};

/// Why run_checked refuses scene under kernel (the kernel cannot step its discs or bumpers), or nothing: what it
/// throws as UnsupportedScene, for a caller to ask first.
std::optional<std::string> refusal(const Scene& scene, KernelId kernel);

/// Runs frames 0..frames of scene under kernel, asserting checks on every frame. Throws UnsupportedScene
/// (kernel.hpp) before stepping if the kernel cannot step the scene. After the first failure
/// the remaining checks are skipped but the run goes on (the hash covers the whole run) unless
/// options.stop_after ends it. The run's World
/// and the checks' own worlds step with options.world (by default as `ricochet run` does), except
/// broad-phase's.
CheckedRun run_checked(const Scene& scene, KernelId kernel, std::int64_t frames, std::span<const Check> checks,
                       const CheckOptions& options = {});

/// The scene mirrored across x = 0: every x coordinate and x velocity negated (walls keep their direction).
Scene mirror_x(const Scene& scene);

}  // namespace ricochet
