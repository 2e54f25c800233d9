// Limits: the accepted range of inputs, the bounce limit per frame, and the bound on the speed error
// per bounce, shared by every kernel.
#pragma once

#include <cmath>

namespace ricochet {

/// Largest accepted magnitude of any coordinate, radius or velocity component.
inline constexpr double k_coordinate_limit = 0x1p256;
/// Most bounces one ball makes in one frame.
inline constexpr int k_max_bounces = 16;
/// Robust and exact: bound on the relative change of |v| per bounce (the rounded reflection).
/// Robust computes v' = v − 2(v·n̂)n̂ with n̂ = m/|m|, m = n scaled by a power of two (exact): |m| is off by
/// ≤ 2ε, n̂ by ≤ 2ε per component, so |n̂|² = 1 ± 6ε; v·n̂ is off by ≤ 4ε|v|, 2(v·n̂)n̂ by ≤ 7ε|v|, the
/// subtraction adds ε per component. Reflecting about n̂ itself changes |v|² by 4(v·n̂)²(|n̂|² − 1).
/// In all ≤ 20ε < 32ε = 2^-48 (ε = 2^-53). Exact rounds each component once (ε). Measured worst over
/// 2·10^6 random reflections at scales 2^±60: see core/tests/frame_test.cpp (SpeedBoundHolds).
inline constexpr double k_speed_rel_bound = 0x1p-48;
/// Robust and exact: absolute part of that bound per bounce, for velocities so small that the rounding
/// is subnormal (each operation then errs by up to 2^-1075 absolutely, not relatively): 2^-1068.
inline constexpr double k_speed_abs_bound = 0x1p-1068;

/// True if x is finite and |x| ≤ k_coordinate_limit: one comparison, as |±∞| > k_coordinate_limit and NaN
/// compares false (inline: every kernel's frame asks it of four numbers twice).
inline bool in_range(double x) { return std::fabs(x) <= k_coordinate_limit; }

}  // namespace ricochet
