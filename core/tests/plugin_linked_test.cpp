// Plug-in tables linked into the program (plugin_loader.hpp, register_plugin): registered, refused and judged
// exactly as a loaded plug-in's, without a shared library. What a user's own test binary does through
// ricochet/properties.hpp (RICOCHET_TEST_KERNEL).
#include <gtest/gtest.h>

#include <csignal>

#include <filesystem>
#include <string>

#include <fmt/format.h>
#include <unistd.h>

#include "ricochet/checks.hpp"
#include "ricochet/kernel.hpp"
#include "ricochet/plugin.h"
#include "ricochet/plugin_guard.hpp"
#include "ricochet/plugin_loader.hpp"
#include "ricochet/sweep.hpp"

namespace ricochet {
namespace {

/// A sweep that never sees a wall: every leg misses, no reason given.
void blind_sweep(void*, ricochet_vec2, ricochet_vec2, const ricochet_wall*, ricochet_sweep_result* out) {
    out->miss = RICOCHET_MISS;
}

/// A version-2 table named name with blind_sweep, as a user writes one in C++.
ricochet_plugin table_named(const char* name) {
    ricochet_plugin t{};
    t.abi_version = RICOCHET_PLUGIN_ABI_VERSION;
    t.struct_size = sizeof(ricochet_plugin);
    t.name = name;
    t.sweep = blind_sweep;
    return t;
}

std::string refusal(const ricochet_plugin& table) {
    std::string error;
    EXPECT_FALSE(register_plugin(table, &error));
    return error;
}

TEST(PluginLinked, RegistersTheTableUnderItsNameOnce) {
    static const ricochet_plugin table = table_named("linked-blind");
    std::string error;
    const auto k = register_plugin(table, &error);
    ASSERT_TRUE(k) << error;
    EXPECT_EQ(kernel_name(*k), "linked-blind");
    EXPECT_EQ(parse_kernel("linked-blind"), k);
    const PluginInfo* info = plugin_info(*k);
    ASSERT_NE(info, nullptr);
    EXPECT_TRUE(info->path.empty());
    EXPECT_EQ(info->abi_version, 2u);
    EXPECT_FALSE(info->discs);
    // Held to the guarantees, as every user kernel is.
    EXPECT_FALSE(kernel_ops(*k).failures_documented);
    // The same table again: the same kernel. Another table with the name: refused, saying who has it.
    const std::size_t kernels = registered_kernels().size();
    EXPECT_EQ(register_plugin(table, &error), k);
    EXPECT_EQ(registered_kernels().size(), kernels);
    static const ricochet_plugin twin = table_named("linked-blind");
    EXPECT_EQ(refusal(twin), "the kernel table 'linked-blind' linked into this program: its kernel name 'linked-blind' "
                             "is taken, by a kernel linked into this program");
    static const ricochet_plugin robust_again = table_named("robust");
    EXPECT_EQ(refusal(robust_again), "the kernel table 'robust' linked into this program: its kernel name 'robust' is "
                                     "taken, by a kernel of ricochet's");
}

TEST(PluginLinked, SaysWhyEachBadTableIsRefused) {
    ricochet_plugin wrong = table_named("linked-wrong");
    wrong.abi_version = 99;
    // A version it does not speak: nothing past the version is read, the name included.
    EXPECT_EQ(refusal(wrong), "the kernel table linked into this program: its table is for plugin.h ABI "
                              "version 99, this ricochet speaks versions 1 and 2 (rebuild it against this ricochet's "
                              "ricochet/plugin.h)");
    ricochet_plugin short_table = table_named("linked-short");
    short_table.struct_size = 8;
    EXPECT_EQ(refusal(short_table), "the kernel table linked into this program: its table says struct_size 8, ABI "
                                    "version 2 needs at least 40 bytes (set it to sizeof(ricochet_plugin))");
    ricochet_plugin nameless = table_named(nullptr);
    EXPECT_EQ(refusal(nameless), "the kernel table linked into this program: its table has no name");
    ricochet_plugin bad_name = table_named("my kernel");
    EXPECT_EQ(refusal(bad_name), "the kernel table 'my kernel' linked into this program: its kernel name 'my kernel' "
                                 "is not 1 to 64 of A-Z a-z 0-9 - _ .");
    ricochet_plugin no_sweep = table_named("linked-no-sweep");
    no_sweep.sweep = nullptr;
    EXPECT_EQ(refusal(no_sweep), "plug-in kernel 'linked-no-sweep' (linked into this program): no sweep function "
                                 "(plugin.h: it is required)");
    ricochet_plugin init_fails = table_named("linked-init-fails");
    init_fails.init = [](void**) -> std::int32_t { return 7; };
    EXPECT_EQ(refusal(init_fails), "plug-in kernel 'linked-init-fails' (linked into this program): its init function "
                                   "failed (returned 7)");
    // None of them took a name.
    EXPECT_FALSE(parse_kernel("linked-wrong"));
    EXPECT_FALSE(parse_kernel("linked-init-fails"));
}

TEST(PluginLinked, ItsKernelIsJudgedByTheChecks) {
    static const ricochet_plugin table = table_named("linked-judged");
    std::string error;
    const auto k = register_plugin(table, &error);
    ASSERT_TRUE(k) << error;
    Scene through;
    through.walls = {{{5, -5}, {5, 5}}};
    through.balls = {{{0, 0}, {10, 0}}};
    through.frames = 1;
    const Check checks[] = {Check::oracle, Check::no_tunnel};
    const CheckedRun run = run_checked(through, *k, through.frames, checks);
    ASSERT_TRUE(run.failure);
    EXPECT_EQ(run.failure->str(),
              "oracle broke at frame 1 ball 0: leg 0 ((0, 0) -> (10, 0)) against wall 0: the kernel says miss, exactly hit");
}

/// A sweep that crashes, as a null pointer in game code does.
void crashing_sweep(void*, ricochet_vec2, ricochet_vec2, const ricochet_wall*, ricochet_sweep_result*) {
    ::raise(SIGSEGV);
}

TEST(PluginLinkedDeathTest, ACrashIsReportedAndTheCaseKeptToRunAgain) {
    GTEST_FLAG_SET(death_test_style, "threadsafe");
    const std::filesystem::path keep =
        std::filesystem::temp_directory_path() / fmt::format("ricochet-linked-{}", ::getpid()) / "case.scene";
    EXPECT_EXIT(
        {
            static ricochet_plugin table = table_named("linked-crash");
            table.sweep = crashing_sweep;
            const auto k = register_plugin(table);
            stage_plugin_input({"running a test of mine", "ricochet 1\nframes 1\n", keep});
            sweep(*k, {0, 0}, {10, 0}, Wall{{5, -5}, {5, 5}});
        },
        testing::ExitedWithCode(k_plugin_fault_exit),
        "plug-in kernel 'linked-crash' \\(linked into this program\\) crashed: SIGSEGV in its sweep function, "
        "called with bs \\(0, 0\\), v \\(10, 0\\), wall \\(5, -5\\) -> \\(5, 5\\).*"
        "the scene is kept as .*case.scene; replay it: run this program again \\(it replays its saved logs first\\)");
    std::error_code ec;
    std::filesystem::remove_all(keep.parent_path(), ec);
}

}  // namespace
}  // namespace ricochet
