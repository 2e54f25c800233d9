// Ground truth for the properties, computed independently of the kernels under test: exact signs by a
// floating-point filter with a GMP fallback, exact point-in-region, exact speed bounds, and the exact
// transformations (mirror, quarter turn, translation) the symmetry properties apply to whole scenes.
#pragma once

#include <span>
#include <vector>

#include "ricochet/kernel.hpp"

#include "ricochet/scene.hpp"
#include "ricochet/shapes.hpp"

namespace ricochet::props {

/// sign((b − a) × (c − a)), exact for every finite double (own filter, GMP when it cannot decide).
int orient_oracle(Vec2 a, Vec2 b, Vec2 c);
/// sign of BC = n·(p − P0), n = (e_y, −e_x): +1 Outside, −1 Inside, 0 On; equals −orient(P0, P1, p).
int side_oracle(Vec2 p, const Wall& w);
/// True if p lies on w's closed segment (on its line and within its bounding box), exactly.
bool on_closed_segment_oracle(Vec2 p, const Wall& w);
/// Where p lies against the region the walls enclose (even-odd rule, exact): +1 strictly inside, 0 on a
/// wall, −1 strictly outside. Wall directions do not matter.
int locate(Vec2 p, std::span<const Wall> walls);

/// sign(|p − c|² − r²), exactly (GMP): −1 inside, 0 on, +1 outside.
int circle_side_oracle(Vec2 p, const Circle& c);
/// |p − c|² ≤ r², exactly (GMP).
bool point_in_circle_oracle(Vec2 p, const Circle& c);
/// |cA − cB|² ≤ (rA + rB)², exactly (GMP).
bool circles_overlap_oracle(const Circle& a, const Circle& b);
/// left ≤ x ≤ right and bottom ≤ y ≤ top (comparisons of doubles are exact).
bool point_in_rect_oracle(Vec2 p, const Rect& r);
/// Closed rectangles intersect.
bool rects_overlap_oracle(const Rect& a, const Rect& b);

/// (1 − b)^m·|v| − m·a ≤ |w| ≤ (1 + b)^m·|v| + m·a (m bounces, relative bound b, absolute bound a per
/// bounce), decided exactly up to a 2^−200 relative bracket of |v| (GMP).
bool speed_within(Vec2 v, Vec2 w, int m, double b, double a);
/// True if a + b is computed exactly in double.
bool sum_exact(double a, double b);
/// 2D cross product's sign of two directions, exactly: sign(a × b).
int cross_sign(Vec2 a, Vec2 b);
/// sign(a · b), exactly.
int dot_sign(Vec2 a, Vec2 b);

/// The exact decision for the leg Bs → Be against w, by kernel.hpp's conventions: degenerate (zero-length
/// wall or Bs = Be), both inside, both outside, parallel (both on the line), leaving (Bs on the line),
/// before P0 / past P1 (the leg's line meets the wall's line outside the closed segment), else a hit.
Miss expected_miss(Vec2 bs, Vec2 be, const Wall& w);

/// The first wall the leg Bs → Be hits (the earliest exact crossing, the lowest index on a tie), or −1.
long first_hit_oracle(Vec2 bs, Vec2 be, std::span<const Wall> walls);

/// kernel.hpp's no-tunnelling definition, followed independently of ricochet::TunnelChecker: a piece
/// from one open side to the other through the closed segment, or arriving on the closed segment from
/// one side and leaving to the other, tunnels; after moving along the line either side is fine.
class PathOracle {
public:
    /// Starts every ball at its initial position.
    PathOracle(std::span<const Wall> walls, std::span<const Ball> balls);
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

/// x ↦ −x (exact).
Vec2 mirror(Vec2 p);
/// A quarter turn counter-clockwise, (x, y) ↦ (−y, x) (exact).
Vec2 rotate90(Vec2 p);
/// The scene with every point, velocity and shape mapped by f (exact maps only); walls keep their direction,
/// rectangles are re-normalized so that left ≤ right and bottom ≤ top.
Scene transform(const Scene& s, Vec2 (*f)(Vec2));
/// The scene translated by t (walls, balls, circles and rects; velocities unchanged). Rounded if t is not
/// exact for some coordinate; use translation_exact first.
Scene translate(const Scene& s, Vec2 t);
/// True if every coordinate of s, and every Bs + v, moves by t without rounding.
bool translation_exact(const Scene& s, Vec2 t);

/// a == b componentwise (−0 equals +0).
inline bool same_value(Vec2 a, Vec2 b) { return a.x == b.x && a.y == b.y; }

}  // namespace ricochet::props
