// Which checks a fuzz input gets (fuzz/README.md, "Which checks an input gets"): every check that reads the run
// once, and the six that step the scene again on a quarter of the inputs, chosen by the input's own bytes, so
// that an input is always asked the same checks and no verdict depends on luck.
#pragma once

#include <xxhash.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <string_view>
#include <vector>

#include "ricochet/check.hpp"

namespace ricochet::fuzz {

/// The checks that step the scene again (mirrored, turned, reversed, translated, without the grid or the plan,
/// twice): the costly tier, asked of one input in k_restep_share.
inline constexpr std::array<Check, 6> k_restepping_checks = {Check::symmetry,    Check::swap, Check::translation,
                                                             Check::broad_phase, Check::plan, Check::deterministic};
inline constexpr std::uint64_t k_restep_share = 4;
/// Set to 1: every input gets every check (a campaign that wants them all at a fraction of the speed).
inline constexpr const char* k_all_checks_env = "RICOCHET_FUZZ_ALL_CHECKS";

/// The checks of `checks` that input (a target's raw bytes) is asked: every one that reads the run once, and the
/// restepping ones where XXH64(input, seed 0) % k_restep_share == 0, or every = true.
inline std::vector<Check> checks_for(std::span<const std::uint8_t> input, std::span<const Check> checks, bool every) {
    const bool restep = every || XXH64(input.data(), input.size(), 0) % k_restep_share == 0;
    std::vector<Check> out;
    for (const Check c : checks)
        if (restep || std::find(k_restepping_checks.begin(), k_restepping_checks.end(), c) == k_restepping_checks.end())
            out.push_back(c);
    return out;
}

/// checks_for with every read from the environment: RICOCHET_FUZZ_ALL_CHECKS=1.
inline std::vector<Check> checks_for(std::span<const std::uint8_t> input, std::span<const Check> checks) {
    static const bool every = [] {
        const char* v = std::getenv(k_all_checks_env);
        return v != nullptr && std::string_view(v) == "1";
    }();
    return checks_for(input, checks, every);
}

}  // namespace ricochet::fuzz
