// check_tiers.hpp: the checks an input gets are decided by its bytes alone, a quarter of inputs get the restepping
// checks, and the rest get every other check.
#include <gtest/gtest.h>

#include <xxhash.h>

#include <cstdint>
#include <vector>

#include "check_tiers.hpp"

namespace ricochet::fuzz {
namespace {

TEST(CheckTiers, TheInputsBytesDecideAndAQuarterGetEveryCheck) {
    const std::vector<Check> all(k_all_checks.begin(), k_all_checks.end());
    int full = 0;
    for (std::uint8_t n = 0; n < 200; ++n) {
        const std::vector<std::uint8_t> input(n, static_cast<std::uint8_t>(n * 37));
        const std::vector<Check> got = checks_for(input, all, false);
        // The same bytes, the same checks.
        EXPECT_EQ(got, checks_for(input, all, false));
        const bool restep = XXH64(input.data(), input.size(), 0) % 4 == 0;
        if (restep) {
            EXPECT_EQ(got, all);
            ++full;
        } else {
            EXPECT_EQ(got.size(), all.size() - k_restepping_checks.size());
            for (const Check c : k_restepping_checks) EXPECT_EQ(std::count(got.begin(), got.end(), c), 0);
        }
        // Every input keeps the checks that read the run once, in the target's order.
        for (const Check c : {Check::no_tunnel, Check::oracle, Check::accuracy, Check::penetration, Check::speed})
            EXPECT_EQ(std::count(got.begin(), got.end(), c), 1);
        EXPECT_EQ(checks_for(input, all, true), all);
    }
    // About a quarter of 200 (a fixed set of inputs: the count is fixed too).
    EXPECT_GT(full, 30);
    EXPECT_LT(full, 70);
}

}  // namespace
}  // namespace ricochet::fuzz
