// Number generators for the properties: the regimes where geometry goes wrong, each shrinking toward
// a simple value. Small integers (and −0), dyadic fractions m/2^k, values near zero down to subnormals,
// magnitudes up to about ±1e15, anything in between (random mantissa), ulp nudges and far offsets.
#pragma once

#include <rapidcheck.h>

#include <cmath>
#include <cstdint>

#include "ricochet/vec2.hpp"

namespace ricochet::props::gen {

namespace rcg = rc::gen;

/// An integer in [0, max], shrinking toward 0.
inline rc::Gen<int> upto(int max) { return rcg::inRange(0, max + 1); }
/// An integer in [−max, max], shrinking toward 0 and then toward positive.
inline rc::Gen<int> signed_upto(int max) {
    return rcg::apply([](int m, bool neg) { return neg ? -m : m; }, upto(max), rcg::arbitrary<bool>());
}
/// x moved by |ulps| representable doubles up (ulps > 0) or down (ulps < 0).
inline double nudge(double x, int ulps) {
    for (; ulps > 0; --ulps) x = std::nextafter(x, INFINITY);
    for (; ulps < 0; ++ulps) x = std::nextafter(x, -INFINITY);
    return x;
}
/// p with each coordinate moved by a few ulps.
inline Vec2 nudge(Vec2 p, int ux, int uy) { return {nudge(p.x, ux), nudge(p.y, uy)}; }

/// Small integers −16..16, including −0.
inline rc::Gen<double> small_integer() {
    return rcg::apply([](int m, bool neg) { return neg ? -double(m) : double(m); }, upto(16),
                      rcg::arbitrary<bool>());
}
/// Dyadic fractions ±m/2^k, m ≤ 256, k ≤ 12: exact, and sums of a few of them stay exact.
inline rc::Gen<double> dyadic() {
    return rcg::apply([](int m, int k) { return std::ldexp(double(m), -k); }, signed_upto(256), upto(12));
}
/// Values near zero: ±(1 + m)·2^−e with e in [30, 1074], reaching the subnormals.
inline rc::Gen<double> near_zero() {
    return rcg::apply([](int m, int e, bool neg) { return (neg ? -1.0 : 1.0) * std::ldexp(1.0 + m, -e); },
                      upto(1 << 20), rcg::inRange(30, 1075), rcg::arbitrary<bool>());
}
/// Large magnitudes: ±(1 + m)·2^e up to about 5.6e14, and ±1e15 itself.
inline rc::Gen<double> large() {
    return rcg::oneOf(
        rcg::apply([](int m, int e, bool neg) { return (neg ? -1.0 : 1.0) * std::ldexp(1.0 + m, e); },
                   upto(1 << 20), upto(29), rcg::arbitrary<bool>()),
        rcg::element(1e15, -1e15));
}
/// Any double with magnitude in [2^−64, 2^50): a random 52-bit mantissa.
inline rc::Gen<double> any_bits() {
    return rcg::apply(
        [](std::int64_t f, int e, bool neg) {
            return (neg ? -1.0 : 1.0) * std::ldexp(1.0 + std::ldexp(double(f), -52), e);
        },
        rcg::inRange<std::int64_t>(0, std::int64_t{1} << 52), signed_upto(49), rcg::arbitrary<bool>());
}
/// A coordinate or velocity component from every regime; simple ones first (what shrinking aims at).
inline rc::Gen<double> coordinate() {
    return rcg::weightedOneOf<double>({{6, small_integer()}, {4, dyadic()}, {3, any_bits()}, {1, near_zero()},
                                       {1, large()}});
}
/// A point or vector from coordinate().
inline rc::Gen<Vec2> vec() {
    return rcg::apply([](double x, double y) { return Vec2{x, y}; }, coordinate(), coordinate());
}
/// A far-from-origin offset: mostly none; else ±(1 + m)·2^e with e in [10, 39] (up to about 5.6e14).
inline rc::Gen<Vec2> offset() {
    const auto far = rcg::apply([](int m, int e, bool neg) { return (neg ? -1.0 : 1.0) * std::ldexp(1.0 + m, e); },
                                upto(1 << 10), rcg::inRange(10, 40), rcg::arbitrary<bool>());
    return rcg::weightedOneOf<Vec2>(
        {{3, rcg::just(Vec2{})},
         {2, rcg::apply([](double x, double y) { return Vec2{x, y}; }, far, far)},
         {1, rcg::apply([](double x) { return Vec2{x, 0.0}; }, far)}});
}

}  // namespace ricochet::props::gen
