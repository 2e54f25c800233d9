// RICOCHET_TEST_KERNEL_CLASS and kernel_table<K> (ricochet/properties.hpp): a kernel written as a C++ class of
// static members becomes a plugin.h table whose functions call the class's, with ricochet's conversions; the
// members a class leaves out stay NULL; and the class's kernel is the one under test. Run with
// --gtest_filter='TestKernelClass.*' (the suite's own properties are linked in too).
#include <gtest/gtest.h>

#include <optional>

#include "generators.hpp"
#include "harness.hpp"
#include "ricochet/kernel.hpp"
#include "ricochet/properties.hpp"

namespace {

using ricochet::Circle;
using ricochet::KernelId;
using ricochet::Sweep;
using ricochet::Vec2;
using ricochet::Wall;
using ricochet::props::DiscHit;

/// robust's sweep and bounce as a user's class: right, so its properties hold.
struct RobustClass {
    static constexpr const char* name = "class-robust";
    static Sweep sweep(Vec2 bs, Vec2 v, const Wall& w) { return ricochet::sweep(KernelId::robust, bs, v, w); }
    static Vec2 reflect(Vec2 v, const Wall& w) { return ricochet::reflect(KernelId::robust, v, w); }
};

/// Every optional member, each answering something recognisable.
struct EveryMember {
    static constexpr const char* name = "class-every-member";
    static Sweep sweep(Vec2, Vec2, const Wall&) { return {ricochet::Miss::past_p1, 0, {}}; }
    static Vec2 reflect(Vec2 v, const Wall&) { return {-v.x, v.y}; }
    static std::optional<DiscHit> sweep_disc(Vec2 bs, Vec2, double r, const Wall&) {
        return DiscHit{0.25, {bs.x + r, bs.y}, {1, 0}};
    }
    static std::optional<DiscHit> sweep_disc_bumper(Vec2, Vec2, double, const Circle& c) {
        if (c.r > 1) return std::nullopt;
        return DiscHit{0.5, c.c, {0, -1}};
    }
    static Vec2 reflect_disc(Vec2 v, Vec2) { return {v.y, v.x}; }
    static constexpr double speed_rel_bound = 1e-9;
    static constexpr double speed_abs_bound = 1e-300;
};

}  // namespace

RICOCHET_TEST_KERNEL_CLASS(RobustClass);

namespace ricochet::props {
namespace {

TEST(TestKernelClass, TheClassIsUnderTestAndItsPropertiesHold) {
    const std::vector<KernelId> kernels = kernels_under_test();
    ASSERT_EQ(kernels.size(), 1u);
    EXPECT_EQ(kernel_name(kernels[0]), "class-robust");
    EXPECT_FALSE(kernel_ops(kernels[0]).failures_documented);
    // Every decision of robust, through the class and the table: the exact oracle agrees.
    run_property({"ClassSweep", Check::oracle, gen::wall_scene(3, 4),
                  checked({Check::oracle, Check::boundary, Check::speed}), 2000},
                 kernels[0]);
}

TEST(TestKernelClass, ATableCallsTheClassAndConvertsItsAnswers) {
    const ricochet_plugin& robust = kernel_table<RobustClass>();
    EXPECT_STREQ(robust.name, "class-robust");
    EXPECT_EQ(robust.abi_version, RICOCHET_PLUGIN_ABI_VERSION);
    EXPECT_EQ(robust.struct_size, sizeof(ricochet_plugin));
    EXPECT_NE(robust.reflect, nullptr);
    EXPECT_EQ(robust.sweep_disc, nullptr);
    EXPECT_EQ(robust.sweep_disc_bumper, nullptr);
    EXPECT_EQ(robust.reflect_disc, nullptr);
    EXPECT_EQ(robust.speed_rel_bound, 0.0);  // robust's bound (plugin.h: both 0)
    // A leg ending on x = 5: a hit at t = 1, B_i = (5, 0).
    const ricochet_wall x5{{5, -5}, {5, 5}};
    ricochet_sweep_result hit{};
    robust.sweep(nullptr, {0, 0}, {5, 0}, &x5, &hit);
    EXPECT_EQ(hit.miss, RICOCHET_HIT);
    EXPECT_EQ(hit.t, 1.0);
    EXPECT_EQ(hit.point.x, 5.0);
    EXPECT_EQ(hit.point.y, 0.0);
    ricochet_sweep_result miss{};
    robust.sweep(nullptr, {0, 0}, {0, 5}, &x5, &miss);
    EXPECT_EQ(miss.miss, RICOCHET_MISS_BOTH_INSIDE);

    const ricochet_plugin& every = kernel_table<EveryMember>();
    ricochet_sweep_result past{};
    every.sweep(nullptr, {0, 0}, {1, 0}, &x5, &past);
    EXPECT_EQ(past.miss, RICOCHET_MISS_PAST_P1);
    const ricochet_vec2 back = every.reflect(nullptr, {3, 4}, &x5);
    EXPECT_EQ(back.x, -3.0);
    EXPECT_EQ(back.y, 4.0);
    ricochet_disc_result disc{};
    every.sweep_disc(nullptr, {1, 2}, {1, 0}, 0.5, &x5, &disc);
    EXPECT_EQ(disc.miss, RICOCHET_HIT);
    EXPECT_EQ(disc.t, 0.25);
    EXPECT_EQ(disc.point.x, 1.5);
    EXPECT_EQ(disc.normal.x, 1.0);
    const ricochet_circle small{{7, 8}, 1}, big{{7, 8}, 2};
    ricochet_disc_result bump{};
    every.sweep_disc_bumper(nullptr, {0, 0}, {1, 0}, 0.5, &small, &bump);
    EXPECT_EQ(bump.miss, RICOCHET_HIT);
    EXPECT_EQ(bump.point.y, 8.0);
    EXPECT_EQ(bump.normal.y, -1.0);
    every.sweep_disc_bumper(nullptr, {0, 0}, {1, 0}, 0.5, &big, &bump);
    EXPECT_EQ(bump.miss, RICOCHET_MISS);
    const ricochet_vec2 swapped = every.reflect_disc(nullptr, {3, 4}, {0, 1});
    EXPECT_EQ(swapped.x, 4.0);
    EXPECT_EQ(every.speed_rel_bound, 1e-9);
    EXPECT_EQ(every.speed_abs_bound, 1e-300);
}

}  // namespace
}  // namespace ricochet::props
