// relabel: numbering the balls the other way round changes nothing but the numbers. The scene with its balls (and
// their masses) in reverse order, stepped in lockstep, prints per ball the run's events, ball i as ball N − 1 − i, a
// meet's other ball too, by value (mapped_run.hpp); from a frame where a meet was taken while another sharing a ball
// was due at the same exact time (three balls at one point, taken pair by pair in index order), or one of such a group
// placed against the balls as they are (MeetRecord::tied), the two runs may part, and the image is compared no more.
#include "checks/frame_check.hpp"
#include "checks/mapped_run.hpp"

namespace ricochet::checks {
namespace {

class Relabel final : public FrameCheck {
public:
    Relabel(const Scene& scene, KernelId kernel, const WorldOptions& world) {
        // Degenerate: balls that do not collide move as if alone; numbered otherwise, each makes the same frames.
        if (scene.balls_collide) image_.emplace(scene, k_reversed, kernel, world);
    }

    std::optional<CheckFailure> frame(const Frame& f) override {
        if (!image_) return std::nullopt;
        return image_->frame(Check::relabel, f);
    }

private:
    static constexpr SceneMap k_reversed{"the run with its balls in reverse order", nullptr, false, true, false};

    std::optional<MappedRun> image_;
};

}  // namespace

std::unique_ptr<FrameCheck> make_relabel(const Scene& scene, KernelId kernel, const WorldOptions& world) {
    return std::make_unique<Relabel>(scene, kernel, world);
}

}  // namespace ricochet::checks
