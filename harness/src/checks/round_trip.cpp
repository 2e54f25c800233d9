// round-trip: the scene written as a log reads back as the same scene bit for bit, and rewriting it
// gives the same text.
#include <fmt/format.h>

#include <variant>

#include "checks/frame_check.hpp"
#include "ricochet/bits.hpp"
#include "ricochet/scene_log_format.hpp"

namespace ricochet::checks {
namespace {

class RoundTrip final : public FrameCheck {
public:
    explicit RoundTrip(const Scene& scene) : scene_(scene) {}

    std::optional<CheckFailure> frame(const Frame& f) override {
        // A property of the scene, not of its run: decided once, at frame 0.
        if (f.index != 0) return std::nullopt;
        const std::string text = write_scene_log(scene_);
        auto parsed = parse_scene_log(text, "round-trip");
        if (const auto* d = std::get_if<Diagnostic>(&parsed))
            return failure(Check::round_trip, 0, 0, fmt::format("the written log does not read back: {}", d->str()));
        const Scene& back = std::get<Scene>(parsed);
        if (!same_bits(back, scene_)) return failure(Check::round_trip, 0, 0, "the scene read back differs from the one written");
        // Unreachable while write_scene_log is a function of the scene's bits: back is scene_, bit for bit.
        if (write_scene_log(back) != text)
            return failure(Check::round_trip, 0, 0, "writing the scene read back changes the text");
        return std::nullopt;
    }

private:
    const Scene& scene_;
};

}  // namespace

std::unique_ptr<FrameCheck> make_round_trip(const Scene& scene, KernelId, const WorldOptions&) { return std::make_unique<RoundTrip>(scene); }

}  // namespace ricochet::checks
