// A scene's domain (domain.hpp, docs/scene-log.md "Domain"): the `domain` lines read, print and round-trip; the
// reader refuses a scene outside its own domain at the number, and a check its domain waives; fit_to_domain
// brings a drawn scene inside by powers of two, or says it cannot; the checks a waived convention switches off are
// not run; RICOCHET_DOMAIN's spelling.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ricochet/checks.hpp"
#include "ricochet/domain.hpp"
#include "ricochet/kernel.hpp"
#include "ricochet/plugin.h"
#include "ricochet/plugin_loader.hpp"
#include "ricochet/scene_log.hpp"
#include "scene_text.hpp"

namespace ricochet {
namespace {

using test::diag;
using test::parse_ok;

TEST(Domain, LinesReadPrintAndRoundTrip) {
    const std::string text =
        "ricochet 1\nkernel robust\nframes 2\ndomain coordinates 1000000\ndomain speed 1000\ndomain wall-length 0.001\n"
        "domain no-subnormals\ndomain waive touching\nwall 0 0 10 0\nball 1 2 3 4\ncheck no-tunnel\n";
    const Scene s = parse_ok(text);
    EXPECT_EQ(s.domain.coordinates, 1e6);
    EXPECT_EQ(s.domain.speed, 1000.0);
    EXPECT_EQ(s.domain.wall_length, 0.001);
    EXPECT_TRUE(s.domain.no_subnormals);
    EXPECT_TRUE(s.domain.waive_touching);
    EXPECT_EQ(write_scene_log(s), text);
    // Without domain lines: the full domain, and nothing written (every older log keeps its bytes).
    const Scene plain = parse_ok("ricochet 1\nwall 0 0 10 0\n");
    EXPECT_TRUE(plain.domain.full());
    EXPECT_EQ(write_scene_log(plain).find("domain"), std::string::npos);
}

TEST(Domain, TheReaderRefusesAsceneOutsideItsDomainAtTheNumber) {
    EXPECT_EQ(diag("ricochet 1\ndomain coordinates 100\nwall 0 0 101 0\n"),
              "t.scene:3:10: error: X1 101 is outside the log's domain (coordinates 100)");
    EXPECT_EQ(diag("ricochet 1\ndomain coordinates 100\nball 0 0 1 1 200\n"),
              "t.scene:3:14: error: R 200 is outside the log's domain (coordinates 100)");
    EXPECT_EQ(diag("ricochet 1\ndomain speed 10\nball 0 0 1 -11\n"),
              "t.scene:3:12: error: VY -11 is outside the log's domain (speed 10)");
    EXPECT_EQ(diag("ricochet 1\ndomain no-subnormals\nball 0 0 5e-324 1\n"),
              "t.scene:3:10: error: VX 5e-324 is subnormal, outside the log's domain (no-subnormals)");
    EXPECT_EQ(diag("ricochet 1\ndomain wall-length 2\nwall 0 0 1 1\n"),
              "t.scene:3:1: error: the wall is shorter than the log's domain (wall-length 2)");
    // Exactly as long: in the domain (|(0, 0) -> (3, 4)| = 5).
    EXPECT_EQ(diag("ricochet 1\ndomain wall-length 5\nwall 0 0 3 4\n"), "parsed");
    EXPECT_EQ(diag("ricochet 1\ndomain waive touching\ncheck oracle\n"),
              "t.scene:3:7: error: check 'oracle' is waived by the log's 'domain waive touching': its kernel does not "
              "promise that touching is a hit");
}

TEST(Domain, BadDomainLinesSayWhy) {
    EXPECT_EQ(diag("ricochet 1\nwall 0 0 1 0\ndomain speed 1\n"),
              "t.scene:3:1: error: 'domain' comes before the first wall, ball, circle, rect, bumper and check (they are "
              "read in it)");
    EXPECT_EQ(diag("ricochet 1\ndomain speed 0\n"), "t.scene:2:14: error: domain speed 0 is not above 0");
    EXPECT_EQ(diag("ricochet 1\ndomain speed 1\ndomain speed 2\n"), "t.scene:3:8: error: duplicate 'domain speed'");
    EXPECT_EQ(diag("ricochet 1\ndomain gravity 1\n"),
              "t.scene:2:8: error: unknown domain 'gravity' (coordinates, speed, wall-length, no-subnormals or waive)");
    EXPECT_EQ(diag("ricochet 1\ndomain waive corners\n"), "t.scene:2:14: error: unknown convention 'corners' (touching)");
    EXPECT_EQ(diag("ricochet 1\ndomain no-subnormals please\n"),
              "t.scene:2:22: error: unexpected 'please' after 'domain' (coordinates C, speed V, wall-length L, "
              "no-subnormals or waive touching expected)");
}

TEST(Domain, FitScalesByPowersOfTwoOrSaysItCannot) {
    Scene s;
    s.walls = {{{-3e9, 0}, {3e9, 1}}};
    s.balls = {{{1, 2}, {5000, -7}, 0.5}};
    Domain d;
    d.coordinates = 1e6;
    d.speed = 100;
    ASSERT_TRUE(fit_to_domain(s, d));
    EXPECT_EQ(s.domain, d);
    // 3e9 · 2^−12 = 732421.875 ≤ 1e6 < 3e9 · 2^−11: every length halved 12 times, exactly.
    EXPECT_EQ(s.walls[0].p0.x, std::ldexp(-3e9, -12));
    EXPECT_EQ(s.balls[0].pos.y, std::ldexp(2.0, -12));
    EXPECT_EQ(s.balls[0].r, std::ldexp(0.5, -12));
    // Then the speed: 5000 · 2^−12 = 1.220703125 fits already.
    EXPECT_EQ(s.balls[0].vel.x, std::ldexp(5000.0, -12));
    EXPECT_FALSE(outside_domain(s, d));
    // A subnormal or a wall too short cannot be brought in: the case is discarded.
    Scene tiny;
    tiny.balls = {{{0, 0}, {5e-324, 1}}};
    EXPECT_FALSE(fit_to_domain(tiny, Domain{.no_subnormals = true}));
    Scene point_wall;
    point_wall.walls = {{{1, 1}, {1, 1}}};
    EXPECT_EQ(outside_domain(point_wall, Domain{.wall_length = 1e-9}),
              std::optional<std::string>("wall 0 is shorter than the domain's wall-length 1e-09"));
}

TEST(Domain, AWaivedConventionSwitchesItsChecksOff) {
    // A leg ending exactly on a wall: touching is a hit, and a kernel that misses it breaks boundary and oracle.
    EXPECT_EQ(waived_checks(Domain{}).size(), 0u);
    const auto waived = waived_checks(Domain{.waive_touching = true});
    ASSERT_EQ(waived.size(), 2u);
    EXPECT_EQ(waived[0], Check::boundary);
    EXPECT_EQ(waived[1], Check::oracle);
    // run_checked leaves them out. A kernel that never counts touching as a hit (a table linked in, plugin.h): a
    // leg ending exactly on a wall breaks the oracle, and holds with the convention waived.
    static const ricochet_plugin table = [] {
        ricochet_plugin t{};
        t.abi_version = RICOCHET_PLUGIN_ABI_VERSION;
        t.struct_size = sizeof(ricochet_plugin);
        t.name = "domain-no-touching";
        t.sweep = [](void*, ricochet_vec2 bs, ricochet_vec2 v, const ricochet_wall* w, ricochet_sweep_result* out) {
            // robust's answer, but a hit at the leg's very end is none.
            const Sweep r = sweep(KernelId::robust, {bs.x, bs.y}, {v.x, v.y}, Wall{{w->p0.x, w->p0.y}, {w->p1.x, w->p1.y}});
            out->miss = r.hit() && r.t < 1 ? RICOCHET_HIT : RICOCHET_MISS;
            out->t = r.t;
            out->point = {r.point.x, r.point.y};
        };
        return t;
    }();
    std::string error;
    const auto k = register_plugin(table, &error);
    ASSERT_TRUE(k) << error;
    Scene s;
    s.kernel = *k;
    s.walls = {{{5, -1}, {5, 1}}};
    s.balls = {{{0, 0}, {5, 0}}};
    s.frames = 1;
    const Check checks[] = {Check::boundary, Check::oracle};
    const CheckedRun judged = run_checked(s, s.kernel, s.frames, checks);
    ASSERT_TRUE(judged.failure);
    EXPECT_EQ(judged.failure->str(),
              "oracle broke at frame 1 ball 0: leg 0 ((0, 0) -> (5, 0)) against wall 0: the kernel says miss, exactly hit");
    s.domain.waive_touching = true;
    const CheckedRun waived_run = run_checked(s, s.kernel, s.frames, checks);
    EXPECT_FALSE(waived_run.failure) << waived_run.failure->str();
}

TEST(Domain, SpecsReadAndPrint) {
    std::string error;
    const auto d = parse_domain_spec("coordinates=1e6,speed=1000,wall-length=0.001,no-subnormals,waive=touching", &error);
    ASSERT_TRUE(d) << error;
    EXPECT_EQ(domain_spec(*d), "coordinates=1000000,speed=1000,wall-length=0.001,no-subnormals,waive=touching");
    EXPECT_TRUE(parse_domain_spec("", &error)->full());
    EXPECT_FALSE(parse_domain_spec("speed=-1", &error));
    EXPECT_EQ(error, "'speed' needs a number above 0 and at most 2^256: speed=-1");
    EXPECT_FALSE(parse_domain_spec("speed", &error));
    EXPECT_EQ(error, "'speed' needs a number above 0 and at most 2^256: speed=X");
    EXPECT_FALSE(parse_domain_spec("no-subnormals,no-subnormals", &error));
    EXPECT_EQ(error, "'no-subnormals' is given twice");
    EXPECT_FALSE(parse_domain_spec("waive=corners", &error));
    EXPECT_EQ(error, "unknown domain item 'waive=corners' (coordinates=C, speed=V, wall-length=L, no-subnormals, "
                     "waive=touching)");
}

}  // namespace
}  // namespace ricochet
