// A disc's frame with exact decisions (frame.hpp), written once for robust and exact: a ball of radius R > 0 among
// walls, every decision exact (contact.hpp), every rounded point walked back until the printed piece to it keeps
// the disc clear. The two kernels differ only in their constructions (robust_disc.cpp, exact_disc.cpp).
//
// A frame, as for points (kernel.hpp): the leg q → b = q + rest·v; the earliest contact over every wall,
// ties to the lowest index; B_i = q + t_i·(b − q) rounded; the bounce; the rest of the frame from B_i with
// rest·(1 − t_i). What a disc adds:
// - The bounce reflects v about the contact normal at the printed B_i: ±n on a face, B_i − P_k on a cap.
//   Corners, one rule as for points: reflect about the contact of the lowest wall, then about each other wall
//   met at the same exact time whose normal the new velocity still goes into, in index order; if one is still
//   gone into, go straight back (v′ = −v). Exact signs decide "goes into" (contact.hpp, normal_sign).
// - Clearance (the `penetration` check, δ = 0): a printed piece q → x is accepted only if it keeps the centre
//   at least R from every wall q is at least R from (exactly: the segments' distance), and crosses no wall's
//   segment (the point ball's tunnel) where q is closer (a scene that starts a disc overlapping a wall). A
//   rounded B_i that fails is walked back towards q, q itself at worst; a leg without a contact needs no walk:
//   its exact path never comes closer than R (contact.hpp: only a tangent touches without entering).
// - A disc tries the walls and bumpers that may come within R of its leg (the wall index's query_near, and the
//   bumper index over the bumpers' centres with R + the largest bumper radius), in index order, as if it tried
//   them all: an obstacle farther than R from the leg has no contact, and no piece near it comes within R.
// - A point ball in a scene with bumpers is stepped here too, as a disc of radius 0: the same contacts (a face
//   contact is then the crossing of the segment), and a rounded point walked back until its piece does not
//   reach any wall's segment (R = 0 has no clearance to keep; the point's no-tunnel is what is kept).
#include "kernels/disc/frame.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "base/bignum.hpp"
#include "kernels/candidates.hpp"
#include "kernels/disc/contact.hpp"
#include "kernels/disc/neighbours.hpp"
#include "ricochet/step_trace.hpp"

namespace ricochet {
namespace {

/// A wall or bumper met at the leg's first contact time.
struct Met {
    disc::Obstacle obstacle;
    disc::Contact contact;
    std::uint32_t index = 0;
    bool bumper = false;
};

/// The obstacles as contact.hpp sees them: wall i, or bumper i.
disc::Obstacle wall_obstacle(const Wall& w) { return {&w, {}, 0.0}; }
disc::Obstacle bumper_obstacle(const Bumper& b) { return {nullptr, b.c, b.r}; }

/// The walls that may come within R of the segment q → x, in index order.
std::span<const std::uint32_t> walls_near(Vec2 q, Vec2 x, double R, const Obstacles& obstacles,
                                          StepScratch& scratch) {
    return detail::candidates_near(obstacles.walls.size(), obstacles.index, q, x, R, scratch.candidates,
                                   scratch.all_walls);
}

/// The bumpers that may come within R of the segment q → x, in index order.
std::span<const std::uint32_t> bumpers_near(Vec2 q, Vec2 x, double R, const Obstacles& obstacles,
                                            StepScratch& scratch) {
    return detail::candidates_near(obstacles.bumpers.size(), obstacles.bumper_index, q, x, R + obstacles.bumper_reach,
                                   scratch.bumper_candidates, scratch.all_bumpers);
}

/// Is the printed piece q → x allowed for a disc of radius R among the obstacles (the clearance rule above)? Only
/// the obstacles near the piece can break it: one farther than R from the whole piece keeps it clear.
bool piece_allowed(Vec2 q, Vec2 x, double R, const Obstacles& obstacles, StepScratch& scratch) {
    for (const std::uint32_t i : walls_near(q, x, R, obstacles, scratch)) {
        const Wall& w = obstacles.walls[i];
        if (R == 0.0) {
            // A point ball (in a scene with bumpers): it must not reach a wall's segment, where the next leg would
            // find no normal and pass through, unless it starts there (then only the crossing is forbidden). A
            // zero-length wall is never hit.
            if (w.p0 == w.p1) continue;
            if (disc::touches(q, q, w) ? disc::crosses(q, x, w) : disc::touches(q, x, w)) return false;
            continue;
        }
        const disc::Obstacle o = wall_obstacle(w);
        if (disc::piece_clear(q, x, R, o)) continue;
        // Already closer than R at q: only the point ball's tunnel through the segment is forbidden.
        if (disc::point_clear(q, R, o) || disc::crosses(q, x, w)) return false;
    }
    for (const std::uint32_t i : bumpers_near(q, x, R, obstacles, scratch)) {
        const disc::Obstacle o = bumper_obstacle(obstacles.bumpers[i]);
        if (!disc::piece_clear(q, x, R, o) && disc::point_clear(q, R, o)) return false;
    }
    return true;
}

/// How many doublings walk_back tries before x's own neighbours. A piece that meets the capsule at a grazing angle
/// gains almost no distance from it along the way back, and whether a rounded point on it is clear is a matter of
/// its rounding: before the walk goes past 16 ulps, the eight doubles next to x (one ulp in x, in y, or both) are
/// tried, and the best allowed one kept (nearest_allowed_neighbour).
constexpr int k_walk_before_neighbours = 4;

/// Of the eight doubles next to x, the one the piece from q may end at that lies nearest the leg's line q + s·d,
/// then furthest along it: |(c − q) × d| smallest, then (c − q)·d largest, both exactly (rationals: the keys of
/// neighbours differ by products of ulps). A mirror or a quarter turn of the scene maps the keys to the same
/// values, so the choice maps to the choice (the `symmetry` check); two allowed neighbours with equal keys are
/// mirror images across the leg's line (a leg along an axis or a diagonal), a choice no rule can make
/// symmetrically: then none is taken and the walk goes on.
std::optional<Vec2> nearest_allowed_neighbour(Vec2 q, Vec2 x, Vec2 d, double R, const Obstacles& obstacles,
                                              StepScratch& scratch) {
    using bignum::Rational;
    const Rational qx = bignum::rational(q.x), qy = bignum::rational(q.y);
    const Rational dx = bignum::rational(d.x), dy = bignum::rational(d.y);
    std::optional<Vec2> best;
    Rational best_across, best_along;
    bool tied = false;
    for_each_on_ring(x, 1, [&](Vec2 c) {
        if (!piece_allowed(q, c, R, obstacles, scratch)) return;
        const Rational ux = bignum::rational(c.x) - qx, uy = bignum::rational(c.y) - qy;
        // |(c − q) × d|, compared by its square.
        const Rational cross = ux * dy - uy * dx, across = cross * cross, along = ux * dx + uy * dy;
        if (!best || across < best_across || (across == best_across && along > best_along)) {
            best = c;
            best_across = across;
            best_along = along;
            tied = false;
        } else if (across == best_across && along == best_along) {
            tied = true;
        }
    });
    return tied ? std::nullopt : best;
}

}  // namespace

Vec2 disc::walk_back(Vec2 q, Vec2 x, double R, const Obstacles& obstacles, StepScratch& scratch) {
    if (piece_allowed(q, x, R, obstacles, scratch)) return x;
    const Vec2 d = x - q;
    const double m = std::max({std::fabs(q.x), std::fabs(q.y), std::fabs(x.x), std::fabs(x.y)});
    const double d_inf = std::max(std::fabs(d.x), std::fabs(d.y));
    int step = 0;
    for (double g = std::max(m * 0x1p-52 / d_inf, 0x1p-60); g < 0.5; g *= 2.0, ++step) {
        if (step == k_walk_before_neighbours)
            if (const auto c = nearest_allowed_neighbour(q, x, d, R, obstacles, scratch)) return *c;
        const Vec2 c = q + (1.0 - g) * d;
        if (c != x && piece_allowed(q, c, R, obstacles, scratch)) return c;
    }
    const Vec2 half = q + 0.5 * d;
    return piece_allowed(q, half, R, obstacles, scratch) ? half : q;
}

FrameStatus disc::step_frame(Ball& ball, const Obstacles& obstacles, std::vector<HitEvent>& hits,
                             StepScratch& scratch, const Constructions& make) {
    // Degenerate: a ball at rest does no sweep.
    if (ball.vel == Vec2{}) return FrameStatus::ok;
    const double R = ball.r;
    Vec2 q = ball.pos, v = ball.vel;
    // A whole frame starts at 0; the rest of a frame after a meet at its time (StepScratch::start).
    double rest = 1.0 - scratch.start, now = scratch.start;
    FrameStatus status = FrameStatus::ok;
    std::vector<Met> met;
    for (int bounce = 0;; ++bounce) {
        const Vec2 b = q + rest * v;
        if (b == q) break;
        if (bounce == k_max_bounces) {
            status = FrameStatus::bounce_limit;
            break;
        }
        TracedLeg* traced = nullptr;
        if (StepTrace* t = scratch.trace) {
            const auto first = static_cast<std::uint32_t>(t->decisions.size());
            traced = &t->legs.emplace_back(TracedLeg{q, b, false, 0, 0, std::nullopt, first, 0, std::nullopt});
            traced->vel = v;
        }
        // The earliest contact, and every obstacle met at that same time (walls in index order, then bumpers).
        const disc::Leg leg{q, b, R};
        met.clear();
        const auto consider = [&](const Met& m) {
            if (!met.empty()) {
                const int order = disc::compare(leg, m.obstacle, m.contact, met.front().obstacle, met.front().contact);
                if (order > 0) return;
                if (order < 0) met.clear();
            }
            met.push_back(m);
        };
        for (const std::uint32_t i : walls_near(q, b, R, obstacles, scratch)) {
            const auto c = disc::first_contact(leg, obstacles.walls[i]);
            if (traced != nullptr) {
                scratch.trace->decisions.push_back({i, c ? Miss::none : Miss::no_reason});
                ++traced->decision_count;
            }
            if (c) consider({wall_obstacle(obstacles.walls[i]), *c, i, false});
        }
        for (const std::uint32_t i : bumpers_near(q, b, R, obstacles, scratch)) {
            const Bumper& bumper = obstacles.bumpers[i];
            if (const auto c = disc::first_contact(leg, bumper.c, bumper.r)) consider({bumper_obstacle(bumper), *c, i, true});
        }
        if (met.empty()) {
            // No contact: the exact leg keeps its distances, and b is printed as it is.
            q = b;
            break;
        }
        const Met& first = met.front();
        const disc::Constructions::Point at =
            first.contact.at_start ? disc::Constructions::Point{0.0, q} : make.contact_point(leg, first.obstacle, first.contact);
        const double t = at.t;
        if (traced != nullptr) {
            (first.bumper ? traced->bumped : traced->hit) = first.index;
            traced->hit_t = t;
        }
        const Vec2 x = disc::walk_back(q, at.x, R, obstacles, scratch);
        now += t * rest;
        hits.push_back({first.index, now, x, first.bumper});
        // Bounce about the first contact's normal at x, then about each other one met now that v′ goes into; if
        // one is still gone into, straight back.
        Vec2 w = make.reflect(v, x, first.obstacle);
        int reflections = 1;
        for (std::size_t k = 1; k < met.size(); ++k)
            if (disc::normal_sign(x, w, met[k].obstacle) < 0) {
                w = make.reflect(w, x, met[k].obstacle);
                ++reflections;
            }
        if (scratch.trace != nullptr) scratch.trace->reflections += reflections;
        for (const Met& m : met)
            if (disc::normal_sign(x, w, m.obstacle) < 0) {
                w = -v;
                break;
            }
        v = w;
        hits.back().out = v;
        rest *= 1.0 - t;
        q = x;
    }
    ball = {q, v};
    return status;
}

}  // namespace ricochet
