// oracle: every decision the kernel makes equals the exact one (truth.hpp), leg by leg on its own legs,
// and every static test the scene poses. A ball stepped as a disc has its legs judged by oracle_discs.cpp; a frame
// whose balls collide has its first meet judged by oracle_meets.cpp.
#include <fmt/format.h>

#include "checks/frame_check.hpp"
#include "checks/oracle_discs.hpp"
#include "checks/oracle_meets.hpp"
#include "ricochet/bits.hpp"
#include "ricochet/format.hpp"
#include "ricochet/truth.hpp"

namespace ricochet::checks {
namespace {

std::string wall_name(long w) { return w < 0 ? std::string("no wall") : fmt::format("wall {}", w); }

class Oracle final : public FrameCheck {
public:
    Oracle(const Scene& scene, KernelId kernel) : scene_(scene), kernel_(kernel), discs_(scene, kernel), meets_(scene, kernel) {}

    bool needs_traces() const override { return true; }

    std::optional<CheckFailure> frame(const Frame& f) override {
        if (f.index == 0)
            if (auto bad = statics()) return bad;
        if (auto bad = positions(f)) return bad;
        if (f.index == 0) return std::nullopt;
        // Balls that collide: the frame's first meet against the exact one (oracle_meets.cpp), reported in ball order
        // among the legs' failures.
        std::optional<CheckFailure> meet = meets_.first_meet(f);
        // A ball that met another was not stepped alone: it has no legs of its own to judge (met_in_frame).
        const std::vector<bool> met = met_in_frame(f, f.before.size());
        for (std::uint32_t i = 0; i < f.before.size(); ++i) {
            if (meet && meet->ball < i) return meet;
            if (met[i]) continue;
            if (auto bad = stepped_as_disc(scene_, i) ? discs_.legs(f, i) : legs(f, i)) return bad;
        }
        return meet;
    }

private:

    /// Frame 0: every pair of static shapes, in both orders.
    std::optional<CheckFailure> statics() const {
        const KernelId k = kernel_;
        for (std::size_t i = 0; i < scene_.circles.size(); ++i)
            for (std::size_t j = 0; j < scene_.circles.size(); ++j) {
                const Circle &a = scene_.circles[i], &b = scene_.circles[j];
                if (circles_overlap(k, a, b) != truth::circles_overlap(a, b))
                    return failure(Check::oracle, 0, 0,
                                   fmt::format("circles_overlap(circle {}, circle {}) = {}, exactly {}", i, j,
                                               circles_overlap(k, a, b), truth::circles_overlap(a, b)));
            }
        for (std::size_t i = 0; i < scene_.rects.size(); ++i)
            for (std::size_t j = 0; j < scene_.rects.size(); ++j) {
                const Rect &a = scene_.rects[i], &b = scene_.rects[j];
                if (rects_overlap(k, a, b) != truth::rects_overlap(a, b))
                    return failure(Check::oracle, 0, 0,
                                   fmt::format("rects_overlap(rect {}, rect {}) = {}, exactly {}", i, j,
                                               rects_overlap(k, a, b), truth::rects_overlap(a, b)));
            }
        return std::nullopt;
    }

    /// Each printed state: its overlap events are exactly the shapes holding it, and its side of every wall
    /// is the exact one.
    std::optional<CheckFailure> positions(const Frame& f) const {
        for (std::size_t j = 0; j < f.events.size(); ++j) {
            const Event& e = f.events[j];
            if (e.kind != Event::Kind::state) continue;
            const auto fail = [&](std::string m) { return failure(Check::oracle, f.index, e.ball, std::move(m)); };
            const Vec2 p = e.pos;
            for (std::size_t w = 0; w < scene_.walls.size(); ++w) {
                const Side got = classify(kernel_, p, scene_.walls[w]);
                const int want = truth::side(p, scene_.walls[w]);
                if (sign_of(got) != want)
                    return fail(fmt::format("classify({}, wall {}) = {}, exactly {}", p, w, got, side_from_sign(want)));
            }
            // The overlaps of this ball as the frame printed them (ball-major, circles then rects, by index).
            std::vector<std::pair<Event::Shape, std::uint32_t>> got, want;
            for (const Event& o : f.events)
                if (o.kind == Event::Kind::overlap && o.ball == e.ball) got.emplace_back(o.shape, o.index);
            // A disc overlaps a sensor it touches at its size (docs/scene-log.md, "Discs and bumpers").
            const double R = scene_.balls[e.ball].r;
            for (std::uint32_t c = 0; c < scene_.circles.size(); ++c)
                if (R > 0 ? truth::disc_in_circle(p, R, scene_.circles[c]) : truth::point_in_circle(p, scene_.circles[c]))
                    want.emplace_back(Event::Shape::circle, c);
            for (std::uint32_t r = 0; r < scene_.rects.size(); ++r)
                if (R > 0 ? truth::disc_in_rect(p, R, scene_.rects[r]) : truth::point_in_rect(p, scene_.rects[r]))
                    want.emplace_back(Event::Shape::rect, r);
            if (got != want) {
                const auto list = [](const auto& v) {
                    std::string s;
                    for (const auto& [shape, i] : v)
                        s += fmt::format("{}{} {}", s.empty() ? "" : ", ", shape == Event::Shape::circle ? "circle" : "rect", i);
                    return s.empty() ? std::string("none") : s;
                };
                return fail(fmt::format("at {} the frame's overlaps are [{}], exactly [{}]", p, list(got), list(want)));
            }
        }
        return std::nullopt;
    }

    /// Ball i's legs this frame, as its kernel swept them: each decision, each first hit and the order of
    /// hits against the exact answers for that same leg.
    std::optional<CheckFailure> legs(const Frame& f, std::uint32_t i) {
        const auto fail = [&](std::string m) { return failure(Check::oracle, f.index, i, std::move(m)); };
        const StepTrace& trace = f.traces[i];
        // The kernel's hits, as the frame printed them.
        std::vector<std::uint32_t> printed;
        for (const Event& e : f.events)
            if (e.kind == Event::Kind::hit && e.ball == i) printed.push_back(e.index);
        // Legs not traced: the exact kernel's are rational (it is the oracle itself); a kernel that steps whole
        // frames (a plug-in's frame step, plugin.h) shows only the frame, judged by its first hit below.
        if (!trace.legs_traced) return kernel_ == KernelId::exact ? std::nullopt : first_hit(f, i, printed);
        std::vector<std::uint32_t> traced;
        std::size_t blocked = 0;  // legs that ended reflecting off a contact wall
        std::vector<bool> decided(scene_.walls.size());
        for (std::size_t l = 0; l < trace.legs.size(); ++l) {
            const TracedLeg& leg = trace.legs[l];
            const std::string where = fmt::format("leg {} ({} -> {})", l, leg.from, leg.to);
            if (!finite_leg(leg))
                return fail(fmt::format("{}: the kernel swept a leg whose end is not finite", where));
            if (leg.blocked) {
                ++blocked;
                // The leg ends on the far side of the contact wall it was stopped by.
                if (truth::side(leg.to, scene_.walls[leg.blocked_wall]) != -leg.blocked_side)
                    return fail(fmt::format("{} is taken as leaving contact wall {} to its far side, but it does not "
                                            "end there exactly",
                                            where, leg.blocked_wall));
                continue;
            }
            std::fill(decided.begin(), decided.end(), false);
            for (std::uint32_t d = leg.first_decision; d < leg.first_decision + leg.decision_count; ++d) {
                const TracedDecision& td = trace.decisions[d];
                decided[td.wall] = true;
                const Miss want = truth::leg_miss(leg.from, leg.to, scene_.walls[td.wall]);
                // A miss without a reason (a plug-in's, sweep.hpp) is judged as a miss: right whenever truth misses.
                const bool same = td.miss == Miss::no_reason ? want != Miss::none : td.miss == want;
                if (!same)
                    return fail(fmt::format("{} against wall {}: the kernel says {}, exactly {}", where, td.wall,
                                            td.miss, want));
            }
            // A wall the kernel did not try (its broad phase left it out) must be missed, exactly.
            for (std::uint32_t w = 0; w < scene_.walls.size(); ++w)
                if (!decided[w] && !(leg.skipped && *leg.skipped == w) &&
                    truth::leg_miss(leg.from, leg.to, scene_.walls[w]) == Miss::none)
                    return fail(fmt::format("{} hits wall {} exactly, but the kernel never tried it", where, w));
            long want = truth::first_hit(leg.from, leg.to, scene_.walls);
            // The kernel's own rule may leave one wall out (lecture: the wall just bounced off).
            if (leg.skipped) want = first_hit_without(leg, *leg.skipped);
            const long got = leg.hit ? static_cast<long>(*leg.hit) : -1;
            if (got != want)
                return fail(fmt::format("{}: the kernel hits {} first, exactly {}", where, wall_name(got),
                                        wall_name(want)));
            if (leg.hit) traced.push_back(*leg.hit);
        }
        // A hit found at the bounce limit is not taken: the ball stays at its last safe point.
        if (trace.stopped_at_limit && traced.size() == printed.size() + 1) traced.pop_back();
        if (traced != printed)
            return fail(fmt::format("the frame printed {} hit(s), the legs swept give {}", printed.size(), traced.size()));
        // The bounce limit, as the spec states it ("at most 16 bounces a frame"; the number is spelled here, not
        // read from limits.hpp, so that a wrong k_max_bounces shows): a bounce is a hit taken or a reflection
        // off a contact wall; a frame stops at the limit only after 16, and then the ball stays at the last
        // point of its path.
        constexpr std::size_t k_spec_bounce_limit = 16;
        const std::size_t bounces = printed.size() + blocked;
        if (bounces > k_spec_bounce_limit || (trace.stopped_at_limit && bounces != k_spec_bounce_limit))
            return fail(fmt::format("the frame made {} bounce(s) ({} hit(s), {} off contact walls) and {} at the limit; "
                                    "the limit is {} bounces",
                                    bounces, printed.size(), blocked, trace.stopped_at_limit ? "stopped" : "did not stop",
                                    k_spec_bounce_limit));
        if (trace.stopped_at_limit) {
            const Event* state = nullptr;
            const Event* last_hit = nullptr;
            for (const Event& e : f.events)
                if (e.ball == i && e.kind == Event::Kind::state) state = &e;
                else if (e.ball == i && e.kind == Event::Kind::hit) last_hit = &e;
            const Vec2 last = last_hit != nullptr ? last_hit->pos : f.before[i].pos;
            // state is never null: every ball prints a state every frame (world.hpp).
            if (state != nullptr && !same_bits(state->pos, last))
                return fail(fmt::format("stopped at the bounce limit at {}, but the last point of its path is {}",
                                        state->pos, last));
        }
        return first_hit(f, i, printed);
    }

    /// The frame's first hit (printed: the hit walls the frame printed for ball i) against the exact kernel's
    /// frame from the same state and memory. (The exact kernel's own frames never come here: it traces no legs.)
    std::optional<CheckFailure> first_hit(const Frame& f, std::uint32_t i, const std::vector<std::uint32_t>& printed) {
        const auto fail = [&](std::string m) { return failure(Check::oracle, f.index, i, std::move(m)); };
        Ball ball = f.before[i];
        BallMemory memory = f.memory_before[i];
        hits_.clear();
        // A frame that leaves the accepted range changes nothing and reports no hits (step.hpp): the exact
        // kernel's reflection may round a component past 2^256 where this kernel's does not (or the other
        // way round), and then there is no exact frame to compare with.
        if (step_ball(KernelId::exact, ball, memory, scene_.walls, hits_, scratch_) == FrameStatus::out_of_range)
            return std::nullopt;
        const long want = hits_.empty() ? -1 : static_cast<long>(hits_.front().wall);
        const long got = printed.empty() ? -1 : static_cast<long>(printed.front());
        if (want != got)
            return fail(fmt::format("from {} moving {} the kernel hits {} first, the exact kernel hits {}",
                                    f.before[i].pos, f.before[i].vel, wall_name(got), wall_name(want)));
        return std::nullopt;
    }

    long first_hit_without(const TracedLeg& leg, std::uint32_t skipped) {
        others_.assign(scene_.walls.begin(), scene_.walls.end());
        // A zero-length wall is never hit: it stands in for the skipped one and keeps the indices.
        others_[skipped] = Wall{};
        return truth::first_hit(leg.from, leg.to, others_);
    }

    const Scene& scene_;
    KernelId kernel_;
    DiscOracle discs_;
    MeetOracle meets_;
    std::vector<HitEvent> hits_;
    StepScratch scratch_;
    std::vector<Wall> others_;
};

}  // namespace

std::unique_ptr<FrameCheck> make_oracle(const Scene& scene, KernelId kernel, const WorldOptions&) {
    return std::make_unique<Oracle>(scene, kernel);
}

}  // namespace ricochet::checks
