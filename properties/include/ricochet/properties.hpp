// ricochet's properties in your own GoogleTest binary: the same generators, checks, saved failure logs and
// contract as ricochet's property suite (ricochet_properties), run against your collision code.
//
//     #include <ricochet/properties.hpp>
//
//     static const ricochet_plugin kTable = {RICOCHET_PLUGIN_ABI_VERSION, sizeof(ricochet_plugin), "my-kernel",
//                                            ..., my_sweep, ...};   // ricochet/plugin.h: your functions
//     RICOCHET_TEST_KERNEL(kTable);
//
// or, for a kernel written as a C++ class of static members on ricochet's types (kernel_table below),
// RICOCHET_TEST_KERNEL_CLASS(MyKernel);
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

#include <cstdint>
#include <optional>

#include "ricochet/plugin.h"
#include "ricochet/shapes.hpp"
#include "ricochet/sweep.hpp"
#include "ricochet/vec2.hpp"

namespace ricochet::props {

/// A disc's first contact, as a kernel class's sweep_disc and sweep_disc_bumper answer it (plugin.h's
/// ricochet_disc_result): t in [0, 1], the centre B_i there, the normal from the obstacle to the disc.
struct DiscHit {
    double t = 0;
    Vec2 point;
    Vec2 normal;
};

namespace detail {
inline Vec2 vec(ricochet_vec2 v) { return {v.x, v.y}; }
inline ricochet_vec2 vec(Vec2 v) { return {v.x, v.y}; }
inline Wall wall(const ricochet_wall* w) { return {vec(w->p0), vec(w->p1)}; }
inline void disc_result(const std::optional<DiscHit>& hit, ricochet_disc_result* out) {
    out->miss = hit ? RICOCHET_HIT : RICOCHET_MISS;
    if (!hit) return;
    out->t = hit->t;
    out->point = vec(hit->point);
    out->normal = vec(hit->normal);
}
}  // namespace detail

/// The plugin.h table of a kernel written as a C++ class of static members on ricochet's own types:
///     static constexpr const char* name = "my-kernel";                                      required
///     static Sweep sweep(Vec2 bs, Vec2 v, const Wall& w);                                   required (sweep.hpp)
///     static Vec2 reflect(Vec2 v, const Wall& w);                                           optional
///     static std::optional<DiscHit> sweep_disc(Vec2 bs, Vec2 v, double r, const Wall& w);   optional
///     static std::optional<DiscHit> sweep_disc_bumper(Vec2 bs, Vec2 v, double r, const Circle& bumper);
///                                                                                           optional, with sweep_disc
///     static Vec2 reflect_disc(Vec2 v, Vec2 normal);                                        optional
///     static constexpr double speed_rel_bound = ..., speed_abs_bound = ...;                 optional
/// What it leaves out ricochet supplies, as for any table (plugin.h). A whole-frame step is the table's alone.
template <class K>
const ricochet_plugin& kernel_table() {
    static const ricochet_plugin table = [] {
        ricochet_plugin t{};
        t.abi_version = RICOCHET_PLUGIN_ABI_VERSION;
        t.struct_size = sizeof(ricochet_plugin);
        t.name = K::name;
        t.sweep = [](void*, ricochet_vec2 bs, ricochet_vec2 v, const ricochet_wall* w, ricochet_sweep_result* out) {
            const Sweep r = K::sweep(detail::vec(bs), detail::vec(v), detail::wall(w));
            // Miss's values are plugin.h's codes, in the same order (RICOCHET_HIT is Miss::none).
            out->miss = static_cast<std::int32_t>(r.miss);
            out->t = r.t;
            out->point = detail::vec(r.point);
        };
        if constexpr (requires { &K::reflect; })
            t.reflect = [](void*, ricochet_vec2 v, const ricochet_wall* w) {
                return detail::vec(K::reflect(detail::vec(v), detail::wall(w)));
            };
        if constexpr (requires { &K::sweep_disc; }) {
            t.sweep_disc = [](void*, ricochet_vec2 bs, ricochet_vec2 v, double r, const ricochet_wall* w,
                              ricochet_disc_result* out) {
                detail::disc_result(K::sweep_disc(detail::vec(bs), detail::vec(v), r, detail::wall(w)), out);
            };
            if constexpr (requires { &K::sweep_disc_bumper; })
                t.sweep_disc_bumper = [](void*, ricochet_vec2 bs, ricochet_vec2 v, double r, const ricochet_circle* c,
                                         ricochet_disc_result* out) {
                    detail::disc_result(
                        K::sweep_disc_bumper(detail::vec(bs), detail::vec(v), r, Circle{detail::vec(c->c), c->r}), out);
                };
        }
        if constexpr (requires { &K::reflect_disc; })
            t.reflect_disc = [](void*, ricochet_vec2 v, ricochet_vec2 n) {
                return detail::vec(K::reflect_disc(detail::vec(v), detail::vec(n)));
            };
        if constexpr (requires { K::speed_rel_bound; K::speed_abs_bound; }) {
            t.speed_rel_bound = K::speed_rel_bound;
            t.speed_abs_bound = K::speed_abs_bound;
        }
        return t;
    }();
    return table;
}

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
/// Runs every property against the kernel class K (kernel_table<K>()): RICOCHET_TEST_KERNEL_CLASS(MyKernel).
#define RICOCHET_TEST_KERNEL_CLASS(K) RICOCHET_TEST_KERNEL(::ricochet::props::kernel_table<K>())
/// The same, in the domain DOMAIN (a string, as RICOCHET_DOMAIN spells it): RICOCHET_TEST_KERNEL_IN(kTable,
/// "coordinates=1e6,no-subnormals").
#define RICOCHET_TEST_KERNEL_IN(TABLE, DOMAIN)                                                           \
    [[maybe_unused]] static const bool RICOCHET_PROPERTIES_CONCAT(ricochet_test_kernel_, __LINE__) = \
        ::ricochet::props::test_kernel(TABLE, DOMAIN)
