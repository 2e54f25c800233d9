// Fuzz target `static`: the four static tests (point/circle, circle/circle, point/rectangle,
// rectangle/rectangle) and the classification of a point against a wall, as a frames-0 scene.
// Oracle: the shared checker (run_checked) with the checks below, exactly as `ricochet replay` runs
// them on the saved log.
#include <cstdint>
#include <vector>

#include "fuzz_common.hpp"

namespace ricochet::fuzz {
namespace {

/// The geometry a static input decodes to.
struct StaticCase {
    Wall wall;
    Circle a, b;
    Rect ra, rb;
    Vec2 p;
    Vec2 v;  ///< a motion starting at p, for the classification/sweep agreement
};

StaticCase decode(const std::uint8_t* data, std::size_t size) {
    ByteReader in(data, size);
    StaticCase c;
    c.wall = in.wall();
    c.a = in.circle();
    c.ra = in.rect();
    c.b = in.circle();
    c.rb = in.rect();
    c.p = in.point();
    c.v = in.velocity(c.p);
    // Last, so that inputs read to their end before it decode as they did: the wall and point (or the motion
    // from it) made near-collinear.
    std::vector<Wall> walls = {c.wall};
    Ball ball{c.p, c.v};
    in.near_degenerate(walls, ball, false);
    c.wall = walls.front();
    c.p = ball.pos;
    c.v = ball.vel;
    return c;
}

/// The case as a scene: the wall, the circles and rectangles, and a ball at p moving v, for 0 frames
/// (static checks only).
Scene to_scene(const StaticCase& c) {
    Scene s;
    s.frames = 0;
    s.walls = {c.wall};
    s.balls = {Ball{c.p, c.v}};
    s.circles = {c.a, c.b};
    s.rects = {c.ra, c.rb};
    return s;
}

/// The checks this target claims: every check a scene log can name (checks.hpp defines each), as replay
/// runs them, so the target and replay cannot disagree about what was asserted.
constexpr std::span<const Check> k_checks = k_all_checks;

}  // namespace
}  // namespace ricochet::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace ricochet::fuzz;
    check_scene("static", to_scene(decode(data, size)), k_checks, {data, size});
    return 0;
}
