// The kernel registry: the built-in kernels by name, and a plug-in kernel joining without any dispatch edit.
#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "ricochet/kernel.hpp"
#include "ricochet/scene_log_format.hpp"

namespace ricochet {
namespace {

TEST(Registry, BuiltInKernelsByName) {
    for (KernelId k : k_all_kernels) EXPECT_EQ(parse_kernel(kernel_name(k)), k);
    EXPECT_EQ(kernel_name(KernelId::lecture_float), "lecture-float");
    EXPECT_EQ(kernel_name(KernelId::exact), "exact");
    EXPECT_FALSE(parse_kernel("fast").has_value());
    EXPECT_EQ(kernel_name(KernelId{200}), "?");
    // Plug-ins, if a test registered one already, come after the built-in four.
    const std::string built_in = "lecture-float, lecture-double, robust, exact";
    EXPECT_EQ(kernel_names().substr(0, built_in.size()), built_in);
    ASSERT_GE(registered_kernels().size(), k_all_kernels.size());
    for (std::size_t i = 0; i < k_all_kernels.size(); ++i) EXPECT_EQ(registered_kernels()[i], k_all_kernels[i]);
}

/// A user's kernel: robust's answers, except that every point is inside every wall; counts its frames.
struct InsideKernel {
    static inline int frames = 0;
    static Side classify(Vec2, const Wall&) { return Side::inside; }
    static bool point_in_circle(Vec2 p, const Circle& c) { return ricochet::point_in_circle(KernelId::robust, p, c); }
    static bool circles_overlap(const Circle& a, const Circle& b) {
        return ricochet::circles_overlap(KernelId::robust, a, b);
    }
    static bool point_in_rect(Vec2 p, const Rect& r) { return ricochet::point_in_rect(KernelId::robust, p, r); }
    static bool rects_overlap(const Rect& a, const Rect& b) { return ricochet::rects_overlap(KernelId::robust, a, b); }
    static Sweep sweep(Vec2 bs, Vec2 v, const Wall& w) { return ricochet::sweep(KernelId::robust, bs, v, w); }
    static Vec2 reflect(Vec2 v, const Wall& w) { return ricochet::reflect(KernelId::robust, v, w); }
    static FrameStatus step_ball(Ball& ball, BallMemory& memory, std::span<const Wall> walls,
                                 std::vector<HitEvent>& hits, StepScratch& scratch, const WallIndex* index) {
        ++frames;
        return ricochet::step_ball(KernelId::robust, ball, memory, walls, hits, scratch, index);
    }
};
static_assert(Kernel<InsideKernel>);

TEST(Registry, PlugInKernelJoinsByName) {
    const std::optional<KernelId> id = register_kernel(make_kernel_ops<InsideKernel>("test-inside"));
    ASSERT_TRUE(id.has_value());
    EXPECT_EQ(parse_kernel("test-inside"), id);
    EXPECT_EQ(kernel_name(*id), "test-inside");
    EXPECT_NE(kernel_names().find(", test-inside"), std::string::npos);
    EXPECT_EQ(registered_kernels().back(), *id);
    // A name already taken is refused; the first kernel of that name stays.
    EXPECT_FALSE(register_kernel(make_kernel_ops<InsideKernel>("robust")).has_value());
    EXPECT_EQ(parse_kernel("robust"), KernelId::robust);
    // The free functions dispatch to it: robust says outside, the plug-in inside.
    const Wall w{{0, 0}, {10, 0}};
    EXPECT_EQ(classify(KernelId::robust, {5, -1}, w), Side::outside);
    EXPECT_EQ(classify(*id, {5, -1}, w), Side::inside);
    // step_ball reaches it through the same range check as every kernel.
    Ball ball{{5, 5}, {1, 0}};
    BallMemory memory;
    StepScratch scratch;
    std::vector<HitEvent> hits;
    const int before = InsideKernel::frames;
    EXPECT_EQ(step_ball(*id, ball, memory, std::span<const Wall>(&w, 1), hits, scratch), FrameStatus::ok);
    EXPECT_EQ(InsideKernel::frames, before + 1);
    EXPECT_EQ(ball.pos, (Vec2{6, 5}));
    Ball far{{0x1p300, 0}, {1, 0}};
    EXPECT_EQ(step_ball(*id, far, memory, std::span<const Wall>(&w, 1), hits, scratch), FrameStatus::out_of_range);
    EXPECT_EQ(InsideKernel::frames, before + 1);
}

TEST(Registry, AnAbsentKernelIsRefusedWithWhy) {
    // A kernel this build knows of but lacks (a peer whose library was not found): not parsed, but told apart
    // from a typo, in the log's FILE:LINE:COL form too.
    ASSERT_TRUE(note_absent_kernel("test-absent", "its library was not found at build time"));
    EXPECT_FALSE(parse_kernel("test-absent").has_value());
    EXPECT_EQ(absent_kernel_message("test-absent"),
              "kernel 'test-absent' is not built into this ricochet: its library was not found at build time");
    EXPECT_FALSE(absent_kernel_message("fast").has_value());
    EXPECT_EQ(kernel_names().find("test-absent"), std::string::npos);
    // Noted once; a registered name is never absent.
    EXPECT_FALSE(note_absent_kernel("test-absent", "again"));
    EXPECT_FALSE(note_absent_kernel("robust", "no"));
    EXPECT_FALSE(absent_kernel_message("robust").has_value());
    const auto parsed = parse_scene_log("ricochet 1\nkernel test-absent\n", "t.scene");
    const auto* d = std::get_if<Diagnostic>(&parsed);
    ASSERT_NE(d, nullptr);
    EXPECT_EQ(d->str(),
              "t.scene:2:8: error: kernel 'test-absent' is not built into this ricochet: its library was not found at "
              "build time");
}

}  // namespace
}  // namespace ricochet
