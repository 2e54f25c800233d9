// The scene of `ricochet bench meet` (meet_scene.hpp).
#include "meet_scene.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ricochet::meet_bench {
namespace {

/// splitmix64: a small generator whose sequence is fixed by its seed on every platform.
struct SplitMix {
    std::uint64_t s;
    std::uint64_t next() {
        std::uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }
    /// Uniform in [0, 1): the top 53 bits.
    double unit() { return static_cast<double>(next() >> 11) * 0x1p-53; }
};

/// x rounded to a multiple of 2^-14.
double grid(double x) { return std::round(x * 0x1p14) * 0x1p-14; }

}  // namespace

MeetScene make_scene(int n, double r, double v_max, std::int64_t frames, std::uint64_t seed) {
    if (n < 1 || !(r > 0.0) || !(v_max >= 0.0)) throw std::invalid_argument("meet scene: n >= 1, r > 0, v_max >= 0");
    MeetScene s;
    s.r = r;
    s.v_max = v_max;
    s.frames = frames;
    // n·πr² = k_area_fraction·side²
    const int k = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(n))));
    s.side = std::ceil(std::sqrt(n * std::numbers::pi * r * r / k_area_fraction) * 256.0) / 256.0;
    const double cell = s.side / k;
    // A centre may move this far from its cell's centre and stay k_start_gap clear of its neighbours' discs (each
    // within its own cell) and of the walls (the grid's outer cells end at the box's sides), after rounding to grid().
    const double jitter = 0.5 * cell - r - 0.5 * k_start_gap - 0x1p-13;
    if (!(jitter >= 0.0)) throw std::invalid_argument("meet scene: the discs do not fit their cells");
    if (s.side >= 0x1p9 || v_max >= 0x1p9) throw std::invalid_argument("meet scene: too large for Box2D's floats");
    SplitMix rng{seed};
    for (int i = 0; i < n; ++i) {
        const double cx = (i % k + 0.5) * cell, cy = (i / k + 0.5) * cell;
        const double x = grid(cx + jitter * (2.0 * rng.unit() - 1.0));
        const double y = grid(cy + jitter * (2.0 * rng.unit() - 1.0));
        const double speed = v_max * rng.unit(), angle = 2.0 * std::numbers::pi * rng.unit();
        s.balls.push_back({{x, y}, {grid(speed * std::cos(angle)), grid(speed * std::sin(angle))}, r});
    }
    return s;
}

Scene to_scene(const MeetScene& s) {
    Scene scene;
    scene.frames = s.frames;
    const double a = s.side;
    scene.walls = {{{0, 0}, {a, 0}}, {{a, 0}, {a, a}}, {{a, a}, {0, a}}, {{0, a}, {0, 0}}};
    scene.balls = s.balls;
    scene.balls_collide = true;
    return scene;
}

}  // namespace ricochet::meet_bench
