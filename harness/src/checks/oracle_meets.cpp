// The oracle for the first meet of a frame (oracle_meets.hpp): each ball's path rebuilt from its own step alone, the
// first meet decided on those paths by truth_meets.cpp, and the World's first record held to it.
#include "checks/oracle_meets.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "checks/near_pairs.hpp"
#include "ricochet/format.hpp"
#include "ricochet/truth.hpp"

namespace ricochet::checks {

MeetOracle::MeetOracle(const Scene& scene, KernelId kernel)
    : scene_(scene), kernel_(kernel), rule_(scene.balls_collide ? kernel_ops(kernel).meet_rule : MeetRule::none) {
    obstacles_.walls = scene.walls;
    obstacles_.bumpers = scene.bumpers;
    obstacles_.balls_meet = true;
    for (const Ball& b : scene.balls) radii_.push_back(reach_of(b.r));
}

void MeetOracle::step_alone(const Frame& f) {
    const std::size_t n = f.before.size();
    paths_.resize(n);
    ends_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        Ball ball = f.before[i];
        ball.r = scene_.balls[i].r;
        BallMemory memory = f.memory_before[i];
        hits_.clear();
        // A step that would leave the range leaves the ball where it was (and the World reports the frame's error).
        step_ball(kernel_, ball, memory, obstacles_, hits_, scratch_);
        ends_[i] = ball;
        // Rule 1: its start at t = 0, each contact at its t_i, its end at t = 1. A rounded t_i is held between the
        // previous point's time and 1, so that the path's times never decrease.
        std::vector<PathPoint>& path = paths_[i];
        path.assign(1, {0.0, f.before[i].pos});
        for (const HitEvent& h : hits_) path.push_back({std::clamp(h.t, path.back().t, 1.0), h.point});
        path.push_back({1.0, ball.pos});
    }
}

std::optional<CheckFailure> MeetOracle::first_meet(const Frame& f) {
    // Degenerate: no meets to judge (balls that pass through each other, frame 0, a kernel that steps no meets).
    if (rule_ == MeetRule::none || f.index == 0) return std::nullopt;
    const MeetRecord* first = f.meets.empty() ? nullptr : &f.meets.front();
    const auto line = std::find_if(f.events.begin(), f.events.end(), [](const Event& e) { return e.kind == Event::Kind::meet; });
    // Every printed meet has its record (momentum holds the two to each other); lines without one cannot be timed.
    if (first == nullptr && line != f.events.end())
        return failure(Check::oracle, f.index, line->ball,
                       fmt::format("the frame printed a meet of balls {} and {}, but the World recorded no meet to "
                                   "judge it by",
                                   line->ball, line->index));
    step_alone(f);
    return rule_ == MeetRule::swept ? swept(f, first, first != nullptr) : end_of_frame(f, first, first != nullptr);
}

std::optional<CheckFailure> MeetOracle::swept(const Frame& f, const MeetRecord* first, bool printed) {
    std::vector<PairBox> boxes(paths_.size());
    for (std::size_t i = 0; i < paths_.size(); ++i)
        for (const PathPoint& p : paths_[i]) boxes[i].add(p.p);
    const auto pairs = near_pairs(boxes, radii_);
    const truth::FirstMeet want = truth::first_meet(paths_, radii_, pairs, printed ? first->t : 0.0);
    const std::string exact =
        want.found ? fmt::format("balls {} and {} at t* = {:.17g}{}{}", want.i, want.j, want.approx,
                                 want.at_start ? " (within R_i + R_j and approaching at a piece's start)" : "",
                                 want.tied ? ", tied with a higher pair at the same exact time: ties go to the lowest pair"
                                           : "")
                   : std::string("no meet");
    if (!printed && !want.found) return std::nullopt;
    if (!printed)
        return failure(Check::oracle, f.index, want.i,
                       fmt::format("the frame printed no meet, but exactly its first meet is {} on the paths the balls "
                                   "make alone",
                                   exact));
    const std::string got = fmt::format("balls {} and {} at t = {}", first->a, first->b, first->t);
    if (!want.found)
        return failure(Check::oracle, f.index, first->a,
                       fmt::format("the frame's first meet is {}, but exactly the paths the balls make alone never "
                                   "meet in this frame (a tangent, a double root, is no meet)",
                                   got));
    if (first->a != want.i || first->b != want.j)
        return failure(Check::oracle, f.index, std::min(first->a, want.i),
                       fmt::format("the frame's first meet is {}, exactly {}", got, exact));
    if (!want.printed_in_time)
        return failure(Check::oracle, f.index, first->a,
                       fmt::format("the frame's first meet is {}, outside [0, t°] for the exact {} (t° the double "
                                   "nearest t*: a meet is printed there or walked back earlier, never later)",
                                   got, exact));
    return std::nullopt;
}

std::optional<CheckFailure> MeetOracle::end_of_frame(const Frame& f, const MeetRecord* first, bool printed) {
    // The lecture's rule: the first pair taken is the lowest i < j whose centres at the frame's end (each stepped
    // alone) are within S, at two points, and approach: |B_i − B_j|² ≤ S², B_i ≠ B_j, (v_i − v_j)·(B_i − B_j) < 0.
    std::vector<PairBox> boxes(ends_.size());
    for (std::size_t i = 0; i < ends_.size(); ++i) boxes[i].add(ends_[i].pos);
    std::optional<std::pair<std::uint32_t, std::uint32_t>> want;
    for (const auto& [i, j] : near_pairs(boxes, radii_)) {
        const Ball &a = ends_[i], &b = ends_[j];
        if (truth::circle_reach_side(a.pos, b.pos, radii_[i], radii_[j]) <= 0 && a.pos != b.pos &&
            truth::approach_sign(a.pos, a.vel, b.pos, b.vel) < 0) {
            want = {i, j};
            break;
        }
    }
    const auto name = [](auto p) { return p ? fmt::format("balls {} and {}", p->first, p->second) : std::string("none"); };
    const std::optional<std::pair<std::uint32_t, std::uint32_t>> got =
        printed ? std::optional(std::pair{first->a, first->b}) : std::nullopt;
    if (got == want) return std::nullopt;
    const std::uint32_t ball = !got ? want->first : !want ? got->first : std::min(got->first, want->first);
    return failure(Check::oracle, f.index, ball,
                   fmt::format("the frame's first meet at its end (the lecture's static test) is {}, exactly {}",
                               name(got), name(want)));
}

}  // namespace ricochet::checks
