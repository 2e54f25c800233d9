// The swept rule of robust and exact (docs/scene-log.md, "Balls that meet"): one frame's meets in exact time order
// on the balls' paths, every decision exact (root.hpp). Internal to kernels/meet/: frame.cpp runs it for step_meets;
// swept_frame.cpp finds and takes the meets, placement.cpp places a meet's centres (rule 4), safe_stop.cpp stops the
// frame at the bound of meets (rule 7).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "kernels/meet/box_grid.hpp"
#include "kernels/meet/root.hpp"
#include "ricochet/kernel.hpp"
#include "ricochet/meet.hpp"
#include "ricochet/step.hpp"

namespace ricochet {

/// A meet found between two balls at some version of their paths.
struct MeetCandidate {
    std::uint32_t a = 0, b = 0;
    std::uint32_t version_a = 0, version_b = 0;
    meet::Root root;
};

/// A meet on the heap: its time's estimate (all the order needs of two times more than 2^−48 apart) and where its
/// candidate lies in the pool (MeetFrameScratch::pool). The heap moves these, not candidates.
struct MeetKey {
    double estimate = 0.0;
    std::uint32_t slot = 0;
};

/// A ball's path as it was before a meet moved it, kept while meets at that meet's exact time on other pairs are
/// due: their placements see the ball as it was (docs/scene-log.md, "Balls that meet", 3).
struct MeetSnapshot {
    std::uint64_t group = 0;      // the group of meets at one exact time it was taken in (0: none)
    std::uint32_t a = 0, b = 0;   // the meet that moved the ball
    double seg_t = 0.0;           // its current path's start then
    std::vector<PathPoint> committed, path;
};

/// The swept rule's arrays, kept between frames (StepScratch::meets).
struct MeetFrameScratch {
    std::vector<double> seg_t;
    std::vector<Vec2> seg_vel;
    std::vector<std::uint32_t> version;
    std::vector<std::vector<PathPoint>> committed;
    std::vector<std::vector<HitEvent>> done;
    std::vector<meet::Box> box;
    std::vector<meet::Box> reach;
    meet::BoxGrid grid;
    std::vector<std::uint32_t> seen;
    std::vector<MeetCandidate> pool;  // the heap's candidates, each where its key's slot says
    std::vector<std::uint32_t> free;  // the pool's slots taken off the heap, free again
    std::vector<MeetKey> heap;
    std::vector<PathPoint> cut_a, cut_b;
    std::vector<PathPoint> full_a, full_b, full_k;
    std::vector<MeetSnapshot> before;
    std::vector<std::uint32_t> touched;  // the balls a meet or the safe stop cut (their lists above are filled)
};

namespace meet {

/// How many rings of neighbouring doubles (1, 2, 3 ulps out) a nudge of overlapping centres and a safe stop try
/// (docs/scene-log.md, "Balls that meet", 4 and 7).
inline constexpr int k_rings = 3;

/// The box b around a ball's path's points widened by its radius R (path_box).
inline Box widened(Box b, double R) {
    // Widened by R and a relative margin, so that a rounded box never leaves out a pair whose exact paths come
    // within R_a + R_b (the exact decision is first_meet's).
    const double m = std::max({std::fabs(b.lo.x), std::fabs(b.lo.y), std::fabs(b.hi.x), std::fabs(b.hi.y)});
    const double pad = R + R * 0x1p-40 + m * 0x1p-40;
    return {{b.lo.x - pad, b.lo.y - pad}, {b.hi.x + pad, b.hi.y + pad}};
}

/// A box around a ball's path, widened by its radius.
inline Box path_box(std::span<const PathPoint> path, double R) {
    Box b{path.front().p, path.front().p};
    for (const PathPoint& p : path) {
        b.lo = {std::min(b.lo.x, p.p.x), std::min(b.lo.y, p.p.y)};
        b.hi = {std::max(b.hi.x, p.p.x), std::max(b.hi.y, p.p.y)};
    }
    return widened(b, R);
}

/// path_box of the path of two points p0 and p1, from the points themselves.
inline Box segment_box(Vec2 p0, Vec2 p1, double R) {
    return widened({{std::min(p0.x, p1.x), std::min(p0.y, p1.y)}, {std::max(p0.x, p1.x), std::max(p0.y, p1.y)}}, R);
}

/// The path of a step from (t0, p0): its start, each contact at its time (never before the previous one, never
/// after 1: rounded times), its end at 1.
inline void build_path(std::vector<PathPoint>& path, double t0, Vec2 p0, std::span<const HitEvent> hits, Vec2 end) {
    path.clear();
    path.push_back({t0, p0});
    for (const HitEvent& h : hits) path.push_back({std::clamp(h.t, path.back().t, 1.0), h.point});
    path.push_back({1.0, end});
}

/// The heap's order: a comes out after b (later time; on an exact tie the higher pair).
bool later(const MeetCandidate& x, const MeetCandidate& y);

/// later on the candidates the keys stand for (pool), from the keys alone where their estimates decide it.
bool later(const MeetKey& x, const MeetKey& y, const std::vector<MeetCandidate>& pool);

}  // namespace meet

/// The swept rule: meets in exact time order on the balls' paths.
class SweptFrame {
public:
    SweptFrame(KernelId k, const Obstacles& obstacles, std::span<const double> masses, std::span<BallFrame> balls,
               std::vector<MeetRecord>& meets, StepScratch& scratch, MeetFrameScratch& kept);

    /// The frame: every ball's path, the meets in time order, each ball's whole story.
    void run();

private:
    using Candidate = MeetCandidate;
    using Box = meet::Box;

    double radius(std::size_t i) const { return balls_[i].before.r; }

    // Finding meets (swept_frame.cpp).

    /// Calls f(j) once for every other ball j the grid lists near ball i's box (f asks for no other ball's).
    template <class F>
    void neighbours(std::uint32_t i, F&& f) {
        for (const std::uint32_t j : near(i)) f(j);
    }

    /// The balls the grid lists near ball i's box, each once, in the order the grid gives them. The lists of the last
    /// two balls asked about are kept until a path changes (the grid and the boxes stay as they are until then, and a
    /// meet's placement asks about its two balls again and again).
    const std::vector<std::uint32_t>& near(std::uint32_t i);

    /// The pair's next meet on the current paths, from `from` (default: the later of their starts) on.
    std::optional<meet::Root> search(std::uint32_t a, std::uint32_t b, double from = -1.0) const;

    /// The next printed time of either ball's current path after t (1 if none).
    double next_printed(std::uint32_t a, std::uint32_t b, double t) const;

    void push(std::uint32_t a, std::uint32_t b, meet::Root root);

    /// The heap's order on keys (meet::later).
    auto later() const {
        return [this](const MeetKey& x, const MeetKey& y) { return meet::later(x, y, pool_); };
    }

    /// Takes the heap's first meet off it: its candidate, its pool slot freed.
    Candidate pop();

    /// Searches the pair's next meet on the current paths and puts it on the heap.
    void consider(std::uint32_t a, std::uint32_t b) {
        if (std::optional<meet::Root> root = search(a, b)) push(a, b, std::move(*root));
    }

    // Placing a meet's centres (placement.cpp).

    /// The last placement of a ball: its path's rounded point and where that point was placed.
    struct Placed {
        bool valid = false;
        meet::PointOnPath raw, at;
    };

    /// Ball i's centre at frame time t on its current path, placed clear of the walls (walked back toward the
    /// printed point the piece starts from), and the index of that point. The walk back depends on the rounded point
    /// alone: where it is the last one's, bit for bit (an earlier t often rounds to the same centre), the last
    /// placement is the answer.
    meet::PointOnPath place(std::size_t i, double t, Placed& last);

    /// Would the meet's printed centres at t leave balls a and b closer than S: the centres themselves, or the pieces
    /// to them from their last printed points (a grazing meet's rounded centres may be apart while the pieces dip)?
    /// Two balls not held `apart` (placed_in_reach) are asked neither clause about the two alone, only an entry
    /// from outside S.
    bool too_close(std::uint32_t a, std::uint32_t b, meet::Radii S, double lo, double t, const meet::PointOnPath& pa,
                   const meet::PointOnPath& pb, bool apart = true);

    /// Whether the pieces to the centres (cut_a_, cut_b_, made by too_close) enter each other's reach before t, or
    /// one that starts before lo enters the other's printed path there: from outside S (pass-through's rule), or, with
    /// `any`, before t also from within. `any` is asked only where the centres are not closer than S (too_close).
    bool pieces_enter(std::uint32_t a, std::uint32_t b, meet::Radii S, double lo, double t, bool any);

    /// Whether balls a and b were closer than S at lo already, placed so by the scene: on their paths' exact points
    /// there and on those points rounded. At the floor of the walk back they are not held apart.
    bool placed_in_reach(std::uint32_t a, std::uint32_t b, meet::Radii S, double lo) const;

    /// Ball i's current path cut at frame time t, where it would be at centre p: its points up to the one the piece
    /// holding p starts from, then p at t.
    void cut_to(std::uint32_t i, const meet::PointOnPath& p, double t, std::vector<PathPoint>& out) const;

    /// Ends out, ball i's points up to the one the piece holding p starts from, at centre p, time t: p appended, or
    /// put in place of the last point where that is at t and is no print (the path's end) or p itself; a centre moved
    /// off a printed point at its time is a jump after it.
    void end_at(std::uint32_t i, const meet::PointOnPath& p, double t, std::vector<PathPoint>& out) const;

    /// The time a path cut at a meet's centre (too_close) leaves its last printed point: its last piece's start.
    static double piece_start(const std::vector<PathPoint>& cut) {
        return cut.size() >= 2 ? cut[cut.size() - 2].t : cut.back().t;
    }

    /// Ball k's printed path so far, its committed points then `current` (its current path, or that cut at a
    /// centre), in out where it has committed points.
    const std::vector<PathPoint>& printed(std::uint32_t k, const std::vector<PathPoint>& current,
                                          std::vector<PathPoint>& out) const;

    /// committed then current, in out where committed has points (else current itself).
    static const std::vector<PathPoint>& joined(const std::vector<PathPoint>& committed,
                                                const std::vector<PathPoint>& current, std::vector<PathPoint>& out);

    /// A third ball k as the placement of the meet being taken sees it: where that meet is not tied and the last
    /// meet of its group that moved k is on a pair sharing no ball with it, k as it was before that meet (its
    /// snapshot); else null, k as it is (a tied meet's order decides its outcome anyway).
    const MeetSnapshot* before(std::uint32_t k) const {
        if (!see_before_ || taking_tied_ || group_ == 0 || before_[k].group != group_) return nullptr;
        const MeetSnapshot& s = before_[k];
        return s.a == taking_a_ || s.a == taking_b_ || s.b == taking_a_ || s.b == taking_b_ ? nullptr : &s;
    }

    /// Whether third ball k is surely out of ball i's reach from frame time `from` on, i one of the meet's two balls
    /// and `from` no earlier than its current path's start: k seen as it is (not as it was, before), and i's box apart
    /// from k's current path's, where that is all k printed from `from` on (no path before it in this frame, or one
    /// left before `from`), else from the box around every path k had in this frame (reach_). The piece to i's centre
    /// lies in i's box (its path's points, the centre rounded or moved a few ulps off it, within path_box's margin),
    /// so no entry, crowding or jump between the two can be found there (the test too_close makes of k's current
    /// path).
    bool out_of_reach(std::uint32_t i, std::uint32_t k, double from) const {
        if (before(k) != nullptr) return false;
        return !meet::boxes_overlap(box_[i], version_[k] == 0 || seg_t_[k] < from ? box_[k] : reach_[k]);
    }

    /// Third ball k's printed path so far, as the placement sees it (before): its committed points then its
    /// current path, in out where it has committed points.
    const std::vector<PathPoint>& third_printed(std::uint32_t k, std::vector<PathPoint>& out) const;

    /// The walk back reached its floor t (the pieces' common start lo, or the last meet's time) and the centres still
    /// leave the balls too close (a centre rounded back onto its ball's last printed point holds that ball still on
    /// its piece, while the other went by it earlier on a path it has left since): one of the two centres moved to a
    /// neighbouring double (one ulp in x, y or both) whose piece stays clear of the walls, with which no clause of
    /// too_close holds and which crowds no third ball (crowds_others), the one nearest its rounded centre, exactly;
    /// none where two are as near (no choice a mirror image or a renumbering would make the other way), nor where
    /// none clears — except where the rounded centres themselves overlap or a piece to them would pass through a
    /// third ball as printed: there ties go on to the nearest to the ball's exact point, then by a later piece start,
    /// then back along the approach, then (where a piece passes through a third ball) to the first tied with none,
    /// else to the next distance out, and where none is taken, the doubles 2, then 3 ulps out are tried the same way.
    bool nudge(std::uint32_t a, std::uint32_t b, meet::Radii S, double lo, double t, meet::PointOnPath& pa,
               meet::PointOnPath& pb, bool apart);

    /// Whether the centres at t (held `apart`: closer than S) or the pieces to them would break what ball-overlap and
    /// pass-through see: the pieces entering each other's reach, or a third ball's printed path, from outside it
    /// before t (cut_a_ and cut_b_ left cut at the centres).
    bool passes(std::uint32_t a, std::uint32_t b, meet::Radii S, double lo, double t, const meet::PointOnPath& pa,
                const meet::PointOnPath& pb, bool apart);

    /// Whether the piece to ball i's centre (cut: its current path cut there), where it starts before `until`,
    /// enters the printed path of a ball other than a and b from outside its reach before `until`: pass-through's
    /// rule (too_close asks it before lo, of a piece that starts before the other ball of the meet stepped on, as it
    /// asks it of a and b, and of a third ball's points printed before its current path where that began after lo;
    /// nudge before t, where it decides how a tie is broken).
    bool enters_before(std::uint32_t i, std::uint32_t a, std::uint32_t b, const std::vector<PathPoint>& cut,
                       double until);

    /// For nudge: whether ball i's centre moved to `moved` at t (from `rounded`) comes closer than their radii's sum
    /// to a third ball's point there where the rounded centre did not, its jump there (where its piece starts at t)
    /// comes closer than that to a third ball's point it starts at least that far from, or its piece enters a third
    /// ball's printed path before t. (too_close excuses a third ball the piece's own point at lo was already that
    /// close to, which is the moved centre itself where the piece starts at lo.)
    bool crowds_others(std::uint32_t i, std::uint32_t a, std::uint32_t b, const meet::PointOnPath& moved, Vec2 rounded,
                       double t);

    // Taking a meet (swept_frame.cpp).

    /// The velocity ball i has on the piece of its current path that starts at printed point k.
    Vec2 velocity_on(std::size_t i, std::size_t k) const;

    /// Ends ball i's current path at (t, x), reached from printed point k: its contacts up to k are kept, its path's
    /// points up to k committed.
    void cut(std::size_t i, std::size_t k);

    /// Ball i steps on from x at frame time t with velocity v: a new path.
    void restart(std::size_t i, double t, Vec2 x, Vec2 v);

    /// Ball i, just stepped on from a meet at frame time t, stays where it starts to the frame's end instead, keeping
    /// the velocity it left the meet with (docs/scene-log.md, "Balls that meet", 6).
    void hold(std::size_t i, double t);

    /// The other meets due now, at c's exact time: whether one shares a ball with c (a tie) and whether there is
    /// any. The heap's next entries at that time are looked at (stale ones dropped) and put back.
    struct SameTime {
        bool shared = false, any = false;
    };
    SameTime same_time(const Candidate& c);

    /// Rule 4 for meet c: its time t and centres pa, pb (t* taken earlier, a centre nudged, …); false where none
    /// clears.
    bool place_meet(const Candidate& c, meet::Radii S, double lo, double floor, double& t, meet::PointOnPath& pa,
                    meet::PointOnPath& pb);

    /// Whether the centres pa, pb at t stand as well against the third balls as they are as against those the
    /// placement saw as they were (before): every clause of too_close and passes decided alike on both.
    bool stands_as_they_are(std::uint32_t a, std::uint32_t b, meet::Radii S, double lo, double t,
                            const meet::PointOnPath& pa, const meet::PointOnPath& pb);

    /// Takes meet c (tied: another meet sharing a ball is due at its exact time; grouped: another meet is due at
    /// it): its centres placed (rule 4), the response (5), both balls stepped on (6), their pairs with their
    /// neighbours searched again.
    void take(const Candidate& c, bool tied, bool grouped);

    /// The frame's whole story of ball i: its committed contacts and points, then its current path's.
    void finish(std::size_t i);

    // The bound of meets (safe_stop.cpp).

    /// The bound of meets reached: every ball stops where its path is at time t, the last meet's (placed as a meet's
    /// centre is; no meet was due before it, so no two balls were closer than their R_i + R_j there), keeping the
    /// velocity it has there. A stop is a rounded point: the piece to it can come within R_i + R_j of another ball's
    /// path where the ball's own path does not (far out, a ball moving less than an ulp since its last printed point
    /// prints standing still while another passes where it was). Such a ball, in ball order, is moved to the
    /// neighbouring double nearest its stop whose piece stays clear of the walls and of every other ball's path to its
    /// stop (the nearest to its path's exact point there among two as near; none where those tie too, or none clears),
    /// else the same among the doubles 2, then 3 ulps out.
    void safe_stop(double t);

    /// Ball i's printed path with a stop at p, time t: its committed points, its current path's up to the last
    /// before the stop, the stop, and the stop again at t = 1.
    void stop_path(std::uint32_t i, const meet::PointOnPath& p, double t, std::vector<PathPoint>& out) const;

    /// Whether ball i's piece to its stop (from its last printed point, at time s, on its printed path to_stop[i])
    /// comes within R_i + R_k of another ball k's printed path to its stop from outside it (pass-through's rule: on a
    /// common interval, at least that far apart at its start and closer within it; one that starts closer is not
    /// judged).
    bool stop_enters(std::uint32_t i, double s, const std::vector<std::vector<PathPoint>>& to_stop);

    KernelId k_;
    const Obstacles& obstacles_;
    std::span<const double> masses_;
    std::span<BallFrame> balls_;
    std::vector<MeetRecord>& meets_;
    StepScratch& scratch_;
    std::size_t n_;
    // Kept between frames (MeetFrameScratch), made afresh for this one:
    std::vector<double>& seg_t_;                     // the frame time each ball's current path starts at
    std::vector<Vec2>& seg_vel_;                     // the velocity it starts with (once restarted: version_ > 0)
    std::vector<std::uint32_t>& version_;            // bumped when its path changes
    std::vector<std::vector<PathPoint>>& committed_;  // its path's points before the current path
    std::vector<std::vector<HitEvent>>& done_;       // its contacts before the current path, meets included
    std::vector<Box>& box_;
    std::vector<Box>& reach_;  // once its path changed (version_ > 0): the box around every path it had in the frame
    meet::BoxGrid& grid_;
    std::vector<std::uint32_t>& seen_;  // the stamp of the last query near() made that listed the ball
    std::uint32_t stamp_ = 0;
    struct NearList {
        std::uint32_t ball = 0xffffffffu;  // none
        std::uint64_t paths = 0;           // paths_ when it was made
        std::vector<std::uint32_t> balls;
    };
    NearList near_[2];
    int near_next_ = 0;       // the list near() replaces next (the one not asked about last)
    std::uint64_t paths_ = 0;  // how many times a path changed in this frame
    std::vector<Candidate>& pool_;
    std::vector<std::uint32_t>& free_;
    std::vector<MeetKey>& heap_;
    std::vector<PathPoint>&cut_a_, &cut_b_;  // the paths to a meet's centres (too_close)
    std::vector<PathPoint>&full_a_, &full_b_, &full_k_;  // printed paths with their committed points
    double last_t_ = 0.0;                   // the time of the last meet taken
    std::vector<double> tried_;             // the times a meet's walk back tried before the floor
    // Meets at one exact time (rule 3): each group of them is numbered; the first one's floor is every untied one's,
    // and a ball a meet of the group moved is kept as it was (before_) for the others' placements.
    std::vector<MeetSnapshot>& before_;
    std::vector<std::uint32_t>& touched_;  // the balls cut in this frame, each once (their kept lists are filled)
    std::uint64_t group_ = 0;               // the group of the meet being taken (0: alone at its time)
    std::uint64_t groups_ = 0;              // groups numbered so far in this frame
    std::optional<meet::Root> group_root_;  // the exact time of the last group
    double group_floor_ = 0.0;              // the floor of its meets: last_t_ when it began
    bool group_moved_ = false;              // a meet of the group was taken, so snapshots exist
    bool see_before_ = true;                // the placement sees moved third balls as they were
    std::uint32_t taking_a_ = 0, taking_b_ = 0;  // the pair being taken
    bool taking_tied_ = false;                   // and whether it is tied
};

}  // namespace ricochet
