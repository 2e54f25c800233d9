// The robust kernel's disc: the shared disc frame (disc/frame.hpp, every decision exact, every rounded point
// walked back until the printed piece to it keeps the disc clear) with robust's constructions: t_i and B_i from
// doubles where their error bound allows, finer constructions where it does not.
#include <algorithm>
#include <cmath>
#include <vector>

#include "kernels/disc/contact.hpp"
#include "kernels/disc/frame.hpp"
#include "kernels/robust/robust_kernel.hpp"

namespace ricochet {
namespace {

/// The most robust's t_i from doubles may be off by (its running error bound) before a finer construction is taken
/// instead: a contact point within 2^−40·|b − q| of its exact place along the leg.
constexpr double k_time_tolerance = 0x1p-40;

/// B_i = q + t·(b − q) in doubles, for a t in (0, 1].
disc::Constructions::Point on_leg(const disc::Leg& leg, double t) {
    t = std::min(t, 1.0);
    return {t, t == 1.0 ? leg.b : leg.q + t * (leg.b - leg.q)};
}

/// Robust's constructions: t_i rounded from doubles (contact_time), B_i = q + t_i·(b − q) in doubles, the bounce
/// about normal_at's rounded normal with reflect_about. Where the doubles cannot place t_i within 2^−40 (a leg
/// that approaches the line or the circle by ulps over its length: t_i = a rounding error over a tiny n·d or √Δ,
/// anywhere in [0, 1]), or cannot tell it from 0 (a bounce at the leg's start that would leave the ball where it
/// was, and the same leg again): the nearest doubles to t_i and B_i where double-double decides them
/// (nearest_contact_fine), else t_i and B_i rounded from double-double where t_i is within 2^−40 and clear of 0
/// (contact_fine), else the correctly rounded bracket in rationals the exact kernel prints (nearest_contact_point).
disc::Constructions::Point robust_point(const disc::Leg& leg, const disc::Obstacle& o, const disc::Contact& c) {
    const disc::TimeEstimate e = disc::contact_time_estimate(leg, o, c);
    if (e.error <= k_time_tolerance && e.t - e.error > 0.0) return on_leg(leg, e.t);
    if (const auto nearest = disc::nearest_contact_fine(leg, o, c)) return {nearest->t, nearest->x};
    const disc::FineContact fine = disc::contact_fine(leg, o, c);
    if (fine.error <= k_time_tolerance && fine.t - fine.error > 0.0)
        return fine.t >= 1.0 ? disc::Constructions::Point{1.0, leg.b} : disc::Constructions::Point{fine.t, fine.x};
    return disc::nearest_contact_point(leg, o, c);
}
/// v reflected about normal_at's rounded normal with reflect_about, or, where that does not leave the obstacle (a
/// grazing v, whose normal component is below the rounding of v·n: v′ = v, or v′ exactly parallel, and the frame
/// would send the disc straight back, or meet the same face again at once), the exact kernel's correctly rounded
/// reflection (nearest_reflection).
Vec2 robust_reflect(Vec2 v, Vec2 x, const disc::Obstacle& o) {
    const Vec2 w = reflect_about(v, disc::normal_at(x, o));
    if (disc::normal_sign(x, w, o) > 0) return w;
    return disc::nearest_reflection(v, x, o);
}

}  // namespace

FrameStatus RobustKernel::step_disc(Ball& ball, BallMemory& /*memory*/, const Obstacles& obstacles,
                                    std::vector<HitEvent>& hits, StepScratch& scratch) {
    return disc::step_frame(ball, obstacles, hits, scratch, {&robust_point, &robust_reflect});
}

}  // namespace ricochet
