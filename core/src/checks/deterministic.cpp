// deterministic: a second World in lockstep gives the same events bit for bit, and the same hash.
#include "frame_check.hpp"
#include "ricochet/hash.hpp"

namespace ricochet::checks {
namespace {

class Deterministic final : public FrameCheck {
public:
    Deterministic(const Scene& scene, KernelId kernel, const WorldOptions& world) : twin_(scene, kernel, world) {}

    std::optional<CheckFailure> frame(const Frame& f) override {
        other_.clear();
        if (f.index == 0) twin_.start(other_);
        else (void)twin_.step(other_);
        ours_.add(f.events);
        theirs_.add(other_);
        if (auto bad = compare_events(Check::deterministic, f.index, f.events, other_, true, "a second run"))
            return bad;
        // Equal records give equal hashes; a streaming hash that differs is a hasher bug.
        if (ours_.digest() != theirs_.digest())
            return failure(Check::deterministic, f.index, 0, "the same events give a different run hash");
        return std::nullopt;
    }

private:
    World twin_;
    std::vector<Event> other_;
    RunHasher ours_, theirs_;
};

}  // namespace

std::unique_ptr<FrameCheck> make_deterministic(const Scene& scene, KernelId kernel, const WorldOptions& world) {
    return std::make_unique<Deterministic>(scene, kernel, world);
}

}  // namespace ricochet::checks
