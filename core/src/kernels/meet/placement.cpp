// A meet's centres (swept_frame.hpp; docs/scene-log.md, "Balls that meet", 4): each its path's point at t* rounded
// and walked back from the walls, t* taken earlier while the centres or the pieces to them come too close to each
// other or to a third ball, and at the floor one centre moved to a neighbouring double that clears.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

#include "base/bignum.hpp"
#include "kernels/disc/frame.hpp"
#include "kernels/disc/neighbours.hpp"
#include "kernels/meet/swept_frame.hpp"
#include "ricochet/bits.hpp"

namespace ricochet {

bool SweptFrame::place_meet(const Candidate& c, meet::Radii S, double lo, double floor, double& t,
                            meet::PointOnPath& pa, meet::PointOnPath& pb) {
    const std::uint32_t a = c.a, b = c.b;
    t = std::clamp(c.root.estimate, floor, 1.0);
    // The printed centres, no closer than S (exactly): t taken earlier, 1, 2, 4, … ulps, then the floor.
    Placed last_a, last_b;
    pa = place(a, t, last_a);
    pb = place(b, t, last_b);
    std::vector<double>& tried = tried_;
    tried.clear();
    for (double step = std::max(std::fabs(t) * 0x1p-52, 0x1p-1074);
         t > floor && too_close(a, b, S, lo, t, pa, pb); step *= 2.0) {
        tried.push_back(t);
        t = t - step > floor ? t - step : floor;
        pa = place(a, t, last_a);
        pb = place(b, t, last_b);
    }
    // At the floor a centre is nudged; where none clears and the two were closer than S at lo already (placed so by
    // the scene), they are not held apart, only clear of the third balls.
    bool clear = !(t == floor && too_close(a, b, S, lo, t, pa, pb));
    if (!clear) clear = nudge(a, b, S, lo, t, pa, pb, true);
    if (!clear && placed_in_reach(a, b, S, lo))
        clear = !too_close(a, b, S, lo, t, pa, pb, false) || nudge(a, b, S, lo, t, pa, pb, false);
    // Where nothing clears at the floor and the pieces to the centres pass through a ball as printed, the times the
    // walk back tried, latest first: the first with a nudged centre that clears (the floor can hold a piece in
    // another ball's way where a later time only needs a centre moved).
    if (!clear && !passes(a, b, S, lo, t, pa, pb, false)) clear = true;
    for (std::size_t k = 0; !clear && k < tried.size(); ++k) {
        meet::PointOnPath qa = place(a, tried[k], last_a), qb = place(b, tried[k], last_b);
        if (nudge(a, b, S, lo, tried[k], qa, qb, true)) {
            clear = true;
            t = tried[k];
            pa = qa;
            pb = qb;
        }
    }
    return clear;
}

bool SweptFrame::stands_as_they_are(std::uint32_t a, std::uint32_t b, meet::Radii S, double lo, double t,
                                    const meet::PointOnPath& pa, const meet::PointOnPath& pb) {
    std::array<bool, 4> seen[2];
    for (const bool as_they_were : {true, false}) {
        see_before_ = as_they_were;
        seen[as_they_were] = {too_close(a, b, S, lo, t, pa, pb, true), too_close(a, b, S, lo, t, pa, pb, false),
                              passes(a, b, S, lo, t, pa, pb, true), passes(a, b, S, lo, t, pa, pb, false)};
    }
    see_before_ = true;
    return seen[0] == seen[1];
}

meet::PointOnPath SweptFrame::place(std::size_t i, double t, Placed& last) {
    const std::vector<PathPoint>& path = balls_[i].path;
    meet::PointOnPath at = meet::point_at(path, t);
    if (last.valid && at.from == last.raw.from && same_bits(at.x, last.raw.x)) return last.at;
    last.valid = true;
    last.raw = at;
    const Vec2 q = path[at.from].p;
    if (at.x != q) at.x = disc::walk_back(q, at.x, radius(i), obstacles_, scratch_);
    last.at = at;
    return at;
}

bool SweptFrame::too_close(std::uint32_t a, std::uint32_t b, meet::Radii S, double lo, double t,
                           const meet::PointOnPath& pa, const meet::PointOnPath& pb, bool apart) {
    if (apart && meet::closer_than(pa.x, pb.x, S)) return true;
    cut_to(a, pa, t, cut_a_);
    cut_to(b, pb, t, cut_b_);
    if (pieces_enter(a, b, S, lo, t, apart)) return true;
    // A third ball k (three balls meeting at one time, or a graze the rounded centre makes): the centre must not
    // be closer to k's point at t, rounded where k's path puts it, than their radii's sum, nor the piece to the
    // centre enter k's reach at or after lo (touching k there and approaching) and before t where the ball's own
    // path does not — where the two were not closer than that at lo, or the piece enters k's reach from outside
    // after lo.
    bool crowded = false;
    for (const auto& [ball, centre, cut] : {std::tuple{a, pa.x, &cut_a_}, std::tuple{b, pb.x, &cut_b_}}) {
        const std::uint32_t i = ball;
        const Vec2 x = centre;
        const std::vector<PathPoint>& piece = *cut;
        // A centre printed already, by a meet taken at t before this one (the ball's path starts there at t), was
        // judged against the third balls then.
        const PathPoint& start = balls_[i].path.front();
        if (start.t == t && same_bits(start.p, x)) continue;
        if (enters_before(i, a, b, piece, lo)) return true;
        const double from = piece_start(piece);
        const std::vector<PathPoint>* fi = nullptr;  // ball i's printed path, made where first needed
        neighbours(i, [&](std::uint32_t k) {
            const meet::Radii Sk{radius(i), radius(k)};
            if (crowded || k == a || k == b || !(Sk.rounded() > 0.0) || out_of_reach(i, k, from)) return;
            const MeetSnapshot* was = before(k);
            const std::vector<PathPoint>& path = was ? was->path : balls_[k].path;
            const double k_from = was ? was->seg_t : seg_t_[k];
            // k's points printed before its current path, where that began after lo: the piece must not enter them
            // from outside (pass-through's rule, as enters_before asks it up to lo), up to that beginning or t.
            if (k_from > lo && from < k_from) {
                const double u = std::min(t, k_from);
                if (fi == nullptr) fi = &printed(i, piece, full_a_);
                const std::vector<PathPoint>& fk = third_printed(k, full_k_);
                const std::optional<meet::Root> e = meet::first_entry(*fi, fk, Sk, from, u);
                if (e && meet::compare(*e, u) < 0) {
                    crowded = true;
                    return;
                }
            }
            if (path.front().t > t) return;
            // k as it is, with a path whose box (path_box: R_k and a margin for rounding) misses ball i's: the piece to
            // the centre lies in i's path's box (its points, the centre rounded or moved a few ulps off it), so none
            // of the clauses below can hold. (Most neighbours the grid lists are such.)
            if (!was && !meet::boxes_overlap(box_[i], box_[k])) return;
            // Apart at lo — or where k's path starts later, there — as the printed paths put them (the piece to
            // the centre, which may start before lo, and k's path, their exact points) or as the ball's own path
            // does (its point there, rounded): two balls are excused only where both have them closer than that
            // (placed so by the scene).
            const auto apart_at_lo = [&] {
                const double at = std::max(lo, path.front().t);
                const Vec2 own = meet::point_at(balls_[i].path, at).x;
                return !meet::closer_on_paths(piece, path, at, Sk) ||
                       !meet::closer_than(own, meet::point_at(path, at).x, Sk);
            };
            // Where the piece enters k's reach from outside on [lo, t) (k left and came back), the two are not
            // excused as placed in reach either.
            const auto enters = [&] {
                const std::optional<meet::Root> e = meet::first_entry(piece, path, Sk, lo, t);
                return e && meet::compare(*e, t) < 0;
            };
            if (!meet::surely_apart(x, path, t, Sk) && meet::closer_than(x, meet::point_at(path, t).x, Sk)) {
                crowded = apart_at_lo() || enters();
                return;
            }
            // (Where the ball's own path enters k's reach at t too, k is due at t as well, a tie, not a graze
            // the rounding made: the ties' rule takes it. Where it enters before t — a tie at t*, t rounded past
            // it — the piece printed to t would hold the ball in k's way after k is due: t is taken earlier.)
            const std::optional<meet::Root> entry = meet::first_meet(piece, path, Sk, lo, {}, {}, t);
            if (!entry || meet::compare(*entry, t) >= 0) return;
            const std::optional<meet::Root> own = meet::first_meet(balls_[i].path, path, Sk, lo, {}, {}, t);
            if (!own || meet::compare(*own, t) < 0) crowded = apart_at_lo() || enters();
        });
    }
    return crowded;
}

void SweptFrame::cut_to(std::uint32_t i, const meet::PointOnPath& p, double t, std::vector<PathPoint>& out) const {
    const std::vector<PathPoint>& path = balls_[i].path;
    out.assign(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(p.from + 1));
    end_at(i, p, t, out);
}

void SweptFrame::end_at(std::uint32_t i, const meet::PointOnPath& p, double t, std::vector<PathPoint>& out) const {
    // A centre at the time of a printed point (the path's start, a meet's centre or the frame's; a hit or bump) moved
    // off it is a jump after it: the point stays (the piece before it ends there). Only the path's end is no print.
    // Only a nudge makes such a jump (crowds_others judges it): place() puts a centre at a printed point's time on the
    // point itself, since point_at returns it there and the walk back starts from it.
    if (out.back().t < t) out.push_back({t, p.x});
    else if (p.from > balls_[i].events.size() || same_bits(out.back().p, p.x)) out.back().p = p.x;
    else out.push_back({t, p.x});
}

bool SweptFrame::pieces_enter(std::uint32_t a, std::uint32_t b, meet::Radii S, double lo, double t, bool any) {
    // (The common case, decided without the search: two pieces from lo to t alone, closing in at t, whose centres
    // are not closer than S: too_close asks `any` only of such.)
    if (any && meet::surely_no_meet_before_end(cut_a_, cut_b_, lo, t)) return false;
    // An entry before t on the pieces that end at the centres (one at t itself is the meet).
    const std::optional<meet::Root> r =
        any ? meet::first_meet(cut_a_, cut_b_, S, lo, {}, {}, t) : meet::first_entry(cut_a_, cut_b_, S, lo, t);
    if (r && meet::compare(*r, t) < 0) return true;
    // A piece to a rounded centre starts at its ball's last printed point, which may lie before lo, where the
    // other ball was on a path it has left since: there, an entry of that piece into the other's printed path.
    const double s = std::min(piece_start(cut_a_), piece_start(cut_b_));
    if (!(s < lo)) return false;
    const std::vector<PathPoint>&fa = printed(a, cut_a_, full_a_), &fb = printed(b, cut_b_, full_b_);
    const std::optional<meet::Root> e = meet::first_entry(fa, fb, S, s, lo);
    return e && meet::compare(*e, lo) < 0;
}

const std::vector<PathPoint>& SweptFrame::printed(std::uint32_t k, const std::vector<PathPoint>& current,
                                                  std::vector<PathPoint>& out) const {
    return joined(committed_[k], current, out);
}

const std::vector<PathPoint>& SweptFrame::joined(const std::vector<PathPoint>& committed,
                                                 const std::vector<PathPoint>& current, std::vector<PathPoint>& out) {
    if (committed.empty()) return current;
    out.assign(committed.begin(), committed.end());
    out.insert(out.end(), current.begin(), current.end());
    return out;
}

const std::vector<PathPoint>& SweptFrame::third_printed(std::uint32_t k, std::vector<PathPoint>& out) const {
    const MeetSnapshot* was = before(k);
    return was ? joined(was->committed, was->path, out) : printed(k, balls_[k].path, out);
}

bool SweptFrame::placed_in_reach(std::uint32_t a, std::uint32_t b, meet::Radii S, double lo) const {
    const std::vector<PathPoint>&pa = balls_[a].path, &pb = balls_[b].path;
    return meet::closer_on_paths(pa, pb, lo, S) &&
           meet::closer_than(meet::point_at(pa, lo).x, meet::point_at(pb, lo).x, S);
}

bool SweptFrame::nudge(std::uint32_t a, std::uint32_t b, meet::Radii S, double lo, double t, meet::PointOnPath& pa,
                       meet::PointOnPath& pb, bool apart) {
    using bignum::Rational;
    // Every candidate that clears, with what chooses among them: its exact squared distance from its rounded
    // centre, then from its ball's exact centre at t (the point the rounded one rounds), then whether its piece
    // starts at t (a centre moved where the ball already was at t: last), then how far it moves along its ball's
    // approach to the other, (c − X)·(v_i − v_j) (least first: back along it).
    struct Clear {
        bool on_a;
        Vec2 c;
        Rational d2, e2;
        bool jump;
        Rational along;
    };
    // Which one (docs/scene-log.md, "Balls that meet", 4): the nearest; among several as near, none — unless the
    // rounded centres overlap or a piece to them would pass through a third ball as printed (what ball-overlap and
    // pass-through see): then the first by the order above; where the first two tie on all of it, and a piece
    // passes through a third ball, the first that ties with none (a mirror image maps a tied pair onto itself, and
    // that one onto itself), else the next distance out; and where none is taken, the rings of doubles 2, then 3
    // ulps out (a meet far out among balls whose rounded centres crowd every neighbouring double).
    const bool through = passes(a, b, S, lo, t, pa, pb, false);
    const bool overlap = (apart && meet::closer_than(pa.x, pb.x, S)) || through;
    const auto order = [](const Clear& x, const Clear& y) {
        if (x.d2 != y.d2) return x.d2 < y.d2 ? -1 : 1;
        if (x.e2 != y.e2) return x.e2 < y.e2 ? -1 : 1;
        if (x.jump != y.jump) return x.jump ? 1 : -1;
        if (x.along != y.along) return x.along < y.along ? -1 : 1;
        return 0;
    };
    std::vector<Clear> clear;
    for (int ring = 1; ring <= (overlap ? meet::k_rings : 1); ++ring) {
        clear.clear();
        for (const bool on_a : {true, false}) {
            const meet::PointOnPath& p = on_a ? pa : pb;
            const std::uint32_t i = on_a ? a : b;
            const Vec2 q = balls_[i].path[p.from].p;
            const Vec2 w = velocity_on(i, p.from) - velocity_on(on_a ? b : a, (on_a ? pb : pa).from);
            const std::pair<bignum::Rational, bignum::Rational> exact = meet::exact_point(balls_[i].path, t);
            for_each_on_ring(p.x, ring, [&](Vec2 c) {
                if (c != q && !same_bits(disc::walk_back(q, c, radius(i), obstacles_, scratch_), c)) return;
                const meet::PointOnPath moved{c, p.from};
                if (too_close(a, b, S, lo, t, on_a ? moved : pa, on_a ? pb : moved, apart)) return;
                if (crowds_others(i, a, b, moved, p.x, t)) return;
                const Rational dx = Rational(c.x) - Rational(p.x.x), dy = Rational(c.y) - Rational(p.x.y);
                const Rational fx = Rational(c.x) - exact.first, fy = Rational(c.y) - exact.second;
                clear.push_back({on_a, c, dx * dx + dy * dy, fx * fx + fy * fy, balls_[i].path[p.from].t == t,
                                 dx * Rational(w.x) + dy * Rational(w.y)});
            });
        }
        std::sort(clear.begin(), clear.end(), [&](const Clear& x, const Clear& y) { return order(x, y) < 0; });
        for (std::size_t k = 0; k < clear.size();) {
            std::size_t end = k + 1;  // the candidates as near as clear[k]
            while (end < clear.size() && clear[end].d2 == clear[k].d2) ++end;
            if (end == k + 1) {
                (clear[k].on_a ? pa : pb).x = clear[k].c;
                return true;
            }
            if (!overlap) return false;
            if (order(clear[k], clear[k + 1]) != 0) {
                (clear[k].on_a ? pa : pb).x = clear[k].c;
                return true;
            }
            for (std::size_t m = k; through && m < end; ++m) {
                const bool tied = (m > k && order(clear[m - 1], clear[m]) == 0) ||
                                  (m + 1 < end && order(clear[m], clear[m + 1]) == 0);
                if (!tied) {
                    (clear[m].on_a ? pa : pb).x = clear[m].c;
                    return true;
                }
            }
            k = end;
        }
    }
    return false;
}

bool SweptFrame::passes(std::uint32_t a, std::uint32_t b, meet::Radii S, double lo, double t,
                        const meet::PointOnPath& pa, const meet::PointOnPath& pb, bool apart) {
    if (apart && meet::closer_than(pa.x, pb.x, S)) return true;
    cut_to(a, pa, t, cut_a_);
    cut_to(b, pb, t, cut_b_);
    return pieces_enter(a, b, S, lo, t, false) || enters_before(a, a, b, cut_a_, t) ||
           enters_before(b, a, b, cut_b_, t);
}

bool SweptFrame::enters_before(std::uint32_t i, std::uint32_t a, std::uint32_t b, const std::vector<PathPoint>& cut,
                               double until) {
    const double from = piece_start(cut);
    if (!(from < until)) return false;
    bool enters = false;
    const std::vector<PathPoint>* fi = nullptr;  // ball i's printed path, made for the first ball within reach
    neighbours(i, [&](std::uint32_t k) {
        const meet::Radii Sk{radius(i), radius(k)};
        if (enters || k == a || k == b || !(Sk.rounded() > 0.0) || out_of_reach(i, k, from)) return;
        if (fi == nullptr) fi = &printed(i, cut, full_a_);
        const std::vector<PathPoint>& fk = third_printed(k, full_k_);
        const std::optional<meet::Root> e = meet::first_entry(*fi, fk, Sk, from, until);
        enters = e && meet::compare(*e, until) < 0;
    });
    return enters;
}

bool SweptFrame::crowds_others(std::uint32_t i, std::uint32_t a, std::uint32_t b, const meet::PointOnPath& moved,
                               Vec2 rounded, double t) {
    std::vector<PathPoint> piece;
    cut_to(i, moved, t, piece);
    const double s = piece_start(piece);
    // A centre moved off a point its ball printed at t jumps from it there (end_at): the jump must not come closer
    // than their radii's sum to a third ball's point at t that it starts at least that far from (jump-through).
    const std::size_t n = piece.size();
    const bool jumps = n >= 2 && piece[n - 2].t == t && piece[n - 1].t == t;
    bool crowded = false;
    neighbours(i, [&](std::uint32_t k) {
        const meet::Radii Sk{radius(i), radius(k)};
        if (crowded || k == a || k == b || !(Sk.rounded() > 0.0) || out_of_reach(i, k, s)) return;
        const std::vector<PathPoint>& whole = third_printed(k, full_k_);
        if (whole.back().t < t) return;
        const Vec2 at = meet::point_at(whole, t).x;
        if (meet::closer_than(moved.x, at, Sk) && !meet::closer_than(rounded, at, Sk)) crowded = true;
        if (!crowded && jumps) crowded = meet::jump_enters(piece[n - 2].p, moved.x, meet::exact_point(whole, t), Sk);
        if (crowded || !(s < t)) return;
        const std::optional<meet::Root> e = meet::first_entry(piece, whole, Sk, s, t);
        crowded = e && meet::compare(*e, t) < 0;
    });
    return crowded;
}

}  // namespace ricochet
