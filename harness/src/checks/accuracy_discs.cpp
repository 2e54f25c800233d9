// The accuracy check for discs (accuracy_discs.hpp): a disc's contacts as its kernel swept them, against
// truth.hpp's exact contact times, contact points and reflections.
#include "checks/accuracy_discs.hpp"

#include <fmt/format.h>

#include "ricochet/format.hpp"
#include "ricochet/truth.hpp"

namespace ricochet::checks {

std::optional<CheckFailure> DiscAccuracy::contacts(const Frame& f, std::uint32_t i,
                                                   const std::vector<const Event*>& printed) const {
    const StepTrace& trace = f.traces[i];
    const double R = scene_.balls[i].r > 0 ? scene_.balls[i].r : 0.0;
    const auto fail = [&](std::string m) { return failure(Check::accuracy, f.index, i, std::move(m)); };
    // The k-th leg that took a contact printed the k-th hit or bump (one found at the bounce limit is not taken;
    // oracle checks the order, so a leg whose contact differs from its event's ends the comparison).
    std::size_t k = 0;
    for (std::size_t l = 0; l < trace.legs.size() && k < printed.size(); ++l) {
        const TracedLeg& leg = trace.legs[l];
        if (!leg.hit && !leg.bumped) continue;
        const Event& e = *printed[k++];
        if (!printed_as(e, leg) || !finite_leg(leg)) break;
        const bool bumper = !leg.hit;
        const std::uint32_t index = bumper ? *leg.bumped : *leg.hit;
        const char* what = bumper ? "bumper" : "wall";
        const truth::DiscAccuracy r = truth::disc_accuracy(
            leg.from, leg.to, R, scene_.walls, scene_.bumpers, leg.skipped ? static_cast<long>(*leg.skipped) : -1,
            leg.skipped_bumper ? static_cast<long>(*leg.skipped_bumper) : -1, {bumper, index, leg.hit_t, e.pos},
            k_disc_accuracy_ulps);
        // Not the exact first contact: oracle's failure.
        if (!r.taken_first) break;
        if (r.time.conditioned && !r.time.within)
            return fail(fmt::format("leg {} ({} -> {}) of a ball of radius {} meets {} {} at t_i = {}, {:.4g} eps*M "
                                    "along the leg from the exact contact (bound {})",
                                    l, leg.from, leg.to, R, what, index, leg.hit_t, r.time.error, k_disc_accuracy_ulps));
        if (r.point.conditioned && !r.point.within)
            return fail(fmt::format("leg {} ({} -> {}) of a ball of radius {} meets {} {} at {}, {:.4g} eps*M from the "
                                    "exact contact point (bound {})",
                                    l, leg.from, leg.to, R, what, index, e.pos, r.point.error, k_disc_accuracy_ulps));
        // A corner (another obstacle met at the same time) follows the corner rule, not judged here.
        if (r.tied) continue;
        const Vec2 v_out = velocity_after(f, i, l);
        const truth::HitAccuracy rb =
            truth::disc_bounce_accuracy(leg.vel, e.pos, bumper ? nullptr : &scene_.walls[index],
                                        bumper ? &scene_.bumpers[index] : nullptr, v_out, bound_.rel, bound_.abs);
        if (rb.conditioned && !rb.within)
            return fail(fmt::format("leg {} meets {} {} at {} moving {} and leaves moving {}, {:.4g}·|v| from the exact "
                                    "reflection about the normal there (bound 2·{:.4g}·|v| + 2·{:.4g})",
                                    l, what, index, e.pos, leg.vel, v_out, rb.error, bound_.rel, bound_.abs));
    }
    return std::nullopt;
}

}  // namespace ricochet::checks
