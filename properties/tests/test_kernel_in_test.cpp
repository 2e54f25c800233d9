// RICOCHET_TEST_KERNEL_IN (ricochet/properties.hpp): a table put under test with its domain. The kernel is the
// one under test, its domain is the declared one (RICOCHET_DOMAIN overrides it), and every scene a property
// judges has been brought into it (domain.hpp, fit_to_domain) or discarded. Run with
// --gtest_filter='TestKernelIn.*' (the suite's own properties are linked in too).
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include <fmt/format.h>

#include "harness.hpp"
#include "ricochet/domain.hpp"
#include "ricochet/kernel.hpp"
#include "ricochet/properties.hpp"

namespace {

/// robust's sweep behind a table: a kernel of the user's that is right.
void robust_sweep(void*, ricochet_vec2 bs, ricochet_vec2 v, const ricochet_wall* w, ricochet_sweep_result* out) {
    using namespace ricochet;
    const Sweep r = sweep(KernelId::robust, {bs.x, bs.y}, {v.x, v.y}, Wall{{w->p0.x, w->p0.y}, {w->p1.x, w->p1.y}});
    out->miss = r.hit() ? RICOCHET_HIT : RICOCHET_MISS;
    out->t = r.t;
    out->point = {r.point.x, r.point.y};
}

const ricochet_plugin& table() {
    static const ricochet_plugin t = [] {
        ricochet_plugin x{};
        x.abi_version = RICOCHET_PLUGIN_ABI_VERSION;
        x.struct_size = sizeof(ricochet_plugin);
        x.name = "domain-test";
        x.sweep = robust_sweep;
        return x;
    }();
    return t;
}

}  // namespace

RICOCHET_TEST_KERNEL_IN(table(), "coordinates=1000,no-subnormals");

namespace ricochet::props {
namespace {

/// The domain the test expects: RICOCHET_DOMAIN's where set, else the declared one.
std::string expected_spec() {
    const char* env = std::getenv("RICOCHET_DOMAIN");
    return env != nullptr ? env : "coordinates=1000,no-subnormals";
}

TEST(TestKernelIn, TheKernelIsUnderTestInItsDomain) {
    const std::vector<KernelId> kernels = kernels_under_test();
    ASSERT_EQ(kernels.size(), 1u);
    EXPECT_EQ(kernel_name(kernels[0]), "domain-test");
    EXPECT_EQ(domain_spec(domain_under_test(kernels[0])), expected_spec());
    // Another kernel gets the full domain unless RICOCHET_DOMAIN says otherwise.
    if (std::getenv("RICOCHET_DOMAIN") == nullptr) EXPECT_TRUE(domain_under_test(KernelId::robust).full());
}

TEST(TestKernelIn, EveryJudgedSceneLiesInTheDomain) {
    const KernelId k = kernels_under_test().at(0);
    const Domain domain = domain_under_test(k);
    // Walls up to 2^40 long and velocities down to subnormals: most need scaling, a quarter are discarded.
    const auto gen = rc::gen::apply(
        [](int scale, int wall_x, bool subnormal) {
            Scene s;
            s.frames = 1;
            s.walls = {{{std::ldexp(double(wall_x), scale), -1}, {std::ldexp(double(wall_x), scale), 1}}};
            s.balls = {{{0, 0}, {subnormal ? 1e-310 : 3.0, 0.5}}};
            return s;
        },
        rc::gen::inRange(0, 40), rc::gen::inRange(1, 100), rc::gen::weightedOneOf<bool>({{3, rc::gen::just(false)}, {1, rc::gen::just(true)}}));
    long judged = 0;
    run_property({"DomainFit", Check::no_tunnel, gen,
                  [&](KernelId, const Scene& s) -> std::optional<Failure> {
                      ++judged;
                      if (!(s.domain == domain)) return fail(Check::no_tunnel, "the scene does not carry the domain");
                      if (const auto why = outside_domain(s, domain)) return fail(Check::no_tunnel, *why);
                      return std::nullopt;
                  },
                  200},
                 k);
    EXPECT_GE(judged, 200);
}

}  // namespace
}  // namespace ricochet::props
