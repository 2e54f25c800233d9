// Scene: everything a scene log holds, walls, balls (points or discs), bumpers, static circles and
// rectangles, the checks and the expectations. Stepped frame by frame by a kernel into events
// (world.hpp); the same scene gives the same events, bit for bit, on every run.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ricochet/check.hpp"
#include "ricochet/domain.hpp"
#include "ricochet/event.hpp"
#include "ricochet/expect.hpp"
#include "ricochet/kernel_id.hpp"
#include "ricochet/shapes.hpp"

namespace ricochet {

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
    std::vector<Bumper> bumpers;                ///< solid circles balls bounce off
    /// `balls collide`: every pair of balls with R_i + R_j > 0 is solid to each other (docs/scene-log.md, "Balls
    /// that meet"); false, balls pass through each other.
    bool balls_collide = false;
    /// Each ball's mass (`ball X Y VX VY R M`), one per ball; empty where no ball line gave one (every mass 1).
    std::vector<double> masses;
    std::vector<Check> checks;                  ///< in order of appearance, no duplicates
    std::optional<std::uint64_t> expect_hash;
    std::vector<ExpectState> expect_states;
    std::optional<ExpectFailure> expect_failure;
    std::optional<Found> found;                 ///< what the run that saved the log showed (`found`)
    std::vector<std::string> provenance;        ///< the words after each `from`, verbatim
    Domain domain;                              ///< what the scene is drawn from and judged in (`domain` lines)
    friend bool operator==(const Scene&, const Scene&) = default;  ///< by value (same_bits compares bits)
};

/// Ball i's mass: masses[i], or 1 where the scene gives none.
inline double mass_of(const Scene& scene, std::size_t i) { return scene.masses.empty() ? 1.0 : scene.masses[i]; }

/// True if the scene has a disc (a ball of radius > 0) or a bumper: some checks read differently for it
/// (checks.hpp, "Discs and bumpers").
inline bool has_discs_or_bumpers(const Scene& scene) {
    if (!scene.bumpers.empty()) return true;
    for (const Ball& b : scene.balls)
        if (is_disc(b)) return true;
    return false;
}

}  // namespace ricochet
