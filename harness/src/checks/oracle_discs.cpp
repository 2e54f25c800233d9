// The oracle for discs (oracle_discs.hpp): a disc's legs as its kernel swept them, against truth.hpp's exact
// disc contacts.
#include "checks/oracle_discs.hpp"

#include <fmt/format.h>

#include "ricochet/format.hpp"

namespace ricochet::checks {
namespace {

using Contact = truth::DiscContact;

std::string part_name(Contact::Part p) {
    switch (p) {
        case Contact::Part::face: return "its face";
        case Contact::Part::cap0: return "its cap at P0";
        case Contact::Part::cap1: return "its cap at P1";
        case Contact::Part::circle: return "its rim";
    }
    return "?";
}

std::string describe(const Contact& c) {
    if (c.obstacle == Contact::Obstacle::none) return "nothing";
    return fmt::format("{} {} ({}{})", c.obstacle == Contact::Obstacle::wall ? "wall" : "bumper", c.index,
                       part_name(c.part), c.at_start ? ", at t = 0" : "");
}

}  // namespace

std::optional<CheckFailure> DiscOracle::legs(const Frame& f, std::uint32_t i) {
    const auto fail = [&](std::string m) { return failure(Check::oracle, f.index, i, std::move(m)); };
    const StepTrace& trace = f.traces[i];
    const double R = scene_.balls[i].r > 0 ? scene_.balls[i].r : 0.0;
    std::vector<Printed> printed;
    for (const Event& e : f.events)
        if (e.ball == i && (e.kind == Event::Kind::hit || e.kind == Event::Kind::bump))
            printed.push_back({e.kind == Event::Kind::bump, e.index});
    // A kernel that steps whole frames (a plug-in's frame step) shows only the frame, judged by its first contact.
    if (!trace.legs_traced) return kernel_ == KernelId::exact ? std::nullopt : first_contact(f, i, printed);
    std::vector<Printed> traced;
    std::vector<bool> decided(scene_.walls.size());
    for (std::size_t l = 0; l < trace.legs.size(); ++l) {
        const TracedLeg& leg = trace.legs[l];
        const std::string where = fmt::format("leg {} ({} -> {})", l, leg.from, leg.to);
        if (!finite_leg(leg))
            return fail(fmt::format("{}: the kernel swept a leg whose end is not finite", where));
        std::fill(decided.begin(), decided.end(), false);
        for (std::uint32_t d = leg.first_decision; d < leg.first_decision + leg.decision_count; ++d) {
            const TracedDecision& td = trace.decisions[d];
            decided[td.wall] = true;
            const bool got = td.miss == Miss::none;
            if (got != truth::disc_meets_wall(leg.from, leg.to, R, scene_.walls[td.wall]))
                return fail(fmt::format("{} of a ball of radius {} against wall {}: the kernel says {}, exactly {}",
                                        where, R, td.wall, got ? "a contact" : "no contact",
                                        got ? "no contact" : "a contact"));
        }
        // A wall the kernel did not try (its broad phase left it out) must have no contact, exactly.
        for (std::uint32_t w = 0; w < scene_.walls.size(); ++w)
            if (!decided[w] && !(leg.skipped && *leg.skipped == w) &&
                truth::disc_meets_wall(leg.from, leg.to, R, scene_.walls[w]))
                return fail(fmt::format("{} of a ball of radius {} meets wall {} exactly, but the kernel never tried it",
                                        where, R, w));
        const Contact want = truth::disc_first_contact(
            leg.from, leg.to, R, scene_.walls, scene_.bumpers, leg.skipped ? static_cast<long>(*leg.skipped) : -1,
            leg.skipped_bumper ? static_cast<long>(*leg.skipped_bumper) : -1);
        std::optional<Printed> got;
        if (leg.hit) got = Printed{false, *leg.hit};
        else if (leg.bumped) got = Printed{true, *leg.bumped};
        const bool same = want.obstacle == Contact::Obstacle::none
                              ? !got
                              : got && got->bumper == (want.obstacle == Contact::Obstacle::bumper) && got->index == want.index;
        if (!same)
            return fail(fmt::format("{} of a ball of radius {}: the kernel meets {} first, exactly {}", where, R,
                                    got ? fmt::format("{} {}", got->bumper ? "bumper" : "wall", got->index)
                                        : std::string("nothing"),
                                    describe(want)));
        if (got) traced.push_back(*got);
    }
    // A contact found at the bounce limit is not taken: the ball stays at its last safe point.
    if (trace.stopped_at_limit && traced.size() == printed.size() + 1) traced.pop_back();
    if (traced != printed)
        return fail(fmt::format("the frame printed {} hit(s) and bump(s), the legs swept give {}", printed.size(),
                                traced.size()));
    // The bounce limit as the spec states it, spelled here rather than read from limits.hpp.
    constexpr std::size_t k_spec_bounce_limit = 16;
    if (printed.size() > k_spec_bounce_limit || (trace.stopped_at_limit && printed.size() != k_spec_bounce_limit))
        return fail(fmt::format("the frame made {} bounce(s) and {} at the limit; the limit is {} bounces",
                                printed.size(), trace.stopped_at_limit ? "stopped" : "did not stop", k_spec_bounce_limit));
    return first_contact(f, i, printed);
}

std::optional<CheckFailure> DiscOracle::first_contact(const Frame& f, std::uint32_t i, const std::vector<Printed>& printed) {
    if (kernel_ == KernelId::exact) return std::nullopt;
    Ball ball = f.before[i];
    ball.r = scene_.balls[i].r;
    BallMemory memory = f.memory_before[i];
    hits_.clear();
    // A frame that leaves the accepted range changes nothing: no exact frame to compare with.
    // Among balls that collide every ball is stepped as a disc, a point ball too (Obstacles::balls_meet).
    Obstacles obstacles{scene_.walls, scene_.bumpers};
    obstacles.balls_meet = scene_.balls_collide;
    if (step_ball(KernelId::exact, ball, memory, obstacles, hits_, scratch_) ==
        FrameStatus::out_of_range)
        return std::nullopt;
    const auto name = [](std::optional<Printed> c) {
        return c ? fmt::format("{} {}", c->bumper ? "bumper" : "wall", c->index) : std::string("nothing");
    };
    const std::optional<Printed> want =
        hits_.empty() ? std::nullopt : std::optional<Printed>(Printed{hits_.front().bumper, hits_.front().wall});
    const std::optional<Printed> got = printed.empty() ? std::nullopt : std::optional<Printed>(printed.front());
    if (want != got)
        return failure(Check::oracle, f.index, i,
                       fmt::format("from {} moving {} the kernel meets {} first, the exact kernel {}", f.before[i].pos,
                                   f.before[i].vel, name(got), name(want)));
    return std::nullopt;
}

}  // namespace ricochet::checks
