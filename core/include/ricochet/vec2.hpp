// Vec2: the lecture's vector algebra on doubles.
#pragma once

#include <cmath>

namespace ricochet {

/// A 2D vector or point, y up.
struct Vec2 {
    double x = 0.0;
    double y = 0.0;

    friend constexpr bool operator==(Vec2, Vec2) = default;
};

/// Component-wise sum a + b.
constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
/// Component-wise difference a − b.
constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
/// Negation −a.
constexpr Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
/// Scaling k·a.
constexpr Vec2 operator*(double k, Vec2 a) { return {k * a.x, k * a.y}; }
/// Scaling a·k.
constexpr Vec2 operator*(Vec2 a, double k) { return {a.x * k, a.y * k}; }

/// Dot product a·b = ax·bx + ay·by.
constexpr double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
/// 2D cross product a×b = ax·by − ay·bx (positive when b is counter-clockwise of a).
constexpr double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
/// Squared length |a|² = a·a: compare squared lengths to avoid a square root.
constexpr double length_squared(Vec2 a) { return dot(a, a); }
/// Length |a| = √(a·a).
inline double length(Vec2 a) { return std::sqrt(length_squared(a)); }
/// Unit vector a/|a|; the zero vector stays zero (never divided by).
inline Vec2 normalize(Vec2 a) {
    const double len = length(a);
    // Degenerate: a zero vector has no direction.
    if (len == 0.0) return {0.0, 0.0};
    return {a.x / len, a.y / len};
}
/// The lecture's perpendicular (e_y, −e_x): e rotated by −90°, pointing to the right of e.
constexpr Vec2 perp(Vec2 e) { return {e.y, -e.x}; }

}  // namespace ricochet
