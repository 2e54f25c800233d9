// ricochet's World as an Engine (engine.hpp): its paths and meets are what the counter needs, exactly.
#include <stdexcept>
#include <vector>

#include "engine.hpp"
#include "ricochet/world.hpp"

namespace ricochet::meet_bench {
namespace {

class RicochetEngine final : public Engine {
public:
    RicochetEngine(const MeetScene& s, KernelId k)
        : side_(s.side), world_(to_scene(s), k, WorldOptions{BroadPhase::grid, 1}) {}

    void step() override {
        // The events are what World makes for a caller; making them is part of a frame's cost.
        events_.clear();
        if (world_.step(events_)) throw std::runtime_error("a ball left the accepted range");
    }
    std::span<const Ball> balls() override { return world_.balls(); }
    double side() const override { return side_; }
    FrameRecord frame() override {
        paths_.resize(world_.balls().size());
        for (std::size_t i = 0; i < paths_.size(); ++i) paths_[i].assign(world_.path(i).begin(), world_.path(i).end());
        met_.clear();
        for (const MeetRecord& m : world_.meets()) met_.emplace_back(m.a, m.b);
        return {world_.balls(), paths_, met_, {}};
    }

private:
    double side_;
    World world_;
    std::vector<Event> events_;
    std::vector<std::vector<PathPoint>> paths_;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> met_;
};

}  // namespace

std::unique_ptr<Engine> make_ricochet(const MeetScene& s, KernelId k) { return std::make_unique<RicochetEngine>(s, k); }

}  // namespace ricochet::meet_bench
