// The exact answers the generators aim with, under the names they use: the ground truth itself lives
// in core (ricochet/truth.hpp), where the checks use it.
#pragma once

#include "ricochet/truth.hpp"

namespace ricochet::props {

/// truth::orient.
inline int orient_oracle(Vec2 a, Vec2 b, Vec2 c) { return truth::orient(a, b, c); }
/// truth::side.
inline int side_oracle(Vec2 p, const Wall& w) { return truth::side(p, w); }
/// truth::on_closed_segment.
inline bool on_closed_segment_oracle(Vec2 p, const Wall& w) { return truth::on_closed_segment(p, w); }
/// truth::locate.
inline int locate(Vec2 p, std::span<const Wall> walls) { return truth::locate(p, walls); }
/// truth::circle_side.
inline int circle_side_oracle(Vec2 p, const Circle& c) { return truth::circle_side(p, c); }
/// truth::point_in_circle.
inline bool point_in_circle_oracle(Vec2 p, const Circle& c) { return truth::point_in_circle(p, c); }
/// truth::circles_overlap.
inline bool circles_overlap_oracle(const Circle& a, const Circle& b) { return truth::circles_overlap(a, b); }
/// truth::point_in_rect.
inline bool point_in_rect_oracle(Vec2 p, const Rect& r) { return truth::point_in_rect(p, r); }
/// truth::rects_overlap.
inline bool rects_overlap_oracle(const Rect& a, const Rect& b) { return truth::rects_overlap(a, b); }
/// truth::sum_exact.
inline bool sum_exact(double a, double b) { return truth::sum_exact(a, b); }
/// truth::cross_sign.
inline int cross_sign(Vec2 a, Vec2 b) { return truth::cross_sign(a, b); }
/// truth::dot_sign.
inline int dot_sign(Vec2 a, Vec2 b) { return truth::dot_sign(a, b); }
/// truth::leg_miss.
inline Miss expected_miss(Vec2 bs, Vec2 be, const Wall& w) { return truth::leg_miss(bs, be, w); }
/// x ↦ −x (exact).
inline Vec2 mirror(Vec2 p) { return {-p.x, p.y}; }
/// A quarter turn counter-clockwise, (x, y) ↦ (−y, x) (exact).
inline Vec2 rotate90(Vec2 p) { return {-p.y, p.x}; }
/// a == b componentwise (−0 equals +0).
inline bool same_value(Vec2 a, Vec2 b) { return a.x == b.x && a.y == b.y; }

}  // namespace ricochet::props
