// Bit-for-bit equality of core values. operator== treats −0 and +0 as equal; the run hash and the
// scene-log round trip do not, so whoever compares "the same bits" uses these.
#pragma once

#include <cstdint>
#include <cstring>

#include "ricochet/event.hpp"
#include "ricochet/shapes.hpp"

namespace ricochet {

/// The IEEE-754 bit pattern of x: std::bit_cast<std::uint64_t>(x), which wasm32's libc++ (13, emscripten 3.1.6)
/// does not have; a memcpy of 8 bytes compiles to the same one move.
inline std::uint64_t bits_of(double x) {
    std::uint64_t u = 0;
    std::memcpy(&u, &x, sizeof u);
    return u;
}
/// The double whose IEEE-754 bit pattern is u: std::bit_cast<double>(u), by memcpy for the same reason.
inline double double_of_bits(std::uint64_t u) {
    double x = 0.0;
    std::memcpy(&x, &u, sizeof x);
    return x;
}
/// True if a and b have the same IEEE-754 bit pattern.
inline bool same_bits(double a, double b) { return bits_of(a) == bits_of(b); }
/// Both components the same bits.
inline bool same_bits(Vec2 a, Vec2 b) { return same_bits(a.x, b.x) && same_bits(a.y, b.y); }
/// Position, velocity and radius the same bits.
inline bool same_bits(const Ball& a, const Ball& b) {
    return same_bits(a.pos, b.pos) && same_bits(a.vel, b.vel) && same_bits(a.r, b.r);
}
/// Both end points the same bits.
inline bool same_bits(const Wall& a, const Wall& b) { return same_bits(a.p0, b.p0) && same_bits(a.p1, b.p1); }
/// Centre and radius the same bits.
inline bool same_bits(const Circle& a, const Circle& b) { return same_bits(a.c, b.c) && same_bits(a.r, b.r); }
/// Centre and radius the same bits.
inline bool same_bits(const Bumper& a, const Bumper& b) { return same_bits(a.c, b.c) && same_bits(a.r, b.r); }
/// Every side the same bits.
inline bool same_bits(const Rect& a, const Rect& b) {
    return same_bits(a.left, b.left) && same_bits(a.bottom, b.bottom) && same_bits(a.right, b.right) &&
           same_bits(a.top, b.top);
}
/// The same fields and the same bits: the same run-hash record (hash.hpp).
inline bool same_bits(const Event& a, const Event& b) {
    return a.kind == b.kind && a.frame == b.frame && a.ball == b.ball && a.shape == b.shape && a.index == b.index &&
           same_bits(a.pos, b.pos) && same_bits(a.vel, b.vel);
}

}  // namespace ricochet
