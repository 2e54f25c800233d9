// Fuzz target `scene`: a whole small scene decoded from the bytes (an optional closed box, free
// walls, balls, circles, rectangles) stepped for up to 32 frames by the kernel under test.
// Oracle: the shared checker (run_checked) with the checks below, exactly as `ricochet replay` runs
// them on the saved log, so every failure replays.
#include <cmath>
#include <cstdint>

#include "fuzz_common.hpp"
#include "ricochet/checks.hpp"

namespace ricochet::fuzz {
namespace {

/// Most frames a decoded scene runs (keeps one input well under a millisecond).
constexpr std::int64_t k_scene_max_frames = 32;

/// The scene a scene input decodes to.
Scene decode(const std::uint8_t* data, std::size_t size) {
    ByteReader in(data, size);
    Scene s;
    s.kernel = kernel_under_test();
    const unsigned shape = in.u8();
    if (shape % 2 == 0) {
        // A closed box, corners listed counter-clockwise so that every outward normal points out.
        const Vec2 a = in.point(), b = in.point();
        const double l = std::fmin(a.x, b.x), r = std::fmax(a.x, b.x), bo = std::fmin(a.y, b.y), t = std::fmax(a.y, b.y);
        const Vec2 c[4] = {{l, bo}, {r, bo}, {r, t}, {l, t}};
        for (int i = 0; i < 4; ++i) {
            const Wall w{c[(i + 1) % 4], c[i]};  // clockwise P0 → P1: normal (e_y, −e_x) points out
            s.walls.push_back(w);
            in.remember(w);
            in.remember(c[i]);
        }
    }
    const unsigned free_walls = in.below(shape % 2 == 0 ? 3 : 6);
    for (unsigned i = 0; i < free_walls; ++i) s.walls.push_back(in.wall());
    const unsigned balls = 1 + in.below(3);
    for (unsigned i = 0; i < balls; ++i) {
        Ball b;
        b.pos = in.point();
        b.vel = in.velocity(b.pos);
        s.balls.push_back(b);
    }
    const unsigned circles = in.below(3);
    for (unsigned i = 0; i < circles; ++i) s.circles.push_back(in.circle());
    const unsigned rects = in.below(3);
    for (unsigned i = 0; i < rects; ++i) s.rects.push_back(in.rect());
    s.frames = 1 + in.below(static_cast<unsigned>(k_scene_max_frames));
    return s;
}

/// The checks this target claims: every check a scene log can name (checks.hpp defines each), as replay
/// runs them, so the target and replay cannot disagree about what was asserted.
constexpr std::span<const Check> k_checks = k_all_checks;

}  // namespace
}  // namespace ricochet::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace ricochet::fuzz;
    check_scene("scene", decode(data, size), k_checks, {data, size});
    return 0;
}
