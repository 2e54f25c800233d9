// Plug-in kernels (plugin_loader.hpp, kernel_spec.hpp, plugin.h): each way a plug-in is refused, with what the
// message says; one load per file; dispatch to the plug-in's functions and to robust's where it has none; the
// frame loop ricochet runs around a sweep, traced; a whole-frame step under the checks; a miss without a reason;
// ABI version 2's discs: a version-1 table still loads and refuses them, a version-2 one steps them, traced, and an
// answer plugin.h does not allow ends the process with a report.
// The test plug-ins (plugins/test_plugin.c) are built next to each other in RICOCHET_TEST_PLUGIN_DIR.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "ricochet/checks.hpp"
#include "ricochet/kernel.hpp"
#include "ricochet/kernel_spec.hpp"
#include "ricochet/plugin_guard.hpp"
#include "ricochet/plugin_loader.hpp"
#include "ricochet/step_trace.hpp"
#include "ricochet/world.hpp"

namespace ricochet {
namespace {

namespace fs = std::filesystem;

/// The test plug-in built with PLUGIN_NAME (upper case), e.g. plugin("good").
fs::path plugin(std::string_view name) { return fs::path(RICOCHET_TEST_PLUGIN_DIR) / fmt::format("test_plugin_{}.so", name); }

/// The kernel of a plug-in that must load.
KernelId loaded(std::string_view name) {
    std::string error;
    const auto k = load_plugin(plugin(name), &error);
    EXPECT_TRUE(k) << error;
    return k.value_or(KernelId::robust);
}

/// Why a plug-in (or a spec) is refused.
std::string refusal(const fs::path& file) {
    std::string error;
    EXPECT_FALSE(load_plugin(file, &error)) << file;
    return error;
}

std::string spec_refusal(std::string_view spec) {
    std::string error;
    EXPECT_FALSE(resolve_kernel(spec, &error)) << spec;
    return error;
}

/// A temporary folder, removed at the end.
struct TempDir {
    fs::path path = fs::temp_directory_path() / fmt::format("ricochet-plugin-test-{}", ::getpid());
    TempDir() { fs::create_directories(path); }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

const Wall k_wall{{5, -5}, {5, 5}};  // x = 5, outside to the right: n = (e_y, −e_x) = (10, 0)

TEST(PluginLoader, RegistersTheKernelUnderItsOwnNameOncePerFile) {
    const KernelId k = loaded("good");
    EXPECT_EQ(kernel_name(k), "test-good");
    EXPECT_EQ(parse_kernel("test-good"), k);
    const PluginInfo* info = plugin_info(k);
    ASSERT_NE(info, nullptr);
    EXPECT_EQ(info->name, "test-good");
    EXPECT_EQ(info->path, fs::canonical(plugin("good")));
    EXPECT_FALSE(info->frame_step);
    EXPECT_EQ(plugin_info(KernelId::robust), nullptr);
    // A plug-in's failures are the user's bugs, regressions until fixed: its failure logs do not expect them.
    EXPECT_FALSE(kernel_ops(k).failures_documented);
    // robust's speed bound: the plug-in states none.
    EXPECT_EQ(kernel_ops(k).speed_rel_bound, k_speed_rel_bound);
    // Again, by the spec, and through a symbolic link: the same kernel, nothing registered twice.
    const std::size_t kernels = registered_kernels().size();
    std::string error;
    EXPECT_EQ(load_plugin(plugin("good"), &error), k);
    EXPECT_EQ(resolve_kernel(fmt::format("plugin:{}", plugin("good").string()), &error), k);
    TempDir dir;
    fs::create_symlink(plugin("good"), dir.path / "link.so");
    EXPECT_EQ(load_plugin(dir.path / "link.so", &error), k);
    EXPECT_EQ(registered_kernels().size(), kernels);
    // A copy is another file declaring the same name: refused, naming the plug-in that has it.
    fs::copy_file(plugin("good"), dir.path / "copy.so");
    const std::string taken = refusal(dir.path / "copy.so");
    EXPECT_EQ(taken, fmt::format("plug-in {}: its kernel name 'test-good' is taken, by the plug-in {}",
                                 fs::canonical(dir.path / "copy.so").string(), info->path.string()));
    EXPECT_EQ(registered_kernels().size(), kernels);
}

TEST(PluginLoader, SaysWhyEachBadPluginIsRefused) {
    const auto path = [](std::string_view name) { return fs::canonical(plugin(name)).string(); };
    EXPECT_EQ(refusal("/nonexistent/libnothing.so"), "plug-in /nonexistent/libnothing.so: no such file");
    EXPECT_EQ(refusal(RICOCHET_TEST_PLUGIN_DIR), fmt::format("plug-in {}: a folder, not a shared library", RICOCHET_TEST_PLUGIN_DIR));
    // Not a library at all: dlerror's own words follow.
    const std::string not_elf = refusal(RICOCHET_TEST_PLUGIN_SOURCE);
    EXPECT_TRUE(not_elf.starts_with(fmt::format("plug-in {}: cannot load it: ", fs::canonical(RICOCHET_TEST_PLUGIN_SOURCE).string())))
        << not_elf;
    EXPECT_GT(not_elf.size(), std::string_view("plug-in : cannot load it: ").size() + std::string_view(RICOCHET_TEST_PLUGIN_SOURCE).size());
    EXPECT_EQ(refusal(plugin("no_entry")),
              fmt::format("plug-in {}: no symbol ricochet_plugin_entry (a plug-in defines it: see ricochet/plugin.h)", path("no_entry")));
    EXPECT_EQ(refusal(plugin("wrong_abi")),
              fmt::format("plug-in {}: its table is for plugin.h ABI version 99, this ricochet speaks versions 1 and 2 "
                          "(rebuild it against this ricochet's ricochet/plugin.h)",
                          path("wrong_abi")));
    EXPECT_TRUE(refusal(plugin("short_table")).starts_with(fmt::format("plug-in {}: its table says struct_size 8, ABI version 2 needs at least ", path("short_table"))));
    EXPECT_EQ(refusal(plugin("no_table")), fmt::format("plug-in {}: ricochet_plugin_entry returned no table", path("no_table")));
    EXPECT_EQ(refusal(plugin("bad_name")),
              fmt::format("plug-in {}: its kernel name 'bad name' is not 1 to 64 of A-Z a-z 0-9 - _ .", path("bad_name")));
    EXPECT_EQ(refusal(plugin("taken_name")),
              fmt::format("plug-in {}: its kernel name 'robust' is taken, by a kernel of ricochet's", path("taken_name")));
    EXPECT_EQ(refusal(plugin("no_sweep")),
              fmt::format("plug-in kernel 'test-no-sweep' ({}): no sweep function (plugin.h: it is required)", path("no_sweep")));
    EXPECT_EQ(refusal(plugin("init_fails")),
              fmt::format("plug-in kernel 'test-init-fails' ({}): its init function failed (returned 7)", path("init_fails")));
    // None of them joined the registry.
    for (const char* name : {"test-wrong-abi", "test-short", "bad name", "test-no-sweep", "test-init-fails"})
        EXPECT_FALSE(parse_kernel(name)) << name;
}

TEST(PluginLoader, SpecsAndTheTimeoutSetting) {
    EXPECT_EQ(resolve_kernel("exact"), KernelId::exact);
    EXPECT_EQ(spec_refusal("plugin:"), "'plugin:' names no file (plugin:PATH)");
    const std::string unknown = spec_refusal("nope");
    EXPECT_TRUE(unknown.starts_with("unknown kernel 'nope' (lecture-float, lecture-double, robust, exact")) << unknown;
    EXPECT_TRUE(unknown.ends_with(", or plugin:PATH)")) << unknown;
    // The timeout is read when a plug-in is loaded; a bad one refuses the load, naming the variable.
    for (const char* bad : {"soon", "-1", "86401", "1s"}) {
        ::setenv("RICOCHET_PLUGIN_TIMEOUT", bad, 1);
        EXPECT_EQ(spec_refusal(fmt::format("plugin:{}", plugin("frame_wrong").string())),
                  fmt::format("RICOCHET_PLUGIN_TIMEOUT: '{}' is not a number of seconds from 0 (no limit) to 86400", bad));
    }
    ::unsetenv("RICOCHET_PLUGIN_TIMEOUT");
}

TEST(PluginKernel, CallsThePluginAndRobustWhereItHasNothing) {
    const KernelId k = loaded("good");
    // Bs = (0, 0), v = (10, 0) against x = 5: BC(Bs) = n·(Bs − P0) = −50, BC(Be) = 50, n·v = 100, t = 50/100.
    const Sweep hit = sweep(k, {0, 0}, {10, 0}, k_wall);
    EXPECT_EQ(hit.miss, Miss::none);
    EXPECT_EQ(hit.t, 0.5);
    EXPECT_EQ(hit.point, (Vec2{5, 0}));
    // The plug-in's own reason for a miss.
    EXPECT_EQ(sweep(k, {0, 0}, {1, 0}, k_wall).miss, Miss::both_inside);
    // No classify, reflect or static tests in the plug-in: robust's, exactly.
    EXPECT_EQ(classify(k, {6, 0}, k_wall), Side::outside);
    EXPECT_EQ(reflect(k, {3, 4}, k_wall), reflect(KernelId::robust, {3, 4}, k_wall));
    EXPECT_TRUE(point_in_circle(k, {3, 4}, Circle{{0, 0}, 5}));
    EXPECT_TRUE(rects_overlap(k, Rect{0, 0, 1, 1}, Rect{1, 1, 2, 2}));
}

TEST(PluginKernel, StepsASweepInTheLecturesFrameLoopAndTracesItsLegs) {
    const KernelId k = loaded("good");
    // From (0, 0) moving (10, 0): the wall at x = 5 at t = 0.5, back to (0, 0) for the rest of the frame.
    Ball ball{{0, 0}, {10, 0}};
    BallMemory memory;
    std::vector<HitEvent> hits;
    StepScratch scratch;
    StepTrace trace;
    scratch.trace = &trace;
    const Wall walls[] = {k_wall};
    EXPECT_EQ(step_ball(k, ball, memory, walls, hits, scratch), FrameStatus::ok);
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_EQ(hits[0].wall, 0u);
    EXPECT_EQ(hits[0].t, 0.5);
    EXPECT_EQ(hits[0].point, (Vec2{5, 0}));
    EXPECT_EQ(ball, (Ball{{0, 0}, {-10, 0}}));
    // Two legs: (0, 0) → (10, 0) hitting wall 0, then (5, 0) → (0, 0) with wall 0 skipped as just bounced off.
    EXPECT_TRUE(trace.legs_traced);
    ASSERT_EQ(trace.legs.size(), 2u);
    EXPECT_EQ(trace.legs[0].hit, std::optional<std::uint32_t>(0));
    EXPECT_EQ(trace.legs[0].hit_t, 0.5);
    EXPECT_EQ(trace.legs[1].from, (Vec2{5, 0}));
    EXPECT_EQ(trace.legs[1].skipped, std::optional<std::uint32_t>(0));
    EXPECT_EQ(trace.reflections, 1);
    // Under every check a log can name, this well-conditioned box holds for a hundred frames.
    Scene box;
    box.walls = {{{0, 0}, {0, 10}}, {{0, 10}, {10, 10}}, {{10, 10}, {10, 0}}, {{10, 0}, {0, 0}}};
    box.balls = {{{5, 5}, {3, 1.25}}, {{2, 7}, {-4, -2.25}}};
    box.frames = 100;
    const CheckedRun run = run_checked(box, k, box.frames, k_all_checks);
    EXPECT_FALSE(run.failure) << run.failure->str();
}

TEST(PluginKernel, AWholeFrameStepIsJudgedByWhatTheFrameShows) {
    const KernelId k = loaded("frame");
    ASSERT_TRUE(plugin_info(k)->frame_step);
    Ball ball{{0, 0}, {10, 0}};
    BallMemory memory;
    std::vector<HitEvent> hits;
    StepScratch scratch;
    StepTrace trace;
    scratch.trace = &trace;
    const Wall walls[] = {k_wall};
    EXPECT_EQ(step_ball(k, ball, memory, walls, hits, scratch), FrameStatus::ok);
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_EQ(hits[0].point, (Vec2{5, 0}));
    EXPECT_EQ(ball.vel, (Vec2{-10, 0}));
    // No legs to show, and the reflections it reported.
    EXPECT_FALSE(trace.legs_traced);
    EXPECT_TRUE(trace.legs.empty());
    EXPECT_EQ(trace.reflections, 1);
    Scene box;
    box.walls = {{{0, 0}, {0, 10}}, {{0, 10}, {10, 10}}, {{10, 10}, {10, 0}}, {{10, 0}, {0, 0}}};
    box.balls = {{{5, 5}, {3, 1.25}}};
    box.frames = 50;
    const CheckedRun run = run_checked(box, k, box.frames, k_all_checks);
    EXPECT_FALSE(run.failure) << run.failure->str();
    // A frame step that never hits: the oracle compares its first hit with the exact kernel's.
    const KernelId blind = loaded("frame_wrong");
    Scene through;
    through.walls = {k_wall};
    through.balls = {{{0, 0}, {10, 0}}};
    through.frames = 2;
    const Check oracle[] = {Check::oracle};
    const CheckedRun seen = run_checked(through, blind, through.frames, oracle);
    ASSERT_TRUE(seen.failure);
    EXPECT_EQ(seen.failure->str(),
              "oracle broke at frame 1 ball 0: from (0, 0) moving (10, 0) the kernel hits no wall first, the exact "
              "kernel hits wall 0");
}

TEST(PluginKernel, AMissWithoutAReasonIsJudgedAsAMiss) {
    const KernelId k = loaded("no_reason");
    EXPECT_EQ(sweep(k, {0, 0}, {10, 0}, Wall{{7, -5}, {7, 5}}).miss, Miss::no_reason);
    const Check oracle[] = {Check::oracle};
    // Wall x = 5: answered with reasons and right. Wall x = 7 (parallel to the motion, so exactly missed): a
    // miss without a reason, right whatever truth's reason.
    Scene fine;
    fine.walls = {k_wall, {{7, -5}, {7, 5}}};
    fine.balls = {{{6, 0}, {0, 3}}};
    fine.frames = 3;
    const CheckedRun ok = run_checked(fine, k, fine.frames, oracle);
    EXPECT_FALSE(ok.failure) << ok.failure->str();
    // Wall x = 7 across the leg: the kernel says miss, truth says hit.
    Scene blind;
    blind.walls = {{{7, -5}, {7, 5}}};
    blind.balls = {{{0, 0}, {10, 0}}};
    blind.frames = 1;
    const CheckedRun seen = run_checked(blind, k, blind.frames, oracle);
    ASSERT_TRUE(seen.failure);
    EXPECT_EQ(seen.failure->str(),
              "oracle broke at frame 1 ball 0: leg 0 ((0, 0) -> (10, 0)) against wall 0: the kernel says miss, exactly hit");
}

/// One frame of ball among walls and bumpers by kernel k, traced.
struct DiscFrame {
    FrameStatus status;
    Ball ball;
    std::vector<HitEvent> hits;
    StepTrace trace;
};
DiscFrame step_disc_frame(KernelId k, Ball ball, std::span<const Wall> walls, std::span<const Bumper> bumpers) {
    DiscFrame f{};
    BallMemory memory;
    StepScratch scratch;
    scratch.trace = &f.trace;
    f.status = step_ball(k, ball, memory, Obstacles{walls, bumpers}, f.hits, scratch);
    f.ball = ball;
    return f;
}

TEST(PluginDisc, AVersionOneTableStillLoadsAndRefusesDiscsAndBumpers) {
    // test-v1 serves only a loader asking for version 1: the loader asks for 2, then for 1.
    const KernelId k = loaded("v1");
    const PluginInfo* info = plugin_info(k);
    ASSERT_NE(info, nullptr);
    EXPECT_EQ(info->abi_version, 1u);
    // Its table sets sweep_disc past its struct_size: a version-1 table has no disc functions.
    EXPECT_FALSE(info->discs);
    EXPECT_EQ(kernel_ops(k).step_disc, nullptr);
    EXPECT_FALSE(kernel_ops(k).steps_bumpers);
    // Points among walls as ever: its sweep.
    EXPECT_EQ(sweep(k, {0, 0}, {10, 0}, k_wall).t, 0.5);
    const Ball disc{{0, 0}, {10, 0}, 0.5};
    EXPECT_EQ(unsupported_scene(k, std::span<const Ball>(&disc, 1), 0),
              std::optional<std::string>("kernel 'test-v1' steps point balls only: ball 0 has radius 0.5"));
    const Ball point{{0, 0}, {10, 0}};
    EXPECT_EQ(unsupported_scene(k, std::span<const Ball>(&point, 1), 1),
              std::optional<std::string>("kernel 'test-v1' does not step bumpers: the scene has 1 (bumper 0 first)"));
    // A version-2 table without sweep_disc (test-good) refuses them the same way.
    const KernelId good = loaded("good");
    EXPECT_EQ(plugin_info(good)->abi_version, 2u);
    EXPECT_EQ(kernel_ops(good).step_disc, nullptr);
}

TEST(PluginDisc, AVersionTwoTableStepsADiscAmongWallsAndBumpersTracingEachLeg) {
    const KernelId k = loaded("disc");
    ASSERT_TRUE(plugin_info(k)->discs);
    ASSERT_TRUE(plugin_info(k)->bumpers);
    EXPECT_NE(kernel_ops(k).step_disc, nullptr);
    EXPECT_TRUE(kernel_ops(k).steps_bumpers);
    const Wall walls[] = {k_wall};
    // A disc of radius 1 from (0, 0) moving (10, 0) against x = 5: the face shifted by 1, x = 4, at t = 0.4;
    // v′ = (−10, 0) about the normal (−1, 0), the rest of the frame 0.6·v′ from (4, 0): (−2, 0).
    const DiscFrame wall = step_disc_frame(k, Ball{{0, 0}, {10, 0}, 1}, walls, {});
    EXPECT_EQ(wall.status, FrameStatus::ok);
    ASSERT_EQ(wall.hits.size(), 1u);
    EXPECT_EQ(wall.hits[0].wall, 0u);
    EXPECT_FALSE(wall.hits[0].bumper);
    EXPECT_EQ(wall.hits[0].t, 0.4);
    EXPECT_EQ(wall.hits[0].point, (Vec2{4, 0}));
    EXPECT_EQ(wall.ball.pos, (Vec2{-2, 0}));
    EXPECT_EQ(wall.ball.vel, (Vec2{-10, 0}));
    // Two legs: the first decides wall 0 (a contact) and takes it; the second skips it, as just bounced off.
    ASSERT_EQ(wall.trace.legs.size(), 2u);
    EXPECT_EQ(wall.trace.legs[0].hit, std::optional<std::uint32_t>(0));
    EXPECT_EQ(wall.trace.legs[0].hit_t, 0.4);
    EXPECT_EQ(wall.trace.legs[0].vel, (Vec2{10, 0}));
    ASSERT_EQ(wall.trace.legs[0].decision_count, 1u);
    EXPECT_EQ(wall.trace.decisions[wall.trace.legs[0].first_decision].miss, Miss::none);
    EXPECT_EQ(wall.trace.legs[1].skipped, std::optional<std::uint32_t>(0));
    EXPECT_EQ(wall.trace.legs[1].decision_count, 0u);
    EXPECT_EQ(wall.trace.reflections, 1);
    // The same disc against a bumper at (5, 0) of radius 1, no walls: |B − C| = 2 at x = 3, t = 0.3; back to (−4, 0).
    const Bumper bumpers[] = {Bumper{{5, 0}, 1}};
    const DiscFrame bump = step_disc_frame(k, Ball{{0, 0}, {10, 0}, 1}, {}, bumpers);
    ASSERT_EQ(bump.hits.size(), 1u);
    EXPECT_TRUE(bump.hits[0].bumper);
    EXPECT_EQ(bump.hits[0].wall, 0u);
    EXPECT_EQ(bump.hits[0].point, (Vec2{3, 0}));
    EXPECT_EQ(bump.ball.pos, (Vec2{-4, 0}));
    ASSERT_EQ(bump.trace.legs.size(), 2u);
    EXPECT_EQ(bump.trace.legs[0].bumped, std::optional<std::uint32_t>(0));
    EXPECT_EQ(bump.trace.legs[1].skipped_bumper, std::optional<std::uint32_t>(0));
    // Both: the bumper's t = 0.3 comes before the wall's 0.4, and the disc goes back left, never meeting the wall.
    const DiscFrame both = step_disc_frame(k, Ball{{0, 0}, {10, 0}, 1}, walls, bumpers);
    ASSERT_EQ(both.hits.size(), 1u);
    EXPECT_TRUE(both.hits[0].bumper);
    // A box with a bumper in it, discs and a point ball: every check a log can name but one holds for a hundred
    // frames, each leg judged. The one: `penetration` asks every printed piece to keep its distances exactly
    // (δ = 0), which a B_i rounded once, without robust's walk back, does not; it catches this plug-in at once.
    Scene box;
    box.walls = {{{0, 0}, {0, 16}}, {{0, 16}, {16, 16}}, {{16, 16}, {16, 0}}, {{16, 0}, {0, 0}}};
    box.bumpers = {{{8, 8}, 2}};
    box.balls = {{{4, 4}, {3, 1.25}, 1}, {{12, 3}, {-2, 3.5}, 0.5}, {{2, 13}, {1.5, -0.75}}};
    box.frames = 100;
    std::vector<Check> checks(k_all_checks.begin(), k_all_checks.end());
    std::erase(checks, Check::penetration);
    const CheckedRun run = run_checked(box, k, box.frames, checks);
    EXPECT_FALSE(run.failure) << run.failure->str();
    EXPECT_GT(std::count_if(run.events.begin(), run.events.end(), [](const Event& e) { return e.kind == Event::Kind::bump; }), 0);
    const Check penetration[] = {Check::penetration};
    const CheckedRun seen = run_checked(box, k, box.frames, penetration);
    ASSERT_TRUE(seen.failure);
    EXPECT_EQ(seen.failure->check, Check::penetration) << seen.failure->str();
}

TEST(PluginDisc, DiscsAmongWallsOnlyWithoutSweepDiscBumper) {
    const KernelId k = loaded("disc_walls");
    EXPECT_NE(kernel_ops(k).step_disc, nullptr);
    EXPECT_FALSE(kernel_ops(k).steps_bumpers);
    const Ball disc{{0, 0}, {10, 0}, 0.5};
    EXPECT_EQ(unsupported_scene(k, std::span<const Ball>(&disc, 1), 0), std::nullopt);
    EXPECT_EQ(unsupported_scene(k, std::span<const Ball>(&disc, 1), 2),
              std::optional<std::string>("kernel 'test-disc-walls' does not step bumpers: the scene has 2 (bumper 0 first)"));
}

TEST(PluginDiscDeathTest, AnAnswerPluginHDoesNotAllowIsReported) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    const Wall walls[] = {{{-5, -5}, {-5, 5}}, {{-5, -5}, {5, -5}}};
    // Moving left into x = −5: the broken plug-in says t = 2.
    EXPECT_EXIT(
        {
            const KernelId k = loaded("disc_broken");
            step_disc_frame(k, Ball{{0, 0}, {-10, 0}, 1}, std::span<const Wall>(walls, 1), {});
        },
        testing::ExitedWithCode(k_plugin_fault_exit),
        "plug-in kernel 'test-disc-broken' .* broke ricochet/plugin.h: its sweep_disc function answered a hit at t = 2, "
        "which is not in \\[0, 1\\], called with bs \\(0, 0\\), v \\(-10, 0\\), radius 1, wall \\(-5, -5\\) -> \\(-5, 5\\)");
    // Moving down into y = −5: a zero normal.
    EXPECT_EXIT(
        {
            const KernelId k = loaded("disc_broken");
            step_disc_frame(k, Ball{{0, 0}, {0, -10}, 1}, std::span<const Wall>(walls + 1, 1), {});
        },
        testing::ExitedWithCode(k_plugin_fault_exit),
        "its sweep_disc function answered a hit with the normal \\(0, 0\\), which is zero, called with bs \\(0, 0\\), "
        "v \\(0, -10\\), radius 1, wall \\(-5, -5\\) -> \\(5, -5\\)");
}

}  // namespace
}  // namespace ricochet
