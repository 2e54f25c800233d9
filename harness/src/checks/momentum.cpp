// momentum: each meet keeps momentum and kinetic energy within k_meet_momentum_rel and k_meet_energy_rel, or, where
// the centres did not approach, leaves both velocities as they were (checks.hpp). Each of the World's meet records
// must be what the frame printed, so the laws are judged on the printed velocities.
#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "checks/frame_check.hpp"
#include "ricochet/format.hpp"
#include "ricochet/truth.hpp"

namespace ricochet::checks {
namespace {

using Pair = std::pair<std::uint32_t, std::uint32_t>;

class Momentum final : public FrameCheck {
public:
    explicit Momentum(const Scene& scene) : scene_(scene), active_(scene.balls_collide) {}

    std::optional<CheckFailure> frame(const Frame& f) override {
        // Degenerate: balls that do not collide never meet; frame 0 has no meets.
        if (!active_ || f.index == 0) return std::nullopt;
        const auto n = static_cast<std::uint32_t>(scene_.balls.size());
        // Each ball's contacts in order (hits, bumps, meets), and per ordered pair (I, J) where I's meets with J are.
        std::vector<std::vector<const Event*>> contacts(n);
        std::map<Pair, std::vector<std::size_t>> printed;
        for (const Event& e : f.events) {
            if (e.ball >= n || (e.kind != Event::Kind::hit && e.kind != Event::Kind::bump && e.kind != Event::Kind::meet))
                continue;
            if (e.kind == Event::Kind::meet) printed[{e.ball, e.index}].push_back(contacts[e.ball].size());
            contacts[e.ball].push_back(&e);
        }
        found_.reset();
        std::map<Pair, std::size_t> taken;  // records of each pair so far
        for (std::size_t r = 0; r < f.meets.size(); ++r) {
            const MeetRecord& m = f.meets[r];
            const auto fail = [&](std::uint32_t ball, std::string why) {
                if (!found_ || ball < found_->ball)
                    found_ = failure(Check::momentum, f.index, ball,
                                     fmt::format("meet {} of the frame (balls {} and {} at t = {}): {}", r, m.a, m.b, m.t,
                                                 why));
            };
            if (!(m.a < m.b && m.b < n)) {
                fail(std::min(m.a, m.b), "a meet names two balls a < b of the scene");
                continue;
            }
            // The k-th meet of the pair taken is the k-th each ball printed with the other (both in time order).
            const std::size_t k = taken[{m.a, m.b}]++;
            const auto& at_a = printed[{m.a, m.b}];
            const auto& at_b = printed[{m.b, m.a}];
            if (k >= at_a.size() || k >= at_b.size()) {
                fail(m.a, "the World took it, but the frame does not print it under both balls");
                continue;
            }
            const Event &ea = *contacts[m.a][at_a[k]], &eb = *contacts[m.b][at_b[k]];
            if (!(ea.pos == m.pos_a && ea.vel == m.out_a && eb.pos == m.pos_b && eb.vel == m.out_b)) {
                fail(m.a, fmt::format("the World's record (centres {} and {}, leaving with {} and {}) is not what the "
                                      "frame printed ('{}', '{}')",
                                      m.pos_a, m.pos_b, m.out_a, m.out_b, ea, eb));
                continue;
            }
            if (auto why = arriving(f, contacts[m.a], at_a[k], m.a, m.vel_a)) {
                fail(m.a, *why);
                continue;
            }
            if (auto why = arriving(f, contacts[m.b], at_b[k], m.b, m.vel_b)) {
                fail(m.b, *why);
                continue;
            }
            if (auto why = laws(m)) fail(m.a, *why);
        }
        // A printed meet the World did not record is judged by nothing.
        for (const auto& [pair, at] : printed)
            if (pair.first < pair.second) {
                const auto it = taken.find(pair);
                const std::size_t recorded = it == taken.end() ? 0 : it->second;
                if (recorded != at.size() && (!found_ || pair.first < found_->ball))
                    found_ = failure(Check::momentum, f.index, pair.first,
                                     fmt::format("ball {} prints {} meet(s) with ball {}, the World recorded {}",
                                                 pair.first, at.size(), pair.second, recorded));
            }
        return found_;
    }

private:
    /// The velocity a ball arrives at a meet with, where the frame printed it: the one it had before the frame if the
    /// meet is its first contact, the one it left its last meet with if that came just before. (After a hit or a bump
    /// it is not printed.)
    static std::optional<std::string> arriving(const Frame& f, const std::vector<const Event*>& contacts, std::size_t at,
                                               std::uint32_t ball, Vec2 vel) {
        std::optional<Vec2> want;
        if (at == 0 && ball < f.before.size()) want = f.before[ball].vel;
        if (at > 0 && contacts[at - 1]->kind == Event::Kind::meet) want = contacts[at - 1]->vel;
        if (!want || *want == vel) return std::nullopt;
        return fmt::format("ball {} arrives moving {} by the World's record, but {} by what the frame printed", ball, vel,
                           *want);
    }

    /// Momentum and energy kept within the bounds (responded), or both velocities unchanged (not).
    std::optional<std::string> laws(const MeetRecord& m) const {
        if (!m.responded) {
            if (m.out_a == m.vel_a && m.out_b == m.vel_b) return std::nullopt;
            return fmt::format("the centres did not approach (no response), yet the velocities changed: {} -> {} and "
                               "{} -> {}",
                               m.vel_a, m.out_a, m.vel_b, m.out_b);
        }
        const double ma = mass_of(scene_, m.a), mb = mass_of(scene_, m.b);
        const truth::MeetConservation c =
            truth::meet_conservation(ma, mb, m.vel_a, m.vel_b, m.out_a, m.out_b, k_meet_momentum_rel, k_meet_energy_rel,
                                     k_meet_momentum_abs, k_meet_energy_abs);
        if (c.momentum_within && c.energy_within) return std::nullopt;
        return fmt::format("masses {} and {} arrive moving {} and {} and leave moving {} and {}: momentum changes by "
                           "{:.4g} of m_a|v_a| + m_b|v_b| + m_a|v_a'| + m_b|v_b'| (bound {:.4g}), kinetic energy by {:.4g} "
                           "(bound {:.4g})",
                           ma, mb, m.vel_a, m.vel_b, m.out_a, m.out_b, c.momentum_error, k_meet_momentum_rel,
                           c.energy_error, k_meet_energy_rel);
    }

    const Scene& scene_;
    bool active_;
    std::optional<CheckFailure> found_;
};

}  // namespace

std::unique_ptr<FrameCheck> make_momentum(const Scene& scene, KernelId, const WorldOptions&) {
    return std::make_unique<Momentum>(scene);
}

}  // namespace ricochet::checks
