// plan: the run with every decision on the general exact path gives the events of the checked run bit for bit.
#include "checks/frame_check.hpp"

namespace ricochet::checks {
namespace {

class PlanSame final : public FrameCheck {
public:
    PlanSame(const Scene& scene, KernelId kernel, WorldOptions options) : general_(scene, kernel, without_plan(options)) {}

    std::optional<CheckFailure> frame(const Frame& f) override {
        events_.clear();
        if (f.index == 0)
            general_.start(events_);
        else
            (void)general_.step(events_);
        return compare_events(Check::plan, f.index, events_, f.events, true,
                              "the checked run (the walls' plan, wall_plan.hpp)");
    }

private:
    static WorldOptions without_plan(WorldOptions o) {
        o.plan = false;
        return o;
    }
    World general_;
    std::vector<Event> events_;
};

}  // namespace

std::unique_ptr<FrameCheck> make_plan(const Scene& scene, KernelId kernel, const WorldOptions& world) {
    return std::make_unique<PlanSame>(scene, kernel, world);
}

}  // namespace ricochet::checks
