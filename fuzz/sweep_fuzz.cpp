// Fuzz target `sweep`: one point ball against one to four walls for one to three frames.
// Oracle: every per-wall decision (hit, or which of the five tests / degenerate cases misses) equals
// the exact kernel's; reversing a wall never changes whether it is hit; the first wall hit in the
// first frame is the exact kernel's; the printed path never tunnels (TunnelChecker, exact); a hit
// time lies in [0, 1]; for robust and exact, bounces keep |v| within the stated bound.
#include <cmath>
#include <cstdint>
#include <vector>

#include <fmt/format.h>

#include "fuzz_common.hpp"
#include "ricochet/tunnel.hpp"

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

std::string show(Vec2 p) { return fmt::format("({}, {})", p.x, p.y); }

[[noreturn]] void failed(const SweepCase& c, Check check, std::int64_t frame, std::string kind, std::string what) {
    fail("sweep", Failure{check, frame, std::move(kind), std::move(what)}, to_scene(c));
}

void check_decisions(KernelId k, const SweepCase& c) {
    const Vec2 bs = c.ball.pos, v = c.ball.vel;
    for (std::uint32_t i = 0; i < c.walls.size(); ++i) {
        const Wall& w = c.walls[i];
        const Sweep got = sweep(k, bs, v, w);
        const Sweep want = sweep(KernelId::exact, bs, v, w);
        if (got.miss != want.miss)
            failed(c, Check::oracle, 1, "decision",
                   fmt::format("ball {} + {} against wall {} {}→{}: {} says {}, exact says {}", show(bs), show(v), i,
                               show(w.p0), show(w.p1), kernel_name(k), miss_name(got.miss), miss_name(want.miss)));
        if (got.hit() && !(got.t >= 0.0 && got.t <= 1.0))
            failed(c, Check::oracle, 1, "hit-time", fmt::format("wall {}: t_i = {} outside [0, 1]", i, got.t));
        // Reversing P0 → P1 flips n but the segment, and so the hit, stays.
        const Sweep back = sweep(k, bs, v, reversed(w));
        if (back.hit() != got.hit())
            failed(c, Check::symmetry, 1, "reversed-wall",
                   fmt::format("wall {}: hit {} but reversed wall hit {}", i, got.hit(), back.hit()));
    }
}

void check_frames(KernelId k, const SweepCase& c) {
    Ball ball = c.ball;
    BallMemory memory;
    std::vector<HitEvent> hits;
    StepScratch scratch;
    const Ball start = c.ball;
    TunnelChecker tunnel(c.walls, std::span<const Ball>(&start, 1));
    // The first frame's first hit must be the exact kernel's (the ordering of crossings is a decision).
    {
        Ball eb = c.ball;
        BallMemory em;
        std::vector<HitEvent> eh;
        StepScratch es;
        Ball kb = c.ball;
        BallMemory km;
        std::vector<HitEvent> kh;
        const FrameStatus est = step_ball(KernelId::exact, eb, em, c.walls, eh, es);
        const FrameStatus kst = step_ball(k, kb, km, c.walls, kh, scratch);
        if (est != FrameStatus::out_of_range && kst != FrameStatus::out_of_range) {
            const long want = eh.empty() ? -1 : static_cast<long>(eh.front().wall);
            const long got = kh.empty() ? -1 : static_cast<long>(kh.front().wall);
            if (want != got)
                failed(c, Check::oracle, 1, "first-hit",
                       fmt::format("frame 1: {} hits wall {} first, exact wall {} (-1: none)", kernel_name(k), got, want));
        }
    }
    for (std::int64_t f = 1; f <= c.frames; ++f) {
        hits.clear();
        const Vec2 v0 = ball.vel;
        const FrameStatus st = step_ball(k, ball, memory, c.walls, hits, scratch);
        if (st == FrameStatus::out_of_range) return;
        for (const HitEvent& h : hits) {
            if (auto w = tunnel.advance(0, h.point))
                failed(c, Check::no_tunnel, f, "tunnel",
                       fmt::format("frame {}: the piece to hit point {} crosses wall {}", f, show(h.point), *w));
        }
        if (auto w = tunnel.advance(0, ball.pos))
            failed(c, Check::no_tunnel, f, "tunnel",
                   fmt::format("frame {}: the piece to end point {} crosses wall {}", f, show(ball.pos), *w));
        if ((k == KernelId::robust || k == KernelId::exact) && !hits.empty()) {
            // | |v'| − |v| | ≤ bound·|v| per bounce; a frame has at most k_max_bounces hits plus as many
            // reflections off contact walls, and |v| itself is rounded (a few ulps).
            const double n0 = length(v0), n1 = length(ball.vel);
            const double tol = (2.0 * (k_max_bounces + 1) * k_speed_rel_bound + 0x1p-50) * n0;
            if (std::isfinite(n0) && std::isfinite(n1) && n0 > 0x1p-400 && n0 < 0x1p400 && std::fabs(n1 - n0) > tol)
                failed(c, Check::speed, f, "speed", fmt::format("frame {}: |v| {} became {}", f, n0, n1));
        }
    }
}

}  // namespace
}  // namespace ricochet::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace ricochet::fuzz;
    const ricochet::KernelId k = kernel_under_test();
    const SweepCase c = decode(data, size);
    check_decisions(k, c);
    check_frames(k, c);
    return 0;
}
