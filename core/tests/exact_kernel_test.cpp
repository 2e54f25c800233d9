// The exact kernel against its first (mpq) version, bit for bit: every static answer, every sweep and
// reflection, and multi-frame step_ball runs (hits, ball, memory, status) on random, grid-aligned
// (touching, corners, parallel legs), nearly degenerate and extreme-exponent inputs.
#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "kernel_impl.hpp"

namespace ricochet::exact_reference {
Side classify(Vec2 p, const Wall& w);
bool point_in_circle(Vec2 p, const Circle& c);
bool circles_overlap(const Circle& a, const Circle& b);
Sweep sweep(Vec2 bs, Vec2 v, const Wall& w);
Vec2 reflect(Vec2 v, const Wall& w);
FrameStatus step_ball(Ball& ball, BallMemory& memory, std::span<const Wall> walls, std::vector<HitEvent>& hits,
                      StepScratch& scratch);
}  // namespace ricochet::exact_reference

namespace ricochet {
namespace {

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }
bool same(Vec2 a, Vec2 b) { return bits(a.x) == bits(b.x) && bits(a.y) == bits(b.y); }

/// Inputs of one of several styles, chosen per case.
struct Gen {
    std::mt19937_64 rng;
    int style = 0;
    int max_exp = 1023;

    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
    int below(int n) { return static_cast<int>(rng() % static_cast<std::uint64_t>(n)); }
    double any() {
        switch (style) {
            case 0: return below(17) - 8.0;                              // small grid: on lines, corners
            case 1: return (below(129) - 64) * 0x1p-3;                   // finer grid
            case 2: return uniform(-100.0, 100.0);                       // generic
            case 3: {                                                    // one shared exponent band
                const double m = uniform(-1.0, 1.0);
                return std::ldexp(m, below(9) - 4 + (below(2) ? 500 : -500));
            }
            default: {                                                   // any exponent, subnormals too
                const int e = below(max_exp + 1075) - 1074;
                const double m = std::ldexp(static_cast<double>(rng() >> 11), -53);
                const double x = std::ldexp(m, e) * (below(2) ? 1 : -1);
                return std::isfinite(x) ? x : 0.0;
            }
        }
    }
    Vec2 point() { return {any(), any()}; }
    /// Often a point exactly or nearly on w's line.
    Vec2 near_line(const Wall& w) {
        const double f = below(5) * 0.25;
        Vec2 p = w.p0 + f * (w.p1 - w.p0);
        if (below(2)) p.x = std::nextafter(p.x, below(2) ? INFINITY : -INFINITY);
        return p;
    }
};

TEST(ExactKernel, StaticAndSweepMatchTheRationalVersion) {
    Gen g{std::mt19937_64(7)};
    for (int i = 0; i < 100000; ++i) {
        g.style = i % 5;
        const Wall w{g.point(), g.point()};
        const Vec2 p = g.below(3) == 0 ? g.near_line(w) : g.point();
        ASSERT_EQ(exact_kernel::classify(p, w), exact_reference::classify(p, w)) << i;
        const Circle a{g.point(), std::fabs(g.any())}, b{g.point(), std::fabs(g.any())};
        ASSERT_EQ(exact_kernel::point_in_circle(p, a), exact_reference::point_in_circle(p, a)) << i;
        ASSERT_EQ(exact_kernel::circles_overlap(a, b), exact_reference::circles_overlap(a, b)) << i;
        const Vec2 v = g.below(2) ? g.point() : g.near_line(w) - p;
        const Sweep s = exact_kernel::sweep(p, v, w), r = exact_reference::sweep(p, v, w);
        ASSERT_EQ(s.miss, r.miss) << i;
        ASSERT_EQ(bits(s.t), bits(r.t)) << i;
        ASSERT_TRUE(same(s.point, r.point)) << i;
        ASSERT_TRUE(same(exact_kernel::reflect(v, w), exact_reference::reflect(v, w))) << i;
    }
}

void expect_same_frames(Gen& g, int scenes, int frames) {
    for (int sc = 0; sc < scenes; ++sc) {
        std::vector<Wall> walls;
        // A closed box half of the time (corners, contacts), then free walls.
        if (g.below(2)) {
            const double s = g.style == 2 ? 50.0 : 8.0;
            const Vec2 c[4] = {{-s, -s}, {s, -s}, {s, s}, {-s, s}};
            for (int i = 0; i < 4; ++i) walls.push_back({c[(i + 1) % 4], c[i]});
        }
        for (int i = g.below(4); i > 0; --i) walls.push_back({g.point(), g.point()});
        Ball ball{g.point(), g.point()}, ref = ball;
        BallMemory mem, ref_mem;
        StepScratch s1, s2;
        for (int f = 0; f < frames; ++f) {
            std::vector<HitEvent> h1, h2;
            const FrameStatus a = exact_kernel::step_ball(ball, mem, walls, h1, s1);
            const FrameStatus b = exact_reference::step_ball(ref, ref_mem, walls, h2, s2);
            ASSERT_EQ(a, b) << sc << " " << f;
            ASSERT_EQ(h1.size(), h2.size()) << sc << " " << f;
            for (std::size_t i = 0; i < h1.size(); ++i) {
                ASSERT_EQ(h1[i].wall, h2[i].wall);
                ASSERT_EQ(bits(h1[i].t), bits(h2[i].t));
                ASSERT_TRUE(same(h1[i].point, h2[i].point));
            }
            ASSERT_TRUE(same(ball.pos, ref.pos) && same(ball.vel, ref.vel)) << sc << " " << f;
            ASSERT_EQ(mem.count, ref_mem.count);
            for (std::size_t i = 0; i < mem.contacts.size(); ++i) {
                ASSERT_EQ(mem.contacts[i].wall, ref_mem.contacts[i].wall);
                ASSERT_EQ(mem.contacts[i].side, ref_mem.contacts[i].side);
            }
            ASSERT_EQ(mem.bounced_from, ref_mem.bounced_from);
            ASSERT_EQ(mem.bounced_wall, ref_mem.bounced_wall);
            // Keep the ball inside the accepted range, as the dispatcher does.
            if (!(std::fabs(ball.pos.x) <= 0x1p256 && std::fabs(ball.pos.y) <= 0x1p256 &&
                  std::fabs(ball.vel.x) <= 0x1p256 && std::fabs(ball.vel.y) <= 0x1p256))
                break;
        }
    }
}

TEST(ExactKernel, FramesMatchTheRationalVersion) {
    Gen g{std::mt19937_64(11)};
    g.max_exp = 250;
    for (int style = 0; style < 5; ++style) {
        g.style = style;
        expect_same_frames(g, 400, 12);
    }
}

}  // namespace
}  // namespace ricochet
