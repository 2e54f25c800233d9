// ricochet's properties in your own GoogleTest binary: the same generators, checks, saved failure logs and
// contract as ricochet's property suite (ricochet_properties), run against your collision code.
//
//     #include <ricochet/properties.hpp>
//
//     static const ricochet_plugin kTable = {RICOCHET_PLUGIN_ABI_VERSION, sizeof(ricochet_plugin), "my-kernel",
//                                            ..., my_sweep, ...};   // ricochet/plugin.h: your functions
//     RICOCHET_TEST_KERNEL(kTable);
//
// and link the test program with ricochet::properties (find_package(ricochet COMPONENTS properties)) and
// GTest::gtest_main, or a main of your own that calls ::testing::InitGoogleTest. Every property then runs as a
// GoogleTest test per kernel, `Kernels/SUITE.PROPERTY/KERNEL` (e.g. Kernels/Scenes.NoTunnelWalls/my_kernel): all of
// them by default, one with --gtest_filter. A property your table cannot be asked (a disc property for a table
// without sweep_disc) is skipped, saying why.
//
// What a run does, as ricochet_properties does it (docs/properties.md):
// - each property first replays every saved log in the save folder that names it, then searches with RapidCheck
//   from a fixed seed (RC_PARAMS="seed=S max_success=N" explores; RICOCHET_SHRINK_TRIES bounds shrinking);
// - a failure is shrunk, reduced and saved as a scene log in RICOCHET_REPLAY_DIR, or found/ in the current folder,
//   whose `kernel` line names your kernel and which carries no `expect failure`: running the binary again fails on
//   it until the bug is fixed, and `ricochet replay --plugin libmine.so found/` fails it too where the same table
//   is also built as a plug-in (ricochet/plugin.h);
// - the failure message ends with the one command that reproduces it;
// - every call into your table runs under the plug-in guard: a crash or a hang ends the process with a report and
//   the case kept as a scene log.
// RICOCHET_DOMAIN overrides the domain (RICOCHET_TEST_KERNEL_IN), for every kernel under test.
// RICOCHET_KERNEL (names, comma-separated) overrides the kernels under test; without it they are the kernels
// registered with RICOCHET_TEST_KERNEL, or robust and exact when there are none.
//
// Coverage-guided fuzzing is not driven from this binary: build the same table as a plug-in and run
// `ricochet fuzz --kernel plugin:PATH` (docs/testing-your-code.md says why and how).
#pragma once

#include "ricochet/plugin.h"

namespace ricochet::props {

/// Puts table's kernel under test: it is registered (register_plugin, plugin_loader.hpp) when the test program's
/// parameterized tests are set up, after every static initializer has run. A table the loader refuses ends the
/// program then, with status 2 and the loader's message. table must outlive the program (a static is fine).
/// domain: what your world is, as RICOCHET_DOMAIN spells it (ricochet/domain.hpp, docs/scene-log.md "Domain"),
/// e.g. "coordinates=1e6,no-subnormals,waive=touching"; empty: ricochet's whole range and every convention. Every
/// property then draws its scenes inside it, skips the checks a waived convention switches off, and saves its
/// failures with the domain's lines, so that replay judges them the same way. A domain that does not read ends
/// the program with status 2 when the tests are set up.
/// Returns true, so that RICOCHET_TEST_KERNEL can call it from a static initializer.
bool test_kernel(const ricochet_plugin& table, const char* domain = "");

}  // namespace ricochet::props

#define RICOCHET_PROPERTIES_CONCAT_INNER(a, b) a##b
#define RICOCHET_PROPERTIES_CONCAT(a, b) RICOCHET_PROPERTIES_CONCAT_INNER(a, b)
/// Runs every property of ricochet against the kernel of TABLE (a ricochet_plugin, ricochet/plugin.h), one
/// GoogleTest test per property. At namespace scope, once per table.
#define RICOCHET_TEST_KERNEL(TABLE)                                                                      \
    [[maybe_unused]] static const bool RICOCHET_PROPERTIES_CONCAT(ricochet_test_kernel_, __LINE__) = \
        ::ricochet::props::test_kernel(TABLE)
/// The same, in the domain DOMAIN (a string, as RICOCHET_DOMAIN spells it): RICOCHET_TEST_KERNEL_IN(kTable,
/// "coordinates=1e6,no-subnormals").
#define RICOCHET_TEST_KERNEL_IN(TABLE, DOMAIN)                                                           \
    [[maybe_unused]] static const bool RICOCHET_PROPERTIES_CONCAT(ricochet_test_kernel_, __LINE__) = \
        ::ricochet::props::test_kernel(TABLE, DOMAIN)
