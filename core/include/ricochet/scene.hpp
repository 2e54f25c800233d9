// Scenes: walls, point balls, static circles and rectangles, stepped frame by frame by a kernel
// into events. The same scene gives the same events, bit for bit, on every run.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ricochet/kernel.hpp"
#include "ricochet/shapes.hpp"

namespace ricochet {

/// An invariant that replay asserts on every frame (scene-log `check NAME`).
enum class Check : std::uint8_t { no_tunnel, symmetry, boundary, speed, deterministic, oracle };
/// The check's name as logs spell it ("no-tunnel", …).
std::string_view check_name(Check c);
/// The check called name, or nothing.
std::optional<Check> parse_check(std::string_view name);

/// `expect state F I X Y VX VY`: ball I's state at the end of frame F.
struct ExpectState {
    std::int64_t frame = 0;
    std::uint32_t ball = 0;
    Ball state;
    friend bool operator==(const ExpectState&, const ExpectState&) = default;
};
/// `expect failure CHECK F`: the run must break CHECK first at frame F.
struct ExpectFailure {
    Check check = Check::no_tunnel;
    std::int64_t frame = 0;
    friend bool operator==(const ExpectFailure&, const ExpectFailure&) = default;
};

/// Largest accepted `frames N`.
inline constexpr std::int64_t k_max_frames = 10'000'000;

/// Everything a scene log holds.
struct Scene {
    KernelId kernel = KernelId::robust;
    std::int64_t frames = 0;
    std::vector<Wall> walls;
    std::vector<Ball> balls;
    std::vector<Circle> circles;
    std::vector<Rect> rects;
    std::vector<Check> checks;                  ///< in order of appearance, no duplicates
    std::optional<std::uint64_t> expect_hash;
    std::vector<ExpectState> expect_states;
    std::optional<ExpectFailure> expect_failure;
    std::vector<std::string> provenance;        ///< the words after each `from`, verbatim
    friend bool operator==(const Scene&, const Scene&) = default;  ///< bit-for-bit (see same_bits)
};

/// One line of `ricochet run`'s output.
struct Event {
    enum class Kind : std::uint8_t { state, hit, overlap };
    enum class Shape : std::uint8_t { none, circle, rect };
    Kind kind = Kind::state;
    std::int64_t frame = 0;
    std::uint32_t ball = 0;
    Shape shape = Shape::none;   ///< overlap: which kind of static shape
    std::uint32_t index = 0;     ///< hit: the wall; overlap: the circle or rect
    Vec2 pos;                    ///< state: position; hit: the hit point
    Vec2 vel;                    ///< state: velocity
    friend bool operator==(const Event&, const Event&) = default;
};

}  // namespace ricochet
