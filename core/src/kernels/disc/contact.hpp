// Internal: a disc's first contact with a wall or a circle along a leg, decided exactly (the robust kernel).
//
// The disc of radius R, centre on the leg X(t) = q + t·d, d = b − q, t in [0, 1], touches the wall P0P1 when
// its centre reaches the wall's capsule, the points within R of the segment: the two lines n̂·X − n̂·P0 = ±R
// (the faces) and the circles |X − P_k| = R (the caps). It touches a circle C of radius r (a bumper) when
// |X − C| = ρ = R + r. With n = (e_y, −e_x), w = q − P0, s = sign(n·w) (q's side):
//   face   n̂·X(t) − n̂·P0 = s·R  ⇒  t_f = (s·n·w − R·√(n·n)) / (−s·n·d)        (the lecture's t_i, n̂·P0 shifted
//                                                                            by R toward the ball)
//   circle |q + t·d − P|² = ρ²  ⇒  a·t² + 2β·t + γ = 0, a = d·d, β = d·(q − P), γ = |q − P|² − ρ²,
//          t_c = (−β − √Δ)/a with Δ = β² − a·γ (the smaller root)
// The capsule is the union of the band between the faces (within the segment's ends) and the two cap discs,
// so the first contact is the earliest of the face entry (inside the ends) and the two cap entries.
// Rules (kernel.hpp's conventions for points, read for discs):
// - A hit is an entry: the centre's distance to the obstacle reaches ρ while decreasing. A tangential touch
//   (Δ = 0; or moving along a face at distance exactly R) is no hit, so a disc sliding along a chain of
//   collinear walls meets the joint's caps tangentially and does not bounce off the joint.
// - A disc already within ρ (touching, or a scene that starts overlapping) hits at t = 0 if it moves closer,
//   and otherwise does not hit that obstacle during the leg (its distance is convex along the leg).
// - A centre on the segment itself (or on a circle's centre) has no normal: no hit.
// - A zero-length wall is a point: its caps, no face. (A point ball never meets it: no normal.)
// - Ties: within a wall the face, then cap P0, then cap P1; across obstacles the lowest wall, then bumpers.
// Every decision is the sign of a polynomial in the doubles or of p + q·√r; they are evaluated with a filter and
// exactly when it cannot tell (arith.hpp). No square root inside an exact decision.
#pragma once

#include <cstdint>
#include <optional>

#include "ricochet/shapes.hpp"

namespace ricochet::disc {

/// Which part of an obstacle a disc meets.
enum class Part : std::uint8_t {
    face,   ///< a wall's face on side `side`
    cap0,   ///< the circle of radius R around a wall's P0
    cap1,   ///< around P1
    circle  ///< a bumper: the circle of radius R + r around its centre
};

/// What a disc moving along the leg q → b meets first on one obstacle.
struct Contact {
    Part part = Part::face;
    std::int8_t side = 0;     ///< face: s = sign(n·(q − P0)), ±1
    bool at_start = false;    ///< already within reach at q and moving closer: t = 0
};

/// The leg and the disc: q → b, radius R > 0 (a wall) or R ≥ 0 (a circle).
struct Leg {
    Vec2 q;
    Vec2 b;
    double R = 0.0;
};

/// The obstacle a contact is on: a wall, or a circle of radius r (a bumper).
struct Obstacle {
    const Wall* wall = nullptr;  ///< set for a wall
    Vec2 c;                      ///< a circle's centre
    double r = 0.0;              ///< a circle's radius
};

/// The first contact of the leg with wall w (R > 0), or nothing.
std::optional<Contact> first_contact(const Leg& leg, const Wall& w);
/// The first contact of the leg with the circle of radius R + r around c, or nothing.
std::optional<Contact> first_contact(const Leg& leg, Vec2 c, double r);

/// sign(t_a − t_b) for two contacts on one leg, exactly.
int compare(const Leg& leg, const Obstacle& a, const Contact& ca, const Obstacle& b, const Contact& cb);

/// The contact's leg fraction t, rounded, in [0, 1].
double contact_time(const Leg& leg, const Obstacle& o, const Contact& c);

/// contact_time's t before clamping, and a bound on its distance to the exact t (∞ when none is known).
struct TimeEstimate {
    double t = 0.0;
    double error = 0.0;
};
/// The contact's t from doubles, as contact_time computes it (the same operations, so the same bits), with a
/// running error bound: large where the formula cancels (a leg that approaches the line or the circle by a few
/// ulps over its length divides a rounding error by a tiny n·d or √Δ).
TimeEstimate contact_time_estimate(const Leg& leg, const Obstacle& o, const Contact& c);

/// A contact's leg fraction t and centre B_i = q + t·(b − q), each the double nearest to its exact value.
struct RoundedContact {
    double t = 0.0;
    Vec2 x;
};
/// The contact's t (clamped to [0, 1]) and B_i, each the double nearest to its exact value, from the second
/// stage's double-double (arith.hpp) when its bound decides every rounding; nothing when it cannot (a value too
/// near a midpoint, or a cancellation deeper than its precision: then exact_disc.cpp's bracket in rationals).
std::optional<RoundedContact> nearest_contact_fine(const Leg& leg, const Obstacle& o, const Contact& c);

/// A contact from the second stage's double-double: t and B_i = q + t·(b − q) each rounded from their double-double
/// values (hi + lo), and a bound on t's distance to the exact t.
struct FineContact {
    double t = 0.0;
    Vec2 x;
    double error = 0.0;
};
/// The contact's t and B_i from double-double: t's bound is about 2^−100 relative where contact_time_estimate's is
/// 2^−53, so a leg that approaches the line by ulps still gets t to 2^−45 or so, and B_i within half an ulp and
/// that error along the leg.
FineContact contact_fine(const Leg& leg, const Obstacle& o, const Contact& c);

/// The part of wall w nearest to p, exactly: the face, or the cap at the nearer end ((p − P_k)·e's sign).
Part nearest_part(Vec2 p, const Wall& w);

/// sign(v·N) for the outward normal N of obstacle o at p (N = ±n on a face, p − P_k at a cap, p − C at a
/// circle, the part nearest to p): < 0 if moving along v takes the centre closer.
int normal_sign(Vec2 p, Vec2 v, const Obstacle& o);

/// The outward normal of obstacle o at p (not unit): s·n on the part of a wall nearest p that is a face, p − P_k
/// at a cap, p − C at a circle; zero if p lies on the wall's segment or at the centre.
Vec2 normal_at(Vec2 p, const Obstacle& o);

/// True if the piece q → x stays at least R (walls) or R + r (circles) from the obstacle, exactly: the closed
/// segment's distance to the wall's segment, or to the circle's centre.
bool piece_clear(Vec2 q, Vec2 x, double R, const Obstacle& o);
/// True if p is at least R (walls) or R + r (circles) from the obstacle, exactly.
bool point_clear(Vec2 p, double R, const Obstacle& o);
/// True if the piece q → x passes strictly from one side of wall w's line to the other through its closed
/// segment (the point ball's tunnel), exactly.
bool crosses(Vec2 q, Vec2 x, const Wall& w);
/// True if the closed piece q → x (a point if q = x) has a point on wall w's closed segment (a point if w has no
/// length), exactly.
bool touches(Vec2 q, Vec2 x, const Wall& w);

}  // namespace ricochet::disc
