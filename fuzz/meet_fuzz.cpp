// Fuzz target `meet`: a small scene of balls that meet (`balls collide`, docs/scene-log.md "Balls that meet") decoded
// from the bytes — 2 to 6 balls of radius 0, tiny, ordinary or huge and of mass 1, unequal or extreme, placed anywhere,
// near another ball or touching it (at R_i + R_j along an axis: a chain of them is a Newton's cradle), at rest, moving
// freely or aimed at where another ball will be after a quarter to four frames — in the open, in a box given by two
// points or in a box around the balls — stepped for up to 16 frames by the kernel under test.
//
// Why a target of its own rather than `balls collide` in `disc`: it would change what every committed disc input
// decodes to, and a kernel that steps discs but no meets could no longer run `disc`; here every input is a meeting
// scene, with a corpus of its own (corpus/meet/), and `disc` keeps its meaning. Oracle: the shared checker
// (run_checked) with every check (meet_checks()), as `ricochet replay` runs them on the saved log.
//
// A kernel that steps no meets (a peer, a plug-in) cannot be fuzzed here: the target says so and exits with status 2
// on its start (the campaign leaves `meet` out for such a kernel, and refuses it when named).
#include <algorithm>
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
constexpr std::int64_t k_meet_max_frames = 16;


/// A radius: 0 (a point ball, which meets discs only), tiny, m/64, any small dyadic, huge, or any magnitude.
double radius(ByteReader& in) {
    switch (in.u8() % 6) {
        case 0: return 0.0;
        case 1: return scaled(in, -20, -1, 64);                // tiny: 2^-20 .. 2^-83 (times 1..256)
        case 2: return (1.0 + in.u8()) / 64.0;                 // 1/64 .. 4
        case 3: return scaled(in, 0, -1, 9);                   // 1/256 .. 256
        case 4: return clamp_to_range(scaled(in, 20, 1, 40));  // huge: 2^20 .. 2^59 (times 1..256)
        default: return in.magnitude();
    }
}

/// A mass: mostly 1, else 2, 1/2, 3, 1/1000, 1000, or (1 + m/256)·2^e for e in −128..127 (the spec's range is
/// 2^−256 .. 2^256).
double mass(ByteReader& in) {
    switch (in.u8() % 8) {
        case 4: return 2.0;
        case 5: return 0.5;
        case 6: {
            constexpr double k_unequal[3] = {3.0, 1e-3, 1e3};
            return k_unequal[in.u8() % 3];
        }
        case 7: {
            const double m = 1.0 + in.u8() / 256.0;
            return std::ldexp(m, static_cast<std::int8_t>(in.u8()));
        }
        default: return 1.0;
    }
}

/// p moved by d along an axis direction (±x, ±y): exactly touching where the sum is exact.
Vec2 along_axis(Vec2 p, double d, unsigned dir) {
    switch (dir % 4) {
        case 0: return {clamp_to_range(p.x + d), p.y};
        case 1: return {p.x, clamp_to_range(p.y + d)};
        case 2: return {clamp_to_range(p.x - d), p.y};
        default: return {p.x, clamp_to_range(p.y - d)};
    }
}

/// The four walls of the box with corners a and b, clockwise (as `scene` and `disc` build theirs).
void add_box(Scene& s, ByteReader& in, Vec2 a, Vec2 b) {
    const double l = std::fmin(a.x, b.x), r = std::fmax(a.x, b.x), bo = std::fmin(a.y, b.y), t = std::fmax(a.y, b.y);
    const Vec2 c[4] = {{l, bo}, {r, bo}, {r, t}, {l, t}};
    for (int i = 0; i < 4; ++i) {
        const Wall w{c[(i + 1) % 4], c[i]};
        s.walls.push_back(w);
        in.remember(w);
    }
}

/// The scene an input decodes to. Layout: shape, ball count, how masses are given, a common mass, then per ball its
/// radius, placement, velocity and (if each has its own) mass; then the box around the balls (shape 2); then frames.
Scene decode(const std::uint8_t* data, std::size_t size) {
    ByteReader in(data, size);
    Scene s;
    s.kernel = kernel_under_test();
    s.balls_collide = true;
    const unsigned shape = in.u8() % 3;  // 0 open, 1 a box given by two points, 2 a box around the balls
    if (shape == 1) {
        const Vec2 a = in.point(), b = in.point();
        add_box(s, in, a, b);
    }
    const unsigned n = 2 + in.below(5);
    const unsigned masses = in.u8() % 3;  // 0 none (every 1), 1 all the common one, 2 each its own
    const double common = mass(in);
    for (unsigned i = 0; i < n; ++i) {
        Ball b;
        b.r = radius(in);
        const unsigned place = in.u8() % 4;
        if (i > 0 && place == 0) {
            // Touching ball j: at |R_j| + |R| from its centre along an axis (a chain of these: a cradle).
            const Ball& o = s.balls[in.u8() % i];
            b.pos = along_axis(o.pos, clamp_to_range(std::fabs(o.r) + std::fabs(b.r)), in.u8());
        } else if (i > 0 && place == 1) {
            // Near ball j: a small step away.
            const Vec2 o = s.balls[in.u8() % i].pos;
            const double dx = in.number(), dy = in.number();
            b.pos = {clamp_to_range(o.x + dx), clamp_to_range(o.y + dy)};
        } else {
            b.pos = in.point();
        }
        if (in.u8() % 4 == 0) b.pos = {in.nudge(b.pos.x), in.nudge(b.pos.y)};
        switch (in.u8() % 4) {
            case 0: break;  // at rest
            case 1:
                if (i > 0) {
                    // Aimed at where ball j will be after τ = 2^(k − 2) frames: v = (X_j + τ·v_j − X)/τ.
                    const Ball& o = s.balls[in.u8() % i];
                    const double tau = std::ldexp(1.0, static_cast<int>(in.u8() % 5) - 2);
                    b.vel = {clamp_to_range((clamp_to_range(o.pos.x + tau * o.vel.x) - b.pos.x) / tau),
                             clamp_to_range((clamp_to_range(o.pos.y + tau * o.vel.y) - b.pos.y) / tau)};
                    break;
                }
                [[fallthrough]];
            case 2: b.vel = in.velocity(b.pos); break;
            default: {
                const double vx = in.number(), vy = in.number();
                b.vel = {vx, vy};
            }
        }
        if (masses != 0) s.masses.push_back(masses == 2 ? mass(in) : common);
        in.remember(b.pos);
        s.balls.push_back(b);
    }
    if (shape == 2) {
        // A box around every ball, clear of each by twice the largest radius and a margin.
        double reach = 0.0;
        Vec2 lo = s.balls[0].pos, hi = lo;
        for (const Ball& b : s.balls) {
            reach = std::fmax(reach, std::fabs(b.r));
            lo = {std::fmin(lo.x, b.pos.x), std::fmin(lo.y, b.pos.y)};
            hi = {std::fmax(hi.x, b.pos.x), std::fmax(hi.y, b.pos.y)};
        }
        const double m = clamp_to_range(2 * reach + 1 + in.magnitude());
        add_box(s, in, {clamp_to_range(lo.x - m), clamp_to_range(lo.y - m)},
                {clamp_to_range(hi.x + m), clamp_to_range(hi.y + m)});
    }
    s.frames = 1 + in.below(static_cast<unsigned>(k_meet_max_frames));
    return s;
}

/// The checks this target claims, as replay runs them on the saved log: every check, each of which reads meets.
const std::vector<Check>& meet_checks() {
    static const std::vector<Check> checks(k_all_checks.begin(), k_all_checks.end());
    return checks;
}

/// Exits with status 2, saying why, if the kernel under test steps no meets (or no discs, which every ball of a scene
/// whose balls meet is stepped as).
void require_meets() {
    static const bool checked = [] {
        const KernelOps& ops = kernel_ops(kernel_under_test());
        if (ops.meet_rule == MeetRule::none || ops.step_disc == nullptr) {
            fmt::print(stderr,
                       "fuzz_meet: error: kernel '{}' does not step balls that meet ('balls collide'): the meet "
                       "target needs one that does (lecture-float, lecture-double, robust, exact)\n",
                       ops.name);
            std::exit(2);
        }
        return true;
    }();
    (void)checked;
}

}  // namespace
}  // namespace ricochet::fuzz

// libFuzzer asks the kernel before the first input, so that a kernel without meets stops the run without an artifact;
// a plug-in is asked on the first input (as in `disc`: loading it first would install the plug-in guard's handlers
// before libFuzzer's).
extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
    const char* spec = std::getenv(ricochet::fuzz::k_kernel_env);
    if (spec == nullptr || !std::string_view(spec).starts_with(ricochet::k_plugin_spec_prefix))
        ricochet::fuzz::require_meets();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace ricochet::fuzz;
    require_meets();
    check_scene("meet", decode(data, size), meet_checks(), {data, size});
    return 0;
}
