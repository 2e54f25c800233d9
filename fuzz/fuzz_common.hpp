// Shared by the fuzz targets: a deterministic byte decoder that favours the numbers where
// geometry goes wrong (small integers, dyadic fractions, values near zero, huge offsets, a few ulps
// either side of a line), the kernel under test, and the one oracle: the decoded Scene run through the
// shared checker (run_checked, checks.hpp); a failure aborts (libFuzzer saves the input) and, on
// request, saves the failure log (failure_log.hpp) that `ricochet replay` reproduces.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ricochet/checks.hpp"
#include "ricochet/kernel.hpp"
#include "ricochet/scene.hpp"
#include "ricochet/shapes.hpp"

namespace ricochet::fuzz {

/// Environment variable naming the kernel under test (shared with the property tests).
inline constexpr const char* k_kernel_env = "RICOCHET_KERNEL";
/// Environment variable: when set, a failing input also writes its scene log to this path.
inline constexpr const char* k_scene_out_env = "RICOCHET_FUZZ_SCENE_OUT";
/// Environment variable: the SHA1 of the input, for the log's `from fuzz TARGET SHA1` line.
inline constexpr const char* k_sha1_env = "RICOCHET_FUZZ_SHA1";
/// The line prefix of a failure report on stderr (the campaign driver parses it).
inline constexpr std::string_view k_failure_tag = "==ricochet-fuzz== FAILURE";

/// The kernel named by RICOCHET_KERNEL, robust if unset; an unknown name aborts (a typo must not
/// silently fuzz the wrong kernel).
KernelId kernel_under_test();

/// Reads the fuzzer's bytes as geometry. Exhausted input reads as zeros, so every byte string
/// decodes to some case and small inputs decode to simple ones.
class ByteReader {
public:
    /// Reads from the bytes [data, data + size).
    ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
    /// True when every byte was consumed.
    bool empty() const { return pos_ >= size_; }
    /// The next byte, 0 past the end.
    std::uint8_t u8() { return pos_ < size_ ? data_[pos_++] : 0; }
    /// The next two bytes, little-endian (read in sequence: the operands of | are evaluated in an unspecified
    /// order, and an input must decode alike on every compiler).
    std::uint16_t u16() {
        const unsigned lo = u8();
        const unsigned hi = u8();
        return static_cast<std::uint16_t>(lo | (hi << 8));
    }
    /// The next eight bytes, little-endian.
    std::uint64_t u64();
    /// An integer in [0, n), n ≥ 1.
    unsigned below(unsigned n) { return u8() % n; }
    /// A number in the accepted range (kernel.hpp's in_range), mostly simple, sometimes extreme.
    double number();
    /// A non-negative number in range.
    double magnitude();
    /// x moved k ulps (k in [−3, 3], often 0).
    double nudge(double x);
    /// A point: free, or tied to the geometry seen so far (an end point, on a wall's line, on a
    /// circle), each possibly a few ulps off.
    Vec2 point();
    /// Remembers a wall so that later points can land on its line or ends.
    void remember(const Wall& w) { walls_.push_back(w); }
    /// Remembers a point so that later points can reuse it.
    void remember(Vec2 p) { points_.push_back(p); }
    /// A wall (sometimes zero-length), remembered.
    Wall wall();
    /// A velocity: free, towards a decoded target point, or along a remembered wall.
    Vec2 velocity(Vec2 from);
    /// A circle, remembered by its centre.
    Circle circle();
    /// A rectangle with left ≤ right and bottom ≤ top.
    Rect rect();
    /// Read after a case is decoded: a byte that may rewrite its first walls and its ball into a near-degenerate
    /// case the predicates' filters cannot decide, each point exact (fuzz/README.md, "Near-degenerate inputs").
    /// byte % 4: 0 nothing; 1 "collinear + k ulps": walls[0] on a line through the origin and the leg ending on
    /// it, points at mixed magnitudes (2^-1000 to 2^250), Be moved k ulps; 2 the same with the leg starting on
    /// it; 3 "tie + k ulps" (when crossings): a lattice leg and walls[0], walls[1] (added if missing) crossing
    /// it at parameters j/2^q and (j + k)/2^q, ends on the leg or tilted so the crossing rounds; k in [−3, 3].
    /// Exhausted input reads 0: an input this decoder used to read to its end decodes as it did.
    void near_degenerate(std::vector<Wall>& walls, Ball& ball, bool crossings);

private:
    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t pos_ = 0;
    std::vector<Wall> walls_;
    std::vector<Vec2> points_;
};

/// Keeps x in the accepted range: out-of-range or non-finite values become 0.
double clamp_to_range(double x);

/// (1 + a byte) · 2^(base + sign·(the next byte % span)): a number of a chosen magnitude, the mantissa's byte read
/// first (arguments are evaluated in an unspecified order, and an input must decode alike on every platform).
double scaled(ByteReader& in, int base, int sign, unsigned span);

/// Runs scene (decoded from input) under the kernel under test with checks_for(input, checks) (run_checked, no
/// events kept) and, on the first failure, calls fail: a target's whole oracle.
void check_scene(std::string_view target, const Scene& scene, std::span<const Check> checks,
                 std::span<const std::uint8_t> input);

/// Reports failure (of scene under the kernel under test) for target on stderr, writes the failure log
/// (make_failure_log, `from fuzz TARGET SHA1`, the note as a comment) to $RICOCHET_FUZZ_SCENE_OUT if set,
/// then aborts.
[[noreturn]] void fail(std::string_view target, const Scene& scene, const CheckFailure& failure);

}  // namespace ricochet::fuzz
