// One frame's meets (meet.hpp's step_meets; docs/scene-log.md, "Balls that meet"): the swept rule of robust and
// exact, every decision exact (root.hpp), and the lecture's static test at the frame's end.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

#include "kernels/disc/frame.hpp"
#include "kernels/meet/box_grid.hpp"
#include "kernels/meet/root.hpp"
#include "ricochet/bits.hpp"
#include "ricochet/meet.hpp"

namespace ricochet {

/// A meet found between two balls at some version of their paths.
struct MeetCandidate {
    std::uint32_t a = 0, b = 0;
    std::uint32_t version_a = 0, version_b = 0;
    meet::Root root;
};

/// The swept rule's arrays, kept between frames (StepScratch::meets).
struct MeetFrameScratch {
    std::vector<double> seg_t;
    std::vector<Vec2> seg_vel;
    std::vector<std::uint32_t> version;
    std::vector<std::vector<PathPoint>> committed;
    std::vector<std::vector<HitEvent>> done;
    std::vector<meet::Box> box;
    meet::BoxGrid grid;
    std::vector<std::uint32_t> seen;
    std::vector<MeetCandidate> heap;
    std::vector<PathPoint> cut_a, cut_b;
    std::vector<PathPoint> full_a, full_b, full_k;
};

namespace {

using Candidate = MeetCandidate;

using meet::Box;
using meet::boxes_overlap;

/// A box around a ball's path, widened by its radius.
Box path_box(std::span<const PathPoint> path, double R) {
    Box b{path.front().p, path.front().p};
    for (const PathPoint& p : path) {
        b.lo = {std::min(b.lo.x, p.p.x), std::min(b.lo.y, p.p.y)};
        b.hi = {std::max(b.hi.x, p.p.x), std::max(b.hi.y, p.p.y)};
    }
    // Widened by R and a relative margin, so that a rounded box never leaves out a pair whose exact paths come
    // within R_a + R_b (the exact decision is first_meet's).
    const double m = std::max({std::fabs(b.lo.x), std::fabs(b.lo.y), std::fabs(b.hi.x), std::fabs(b.hi.y)});
    const double pad = R + R * 0x1p-40 + m * 0x1p-40;
    return {{b.lo.x - pad, b.lo.y - pad}, {b.hi.x + pad, b.hi.y + pad}};
}

/// The path of a step from (t0, p0): its start, each contact at its time (never before the previous one, never
/// after 1: rounded times), its end at 1.
void build_path(std::vector<PathPoint>& path, double t0, Vec2 p0, std::span<const HitEvent> hits, Vec2 end) {
    path.clear();
    path.push_back({t0, p0});
    for (const HitEvent& h : hits) path.push_back({std::clamp(h.t, path.back().t, 1.0), h.point});
    path.push_back({1.0, end});
}

/// The heap's order: a comes out after b (later time; on an exact tie the higher pair).
bool later(const Candidate& x, const Candidate& y) {
    const int c = meet::compare(x.root, y.root);
    if (c != 0) return c > 0;
    return std::pair(x.a, x.b) > std::pair(y.a, y.b);
}

/// The swept rule: meets in exact time order on the balls' paths.
class SweptFrame {
public:
    SweptFrame(KernelId k, const Obstacles& obstacles, std::span<const double> masses, std::span<BallFrame> balls,
               std::vector<MeetRecord>& meets, StepScratch& scratch, MeetFrameScratch& kept)
        : k_(k), obstacles_(obstacles), masses_(masses), balls_(balls), meets_(meets), scratch_(scratch),
          n_(balls.size()), seg_t_(kept.seg_t), seg_vel_(kept.seg_vel), version_(kept.version),
          committed_(kept.committed), done_(kept.done), box_(kept.box), grid_(kept.grid), seen_(kept.seen),
          heap_(kept.heap), cut_a_(kept.cut_a), cut_b_(kept.cut_b), full_a_(kept.full_a), full_b_(kept.full_b),
          full_k_(kept.full_k) {
        seg_t_.assign(n_, 0.0);
        seg_vel_.resize(n_);
        version_.assign(n_, 0);
        committed_.resize(n_);
        done_.resize(n_);
        for (std::size_t i = 0; i < n_; ++i) {
            committed_[i].clear();
            done_[i].clear();
        }
        box_.resize(n_);
        heap_.clear();
    }

    void run() {
        for (std::size_t i = 0; i < n_; ++i) {
            BallFrame& f = balls_[i];
            seg_vel_[i] = f.before.vel;
            build_path(f.path, 0.0, f.before.pos, f.events, f.state.pos);
            box_[i] = path_box(f.path, f.before.r);
        }
        // Every pair whose boxes overlap, found through a grid of the boxes (the heap's order is total: the order
        // pairs are found in changes nothing).
        grid_.build(box_);
        seen_.assign(n_, 0);
        grid_.pairs(box_, [&](std::uint32_t i, std::uint32_t j) { consider(i, j); });
        const std::size_t limit = static_cast<std::size_t>(k_max_meets_per_ball) * n_;
        std::size_t taken = 0;
        while (!heap_.empty()) {
            std::pop_heap(heap_.begin(), heap_.end(), later);
            const Candidate c = std::move(heap_.back());
            heap_.pop_back();
            if (c.version_a != version_[c.a] || c.version_b != version_[c.b]) continue;  // a path it was found on changed
            if (taken == limit) {
                safe_stop(last_t_);
                break;
            }
            ++taken;
            take(c, tied(c));
        }
        for (std::size_t i = 0; i < n_; ++i) finish(i);
    }

private:
    double radius(std::size_t i) const { return balls_[i].before.r; }

    /// Calls f(j) once for every other ball j the grid lists near ball i's box.
    template <class F>
    void neighbours(std::uint32_t i, F&& f) {
        ++stamp_;
        seen_[i] = stamp_;
        grid_.query(box_[i], [&](std::uint32_t j) {
            if (seen_[j] == stamp_) return;
            seen_[j] = stamp_;
            f(j);
        });
    }

    /// The pair's next meet on the current paths, from `from` (default: the later of their starts) on.
    std::optional<meet::Root> search(std::uint32_t a, std::uint32_t b, double from = -1.0) const {
        const meet::Radii S{radius(a), radius(b)};
        if (!(S.rounded() > 0.0) || !boxes_overlap(box_[a], box_[b])) return std::nullopt;
        from = std::max({from, seg_t_[a], seg_t_[b]});
        return meet::first_meet(balls_[a].path, balls_[b].path, S, from, balls_[a].state.vel, balls_[b].state.vel);
    }

    /// The next printed time of either ball's current path after t (1 if none).
    double next_printed(std::uint32_t a, std::uint32_t b, double t) const {
        double next = 1.0;
        for (const std::uint32_t i : {a, b})
            for (const PathPoint& q : balls_[i].path)
                if (q.t > t) {
                    next = std::min(next, q.t);
                    break;
                }
        return next;
    }

    void push(std::uint32_t a, std::uint32_t b, meet::Root root) {
        heap_.push_back({a, b, version_[a], version_[b], std::move(root)});
        std::push_heap(heap_.begin(), heap_.end(), later);
    }

    /// Searches the pair's next meet on the current paths and puts it on the heap.
    void consider(std::uint32_t a, std::uint32_t b) {
        if (std::optional<meet::Root> root = search(a, b)) push(a, b, std::move(*root));
    }

    /// The last placement of a ball: its path's rounded point and where that point was placed.
    struct Placed {
        bool valid = false;
        meet::PointOnPath raw, at;
    };

    /// Ball i's centre at frame time t on its current path, placed clear of the walls (walked back toward the
    /// printed point the piece starts from), and the index of that point. The walk back depends on the rounded point
    /// alone: where it is the last one's, bit for bit (an earlier t often rounds to the same centre), the last
    /// placement is the answer.
    meet::PointOnPath place(std::size_t i, double t, Placed& last) {
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

    /// Would the meet's printed centres at t leave balls a and b closer than S: the centres themselves, or the pieces
    /// to them from their last printed points (a grazing meet's rounded centres may be apart while the pieces dip)?
    bool too_close(std::uint32_t a, std::uint32_t b, meet::Radii S, double lo, double t, const meet::PointOnPath& pa,
                   const meet::PointOnPath& pb) {
        if (meet::closer_than(pa.x, pb.x, S)) return true;
        cut_to(a, pa, t, cut_a_);
        cut_to(b, pb, t, cut_b_);
        // An entry before t on the pieces that end at the centres (one at t itself is the meet).
        const std::optional<meet::Root> r = meet::first_meet(cut_a_, cut_b_, S, lo, {}, {}, t);
        if (r && meet::compare(*r, t) < 0) return true;
        // A piece to a rounded centre starts at its ball's last printed point, which may lie before lo, where the
        // other ball was on a path it has left since: there, an entry of that piece into the other's printed path.
        const double s = std::min(piece_start(cut_a_), piece_start(cut_b_));
        if (s < lo) {
            const std::vector<PathPoint>&fa = printed(a, cut_a_, full_a_), &fb = printed(b, cut_b_, full_b_);
            const std::optional<meet::Root> e = meet::first_meet(fa, fb, S, s, {}, {}, lo);
            if (e && meet::compare(*e, lo) < 0 && entered(*e, fa, fb, S)) return true;
        }
        // A third ball k (three balls meeting at one time, or a graze the rounded centre makes): the centre must not
        // be closer to k's point at t, rounded where k's path puts it, than their radii's sum, nor the piece to the
        // centre enter k's reach at or after lo (touching k there and approaching) and before t where the ball's own
        // path does not — where the two were not closer than that at lo.
        bool crowded = false;
        for (const auto& [ball, centre, cut] : {std::tuple{a, pa.x, &cut_a_}, std::tuple{b, pb.x, &cut_b_}}) {
            const std::uint32_t i = ball;
            const Vec2 x = centre;
            const std::vector<PathPoint>& piece = *cut;
            // A centre printed already, by a meet taken at t before this one (the ball's path starts there at t), was
            // judged against the third balls then.
            const PathPoint& start = balls_[i].path.front();
            if (start.t == t && same_bits(start.p, x)) continue;
            neighbours(i, [&](std::uint32_t k) {
                const meet::Radii Sk{radius(i), radius(k)};
                const std::vector<PathPoint>& path = balls_[k].path;
                if (crowded || k == a || k == b || !(Sk.rounded() > 0.0) || path.front().t > t) return;
                // Apart at lo, as the printed paths put them (the piece to the centre, which may start before lo,
                // and k's path, their exact points) or as the ball's own path does (its point there, rounded): two
                // balls are excused only where both have them closer than that (placed so by the scene). k's first
                // point stands for it where its path starts later.
                const auto apart_at_lo = [&] {
                    const Vec2 own = meet::point_at(balls_[i].path, lo).x;
                    if (path.front().t > lo)
                        return !meet::closer_than(meet::point_at(piece, lo).x, path.front().p, Sk) ||
                               !meet::closer_than(own, path.front().p, Sk);
                    return !meet::closer_on_paths(piece, path, lo, Sk) ||
                           !meet::closer_than(own, meet::point_at(path, lo).x, Sk);
                };
                if (!meet::surely_apart(x, path, t, Sk) && meet::closer_than(x, meet::point_at(path, t).x, Sk)) {
                    crowded = apart_at_lo();
                    return;
                }
                // (Where the ball's own path enters k's reach by t too, k is due at t as well, a tie, not a graze
                // the rounding made: the ties' rule takes it.)
                const std::optional<meet::Root> entry = meet::first_meet(piece, path, Sk, lo, {}, {}, t);
                if (!entry || meet::compare(*entry, t) >= 0) return;
                if (!meet::first_meet(balls_[i].path, path, Sk, lo, {}, {}, t)) crowded = apart_at_lo();
            });
        }
        return crowded;
    }

    /// Ball i's current path cut at frame time t, where it would be at centre p: its points up to the one the piece
    /// holding p starts from, then p at t.
    void cut_to(std::uint32_t i, const meet::PointOnPath& p, double t, std::vector<PathPoint>& out) const {
        const std::vector<PathPoint>& path = balls_[i].path;
        out.assign(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(p.from + 1));
        if (out.back().t < t) out.push_back({t, p.x});
        else out.back().p = p.x;
    }

    /// Whether a meet of paths a and b is an entry into reach from outside it: a crossing inside its interval, or
    /// one at the interval's start c where the two touch exactly (two balls already closer than S enter nothing).
    static bool entered(const meet::Root& m, std::span<const PathPoint> a, std::span<const PathPoint> b,
                        meet::Radii S) {
        return !m.at_start || !meet::closer_on_paths(a, b, m.c, S);
    }

    /// The time a path cut at a meet's centre (too_close) leaves its last printed point: its last piece's start.
    static double piece_start(const std::vector<PathPoint>& cut) {
        return cut.size() >= 2 ? cut[cut.size() - 2].t : cut.back().t;
    }

    /// Ball k's printed path so far, its committed points then `current` (its current path, or that cut at a
    /// centre), in out where it has committed points.
    const std::vector<PathPoint>& printed(std::uint32_t k, const std::vector<PathPoint>& current,
                                          std::vector<PathPoint>& out) const {
        if (committed_[k].empty()) return current;
        out.assign(committed_[k].begin(), committed_[k].end());
        out.insert(out.end(), current.begin(), current.end());
        return out;
    }

    /// The walk back reached its floor t (the pieces' common start lo, or the last meet's time) and the centres still
    /// leave the balls too close (a centre rounded back onto its ball's last printed point holds that ball still on
    /// its piece, while the other went by it earlier on a path it has left since): one of the two centres moved to a
    /// neighbouring double (one ulp in x, y or both) whose piece stays clear of the walls, with which no clause of
    /// too_close holds and which crowds no third ball (crowds_others), the one nearest its rounded centre, exactly;
    /// none where two are as near (no choice a mirror image or a renumbering would make the other way), nor where
    /// none clears.
    void nudge(std::uint32_t a, std::uint32_t b, meet::Radii S, double lo, double t, meet::PointOnPath& pa,
               meet::PointOnPath& pb) {
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
        std::vector<Clear> clear;
        for (const bool on_a : {true, false}) {
            const meet::PointOnPath& p = on_a ? pa : pb;
            const std::uint32_t i = on_a ? a : b;
            const Vec2 q = balls_[i].path[p.from].p;
            const Vec2 w = velocity_on(i, p.from) - velocity_on(on_a ? b : a, (on_a ? pb : pa).from);
            const auto [ex, ey] = meet::exact_point(balls_[i].path, t);
            for (const double sx : {-1.0, 0.0, 1.0})
                for (const double sy : {-1.0, 0.0, 1.0}) {
                    const Vec2 c{sx == 0.0 ? p.x.x : std::nextafter(p.x.x, sx * HUGE_VAL),
                                 sy == 0.0 ? p.x.y : std::nextafter(p.x.y, sy * HUGE_VAL)};
                    if (c == p.x || !std::isfinite(c.x) || !std::isfinite(c.y)) continue;
                    if (c != q && !same_bits(disc::walk_back(q, c, radius(i), obstacles_, scratch_), c)) continue;
                    const meet::PointOnPath moved{c, p.from};
                    if (too_close(a, b, S, lo, t, on_a ? moved : pa, on_a ? pb : moved)) continue;
                    if (crowds_others(i, a, b, moved, p.x, t)) continue;
                    const Rational dx = Rational(c.x) - Rational(p.x.x), dy = Rational(c.y) - Rational(p.x.y);
                    const Rational fx = Rational(c.x) - ex, fy = Rational(c.y) - ey;
                    clear.push_back({on_a, c, dx * dx + dy * dy, fx * fx + fy * fy, balls_[i].path[p.from].t == t,
                                     dx * Rational(w.x) + dy * Rational(w.y)});
                }
        }
        // Past the distance from the rounded centre only where the rounded centres themselves overlap.
        const bool overlap = meet::closer_than(pa.x, pb.x, S);
        const auto order = [overlap](const Clear& x, const Clear& y) {
            if (x.d2 != y.d2) return x.d2 < y.d2 ? -1 : 1;
            if (!overlap) return 0;
            if (x.e2 != y.e2) return x.e2 < y.e2 ? -1 : 1;
            if (x.jump != y.jump) return x.jump ? 1 : -1;
            if (x.along != y.along) return x.along < y.along ? -1 : 1;
            return 0;
        };
        const Clear* best = nullptr;
        bool tie = false;
        for (const Clear& x : clear) {
            const int o = best ? order(x, *best) : -1;
            if (o < 0) {
                best = &x;
                tie = false;
            } else if (o == 0) {
                tie = true;
            }
        }
        if (best && !tie) (best->on_a ? pa : pb).x = best->c;
    }

    /// For nudge: whether ball i's centre moved to `moved` at t (from `rounded`) comes closer than their radii's sum
    /// to a third ball's point there where the rounded centre did not, or its piece enters a third ball's printed
    /// path before t. (too_close excuses a third ball the piece's own point at lo was already that close to, which
    /// is the moved centre itself where the piece starts at lo.)
    bool crowds_others(std::uint32_t i, std::uint32_t a, std::uint32_t b, const meet::PointOnPath& moved, Vec2 rounded,
                       double t) {
        std::vector<PathPoint> piece;
        cut_to(i, moved, t, piece);
        const double s = piece_start(piece);
        bool crowded = false;
        neighbours(i, [&](std::uint32_t k) {
            const meet::Radii Sk{radius(i), radius(k)};
            if (crowded || k == a || k == b || !(Sk.rounded() > 0.0)) return;
            const std::vector<PathPoint>& whole = printed(k, balls_[k].path, full_k_);
            if (whole.back().t < t) return;
            const Vec2 at = meet::point_at(whole, t).x;
            if (meet::closer_than(moved.x, at, Sk) && !meet::closer_than(rounded, at, Sk)) crowded = true;
            if (crowded || !(s < t)) return;
            const std::optional<meet::Root> e = meet::first_meet(piece, whole, Sk, s, {}, {}, t);
            crowded = e && meet::compare(*e, t) < 0 && entered(*e, piece, whole, Sk);
        });
        return crowded;
    }

    /// The velocity ball i has on the piece of its current path that starts at printed point k.
    Vec2 velocity_on(std::size_t i, std::size_t k) const {
        const BallFrame& f = balls_[i];
        if (k == 0) return seg_vel_[i];
        if (k <= f.events.size()) return f.events[k - 1].out;
        return f.state.vel;
    }

    /// Ends ball i's current path at (t, x), reached from printed point k: its contacts up to k are kept, its path's
    /// points up to k committed.
    void cut(std::size_t i, std::size_t k) {
        BallFrame& f = balls_[i];
        // Its start and contacts up to k; the path's end (k past the last contact: a meet at t = 1) is not printed,
        // the meet's point is.
        const std::size_t kept = std::min(k, f.events.size());
        done_[i].insert(done_[i].end(), f.events.begin(), f.events.begin() + static_cast<std::ptrdiff_t>(kept));
        committed_[i].insert(committed_[i].end(), f.path.begin(), f.path.begin() + static_cast<std::ptrdiff_t>(kept + 1));
    }

    /// Ball i steps on from x at frame time t with velocity v: a new path.
    void restart(std::size_t i, double t, Vec2 x, Vec2 v) {
        BallFrame& f = balls_[i];
        Ball ball{x, v, radius(i)};
        BallMemory memory = f.memory;
        f.events.clear();
        scratch_.start = t;
        f.status = step_ball(k_, ball, memory, obstacles_, f.events, scratch_);
        scratch_.start = 0.0;
        f.state = ball;
        seg_t_[i] = t;
        seg_vel_[i] = v;
        build_path(f.path, t, x, f.events, ball.pos);
        box_[i] = path_box(f.path, radius(i));
        ++version_[i];
    }

    /// Ball i, just stepped on from a meet at frame time t, stays where it starts to the frame's end instead, keeping
    /// the velocity it left the meet with (docs/scene-log.md, "Balls that meet", 6).
    void hold(std::size_t i, double t) {
        BallFrame& f = balls_[i];
        const Vec2 x = f.path.front().p;
        f.events.clear();
        if (f.status != FrameStatus::out_of_range) f.status = FrameStatus::ok;
        f.state = {x, seg_vel_[i], radius(i)};
        f.path = {{t, x}, {1.0, x}};
        box_[i] = path_box(f.path, radius(i));
        ++version_[i];
    }

    /// True if another meet due now, at c's exact time, shares a ball with c: the heap's next entries at that time
    /// are looked at (stale ones dropped) and put back.
    bool tied(const Candidate& c) {
        bool shared = false;
        std::vector<Candidate> same;
        while (!heap_.empty()) {
            const Candidate& next = heap_.front();
            const bool stale = next.version_a != version_[next.a] || next.version_b != version_[next.b];
            if (!stale && meet::compare(next.root, c.root) != 0) break;
            std::pop_heap(heap_.begin(), heap_.end(), later);
            // The entry just looked at is at the back now.
            const Candidate& x = heap_.back();
            if (!stale) {
                shared = shared || x.a == c.a || x.a == c.b || x.b == c.a || x.b == c.b;
                same.push_back(std::move(heap_.back()));
            }
            heap_.pop_back();
        }
        for (Candidate& x : same) {
            heap_.push_back(std::move(x));
            std::push_heap(heap_.begin(), heap_.end(), later);
        }
        return shared;
    }

    void take(const Candidate& c, bool tied) {
        const std::uint32_t a = c.a, b = c.b;
        const meet::Radii S{radius(a), radius(b)};
        const double lo = std::max(seg_t_[a], seg_t_[b]);
        // Never before the meet taken last: the frame's meets keep their time order as printed too (the pair's
        // other meets with balls met since are searched from there on).
        const double floor = std::max(lo, last_t_);
        double t = std::clamp(c.root.estimate, floor, 1.0);
        // The printed centres, no closer than S (exactly): t taken earlier, 1, 2, 4, … ulps, then the floor.
        Placed last_a, last_b;
        meet::PointOnPath pa = place(a, t, last_a), pb = place(b, t, last_b);
        for (double step = std::max(std::fabs(t) * 0x1p-52, 0x1p-1074);
             t > floor && too_close(a, b, S, lo, t, pa, pb); step *= 2.0) {
            t = t - step > floor ? t - step : floor;
            pa = place(a, t, last_a);
            pb = place(b, t, last_b);
        }
        if (t == floor && too_close(a, b, S, lo, t, pa, pb)) nudge(a, b, S, lo, t, pa, pb);
        Ball ba{pa.x, velocity_on(a, pa.from), radius(a)}, bb{pb.x, velocity_on(b, pb.from), radius(b)};
        last_t_ = t;
        MeetRecord record{a, b, t, pa.x, pb.x, ba.vel, bb.vel, {}, {}, false, tied};
        record.responded = kernel_ops(k_).respond(ba, bb, masses_[a], masses_[b]);
        record.out_a = ba.vel;
        record.out_b = bb.vel;
        meets_.push_back(record);
        cut(a, pa.from);
        cut(b, pb.from);
        done_[a].push_back({b, t, pa.x, false, true, ba.vel});
        done_[b].push_back({a, t, pb.x, false, true, bb.vel});
        restart(a, t, pa.x, ba.vel);
        restart(b, t, pb.x, bb.vel);
        // The new paths close in at t itself again (rule 6): two balls the scene placed closer than S are searched
        // past it, from the next printed time on (the start-in-reach rule at the meet itself, its response decided);
        // two that touch both stay at their centres to the frame's end (far from the origin their rounded ends can
        // converge where no velocity a double holds keeps them apart).
        std::optional<meet::Root> again = search(a, b);
        if (again && again->at_start && meet::compare(*again, t) == 0) {
            again.reset();
            if (meet::closer_than(pa.x, pb.x, S)) {
                const double next = next_printed(a, b, t);
                if (next > t) again = search(a, b, next);
            } else {
                hold(a, t);
                hold(b, t);
            }
        }
        grid_.insert(a, box_[a]);
        grid_.insert(b, box_[b]);
        if (again) push(a, b, std::move(*again));
        neighbours(a, [&](std::uint32_t k) {
            if (k != b) consider(std::min(a, k), std::max(a, k));
        });
        neighbours(b, [&](std::uint32_t k) {
            if (k != a) consider(std::min(b, k), std::max(b, k));
        });
    }

    /// The bound of meets reached: every ball stops where its path is at time t, the last meet's (placed as a meet's
    /// centre is; no meet was due before it, so no two balls were closer than their R_i + R_j there), keeping the
    /// velocity it has there. A stop is a rounded point: the piece to it can come within R_i + R_j of another ball's
    /// path where the ball's own path does not (far out, a ball moving less than an ulp since its last printed point
    /// prints standing still while another passes where it was). Such a ball, in ball order, is moved to the
    /// neighbouring double nearest its stop whose piece stays clear of the walls and of every other ball's path to its
    /// stop (the nearest to its path's exact point there among two as near; none where those tie too, or none clears).
    void safe_stop(double t) {
        std::vector<double> when(n_);
        std::vector<meet::PointOnPath> at(n_);
        std::vector<std::vector<PathPoint>> to_stop(n_);
        for (std::uint32_t i = 0; i < n_; ++i) {
            when[i] = std::max(t, seg_t_[i]);
            Placed none;
            at[i] = place(i, when[i], none);
            stop_path(i, at[i], when[i], to_stop[i]);
        }
        std::vector<PathPoint> moved;
        for (std::uint32_t i = 0; i < n_; ++i) {
            const double s = balls_[i].path[at[i].from].t;
            if (!stop_enters(i, s, to_stop)) continue;
            using bignum::Rational;
            const Vec2 x = at[i].x, q = balls_[i].path[at[i].from].p;
            const auto [ex, ey] = meet::exact_point(balls_[i].path, when[i]);
            std::optional<Vec2> best;
            Rational best_d2, best_e2;
            bool tie = false;
            for (const double sx : {-1.0, 0.0, 1.0})
                for (const double sy : {-1.0, 0.0, 1.0}) {
                    const Vec2 c{sx == 0.0 ? x.x : std::nextafter(x.x, sx * HUGE_VAL),
                                 sy == 0.0 ? x.y : std::nextafter(x.y, sy * HUGE_VAL)};
                    if (c == x || !std::isfinite(c.x) || !std::isfinite(c.y)) continue;
                    if (c != q && !same_bits(disc::walk_back(q, c, radius(i), obstacles_, scratch_), c)) continue;
                    stop_path(i, {c, at[i].from}, when[i], moved);
                    std::swap(moved, to_stop[i]);
                    const bool enters = stop_enters(i, s, to_stop);
                    std::swap(moved, to_stop[i]);
                    if (enters) continue;
                    const Rational dx = Rational(c.x) - Rational(x.x), dy = Rational(c.y) - Rational(x.y);
                    const Rational fx = Rational(c.x) - ex, fy = Rational(c.y) - ey;
                    const Rational d2 = dx * dx + dy * dy, e2 = fx * fx + fy * fy;
                    if (!best || d2 < best_d2 || (d2 == best_d2 && e2 < best_e2)) {
                        best = c;
                        best_d2 = d2;
                        best_e2 = e2;
                        tie = false;
                    } else if (d2 == best_d2 && e2 == best_e2) {
                        tie = true;
                    }
                }
            if (!best || tie) continue;
            at[i].x = *best;
            stop_path(i, at[i], when[i], to_stop[i]);
        }
        for (std::size_t i = 0; i < n_; ++i) {
            const meet::PointOnPath& p = at[i];
            const Vec2 v = velocity_on(i, p.from);
            cut(i, p.from);
            BallFrame& f = balls_[i];
            f.events.clear();
            f.state = {p.x, v, radius(i)};
            // It stops there at time `when` and stays to the frame's end: the point is printed once, as its state; the
            // path says when it got there (pass-through reads the path with its times).
            f.path = {{when[i], p.x}, {1.0, p.x}};
        }
    }

    /// Ball i's printed path with a stop at p, time t: its committed points, its current path's up to the last
    /// before the stop, the stop, and the stop again at t = 1.
    void stop_path(std::uint32_t i, const meet::PointOnPath& p, double t, std::vector<PathPoint>& out) const {
        const std::vector<PathPoint>& path = balls_[i].path;
        out.assign(committed_[i].begin(), committed_[i].end());
        out.insert(out.end(), path.begin(), path.begin() + static_cast<std::ptrdiff_t>(p.from + 1));
        if (out.back().t < t) out.push_back({t, p.x});
        else out.back().p = p.x;
        out.push_back({1.0, p.x});
    }

    /// Whether ball i's piece to its stop (from its last printed point, at time s, on its printed path to_stop[i])
    /// comes within R_i + R_k of another ball k's printed path to its stop from outside it (pass-through's rule: on a
    /// common interval, at least that far apart at its start and closer within it; one that starts closer is not
    /// judged).
    bool stop_enters(std::uint32_t i, double s, const std::vector<std::vector<PathPoint>>& to_stop) {
        bool enters = false;
        neighbours(i, [&](std::uint32_t k) {
            const meet::Radii S{radius(i), radius(k)};
            if (enters || !(S.rounded() > 0.0)) return;
            const std::vector<PathPoint>&a = to_stop[i], &b = to_stop[k];
            double from = s;
            while (from < 1.0) {
                const std::optional<meet::Root> m = meet::first_meet(a, b, S, from);
                if (!m) return;
                if (entered(*m, a, b, S)) {
                    enters = true;
                    return;
                }
                from = next_point(a, b, m->c);
            }
        });
        return enters;
    }

    /// The first time after t at which path a or b has a point (1 if none).
    static double next_point(std::span<const PathPoint> a, std::span<const PathPoint> b, double t) {
        double next = 1.0;
        for (const std::span<const PathPoint> path : {a, b})
            for (const PathPoint& q : path)
                if (q.t > t) {
                    next = std::min(next, q.t);
                    break;
                }
        return next;
    }

    /// The frame's whole story of ball i: its committed contacts and points, then its current path's.
    void finish(std::size_t i) {
        BallFrame& f = balls_[i];
        if (done_[i].empty() && committed_[i].empty()) return;
        done_[i].insert(done_[i].end(), f.events.begin(), f.events.end());
        f.events.swap(done_[i]);  // (the old lists stay behind, their storage for the next frame)
        committed_[i].insert(committed_[i].end(), f.path.begin(), f.path.end());
        f.path.swap(committed_[i]);
    }

    KernelId k_;
    const Obstacles& obstacles_;
    std::span<const double> masses_;
    std::span<BallFrame> balls_;
    std::vector<MeetRecord>& meets_;
    StepScratch& scratch_;
    std::size_t n_;
    // Kept between frames (MeetFrameScratch), made afresh for this one:
    std::vector<double>& seg_t_;                     // the frame time each ball's current path starts at
    std::vector<Vec2>& seg_vel_;                     // the velocity it starts with
    std::vector<std::uint32_t>& version_;            // bumped when its path changes
    std::vector<std::vector<PathPoint>>& committed_;  // its path's points before the current path
    std::vector<std::vector<HitEvent>>& done_;       // its contacts before the current path, meets included
    std::vector<Box>& box_;
    meet::BoxGrid& grid_;
    std::vector<std::uint32_t>& seen_;  // the stamp of the last neighbours() call that listed the ball
    std::uint32_t stamp_ = 0;
    std::vector<Candidate>& heap_;
    std::vector<PathPoint>&cut_a_, &cut_b_;  // the paths to a meet's centres (too_close)
    std::vector<PathPoint>&full_a_, &full_b_, &full_k_;  // printed paths with their committed points
    double last_t_ = 0.0;                   // the time of the last meet taken
};

/// The lecture's rule: each ball stepped alone, then every pair whose boxes at the frame's end overlap, in index
/// order, through the kernel's static test and push apart (meet_at_end).
void end_of_frame(KernelId k, std::span<const double> masses, std::span<BallFrame> balls,
                  std::vector<MeetRecord>& meets) {
    const std::size_t n = balls.size();
    for (BallFrame& f : balls) build_path(f.path, 0.0, f.before.pos, f.events, f.state.pos);
    std::vector<std::uint32_t> order(n);
    for (std::uint32_t i = 0; i < n; ++i) order[i] = i;
    const auto lo = [&](std::uint32_t i) { return balls[i].state.pos.x - balls[i].state.r; };
    const auto hi = [&](std::uint32_t i) { return balls[i].state.pos.x + balls[i].state.r; };
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return lo(a) < lo(b) || (lo(a) == lo(b) && a < b);
    });
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
    for (std::size_t x = 0; x < n; ++x)
        for (std::size_t y = x + 1; y < n && lo(order[y]) <= hi(order[x]); ++y)
            pairs.emplace_back(std::min(order[x], order[y]), std::max(order[x], order[y]));
    std::sort(pairs.begin(), pairs.end());
    const KernelOps& ops = kernel_ops(k);
    for (const auto& [a, b] : pairs) {
        Ball& ba = balls[a].state;
        Ball& bb = balls[b].state;
        if (!(ba.r + bb.r > 0.0)) continue;
        const Vec2 va = ba.vel, vb = bb.vel;
        if (!ops.meet_at_end(ba, bb, masses[a], masses[b])) continue;
        meets.push_back({a, b, 1.0, ba.pos, bb.pos, va, vb, ba.vel, bb.vel, true});
        balls[a].events.push_back({b, 1.0, ba.pos, false, true, ba.vel});
        balls[b].events.push_back({a, 1.0, bb.pos, false, true, bb.vel});
        balls[a].path.push_back({1.0, ba.pos});
        balls[b].path.push_back({1.0, bb.pos});
    }
}

}  // namespace

void step_meets(KernelId k, const Obstacles& obstacles, std::span<const double> masses, std::span<BallFrame> balls,
                std::vector<MeetRecord>& meets, StepScratch& scratch) {
    switch (kernel_ops(k).meet_rule) {
        case MeetRule::none: return;
        case MeetRule::end_of_frame: end_of_frame(k, masses, balls, meets); return;
        case MeetRule::swept:
            if (!scratch.meets) scratch.meets = std::make_shared<MeetFrameScratch>();
            SweptFrame(k, obstacles, masses, balls, meets, scratch, *scratch.meets).run();
            return;
    }
}

}  // namespace ricochet
