// Vec2T: the lecture's vector algebra, written once for every precision. Vec2 (double) is the
// core's type; the lecture kernels instantiate it with float and double, the exact kernel with its
// exact number type, so the same formulas are read everywhere.
#pragma once

#include <cmath>

#include "ricochet/fp_guard.hpp"  // dot and cross are inline: the user's flags decide their bits

namespace ricochet {

/// A 2D vector or point, y up, with components of type T (float, double or an exact number).
/// The operations are hidden friends: found by argument-dependent lookup, with T's own conversions.
template <class T>
struct Vec2T {
    T x{};
    T y{};

    /// Component-wise equality (−0 = +0); constexpr wherever T's own == is.
    friend bool operator==(const Vec2T&, const Vec2T&) = default;

    /// Component-wise sum a + b.
    friend constexpr Vec2T operator+(const Vec2T& a, const Vec2T& b) { return {a.x + b.x, a.y + b.y}; }
    /// Component-wise difference a − b.
    friend constexpr Vec2T operator-(const Vec2T& a, const Vec2T& b) { return {a.x - b.x, a.y - b.y}; }
    /// Negation −a.
    friend constexpr Vec2T operator-(const Vec2T& a) { return {-a.x, -a.y}; }
    /// Scaling k·a.
    friend constexpr Vec2T operator*(const T& k, const Vec2T& a) { return {k * a.x, k * a.y}; }
    /// Scaling a·k.
    friend constexpr Vec2T operator*(const Vec2T& a, const T& k) { return {a.x * k, a.y * k}; }

    /// Dot product a·b = ax·bx + ay·by.
    friend constexpr T dot(const Vec2T& a, const Vec2T& b) { return a.x * b.x + a.y * b.y; }
    /// 2D cross product a×b = ax·by − ay·bx (positive when b is counter-clockwise of a).
    friend constexpr T cross(const Vec2T& a, const Vec2T& b) { return a.x * b.y - a.y * b.x; }
    /// Squared length |a|² = a·a: compare squared lengths to avoid a square root.
    friend constexpr T length_squared(const Vec2T& a) { return dot(a, a); }
    /// The lecture's perpendicular (e_y, −e_x): e rotated by −90°, pointing to the right of e.
    friend constexpr Vec2T perp(const Vec2T& e) { return {e.y, -e.x}; }
};

/// The core's vector: doubles.
using Vec2 = Vec2T<double>;

/// p with each component converted to T (rounded to nearest when T is narrower).
template <class T, class U>
constexpr Vec2T<T> vec_cast(const Vec2T<U>& p) {
    return {static_cast<T>(p.x), static_cast<T>(p.y)};
}

/// Length |a| = √(a·a) (floating-point T).
template <class T>
T length(const Vec2T<T>& a) {
    using std::sqrt;
    return sqrt(length_squared(a));
}
/// Unit vector a/|a|; the zero vector stays zero (never divided by). Floating-point T.
template <class T>
Vec2T<T> normalize(const Vec2T<T>& a) {
    const T len = length(a);
    // Degenerate: a zero vector has no direction.
    if (len == T(0)) return {T(0), T(0)};
    return {a.x / len, a.y / len};
}

}  // namespace ricochet
