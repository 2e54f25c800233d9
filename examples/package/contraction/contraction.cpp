// Prints cross(a, b) for a = (u, u), b = (w, u), u = 1 + 2^-30, w = 1 + 2^-30 + 2^-52, and exits 0 iff it
// is the unfused result. cross = u·u − u·w; each product rounded once:
//   u·u = 1 + 2^-29 + 2^-60                    → 1 + 2^-29
//   u·w = 1 + 2^-29 + 2^-52 + 2^-60 + 2^-82    → 1 + 2^-29 + 2^-52
// so cross = −2^-52 exactly. Fused into one FMA either product stays exact and the result is
// 2^-60 − 2^-52 or −(2^-52 + 2^-60 + 2^-82): never −2^-52.
#include <fmt/core.h>

#include "ricochet/vec2.hpp"

int main() {
    // Read at run time, so the compiler cannot fold the products before contracting them.
    volatile double u_in = 1 + 0x1p-30;
    volatile double w_in = 1 + 0x1p-30 + 0x1p-52;
    const double u = u_in;
    const double w = w_in;
    const double got = cross(ricochet::Vec2{u, u}, ricochet::Vec2{w, u});
    const double unfused = -0x1p-52;
    fmt::print("cross {:a} unfused {:a}\n", got, unfused);
    return got == unfused ? 0 : 1;
}
