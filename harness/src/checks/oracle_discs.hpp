// Internal: the oracle check for a ball stepped as a disc (a ball of radius R > 0, or any ball in a scene with
// bumpers), leg by leg against truth.hpp's DiscContact (checks.hpp, `oracle`).
#pragma once

#include <optional>
#include <vector>

#include "checks/frame_check.hpp"
#include "ricochet/truth.hpp"

namespace ricochet::checks {

class DiscOracle {
public:
    DiscOracle(const Scene& scene, KernelId kernel) : scene_(scene), kernel_(kernel) {}
    /// Ball i's frame f: each leg's per-wall contact decisions and first contact against the exact ones, the
    /// contacts the frame printed against the legs', the bounce limit, and the frame's first contact against the
    /// exact kernel's frame from the same state.
    std::optional<CheckFailure> legs(const Frame& f, std::uint32_t i);

private:
    /// A contact as the frame printed it: a hit (wall) or a bump (bumper) and its index.
    struct Printed {
        bool bumper = false;
        std::uint32_t index = 0;
        friend bool operator==(const Printed&, const Printed&) = default;
    };
    std::optional<CheckFailure> first_contact(const Frame& f, std::uint32_t i, const std::vector<Printed>& printed);

    const Scene& scene_;
    KernelId kernel_;
    std::vector<HitEvent> hits_;
    StepScratch scratch_;
};

}  // namespace ricochet::checks
