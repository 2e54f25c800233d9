// Fuzz target `sweep`: one point ball against one to four walls for one to three frames.
// Oracle: the shared checker (run_checked) with the checks below, exactly as `ricochet replay` runs
// them on the saved log.
#include <cstdint>
#include <vector>

#include "fuzz_common.hpp"

namespace ricochet::fuzz {
namespace {

/// The geometry a sweep input decodes to.
struct SweepCase {
    std::vector<Wall> walls;
    Ball ball;
    std::int64_t frames = 1;
};

SweepCase decode(const std::uint8_t* data, std::size_t size) {
    ByteReader in(data, size);
    SweepCase c;
    const unsigned walls = 1 + in.below(4);
    for (unsigned i = 0; i < walls; ++i) c.walls.push_back(in.wall());
    c.ball.pos = in.point();
    c.ball.vel = in.velocity(c.ball.pos);
    c.frames = 1 + in.below(3);
    // Last, so that inputs read to their end before it decode as they did: near-collinear or tied crossings.
    in.near_degenerate(c.walls, c.ball, true);
    return c;
}

/// The case as a scene: its walls, its one ball, its frames.
Scene to_scene(const SweepCase& c) {
    Scene s;
    s.frames = c.frames;
    s.walls = c.walls;
    s.balls = {c.ball};
    return s;
}

/// The checks this target claims: every check a scene log can name (checks.hpp defines each), as replay
/// runs them, so the target and replay cannot disagree about what was asserted.
constexpr std::span<const Check> k_checks = k_all_checks;

}  // namespace
}  // namespace ricochet::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace ricochet::fuzz;
    check_scene("sweep", to_scene(decode(data, size)), k_checks, {data, size});
    return 0;
}
