// broad-phase: the run with no broad phase on one thread and with the grid on two threads give the
// events of the checked run bit for bit.
#include "checks/frame_check.hpp"

namespace ricochet::checks {
namespace {

class BroadPhaseSame final : public FrameCheck {
public:
    BroadPhaseSame(const Scene& scene, KernelId kernel)
        : plain_(scene, kernel, {.broad_phase = BroadPhase::none, .threads = 1}),
          grid_(scene, kernel, {.broad_phase = BroadPhase::grid, .threads = 2}) {}

    std::optional<CheckFailure> frame(const Frame& f) override {
        plain_events_.clear();
        grid_events_.clear();
        if (f.index == 0) {
            plain_.start(plain_events_);
            grid_.start(grid_events_);
        } else {
            (void)plain_.step(plain_events_);
            (void)grid_.step(grid_events_);
        }
        if (auto bad = compare_events(Check::broad_phase, f.index, plain_events_, f.events, true,
                                      "the checked run (default options)"))
            return bad;
        return compare_events(Check::broad_phase, f.index, plain_events_, grid_events_, true,
                              "the grid on 2 threads");
    }

private:
    World plain_, grid_;
    std::vector<Event> plain_events_, grid_events_;
};

}  // namespace

std::unique_ptr<FrameCheck> make_broad_phase(const Scene& scene, KernelId kernel, const WorldOptions&) {
    return std::make_unique<BroadPhaseSame>(scene, kernel);
}

}  // namespace ricochet::checks
