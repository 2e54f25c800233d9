// The robust kernel: exact decisions (predicates.hpp, the leg test in robust_leg.hpp), rounded
// constructions that are never accepted across a wall (path.hpp).
#include <algorithm>
#include <cmath>

#include "kernels/candidates.hpp"
#include "kernels/robust/path.hpp"
#include "kernels/robust/robust_kernel.hpp"
#include "kernels/robust/robust_leg.hpp"
#include "ricochet/bits.hpp"
#include "ricochet/predicates.hpp"
#include "ricochet/step_trace.hpp"

namespace ricochet {
namespace {

using robust::Leg;
using robust::test_leg;

/// The leg fraction s at which q → b meets w's line: BC(q)/(BC(q) − BC(b)), rounded, in [0, 1]. It is
/// the lecture's t_i for the leg q → b, n̂·(q + s·(b − q)) = n̂·P0, solved on BC values instead of n̂·v.
double crossing(Vec2 q, Vec2 b, const Wall& w, int sb) {
    if (sb == 0) return 1.0;
    const Vec2 e = edge(w);
    // BC ∝ n·(p − P0) = −e × (p − P0); the common factor 1/|n| cancels in the ratio.
    const double bq = -cross(e, q - w.p0);
    const double bb = -cross(e, b - w.p0);
    const double s = bq / (bq - bb);
    return std::isfinite(s) ? std::clamp(s, 0.0, 1.0) : 0.0;
}

}  // namespace

Side RobustKernel::classify(Vec2 p, const Wall& w) { return side_from_sign(exact::side(p, w)); }
bool RobustKernel::point_in_circle(Vec2 p, const Circle& c) { return exact::point_circle(p, c) <= 0; }
bool RobustKernel::circles_overlap(const Circle& a, const Circle& b) { return exact::circle_circle(a, b) <= 0; }

Vec2 RobustKernel::reflect(Vec2 v, const Wall& w) { return reflect_about(v, normal(w)); }

namespace {

/// n·2^-k with k = ilogb(big), big = |n|∞ > 0: the larger component in [1, 2), exactly as ldexp(n, −k) rounds
/// (a product by a power of two is correctly rounded, as ldexp is). For a normal big with biased exponent E in
/// [1, 2045], 2^-k = 2^(1023 − E) is a double whose biased exponent 2046 − E is built directly (2^-1023, E = 2046,
/// would be subnormal; and a subnormal big has no such 2^-k): those rare cases go to ldexp.
Vec2 scaled_to_unit(Vec2 n, double big) {
    const auto e = static_cast<unsigned>((bits_of(big) >> 52) & 0x7ffu);
    if (e >= 1 && e <= 2045) {
        const double s = double_of_bits(static_cast<std::uint64_t>(2046 - e) << 52);
        return {n.x * s, n.y * s};
    }
    const int k = std::ilogb(big);
    return {std::ldexp(n.x, -k), std::ldexp(n.y, -k)};
}

}  // namespace

Vec2 reflect_about(Vec2 v, Vec2 n) {
    const double big = std::max(std::fabs(n.x), std::fabs(n.y));
    // Degenerate: a zero-length wall (a zero vector) has no normal.
    if (big == 0.0) return v;
    // m = n·2^-k with its larger component in [1, 2): exact, and m·m can neither overflow nor underflow,
    // so n̂ = m/|m| is good to a few ulps for walls of any length. sqrt is correctly rounded: the same
    // bits everywhere (std::hypot is not required to be).
    const Vec2 m = scaled_to_unit(n, big);
    const double len = std::sqrt(dot(m, m));
    const Vec2 u{m.x / len, m.y / len};
    // v' = v − 2(v·n̂)n̂; with |n̂| ≈ 1 no intermediate underflows before v itself does.
    return v - (2.0 * dot(v, u)) * u;
}

Sweep RobustKernel::sweep(Vec2 bs, Vec2 v, const Wall& w) {
    const Vec2 be = bs + v;
    const Leg leg = test_leg(bs, be, w);
    if (leg.miss != Miss::none) return {leg.miss, 0.0, {}};
    const double s = crossing(bs, be, w, leg.sb);
    return {Miss::none, s, leg.sb == 0 ? be : bs + s * (be - bs)};
}

namespace {

/// RobustKernel::step_ball's frame; Axis: the walls' plan found axis-aligned walls (wall_plan.hpp), whose sides
/// are comparisons. Both instances make the same decisions, so the same bits.
template <bool Axis>
FrameStatus step_frame(Ball& ball, BallMemory& memory, std::span<const Wall> walls, std::vector<HitEvent>& hits,
                       StepScratch& scratch, const WallIndex* index) {
    constexpr auto side = exact::detail::side_as<Axis>;
    const auto reflect = RobustKernel::reflect;
    Vec2 q = ball.pos, v = ball.vel;
    double rest = 1.0, now = 0.0;
    FrameStatus status = FrameStatus::ok;
    // The last wall bounced off, kept on its side until the next bounce (BallMemory).
    std::uint32_t bounced_wall = memory.bounced_wall;
    detail::Keep bounced{memory.bounced_from != 0 ? &walls[memory.bounced_wall] : nullptr, memory.bounced_from};
    for (int bounce = 0;; ++bounce) {
        // A motion below an ulp of the position does not move the ball; v = 0 (a subnormal velocity a
        // reflection rounded away) gives b = q too, so it needs no test of its own.
        const Vec2 b = q + rest * v;
        if (b == q) break;
        if (bounce == k_max_bounces) {
            status = FrameStatus::bounce_limit;
            break;
        }
        // A leg that would leave a contact wall to its far side bounces off that wall instead.
        const Contact* blocked = nullptr;
        for (std::uint8_t k = 0; k < memory.count; ++k)
            if (side(b, walls[memory.contacts[k].wall]) == -memory.contacts[k].side) {
                blocked = &memory.contacts[k];
                break;
            }
        if (blocked != nullptr) {
            if (StepTrace* t = scratch.trace) {
                t->legs.push_back({q, b, true, blocked->wall, blocked->side, std::nullopt, 0, 0, std::nullopt});
                t->legs.back().vel = v;
                ++t->reflections;
            }
            v = reflect(v, walls[blocked->wall]);
            continue;
        }
        TracedLeg* traced = nullptr;
        if (StepTrace* t = scratch.trace) {
            const auto first = static_cast<std::uint32_t>(t->decisions.size());
            traced = &t->legs.emplace_back(TracedLeg{q, b, false, 0, 0, std::nullopt, first, 0, std::nullopt});
            traced->vel = v;
        }
        // The earliest hit: exact ordering of crossings, the lowest index on a tie.
        bool found = false;
        std::uint32_t best = 0;
        int best_sq = 0, best_sb = 0;
        // b's side of the wall bounced off, once its leg test has decided it (2: not tried).
        int bounced_sb = 2;
        for (std::uint32_t i : detail::candidates(walls, index, q, b, scratch.candidates, scratch.all_walls)) {
            const Leg leg = test_leg<Axis>(q, b, walls[i]);
            if (traced != nullptr) {
                scratch.trace->decisions.push_back({i, leg.miss});
                ++traced->decision_count;
            }
            // q ≠ b here, so a test of a wall with a normal decided sb.
            if (&walls[i] == bounced.wall && leg.miss != Miss::degenerate) bounced_sb = leg.sb;
            if (leg.miss != Miss::none) continue;
            if (found) {
                const int c = exact::compare_crossings(q, b, walls[i], walls[best]);
                if (c > 0 || (c == 0 && i > best)) continue;
            }
            found = true;
            best = i;
            best_sq = leg.sq;
            best_sb = leg.sb;
        }
        if (!found) {
            // No wall meets q → b, so no wall is crossed and none is touched from a side. Straight on from a
            // bounce the ball stays on the side it met that wall from: an end point rounded just across its
            // line (beyond an end) is walked back.
            if (bounced.wall != nullptr && bounced_sb == 2) bounced_sb = side(b, *bounced.wall);
            const detail::SafePoint safe =
                bounced.wall != nullptr && bounced_sb == -bounced.from
                    ? detail::make_safe({.q = q, .r = b, .memory = memory, .walls = walls, .index = index,
                                         .scratch = scratch, .keep = {bounced}})
                    : detail::SafePoint{b, {}};
            const Vec2 end = safe.x;
            // Walked back: the walls the new end lies on, worked out afresh. Else a contact stays while the ball
            // slides along its wall's line on the closed segment.
            BallMemory kept = end != b ? safe.arrived : BallMemory{};
            for (std::uint8_t k = 0; k < memory.count && end == b; ++k) {
                const Wall& w = walls[memory.contacts[k].wall];
                if (side(end, w) == 0 && in_segment_box(end, w)) kept.contacts[kept.count++] = memory.contacts[k];
            }
            memory = kept;
            q = end;
            break;
        }
        const double s = crossing(q, b, walls[best], best_sb);
        if (traced != nullptr) {
            traced->hit = best;
            traced->hit_t = s;
        }
        const auto [x, arrived] =
            detail::make_safe({.q = q, .r = best_sb == 0 ? b : q + s * (b - q), .memory = memory, .walls = walls,
                               .index = index, .scratch = scratch,
                               .keep = {detail::Keep{&walls[best], best_sq}, bounced}});
        bounced = {&walls[best], best_sq};
        bounced_wall = best;
        now += s * rest;
        hits.push_back({best, now, x});
        // Bounce off the wall hit, then off each other wall met here whose far side v' still points
        // to; if one is still crossed, go straight back.
        Vec2 w = reflect(v, walls[best]);
        int reflections = 1;
        for (std::uint8_t k = 0; k < arrived.count; ++k) {
            const Contact& c = arrived.contacts[k];
            if (c.wall != best && exact::direction_side(w, walls[c.wall]) == -c.side) {
                w = reflect(w, walls[c.wall]);
                ++reflections;
            }
        }
        if (scratch.trace != nullptr) scratch.trace->reflections += reflections;
        for (std::uint8_t k = 0; k < arrived.count; ++k)
            if (exact::direction_side(w, walls[arrived.contacts[k].wall]) == -arrived.contacts[k].side) w = -v;
        // The ball leaves the wall it hit towards the side it came from: a grazing v whose rounded reflection
        // does not point strictly back goes straight back instead (v crossed the line, so −v points back).
        if (exact::direction_side(w, walls[best]) != best_sq) w = -v;
        v = w;
        rest *= 1.0 - s;
        q = x;
        memory = arrived;
    }
    memory.bounced_from = static_cast<std::int8_t>(bounced.from);
    memory.bounced_wall = bounced_wall;
    ball = {q, v};
    return status;
}

}  // namespace

FrameStatus RobustKernel::step_ball(Ball& ball, BallMemory& memory, std::span<const Wall> walls,
                                    std::vector<HitEvent>& hits, StepScratch& scratch, const WallIndex* index) {
    // Degenerate: a ball at rest does no sweep. The frame's loop would leave at once with ball and memory
    // unchanged, bit for bit; returning here says so, and no caller needs a rule of its own for rest.
    if (ball.vel == Vec2{}) return FrameStatus::ok;
    return planned(scratch, walls).axis_aligned != 0 ? step_frame<true>(ball, memory, walls, hits, scratch, index)
                                                     : step_frame<false>(ball, memory, walls, hits, scratch, index);
}

}  // namespace ricochet
