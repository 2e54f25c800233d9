// accuracy: every well-conditioned hit's t_i and B_i lie within k_hit_accuracy_ulps·ε·M of the exact
// crossing of the leg the kernel swept, a well-conditioned bounce off a lone wall leaves within the speed
// bound of the exact reflection, and each leg is the rest of the frame from where the last one ended
// (checks.hpp). A ball stepped as a disc has its contacts judged by accuracy_discs.cpp.
#include <fmt/format.h>

#include <cmath>
#include <vector>

#include "checks/accuracy_discs.hpp"
#include "checks/frame_check.hpp"
#include "ricochet/format.hpp"
#include "ricochet/truth.hpp"

namespace ricochet::checks {
namespace {

bool finite(Vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

class Accuracy final : public FrameCheck {
public:
    bool needs_traces() const override { return true; }

    Accuracy(const Scene& scene, KernelId kernel)
        : scene_(scene), bound_(speed_bound(kernel)), discs_(scene, bound_) {}

    std::optional<CheckFailure> frame(const Frame& f) override {
        if (f.index == 0) return std::nullopt;
        const std::vector<bool> met = met_in_frame(f, f.traces.size());
        for (std::uint32_t i = 0; i < f.traces.size(); ++i) {
            // The exact kernel's point legs are rational (not traced): its B_i is the exact crossing, rounded once;
            // a plug-in's frame step shows no legs; a ball that met another was not stepped alone (met_in_frame).
            if (!f.traces[i].legs_traced || met[i]) continue;
            std::vector<const Event*> contacts;
            for (const Event& e : f.events)
                if ((e.kind == Event::Kind::hit || e.kind == Event::Kind::bump) && e.ball == i) contacts.push_back(&e);
            if (auto bad = stepped_as_disc(scene_, i) ? discs_.contacts(f, i, contacts) : ball(f, i, contacts)) return bad;
            if (auto bad = rest_of_frame(f, i, contacts)) return bad;
        }
        return std::nullopt;
    }

private:
    /// A point ball among walls: its hits (no bumps: the scene has no bumpers).
    std::optional<CheckFailure> ball(const Frame& f, std::uint32_t i, const std::vector<const Event*>& hits) const {
        const StepTrace& trace = f.traces[i];
        // The k-th leg that took a hit printed the k-th hit (a hit found at the bounce limit is not taken;
        // oracle checks the order, so a leg whose wall differs from its event's ends the comparison).
        std::size_t k = 0;
        // The wall the ball last bounced off and the side it met it from (the bounce-side rule's line): from
        // the memory before the frame, then each hit's wall, met from the side of that leg's start.
        const BallMemory& memory = f.memory_before[i];
        const Wall* kept = memory.bounced_from != 0 ? &scene_.walls[memory.bounced_wall] : nullptr;
        int kept_from = memory.bounced_from;
        for (std::size_t l = 0; l < trace.legs.size() && k < hits.size(); ++l) {
            const TracedLeg& leg = trace.legs[l];
            if (leg.blocked || !leg.hit) continue;
            const Event& hit = *hits[k++];
            // A leg with a non-finite end is oracle's failure; there is no exact crossing to compare with (nor
            // an exact side of its start to keep).
            if (!finite(leg.from) || !finite(leg.to)) break;
            const Wall* keep_now = kept;
            const int keep_now_from = kept_from;
            // The exact side of the leg's start on the hit wall's line (0: on it, or no such wall).
            const int from = hit.index < scene_.walls.size() ? truth::side(leg.from, scene_.walls[hit.index]) : 0;
            if (from != 0) {
                kept = &scene_.walls[hit.index];
                kept_from = from;
            }
            if (hit.index != *leg.hit) break;
            // t_i: the fraction of the leg the kernel put the crossing at (the trace's, since a log does not
            // print it), against the exact s.
            const truth::HitAccuracy rt =
                truth::hit_time_accuracy(leg.from, leg.to, scene_.walls[hit.index], leg.hit_t, k_hit_accuracy_ulps);
            if (rt.conditioned && !rt.within)
                return failure(Check::accuracy, f.index, i,
                               fmt::format("leg {} ({} -> {}) hits wall {} at t_i = {}, {:.4g} eps*M along the leg "
                                           "from the exact crossing (bound {})",
                                           l, leg.from, leg.to, hit.index, leg.hit_t, rt.error, k_hit_accuracy_ulps));
            const truth::HitAccuracy r = truth::hit_accuracy(leg.from, leg.to, scene_.walls[hit.index], hit.pos,
                                                             k_hit_accuracy_ulps, keep_now, keep_now_from);
            if (r.conditioned && !r.within)
                return failure(Check::accuracy, f.index, i,
                               fmt::format("leg {} ({} -> {}) hits wall {} at {}, {:.4g} eps*M from the exact "
                                           "crossing (bound {})",
                                           l, leg.from, leg.to, hit.index, hit.pos, r.error, k_hit_accuracy_ulps));
            const Vec2 v_out = velocity_after(f, i, l);
            if (!lone_wall(hit.pos, hit.index)) {
                if (auto bad = corner(f, i, l, leg, hit, v_out)) return bad;
                continue;
            }
            // Judged where v goes into the wall from the side the leg starts on (or the leg starts on its line):
            // a leg whose rounded end reaches the line while v itself moves away (|v| under an ulp of M, say)
            // meets it by rounding alone, and the exact reflection of v is no answer there.
            if (from != 0 && truth::direction_side(leg.vel, scene_.walls[hit.index]) != -from) continue;
            const truth::HitAccuracy rb =
                truth::bounce_accuracy(leg.vel, scene_.walls[hit.index], v_out, bound_.rel, bound_.abs);
            if (rb.conditioned && !rb.within)
                return failure(Check::accuracy, f.index, i,
                               fmt::format("leg {} hits wall {} moving {} and leaves moving {}, {:.4g}·|v| from the "
                                           "exact reflection v - 2(v·n)n/(n·n) (bound 2·{:.4g}·|v| + 2·{:.4g})",
                                           l, hit.index, leg.vel, v_out, rb.error, bound_.rel, bound_.abs));
        }
        return std::nullopt;
    }

    /// kernel.hpp's legs: the first runs from Bs to Bs + v; after a hit (or a bump) at B_i the next runs from the
    /// printed B_i for the rest of the frame, (1 − t_i)·v′ (R = Π(1 − t_k) after several); a reflection off a
    /// contact wall starts the next leg where this one started, with the same R.
    std::optional<CheckFailure> rest_of_frame(const Frame& f, std::uint32_t i,
                                              const std::vector<const Event*>& contacts) const {
        const StepTrace& trace = f.traces[i];
        std::vector<double> ts;
        Vec2 start = f.before[i].pos;
        std::size_t k = 0;
        for (std::size_t l = 0; l < trace.legs.size(); ++l) {
            const TracedLeg& leg = trace.legs[l];
            // A non-finite point is oracle's failure (not a segment). A non-finite velocity leaves the accepted
            // range, and such a frame is never checked (the run stops with a step error): a guard, since GMP's
            // rational of a NaN raises SIGFPE.
            if (!finite(leg.from) || !finite(leg.to) || !finite(leg.vel)) break;
            if (!(leg.from == start))
                return failure(Check::accuracy, f.index, i,
                               fmt::format("leg {} starts at {}, not at {} where the {} ended", l, leg.from, start,
                                           l == 0 ? "previous frame" : "previous leg"));
            const truth::HitAccuracy r = truth::leg_end_accuracy(leg.from, leg.vel, ts, leg.to);
            if (!r.within)
                return failure(Check::accuracy, f.index, i,
                               fmt::format("leg {} ({} -> {}) moving {} after {} hits is not the rest of the frame: "
                                           "{:.4g} eps*M from {} + R*v, R = prod(1 - t_i) (bound {})",
                                           l, leg.from, leg.to, leg.vel, ts.size(), r.error, leg.from,
                                           2 * ts.size() + 3));
            if (leg.blocked) continue;
            // A contact taken (it printed the k-th hit or bump): the next leg starts at its printed B_i. (k <
            // contacts.size() and the leg's obstacle is contacts[k]'s for every kernel the tests run: a kernel that
            // meets an obstacle without printing it, or prints another, fails `oracle` and `event-order`; here the
            // walk just stops.)
            if (k >= contacts.size() || !printed_as(*contacts[k], leg)) break;
            start = contacts[k++]->pos;
            ts.push_back(leg.hit_t);
        }
        return std::nullopt;
    }

    /// A hit at a point on other walls too: the corner rule (kernel.hpp), where every wall there is met from a
    /// side (a ball that slid along one's line has a memory the rule reads, and is not checked).
    std::optional<CheckFailure> corner(const Frame& f, std::uint32_t i, std::size_t l, const TracedLeg& leg,
                                       const Event& hit, Vec2 v_out) const {
        const Wall& w = scene_.walls[hit.index];
        const int hit_from = truth::side(leg.from, w);
        std::vector<Wall> others;
        std::vector<int> from;
        for (std::uint32_t j = 0; j < scene_.walls.size(); ++j) {
            const Wall& c = scene_.walls[j];
            if (j == hit.index || c.p0 == c.p1 || !truth::on_closed_segment(hit.pos, c)) continue;
            others.push_back(c);
            from.push_back(truth::side(leg.from, c));
            if (from.back() == 0) return std::nullopt;
        }
        // A leg that starts on the line of the wall it hits comes from no side, and the corner rule does not say
        // where it goes: not judged. (No test has met one: robust's and exact's sweeps call such a leg `leaving`,
        // never a hit; a lecture kernel would need a leg from exactly on the line to a corner.)
        if (hit_from == 0) return std::nullopt;
        const truth::HitAccuracy r =
            truth::corner_accuracy(leg.vel, w, hit_from, others, from, v_out, bound_.rel, bound_.abs);
        if (r.conditioned && !r.within)
            return failure(Check::accuracy, f.index, i,
                           fmt::format("leg {} hits wall {} at the corner {} ({} other walls there) moving {} and "
                                       "leaves moving {}, {:.4g}·|v| from the corner rule's v' (bound 3m·(2·{:.4g}·|v| "
                                       "+ {:.4g}), m reflections; straight back is exact)",
                                       l, hit.index, hit.pos, others.size(), leg.vel, v_out, r.error, bound_.rel,
                                       bound_.abs));
        return std::nullopt;
    }

    /// p lies on no wall's closed segment but wall w's (exactly).
    bool lone_wall(Vec2 p, std::uint32_t w) const {
        for (std::uint32_t j = 0; j < scene_.walls.size(); ++j)
            if (j != w && truth::on_closed_segment(p, scene_.walls[j])) return false;
        return true;
    }

    const Scene& scene_;
    SpeedBound bound_;
    DiscAccuracy discs_;
};

}  // namespace

std::unique_ptr<FrameCheck> make_accuracy(const Scene& scene, KernelId kernel, const WorldOptions&) {
    return std::make_unique<Accuracy>(scene, kernel);
}

}  // namespace ricochet::checks
