// Internal: when two balls' paths first come within S = R_i + R_j of each other (docs/scene-log.md, "Balls that
// meet", 2 and 3), decided exactly on the printed doubles, and the order of two such times. A path is printed
// points at frame times, the centre moving uniformly between consecutive ones, so on a common time interval the
// relative position is linear in t with rational coefficients and the meet time a root of a quadratic.
#pragma once

#include <optional>
#include <span>
#include <utility>

#include "base/bignum.hpp"
#include "ricochet/meet.hpp"

namespace ricochet::meet {

/// Two balls' radii. Their sum S = R_i + R_j is taken exactly wherever a decision rests on it (a sum rounded to
/// the larger radius would let the balls meet closer than they are wide); `rounded()` serves the filters only.
struct Radii {
    double a = 0.0, b = 0.0;
    double rounded() const { return a + b; }
};

/// A piece of a path: from p0 at t0 to p1 at t1 > t0, or a ball at p0 from t0 on (t1 = t0), which moves there with
/// the velocity its ball ends the frame with.
struct Piece {
    double t0 = 0.0, t1 = 0.0;
    Vec2 p0, p1;
};

/// A meet time: the double nearest it (docs/scene-log.md, "Balls that meet", 4: t* rounded), and what it is
/// computed from, the common interval's start c and the two pieces over it, so that its exact value, t = p + q·√r
/// (r ≥ 0; q = 0 for a meet at c), is made only when a decision needs it (compare, on estimates within 2^−48).
struct Root {
    double estimate = 0.0;
    bool at_start = false;  // a meet at c itself: the balls within S there and approaching
    double c = 0.0;
    Piece a, b;
    Vec2 end_a, end_b;
    Radii S;
    struct Exact {
        bignum::Rational p, q, r;
    };
    mutable std::optional<Exact> exact;  // filled by exact_of
};

/// The root's exact value (made once, then kept in the root).
const Root::Exact& exact_of(const Root& root);

/// The first time at or after `from` at which paths a and b (each at least one point, times non-decreasing, the
/// last at 1) come within S of each other while approaching: on each common interval [a, b] of a piece of one and
/// a piece of the other, D(u) = D_a + W·u, the smaller root of |D(u)|² = S² with a + u in [a, b] (a double root,
/// the tangent, is none), or a itself where |D_a| ≤ S and D_a·W < 0. Nothing if they do not meet by t = 1. A path
/// that ends at its start (a ball stepped on from a meet at t = 1) has no piece to take a velocity from: end_a and
/// end_b, the velocities the balls end the frame with, stand for it there.
/// `until` (at most 1) ends the search earlier: nothing after it is looked at.
std::optional<Root> first_meet(std::span<const PathPoint> a, std::span<const PathPoint> b, Radii S, double from,
                               Vec2 end_a = {}, Vec2 end_b = {}, double until = 1.0);

/// The sign of x − y where two roots' estimates x and y decide it, else 0. The estimates are the doubles nearest their
/// exact values (within 2^−53 of them, t ≤ 1): farther apart than 2^−48, they decide.
inline int compare_estimates(double x, double y) {
    if (x < y - 0x1p-48) return -1;
    if (x > y + 0x1p-48) return 1;
    return 0;
}

/// The sign of x − y, exactly.
int compare(const Root& x, const Root& y);

/// The sign of x − t for a double t, exactly.
int compare(const Root& x, double t);

/// The ball's centre at frame time t on its path (t within the path's times), correctly rounded: the piece holding
/// t (the last one starting at or before t), and the index of the printed point it starts from.
struct PointOnPath {
    Vec2 x;
    std::size_t from = 0;
};
PointOnPath point_at(std::span<const PathPoint> path, double t);

/// The ball's centre at frame time t on its path (t within the path's times), exactly: the point point_at rounds.
std::pair<bignum::Rational, bignum::Rational> exact_point(std::span<const PathPoint> path, double t);

/// Whether meet m of paths a and b is an entry into reach from outside it: a crossing inside its interval, or one at
/// the interval's start c where the two touch exactly (two balls already closer than S there enter nothing).
bool entered(const Root& m, std::span<const PathPoint> a, std::span<const PathPoint> b, Radii S);

/// The first meet of paths a and b at or after `from`, up to `until` as first_meet looks, that is an entry from
/// outside (entered), or nothing: a meet that is none (the two closer than S at an interval's start, approaching) is
/// passed over for the next interval before `until`, where they may have left reach and come back (on one interval
/// |D(u)|² is a quadratic in u: once out of reach there, they stay out there). Pass-through's rule, on every
/// interval rather than the first meet's alone.
std::optional<Root> first_entry(std::span<const PathPoint> a, std::span<const PathPoint> b, Radii S, double from,
                                double until = 1.0);

/// The first time after t at which path a or b has a point (1 if none).
double next_point(std::span<const PathPoint> a, std::span<const PathPoint> b, double t);

/// |a − b|² < S², exactly (a filter in doubles first).
bool closer_than(Vec2 a, Vec2 b, Radii S);

/// Whether two balls moving from a0, b0 to a1, b1 on one interval come no farther apart at its end: the sign of
/// D1·(D1 − D0) ≤ 0, D0 = a0 − b0, D1 = a1 − b1 (the end of |D(u)|², a convex quadratic, falls or is flat). In
/// bounded double-double; nothing where the bound does not decide it.
std::optional<bool> closing_at_end(Vec2 a0, Vec2 b0, Vec2 a1, Vec2 b1);

/// True if paths a and b, each one piece from lo to t (lo < t), whose ends at t are not closer than S (the caller's
/// to know), surely hold no meet before t: where the two close in at t (closing_at_end). On [lo, t], |D(u)|² − S² is
/// convex with a slope ≤ 0 at t, so it falls all through to a value ≥ 0 at t. False decides nothing (other paths, or
/// the bound undecided: first_meet's search decides).
bool surely_no_meet_before_end(std::span<const PathPoint> a, std::span<const PathPoint> b, double lo, double t);

/// Whether a jump p0 → p1 (a centre moved at one time) that starts at least S from the point k comes closer than S
/// to it along the way: |D + W·u|² < S² for some u in [0, 1], D = p0 − k, W = p1 − p0, exactly (jump-through's rule).
bool jump_enters(Vec2 p0, Vec2 p1, const std::pair<bignum::Rational, bignum::Rational>& k, Radii S);

/// |P_a(t) − P_b(t)|² < S² on the paths' exact points at t (not rounded), exactly: the balls closer than S there.
/// Both paths must reach t (their first times at most t).
bool closer_on_paths(std::span<const PathPoint> a, std::span<const PathPoint> b, double t, Radii S);

/// True if the filter proves that the path's centre at t (point_at's, rounded) is farther than S from x: a cheap
/// look before point_at's exact one. False decides nothing.
bool surely_apart(Vec2 x, std::span<const PathPoint> path, double t, Radii S);

}  // namespace ricochet::meet
