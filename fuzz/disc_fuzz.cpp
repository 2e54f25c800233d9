// Fuzz target `disc`: a small scene of discs (balls with radii), bumpers and walls decoded from the bytes (a
// closed box, a chain of walls sharing end points, free walls, bumpers, balls of radius 0, −0, subnormal, tiny,
// ordinary or huge, placed anywhere or exactly at their radius from a wall's line, an end point or a bumper) and
// stepped for up to 32 frames by the kernel under test.
//
// Why a target of its own rather than radii in `scene`: radii in `scene` would change what every committed `scene`
// input decodes to, and a kernel that steps point balls only (a peer, a plug-in without sweep_disc) could no longer
// run `scene`; here every input is a disc scene, with a corpus and a dictionary of its own, and `scene` keeps its
// meaning.
// Oracle: the shared checker (run_checked) with every check, as `ricochet replay` runs them on the saved log, so
// every failure replays.
//
// A kernel that steps point balls only cannot be fuzzed here: the target says so and exits with status 2 on its
// start (the campaign refuses `--target disc` for such a kernel before starting). A kernel that steps discs
// among walls only gets scenes without bumpers.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>
#include <vector>

#include <fmt/core.h>

#include "fuzz_common.hpp"
#include "ricochet/checks.hpp"
#include "ricochet/kernel_spec.hpp"

namespace ricochet::fuzz {
namespace {

/// Most frames a decoded scene runs.
constexpr std::int64_t k_disc_max_frames = 32;


/// A radius from every regime: zero of both signs, subnormal, tiny, a small dyadic, any number, huge (to 2^256).
double radius(ByteReader& in) {
    switch (in.u8() % 8) {
        case 0: return 0.0;
        case 1: return -0.0;
        case 2: return scaled(in, -1000, -1, 75);                  // subnormal or nearly
        case 3: return scaled(in, -20, -1, 64);                    // tiny
        case 4: return clamp_to_range(scaled(in, 30, 1, 220));     // huge
        case 5: return in.magnitude();
        default: return scaled(in, 0, -1, 9);                      // 1/256 .. 256
    }
}

/// |e|, the same double on every platform: std::hypot is libm's and not correctly rounded everywhere; this is
/// scaled by a power of two (exact) around one correctly rounded square root.
double length(Vec2 e) {
    const double big = std::fmax(std::fabs(e.x), std::fabs(e.y));
    if (big == 0.0 || !std::isfinite(big)) return big;
    int k = 0;
    std::frexp(big, &k);
    const double x = std::ldexp(e.x, -k), y = std::ldexp(e.y, -k);
    return std::ldexp(std::sqrt(x * x + y * y), k);
}

/// p moved by d along an axis direction (±x, ±y): exactly tangent where the sum is exact.
Vec2 along_axis(Vec2 p, double d, unsigned dir) {
    switch (dir % 4) {
        case 0: return {clamp_to_range(p.x + d), p.y};
        case 1: return {p.x, clamp_to_range(p.y + d)};
        case 2: return {clamp_to_range(p.x - d), p.y};
        default: return {p.x, clamp_to_range(p.y - d)};
    }
}

/// The scene an input decodes to; bumpers only if the kernel steps them.
Scene decode(const std::uint8_t* data, std::size_t size, bool bumpers) {
    ByteReader in(data, size);
    Scene s;
    s.kernel = kernel_under_test();
    const auto add_wall = [&](const Wall& w) {
        s.walls.push_back(w);
        in.remember(w);
        in.remember(w.p0);
        in.remember(w.p1);
    };
    const unsigned shape = in.u8() % 4;
    if (shape == 0) {
        // A closed box, clockwise so that every outward normal points out (as `scene` builds it).
        const Vec2 a = in.point(), b = in.point();
        const double l = std::fmin(a.x, b.x), r = std::fmax(a.x, b.x), bo = std::fmin(a.y, b.y), t = std::fmax(a.y, b.y);
        const Vec2 c[4] = {{l, bo}, {r, bo}, {r, t}, {l, t}};
        for (int i = 0; i < 4; ++i) add_wall({c[(i + 1) % 4], c[i]});
    } else if (shape == 1) {
        // A chain of walls sharing end points: joints P + i·e (collinear where the products are exact), a joint
        // sometimes moved a few ulps or bent by a second step, a wall sometimes reversed.
        const Vec2 p = in.point();
        const Vec2 e{in.number(), in.number()};
        const unsigned n = 2 + in.below(5);
        Vec2 prev = p;
        for (unsigned i = 1; i <= n; ++i) {
            Vec2 next{clamp_to_range(p.x + double(i) * e.x), clamp_to_range(p.y + double(i) * e.y)};
            if (in.u8() % 8 == 0) next = {in.nudge(next.x), in.nudge(next.y)};
            Wall w{prev, next};
            if (in.u8() & 1) std::swap(w.p0, w.p1);
            add_wall(w);
            prev = next;
        }
    }
    const unsigned free_walls = in.below(shape == 3 ? 5 : 3);
    for (unsigned i = 0; i < free_walls; ++i) add_wall(in.wall());
    const unsigned bumper_count = in.below(4);
    for (unsigned i = 0; i < bumper_count && bumpers; ++i) {
        Bumper u{in.point(), radius(in)};
        u.r = std::fabs(u.r);
        s.bumpers.push_back(u);
        in.remember(u.c);
    }
    const unsigned balls = 1 + in.below(3);
    for (unsigned i = 0; i < balls; ++i) {
        Ball b;
        b.r = radius(in);
        const double reach = std::fabs(b.r);
        switch (in.u8() % 5) {
            case 0:
                if (!s.walls.empty()) {
                    // At its radius from a wall's line, beside a point of it: exact for axis-aligned walls.
                    const Wall& w = s.walls[in.u8() % s.walls.size()];
                    const Vec2 e = w.p1 - w.p0;
                    const double len = length(e);
                    const double fm = static_cast<std::int8_t>(in.u8());
                    const double f = std::ldexp(fm, -static_cast<int>(in.u8() % 8));
                    const Vec2 on{clamp_to_range(w.p0.x + f * e.x), clamp_to_range(w.p0.y + f * e.y)};
                    const double side = in.u8() & 1 ? 1.0 : -1.0;
                    b.pos = len > 0 && std::isfinite(reach / len)
                                ? Vec2{clamp_to_range(on.x + side * (reach / len) * e.y), clamp_to_range(on.y - side * (reach / len) * e.x)}
                                : on;
                    break;
                }
                [[fallthrough]];
            case 1:
                if (!s.walls.empty()) {
                    // At its radius from an end point, along an axis: touching the cap.
                    const Wall& w = s.walls[in.u8() % s.walls.size()];
                    const Vec2 end = in.u8() & 1 ? w.p1 : w.p0;
                    b.pos = along_axis(end, reach, in.u8());
                    break;
                }
                [[fallthrough]];
            case 2:
                if (!s.bumpers.empty()) {
                    // At R + r from a bumper's centre, along an axis: touching it.
                    const Bumper& u = s.bumpers[in.u8() % s.bumpers.size()];
                    b.pos = along_axis(u.c, clamp_to_range(reach + u.r), in.u8());
                    break;
                }
                [[fallthrough]];
            default: b.pos = in.point();
        }
        if (in.u8() % 4 == 0) b.pos = {in.nudge(b.pos.x), in.nudge(b.pos.y)};
        // Free, toward a point (a joint, an end point, a bumper's centre), or along a wall: sliding at its radius.
        b.vel = in.velocity(b.pos);
        in.remember(b.pos);
        s.balls.push_back(b);
    }
    s.frames = 1 + in.below(static_cast<unsigned>(k_disc_max_frames));
    return s;
}

/// The checks this target claims: every check (each is defined for discs and bumpers), as replay runs them on the
/// saved log.
const std::vector<Check>& disc_checks() {
    static const std::vector<Check> checks(k_all_checks.begin(), k_all_checks.end());
    return checks;
}

/// Whether the kernel under test steps bumpers; exits with status 2, saying why, if it steps no discs at all.
bool kernel_steps_bumpers() {
    static const bool steps = [] {
        const KernelOps& ops = kernel_ops(kernel_under_test());
        if (ops.step_disc == nullptr) {
            fmt::print(stderr, "fuzz_disc: error: kernel '{}' steps point balls only: the disc target needs a kernel that "
                               "steps discs (lecture-float, lecture-double, robust, exact)\n", ops.name);
            std::exit(2);
        }
        return ops.steps_bumpers;
    }();
    return steps;
}

}  // namespace
}  // namespace ricochet::fuzz

// libFuzzer asks the kernel before the first input, so that a kernel without discs stops the run without an
// artifact; the standalone driver (gcc) asks on the first input. A plug-in (plugin.h ABI version 2 steps discs) is
// asked on the first input too: loading it installs the plug-in guard's signal handlers, and libFuzzer, finding a
// handler already there, would install none of its own for SIGABRT, so a failure found (or a crash) would end the
// worker with no artifact. Loaded after libFuzzer's handlers, the guard hands them on, as in the other targets,
// which load every kernel on the first input. (The campaign refuses a plug-in without discs before any worker
// starts.)
extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
    const char* spec = std::getenv(ricochet::fuzz::k_kernel_env);
    if (spec == nullptr || !std::string_view(spec).starts_with(ricochet::k_plugin_spec_prefix))
        (void)ricochet::fuzz::kernel_steps_bumpers();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace ricochet::fuzz;
    check_scene("disc", decode(data, size, kernel_steps_bumpers()), disc_checks(), {data, size});
    return 0;
}
