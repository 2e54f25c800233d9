// The swept frame's search and its meets (swept_frame.hpp): every ball's path and the pairs whose boxes overlap
// through a grid, a heap of each pair's next meet in exact time order, and each meet taken (docs/scene-log.md, "Balls
// that meet", 3 to 6).
#include "kernels/meet/swept_frame.hpp"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "ricochet/limits.hpp"

namespace ricochet {

SweptFrame::SweptFrame(KernelId k, const Obstacles& obstacles, std::span<const double> masses,
                       std::span<BallFrame> balls, std::vector<MeetRecord>& meets, StepScratch& scratch,
                       MeetFrameScratch& kept)
    : k_(k), obstacles_(obstacles), masses_(masses), balls_(balls), meets_(meets), scratch_(scratch),
      n_(balls.size()), seg_t_(kept.seg_t), seg_vel_(kept.seg_vel), version_(kept.version),
      committed_(kept.committed), done_(kept.done), box_(kept.box), reach_(kept.reach), grid_(kept.grid),
      seen_(kept.seen), pool_(kept.pool), free_(kept.free), heap_(kept.heap), cut_a_(kept.cut_a), cut_b_(kept.cut_b),
      full_a_(kept.full_a), full_b_(kept.full_b), full_k_(kept.full_k), before_(kept.before), touched_(kept.touched) {
    seg_t_.assign(n_, 0.0);
    seg_vel_.resize(n_);
    version_.assign(n_, 0);
    // Only the balls the last frame cut have anything in the kept lists (finish left their old lists there).
    for (const std::uint32_t i : touched_) {
        if (i >= committed_.size()) continue;
        committed_[i].clear();
        done_[i].clear();
        before_[i].group = 0;
    }
    touched_.clear();
    committed_.resize(n_);
    done_.resize(n_);
    before_.resize(n_);
    box_.resize(n_);
    reach_.resize(n_);
    heap_.clear();
    pool_.clear();
    free_.clear();
}

const std::vector<std::uint32_t>& SweptFrame::near(std::uint32_t i) {
    for (int k = 0; k < 2; ++k)
        if (near_[k].ball == i && near_[k].paths == paths_) {
            near_next_ = 1 - k;
            return near_[k].balls;
        }
    NearList& l = near_[near_next_];
    near_next_ = 1 - near_next_;
    l.ball = i;
    l.paths = paths_;
    l.balls.clear();
    ++stamp_;
    seen_[i] = stamp_;
    grid_.query(box_[i], [&](std::uint32_t j) {
        if (seen_[j] == stamp_) return;
        seen_[j] = stamp_;
        l.balls.push_back(j);
    });
    return l.balls;
}

void SweptFrame::run() {
    // Each ball's path has storage of its own, where it was allocated: it is asked for a few balls ahead.
    constexpr std::size_t ahead = 8;
    for (std::size_t i = 0; i < n_; ++i) {
        if (i + ahead < n_) __builtin_prefetch(balls_[i + ahead].path.data(), 1);
        BallFrame& f = balls_[i];
        if (f.events.empty()) {
            // (most balls: a path of two points, written in place)
            f.path.resize(2);
            f.path[0] = {0.0, f.before.pos};
            f.path[1] = {1.0, f.state.pos};
            box_[i] = meet::segment_box(f.before.pos, f.state.pos, f.before.r);
        } else {
            meet::build_path(f.path, 0.0, f.before.pos, f.events, f.state.pos);
            box_[i] = meet::path_box(f.path, f.before.r);
        }
    }
    // Every pair whose boxes overlap, found through a grid of the boxes (the heap's order is total: the order
    // pairs are found in changes nothing).
    grid_.build(box_, [&](std::uint32_t i, std::uint32_t j) { consider(i, j); });
    seen_.assign(n_, 0);
    const std::size_t limit = static_cast<std::size_t>(k_max_meets_per_ball) * n_;
    std::size_t taken = 0;
    while (!heap_.empty()) {
        const Candidate c = pop();
        if (c.version_a != version_[c.a] || c.version_b != version_[c.b]) continue;  // a path it was found on changed
        if (taken == limit) {
            safe_stop(last_t_);
            break;
        }
        ++taken;
        // Meets at one exact time on several pairs are a group (rule 3): numbered, so that each one's placement sees
        // the balls the others moved as they were. A meet at another time ends the group.
        const SameTime now = same_time(c);
        if (group_ == 0 || meet::compare(c.root, *group_root_) != 0) {
            group_ = 0;
            group_root_.reset();
            group_moved_ = false;
            if (now.any) {
                group_ = ++groups_;
                group_root_ = c.root;
                group_floor_ = last_t_;
            }
        }
        take(c, now.shared, group_ != 0);
    }
    for (const std::uint32_t i : touched_) finish(i);
}

std::optional<meet::Root> SweptFrame::search(std::uint32_t a, std::uint32_t b, double from) const {
    const meet::Radii S{radius(a), radius(b)};
    if (!(S.rounded() > 0.0) || !meet::boxes_overlap(box_[a], box_[b])) return std::nullopt;
    from = std::max({from, seg_t_[a], seg_t_[b]});
    return meet::first_meet(balls_[a].path, balls_[b].path, S, from, balls_[a].state.vel, balls_[b].state.vel);
}

void SweptFrame::push(std::uint32_t a, std::uint32_t b, meet::Root root) {
    std::uint32_t slot;
    if (free_.empty()) {
        slot = static_cast<std::uint32_t>(pool_.size());
        pool_.emplace_back();
    } else {
        slot = free_.back();
        free_.pop_back();
    }
    heap_.push_back({root.estimate, slot});
    pool_[slot] = {a, b, version_[a], version_[b], std::move(root)};
    std::push_heap(heap_.begin(), heap_.end(), later());
}

SweptFrame::Candidate SweptFrame::pop() {
    std::pop_heap(heap_.begin(), heap_.end(), later());
    const std::uint32_t slot = heap_.back().slot;
    heap_.pop_back();
    free_.push_back(slot);
    return std::move(pool_[slot]);
}

double SweptFrame::next_printed(std::uint32_t a, std::uint32_t b, double t) const {
    return meet::next_point(balls_[a].path, balls_[b].path, t);
}

Vec2 SweptFrame::velocity_on(std::size_t i, std::size_t k) const {
    const BallFrame& f = balls_[i];
    if (k == 0) return version_[i] == 0 ? f.before.vel : seg_vel_[i];  // (a path not restarted starts the frame)
    if (k <= f.events.size()) return f.events[k - 1].out;
    return f.state.vel;
}

void SweptFrame::cut(std::size_t i, std::size_t k) {
    BallFrame& f = balls_[i];
    if (committed_[i].empty()) touched_.push_back(static_cast<std::uint32_t>(i));
    // Its start and contacts up to k; the path's end (k past the last contact: a meet at t = 1) is not printed,
    // the meet's point is.
    const std::size_t kept = std::min(k, f.events.size());
    done_[i].insert(done_[i].end(), f.events.begin(), f.events.begin() + static_cast<std::ptrdiff_t>(kept));
    committed_[i].insert(committed_[i].end(), f.path.begin(), f.path.begin() + static_cast<std::ptrdiff_t>(kept + 1));
}

void SweptFrame::restart(std::size_t i, double t, Vec2 x, Vec2 v) {
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
    meet::build_path(f.path, t, x, f.events, ball.pos);
    if (version_[i] == 0) reach_[i] = box_[i];
    box_[i] = meet::path_box(f.path, radius(i));
    reach_[i] = meet::enclosing(reach_[i], box_[i]);
    ++version_[i];
    ++paths_;
}

void SweptFrame::hold(std::size_t i, double t) {
    BallFrame& f = balls_[i];
    const Vec2 x = f.path.front().p;
    f.events.clear();
    if (f.status != FrameStatus::out_of_range) f.status = FrameStatus::ok;
    f.state = {x, seg_vel_[i], radius(i)};
    f.path = {{t, x}, {1.0, x}};
    box_[i] = meet::path_box(f.path, radius(i));
    reach_[i] = meet::enclosing(reach_[i], box_[i]);
    ++version_[i];
    ++paths_;
}

SweptFrame::SameTime SweptFrame::same_time(const Candidate& c) {
    SameTime out;
    std::vector<MeetKey> same;
    while (!heap_.empty()) {
        const Candidate& next = pool_[heap_.front().slot];
        const bool stale = next.version_a != version_[next.a] || next.version_b != version_[next.b];
        if (!stale && meet::compare(next.root, c.root) != 0) break;
        if (!stale) {
            out.shared = out.shared || next.a == c.a || next.a == c.b || next.b == c.a || next.b == c.b;
            out.any = true;
        }
        std::pop_heap(heap_.begin(), heap_.end(), later());
        // The entry just looked at is at the back now.
        if (stale) free_.push_back(heap_.back().slot);
        else same.push_back(heap_.back());
        heap_.pop_back();
    }
    for (const MeetKey& x : same) {
        heap_.push_back(x);
        std::push_heap(heap_.begin(), heap_.end(), later());
    }
    return out;
}

void SweptFrame::take(const Candidate& c, bool tied, bool grouped) {
    const std::uint32_t a = c.a, b = c.b;
    const meet::Radii S{radius(a), radius(b)};
    const double lo = std::max(seg_t_[a], seg_t_[b]);
    // Never before the meet taken last: the frame's meets keep their time order as printed too (the pair's
    // other meets with balls met since are searched from there on). The meets of a group share one floor, the
    // first one's, so that none's walk back depends on which of them came first.
    const double floor = std::max(lo, grouped && !tied ? group_floor_ : last_t_);
    taking_a_ = a;
    taking_b_ = b;
    taking_tied_ = tied;
    double t = 0.0;
    meet::PointOnPath pa, pb;
    see_before_ = true;
    place_meet(c, S, lo, floor, t, pa, pb);
    // Placed against the balls the group's earlier meets moved as they were; where the centres do not stand as well
    // against those balls as they are, placed against them as they are: then the group's order decides (a tie).
    if (grouped && group_moved_ && !tied && !stands_as_they_are(a, b, S, lo, t, pa, pb)) {
        see_before_ = false;
        place_meet(c, S, lo, floor, t, pa, pb);
        see_before_ = true;
        tied = true;
    }
    if (grouped) {
        // The two balls as they were, for the group's later meets.
        for (const std::uint32_t i : {a, b})
            before_[i] = {group_, a, b, seg_t_[i], committed_[i], balls_[i].path};
        group_moved_ = true;
    }
    Ball ba{pa.x, velocity_on(a, pa.from), radius(a)}, bb{pb.x, velocity_on(b, pb.from), radius(b)};
    last_t_ = std::max(last_t_, t);
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
    // Made afresh once the entries made since outnumber twice the balls (each meet leaves its balls' old ones behind,
    // stale, for every query to pass over).
    if (grid_.inserted() > 2 * n_) grid_.build(box_);
    ++paths_;  // (the grid lists them where they go now)
    if (again) push(a, b, std::move(*again));
    neighbours(a, [&](std::uint32_t k) {
        if (k != b) consider(std::min(a, k), std::max(a, k));
    });
    neighbours(b, [&](std::uint32_t k) {
        if (k != a) consider(std::min(b, k), std::max(b, k));
    });
}

void SweptFrame::finish(std::size_t i) {
    BallFrame& f = balls_[i];
    if (done_[i].empty() && committed_[i].empty()) return;
    done_[i].insert(done_[i].end(), f.events.begin(), f.events.end());
    f.events.swap(done_[i]);  // (the old lists stay behind, their storage for the next frame)
    committed_[i].insert(committed_[i].end(), f.path.begin(), f.path.end());
    f.path.swap(committed_[i]);
}

}  // namespace ricochet
