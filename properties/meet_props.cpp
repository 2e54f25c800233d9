// Balls that meet (`balls collide`, docs/scene-log.md "Balls that meet"): the swept rule of robust and exact judged
// directly on World::meets(), World::path(i) and the balls' states, every comparison exact in rationals (GMP's mpq):
// equal masses head-on exchange their velocities; every meet's response is the elastic collision along the line of the
// printed centres and keeps momentum and energy; a Newton's cradle passes its momentum down the line; a break shot and
// random meeting scenes never leave two balls closer than R_i + R_j, at a frame's end, at a meet or between printed
// points; simultaneous meets give the same bits on every run; a mirrored scene gives the mirrored run and a relabelled
// one the same physics; two paths that only touch do not meet; of meets tied at one exact time the lowest pair goes
// first (`oracle`); and where robust and exact meet fast crossing balls, the lecture kernels let them through.
// Generators: generators_meets.hpp.
//
// The statements are judged here, not by run_checked's ball-overlap, pass-through, momentum and relabel, which the
// harness defines for meets separately; each statement names the check a failure of it breaks, so that its log is
// saved under that check. MeetChecks asks a meet scene every check the harness reads meets with (meet_checks()).
//
// A kernel that steps no meets (a peer, a plug-in) refuses these scenes; the lecture kernels step them by the static
// test at the frame's end, whose weakness LecturePassesThrough states. Both are skipped here with the reason.
#include <gmpxx.h>

#include <algorithm>
#include <utility>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "generators_meets.hpp"
#include "harness.hpp"
#include "ricochet/bits.hpp"
#include "ricochet/checks.hpp"
#include "ricochet/world.hpp"

namespace ricochet::props::meets {
namespace {

/// Why kernel k is not asked these properties, or nothing if it steps meets by the swept rule.
std::optional<std::string> not_swept(KernelId k) {
    switch (kernel_ops(k).meet_rule) {
        case MeetRule::swept: return std::nullopt;
        case MeetRule::end_of_frame:
            return std::string(
                "this kernel steps balls that meet by the lecture's static test at the frame's end "
                "(LecturePassesThrough states where that fails); these properties are the swept rule's");
        case MeetRule::none: break;
    }
    return std::string("this kernel does not step balls that meet ('balls collide')");
}

#define RICOCHET_SKIP_UNLESS_SWEPT(k)                                                                                  \
    if (const auto why = not_swept(k)) GTEST_SKIP() << *why

/// The checks asked of a meet scene (MeetChecks): every check, each of which reads meets (checks.hpp).
std::vector<Check> meet_checks() { return {k_all_checks.begin(), k_all_checks.end()}; }

// ---- exact numbers ----------------------------------------------------------------------------------------

/// x exactly.
mpq_class q(double x) { return mpq_class(x); }
/// |a − b|², exactly.
mpq_class dist2(Vec2 a, Vec2 b) {
    const mpq_class dx = q(a.x) - q(b.x), dy = q(a.y) - q(b.y);
    return dx * dx + dy * dy;
}
/// (R_a + R_b)², the sum not rounded.
mpq_class reach2(double ra, double rb) {
    const mpq_class s = q(ra) + q(rb);
    return s * s;
}
/// |x|.
mpq_class qabs(const mpq_class& x) { return x < 0 ? mpq_class(-x) : x; }
/// |v|∞, exactly.
mpq_class norm_inf(Vec2 v) { return std::max(qabs(q(v.x)), qabs(q(v.y))); }

/// The double nearest x (ties to even): mpq's get_d truncates, so the neighbour away from zero is compared too.
double nearest(const mpq_class& x) {
    if (sgn(x) == 0) return 0.0;
    const double d = x.get_d();
    const double e = std::nextafter(d, sgn(x) > 0 ? INFINITY : -INFINITY);
    if (!std::isfinite(e)) return d;
    const mpq_class ed = qabs(x - q(d)), ee = qabs(x - q(e));
    if (ed != ee) return ed < ee ? d : e;
    // A tie: the one with an even last bit.
    return (bits_of(d) & 1) == 0 ? d : e;
}

/// x to about 17 digits, for messages.
std::string qstr(const mpq_class& x) { return fmt::format("{:.17g}", x.get_d()); }

// ---- a run, frame by frame --------------------------------------------------------------------------------

/// One frame: its events, the meets the World took, the balls' paths (World::path) and their states at its end.
struct FrameRun {
    std::vector<Event> events;
    std::vector<MeetRecord> meets;
    std::vector<std::vector<PathPoint>> paths;
    std::vector<Ball> balls;
};

/// Frames 0..frames (frame 0: the initial states), up to the frame a ball left the accepted range (then error).
struct MeetRun {
    std::vector<FrameRun> frames;
    bool error = false;
};

MeetRun run_meets(const Scene& s, KernelId k, WorldOptions options = {}) {
    MeetRun run;
    World w(s, k, options);
    FrameRun first;
    w.start(first.events);
    first.balls.assign(w.balls().begin(), w.balls().end());
    run.frames.push_back(std::move(first));
    for (std::int64_t f = 1; f <= s.frames; ++f) {
        FrameRun fr;
        const auto error = w.step(fr.events);
        fr.meets.assign(w.meets().begin(), w.meets().end());
        for (std::size_t i = 0; i < s.balls.size(); ++i) fr.paths.emplace_back(w.path(i).begin(), w.path(i).end());
        fr.balls.assign(w.balls().begin(), w.balls().end());
        run.frames.push_back(std::move(fr));
        if (error) {
            run.error = true;
            break;
        }
    }
    classify(run.error, "a ball left the accepted range");
    return run;
}

/// Labels for the classification table: how many meets, at one time, with unequal masses, in a box.
void meet_tags(const Scene& s, const MeetRun& r) {
    std::size_t meets = 0;
    bool shared = false, unequal = false, fast = false;
    for (const FrameRun& f : r.frames) {
        meets += f.meets.size();
        for (std::size_t i = 0; i < f.meets.size(); ++i) {
            const MeetRecord& m = f.meets[i];
            unequal |= mass_of(s, m.a) != mass_of(s, m.b);
            for (std::size_t j = i + 1; j < f.meets.size(); ++j) {
                const MeetRecord& n = f.meets[j];
                shared |= n.t == m.t && (n.a == m.a || n.a == m.b || n.b == m.a || n.b == m.b);
            }
        }
        // Closing faster than R_a + R_b a frame: a meet the lecture's test at the frame's end could miss.
        for (const MeetRecord& m : f.meets) {
            const Vec2 w = m.vel_a - m.vel_b;
            fast |= std::fmax(std::fabs(w.x), std::fabs(w.y)) > s.balls[m.a].r + s.balls[m.b].r;
        }
    }
    classify(meets == 0, "no meet");
    classify(meets > 0 && meets < 4, "1-3 meets");
    classify(meets >= 4, "4 or more meets");
    classify(shared, "two meets at one time sharing a ball");
    classify(unequal, "a meet of unequal masses");
    classify(fast, "a meet of balls closing faster than R_a + R_b a frame");
    classify(!s.walls.empty(), "walls");
}

// ---- the response -----------------------------------------------------------------------------------------

/// The elastic response at a meet, exactly: with n = X_a − X_b (the printed centres) and w = v_a − v_b, u = w·n/(n·n),
/// v_a′ = v_a − 2·m_b/(m_a + m_b)·u·n and v_b′ = v_b + 2·m_a/(m_a + m_b)·u·n where they approach (w·n < 0); else
/// none (the velocities stay).
struct ExactResponse {
    bool approach = false;
    mpq_class ax, ay, bx, by;
};

ExactResponse exact_response(const MeetRecord& m, double ma, double mb) {
    const mpq_class nx = q(m.pos_a.x) - q(m.pos_b.x), ny = q(m.pos_a.y) - q(m.pos_b.y);
    const mpq_class wx = q(m.vel_a.x) - q(m.vel_b.x), wy = q(m.vel_a.y) - q(m.vel_b.y);
    const mpq_class wn = wx * nx + wy * ny;
    ExactResponse r{wn < 0, q(m.vel_a.x), q(m.vel_a.y), q(m.vel_b.x), q(m.vel_b.y)};
    if (!r.approach) return r;
    const mpq_class k = mpq_class(2) * wn / ((nx * nx + ny * ny) * (q(ma) + q(mb)));
    r.ax -= k * q(mb) * nx;
    r.ay -= k * q(mb) * ny;
    r.bx += k * q(ma) * nx;
    r.by += k * q(ma) * ny;
    return r;
}

/// How far robust's response in doubles may be from the exact one, per component: |v′ − v′_exact| ≤
/// k_response_ulps·ε·(|v_a|∞ + |v_b|∞) + 2^−1070. Its u = (w·n)/(n·n) and v′ = v − (2·m_b/M)·u·n round a dozen
/// times on terms no larger than 2·|w| ≤ 2√2·(|v_a|∞ + |v_b|∞) (|u·n| ≤ |w|, 2·m_b/M ≤ 2): about 30·ε of that sum;
/// 64 leaves a factor of 2. The exact kernel rounds the exact values once: it must give the nearest doubles.
constexpr double k_response_ulps = 64.0;

/// Whether a meet's printed velocities are its response: for the exact kernel the nearest doubles of the exact
/// response, for another the exact response within the bound above; where the centres do not approach, the
/// velocities unchanged and `responded` false.
std::optional<std::string> response_kept(KernelId k, const MeetRecord& m, double ma, double mb) {
    const ExactResponse e = exact_response(m, ma, mb);
    if (!e.approach) {
        if (m.responded || !(m.out_a == m.vel_a) || !(m.out_b == m.vel_b))
            return fmt::format(
                "balls {} and {} at t = {} do not approach at their printed centres {} and {}, yet leave "
                "with {} and {} (arriving with {} and {})",
                m.a, m.b, m.t, str(m.pos_a), str(m.pos_b), str(m.out_a), str(m.out_b), str(m.vel_a), str(m.vel_b));
        return std::nullopt;
    }
    if (!m.responded)
        return fmt::format(
            "balls {} and {} at t = {} approach at their printed centres {} and {} but no response was "
            "made",
            m.a, m.b, m.t, str(m.pos_a), str(m.pos_b));
    const double got[4] = {m.out_a.x, m.out_a.y, m.out_b.x, m.out_b.y};
    const mpq_class* want[4] = {&e.ax, &e.ay, &e.bx, &e.by};
    const mpq_class bound = q(k_response_ulps) * q(0x1p-53) * (norm_inf(m.vel_a) + norm_inf(m.vel_b)) + q(0x1p-1070);
    for (int c = 0; c < 4; ++c) {
        const bool ok = k == KernelId::exact ? got[c] == nearest(*want[c]) : qabs(q(got[c]) - *want[c]) <= bound;
        if (!ok)
            return fmt::format(
                "balls {} and {} at t = {} (centres {} and {}, arriving {} and {}, masses {} and {}): "
                "ball {} leaves with {}, the elastic response is ({}, {}) for ball {} and ({}, {}) for "
                "ball {}{}",
                m.a, m.b, m.t, str(m.pos_a), str(m.pos_b), str(m.vel_a), str(m.vel_b), ma, mb, c < 2 ? m.a : m.b,
                str(c < 2 ? m.out_a : m.out_b), qstr(e.ax), qstr(e.ay), m.a, qstr(e.bx), qstr(e.by), m.b,
                k == KernelId::exact ? " (exact: the nearest doubles)" : " (beyond the bound)");
    }
    return std::nullopt;
}

/// The `momentum` check's statement on one meet (checks.hpp): each component of m_a·v_a′ + m_b·v_b′ − (m_a·v_a +
/// m_b·v_b) at most 2^−40 of m_a·|v_a|∞ + m_b·|v_b|∞ + m_a·|v_a′|∞ + m_b·|v_b′|∞, and (1 − 2^−40)·E ≤ E′ ≤
/// (1 + 2^−40)·E for E = m_a·|v_a|² + m_b·|v_b|²; exactly.
std::optional<std::string> conserved(const MeetRecord& m, double ma, double mb) {
    const mpq_class Ma = q(ma), Mb = q(mb), rel = q(0x1p-40);
    const mpq_class scale =
        Ma * norm_inf(m.vel_a) + Mb * norm_inf(m.vel_b) + Ma * norm_inf(m.out_a) + Mb * norm_inf(m.out_b);
    const mpq_class dpx = Ma * q(m.out_a.x) + Mb * q(m.out_b.x) - Ma * q(m.vel_a.x) - Mb * q(m.vel_b.x);
    const mpq_class dpy = Ma * q(m.out_a.y) + Mb * q(m.out_b.y) - Ma * q(m.vel_a.y) - Mb * q(m.vel_b.y);
    if (qabs(dpx) > rel * scale || qabs(dpy) > rel * scale)
        return fmt::format(
            "balls {} and {} at t = {} (masses {} and {}): momentum changes by ({}, {}), more than 2^-40 "
            "of {}",
            m.a, m.b, m.t, ma, mb, qstr(dpx), qstr(dpy), qstr(scale));
    const auto energy = [&](Vec2 va, Vec2 vb) -> mpq_class {
        return Ma * (q(va.x) * q(va.x) + q(va.y) * q(va.y)) + Mb * (q(vb.x) * q(vb.x) + q(vb.y) * q(vb.y));
    };
    const mpq_class E = energy(m.vel_a, m.vel_b), E1 = energy(m.out_a, m.out_b);
    if (E1 < (1 - rel) * E || E1 > (1 + rel) * E)
        return fmt::format("balls {} and {} at t = {} (masses {} and {}): the energy goes from {} to {}", m.a, m.b, m.t,
                           ma, mb, qstr(E), qstr(E1));
    return std::nullopt;
}

// ---- statements -------------------------------------------------------------------------------------------

/// Every meet with equal masses, whose printed centres lie on a line along an axis and whose arriving velocities run
/// along it: the balls exchange velocities, exactly under exact, within 16 ulps of the larger speed otherwise (robust
/// rounds u = w·n/(n·n) and u·n: a few roundings of |w| ≤ twice that).
std::optional<Failure> head_on(KernelId k, const Scene& s) {
    const MeetRun r = run_meets(s, k);
    meet_tags(s, r);
    for (std::size_t f = 1; f < r.frames.size(); ++f)
        for (const MeetRecord& m : r.frames[f].meets) {
            if (mass_of(s, m.a) != mass_of(s, m.b)) continue;
            const bool along_x = m.pos_a.y == m.pos_b.y && m.vel_a.y == 0 && m.vel_b.y == 0;
            const bool along_y = m.pos_a.x == m.pos_b.x && m.vel_a.x == 0 && m.vel_b.x == 0;
            if (!along_x && !along_y) continue;
            tag("a head-on meet of equal masses");
            const ExactResponse e = exact_response(m, mass_of(s, m.a), mass_of(s, m.b));
            if (!e.approach) continue;  // a chase that did not close: response_kept's (Glancing's) to judge
            const double tol = k == KernelId::exact
                                   ? 0.0
                                   : 16 * 0x1p-53 * std::fmax(norm_inf(m.vel_a).get_d(), norm_inf(m.vel_b).get_d());
            const auto near = [tol](Vec2 a, Vec2 b) {
                return std::fabs(a.x - b.x) <= tol && std::fabs(a.y - b.y) <= tol;
            };
            if (!near(m.out_a, m.vel_b) || !near(m.out_b, m.vel_a))
                return fail(
                    Check::momentum,
                    fmt::format("frame {}: balls {} and {} of equal masses meet head-on at t = {} arriving with "
                                "{} and {} and leave with {} and {}: not exchanged{}",
                                f, m.a, m.b, m.t, str(m.vel_a), str(m.vel_b), str(m.out_a), str(m.out_b),
                                tol > 0 ? fmt::format(" (within {})", tol) : std::string(" exactly")));
        }
    return std::nullopt;
}

/// Every meet's printed velocities are the elastic response along the line of its printed centres (response_kept).
std::optional<Failure> glancing(KernelId k, const Scene& s) {
    const MeetRun r = run_meets(s, k);
    meet_tags(s, r);
    for (std::size_t f = 1; f < r.frames.size(); ++f)
        for (const MeetRecord& m : r.frames[f].meets) {
            const bool head_on = (m.pos_a.x == m.pos_b.x || m.pos_a.y == m.pos_b.y);
            classify(!head_on, "a meet off the axes");
            if (const auto why = response_kept(k, m, mass_of(s, m.a), mass_of(s, m.b)))
                return fail(Check::momentum, fmt::format("frame {}: {}", f, *why));
        }
    return std::nullopt;
}

/// Every meet keeps momentum and energy (conserved).
std::optional<Failure> unequal_masses(KernelId k, const Scene& s) {
    const MeetRun r = run_meets(s, k);
    meet_tags(s, r);
    for (std::size_t f = 1; f < r.frames.size(); ++f)
        for (const MeetRecord& m : r.frames[f].meets)
            if (const auto why = conserved(m, mass_of(s, m.a), mass_of(s, m.b)))
                return fail(Check::momentum, fmt::format("frame {}: {}", f, *why));
    return std::nullopt;
}

/// A Newton's cradle, recognized exactly: no walls, every radius R > 0 and every mass one, balls 1..N−1 at rest,
/// touching in a row along an axis (each 2R past the one before), ball 0 behind ball 1 on that line moving along it
/// toward it at speed s, arriving (the gap g = |X_1 − X_0| − 2R ≥ 0) before the run's last frame ends: ⌊g/s⌋ + 1 ≤
/// frames. (One arriving at a frame's very end, t = 1, passes its momentum on at the next frame's start: the rest of
/// its frame has no duration, and pieces of none are left out of the meet search.) Then at the end
/// balls 0..N−2 are at rest, balls 1..N−2 where they started, and ball N−1 moves with ball 0's velocity: exactly under
/// exact, and under any kernel where every number is exact (R a power of two, g/s a multiple of 1/4); else within
/// 64·N ulps of s.
std::optional<Failure> cradle(KernelId k, const Scene& s) {
    const std::size_t n = s.balls.size();
    if (n < 2 || !s.walls.empty() || !s.bumpers.empty()) return std::nullopt;
    const double R = s.balls[0].r;
    const Vec2 v = s.balls[0].vel;
    if (!(R > 0)) return std::nullopt;
    for (std::size_t i = 0; i < n; ++i)
        if (s.balls[i].r != R || mass_of(s, i) != mass_of(s, 0) || (i > 0 && !(s.balls[i].vel == Vec2{})))
            return std::nullopt;
    // The row's axis: the coordinate that changes from ball 1 to ball 2 (or to ball 0).
    const Vec2 p0 = s.balls[0].pos, p1 = s.balls[1].pos;
    const int axis = p0.y == p1.y && v.y == 0 ? 0 : p0.x == p1.x && v.x == 0 ? 1 : -1;
    if (axis < 0) return std::nullopt;
    const auto along = [axis](Vec2 p) { return axis == 0 ? p.x : p.y; };
    const auto across = [axis](Vec2 p) { return axis == 0 ? p.y : p.x; };
    const int dir = along(v) > 0 ? 1 : along(v) < 0 ? -1 : 0;
    if (dir == 0) return std::nullopt;
    for (std::size_t i = 2; i < n; ++i)
        if (across(s.balls[i].pos) != across(p1) ||
            q(along(s.balls[i].pos)) - q(along(s.balls[i - 1].pos)) != dir * 2 * q(R))
            return std::nullopt;
    const mpq_class gap = dir * (q(along(p1)) - q(along(p0))) - 2 * q(R), speed = qabs(q(along(v)));
    if (gap < 0) return std::nullopt;
    // ⌊g/s⌋ + 1 ≤ frames.
    mpq_class arrival = gap / speed;
    arrival.canonicalize();
    const mpz_class whole = arrival.get_num() / arrival.get_den();
    if (whole + 1 > mpz_class(static_cast<long>(s.frames))) return std::nullopt;  // frames ≤ 10^7: a long anywhere
    tag(fmt::format("a cradle of {} balls", n));
    mpq_class quarters = arrival * 4;
    quarters.canonicalize();
    int e = 0;
    const bool exact_numbers = std::frexp(R, &e) == 0.5 && quarters.get_den() == 1;
    classify(exact_numbers, "every number exact");
    const MeetRun r = run_meets(s, k);
    meet_tags(s, r);
    if (r.error) return std::nullopt;
    const std::vector<Ball>& end = r.frames.back().balls;
    const double tol = k == KernelId::exact || exact_numbers ? 0.0 : 64.0 * double(n) * 0x1p-53 * std::fabs(along(v));
    const auto near = [tol](Vec2 a, Vec2 b) { return std::fabs(a.x - b.x) <= tol && std::fabs(a.y - b.y) <= tol; };
    for (std::size_t i = 0; i + 1 < n; ++i) {
        if (!near(end[i].vel, {}))
            return fail(Check::momentum,
                        fmt::format("a cradle of {} balls: ball {} ends moving at {}, not at rest{}", n, i,
                                    str(end[i].vel), tol > 0 ? fmt::format(" (within {})", tol) : ""));
        if (i > 0 && tol == 0 && !(end[i].pos == s.balls[i].pos))
            return fail(Check::momentum,
                        fmt::format("a cradle of {} balls: ball {} ends at {}, not where it started, {}", n, i,
                                    str(end[i].pos), str(s.balls[i].pos)));
    }
    if (!near(end[n - 1].vel, v))
        return fail(Check::momentum,
                    fmt::format("a cradle of {} balls: the last ends moving at {}, not with the first's "
                                "velocity {}",
                                n, str(end[n - 1].vel), str(v)));
    return std::nullopt;
}

/// The `ball-overlap` statement (checks.hpp), judged exactly: for each pair with S = R_i + R_j > 0, once it has been
/// at least S apart at a common printed time (the frame's end states, frame 0 the initial ones, or the two centres of
/// one of its meets), it is at no later one closer than S.
std::optional<Failure> no_overlap(KernelId k, const Scene& s) {
    const MeetRun r = run_meets(s, k);
    meet_tags(s, r);
    const std::size_t n = s.balls.size();
    std::vector<std::vector<bool>> clear(n, std::vector<bool>(n, false));
    const auto judge = [&](std::size_t a, std::size_t b, Vec2 pa, Vec2 pb, std::size_t f,
                           const char* when) -> std::optional<Failure> {
        const double ra = s.balls[a].r, rb = s.balls[b].r;
        if (!(ra + rb > 0)) return std::nullopt;
        const bool closer = dist2(pa, pb) < reach2(ra, rb);
        if (closer && clear[a][b])
            return fail(Check::ball_overlap,
                        fmt::format("frame {}: balls {} and {} are closer than R_a + R_b = {} + {} {}: at {} and {}", f,
                                    a, b, ra, rb, when, str(pa), str(pb)));
        if (!closer) clear[a][b] = true;
        return std::nullopt;
    };
    for (std::size_t f = 0; f < r.frames.size(); ++f) {
        for (const MeetRecord& m : r.frames[f].meets)
            if (auto bad = judge(m.a, m.b, m.pos_a, m.pos_b, f, "at their meet")) return bad;
        for (std::size_t a = 0; a < n; ++a)
            for (std::size_t b = a + 1; b < n; ++b)
                if (auto bad = judge(a, b, r.frames[f].balls[a].pos, r.frames[f].balls[b].pos, f, "at the frame's end"))
                    return bad;
    }
    return std::nullopt;
}

/// The centre of a path at frame time t (t within it): the point of the last piece starting at or before t,
/// p_k + (p_{k+1} − p_k)·(t − t_k)/(t_{k+1} − t_k), exactly; and that piece's velocity (its displacement per unit of
/// frame time; zero past the last point).
struct PathAt {
    mpq_class x, y, vx, vy;
};

PathAt path_at(std::span<const PathPoint> path, const mpq_class& t) {
    std::size_t k = 0;
    while (k + 1 < path.size() && q(path[k + 1].t) <= t) ++k;
    PathAt at{q(path[k].p.x), q(path[k].p.y), 0, 0};
    if (k + 1 < path.size() && path[k + 1].t > path[k].t) {
        const mpq_class dt = q(path[k + 1].t) - q(path[k].t);
        at.vx = (q(path[k + 1].p.x) - q(path[k].p.x)) / dt;
        at.vy = (q(path[k + 1].p.y) - q(path[k].p.y)) / dt;
        const mpq_class u = t - q(path[k].t);
        at.x += at.vx * u;
        at.y += at.vy * u;
    }
    return at;
}

/// The `pass-through` statement (checks.hpp), judged exactly on World::path: for each frame and each pair with S > 0,
/// over each common time interval [lo, hi] of a piece of each path, a pair at least S apart at lo stays so: with
/// D(lo + u) = D + W·u, |D + W·u|² ≥ S² for u in [0, hi − lo], its least at u* = −D·W/(W·W) clamped to the interval.
std::optional<Failure> no_pass_through(KernelId k, const Scene& s) {
    const MeetRun r = run_meets(s, k);
    meet_tags(s, r);
    const std::size_t n = s.balls.size();
    for (std::size_t f = 1; f < r.frames.size(); ++f) {
        const auto& paths = r.frames[f].paths;
        for (std::size_t a = 0; a < n; ++a)
            for (std::size_t b = a + 1; b < n; ++b) {
                const double ra = s.balls[a].r, rb = s.balls[b].r;
                if (!(ra + rb > 0)) continue;
                const mpq_class S2 = reach2(ra, rb);
                // The common breakpoints, in order.
                std::vector<double> ts;
                for (const PathPoint& p : paths[a]) ts.push_back(p.t);
                for (const PathPoint& p : paths[b]) ts.push_back(p.t);
                std::sort(ts.begin(), ts.end());
                ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
                for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
                    const mpq_class lo = q(ts[i]), h = q(ts[i + 1]) - lo;
                    const PathAt pa = path_at(paths[a], lo), pb = path_at(paths[b], lo);
                    const mpq_class dx = pa.x - pb.x, dy = pa.y - pb.y, wx = pa.vx - pb.vx, wy = pa.vy - pb.vy;
                    if (dx * dx + dy * dy < S2) continue;  // closer at lo: ball-overlap's to judge
                    const mpq_class ww = wx * wx + wy * wy;
                    if (sgn(ww) == 0) continue;
                    mpq_class u = -(dx * wx + dy * wy) / ww;
                    if (u <= 0) continue;  // moving apart from lo on
                    if (u > h) u = h;
                    const mpq_class mx = dx + wx * u, my = dy + wy * u;
                    if (mx * mx + my * my < S2)
                        return fail(Check::pass_through,
                                    fmt::format("frame {}: balls {} and {} (R {} and {}) come closer than R_a + R_b "
                                                "between frame times {} and {}, at t = {}, without a meet",
                                                f, a, b, ra, rb, ts[i], ts[i + 1], qstr(lo + u)));
                }
            }
    }
    return std::nullopt;
}

/// e with x and vx negated (the mirror x ↦ −x).
Event mirrored(Event e) {
    e.pos.x = -e.pos.x;
    e.vel.x = -e.vel.x;
    return e;
}

/// The scene mirrored across x = 0 (mirror_x: walls keep their direction, masses go with their balls) prints the
/// mirrored events, compared by value (−0 = +0): every decision is exact and every construction rounds the mirrored
/// numbers.
std::optional<Failure> mirror(KernelId k, const Scene& s) {
    const MeetRun r = run_meets(s, k), m = run_meets(mirror_x(s), k);
    meet_tags(s, r);
    for (std::size_t f = 0; f < std::min(r.frames.size(), m.frames.size()); ++f) {
        const auto& a = r.frames[f].events;
        const auto& b = m.frames[f].events;
        for (std::size_t i = 0; i < std::max(a.size(), b.size()); ++i) {
            const bool same = i < a.size() && i < b.size() && mirrored(a[i]) == b[i];
            if (!same)
                return fail(Check::symmetry, fmt::format("mirrored in x, frame {}'s event {} should be `{}`, is `{}`",
                                                         f, i, i < a.size() ? format_event(mirrored(a[i])) : "none",
                                                         i < b.size() ? format_event(b[i]) : "none"));
        }
    }
    if (r.frames.size() != m.frames.size())
        return fail(Check::symmetry, fmt::format("mirrored in x, the run {} the accepted range, the scene's {}",
                                                 m.error ? "leaves" : "stays in", r.error ? "leaves it" : "does not"));
    return std::nullopt;
}

/// The first frame in which a ball of the run takes part in two meets, or past the run.
std::size_t first_shared_ball(const MeetRun& r) {
    for (std::size_t f = 0; f < r.frames.size(); ++f) {
        const auto& ms = r.frames[f].meets;
        for (std::size_t i = 0; i < ms.size(); ++i)
            for (std::size_t j = i + 1; j < ms.size(); ++j)
                if (ms[i].a == ms[j].a || ms[i].a == ms[j].b || ms[i].b == ms[j].a || ms[i].b == ms[j].b) return f;
    }
    return r.frames.size();
}

/// Relabelling: the scene with its balls and their masses in reverse order prints per ball the run's events, ball i as
/// ball N − 1 − i (a meet's other ball too), by value. Meets at the same exact time are taken pair by pair in index
/// order, so where a ball has two at one time the runs may part; and that tie cannot be read from the meets taken:
/// once the first is taken, the other pair is searched again on the new paths from the rounded, printed centres, and
/// meets a little later (3·10^−7 of a frame later in a break shot at 3·10^6 found here). So the frames are compared up
/// to the first in which, in either run, a ball takes part in two meets; from there on they are not. (The `relabel`
/// check's "two meets at the same rounded time" does not see that tie.)
std::optional<Failure> relabel(KernelId k, const Scene& s) {
    const std::size_t n = s.balls.size();
    Scene rev = s;
    std::reverse(rev.balls.begin(), rev.balls.end());
    std::reverse(rev.masses.begin(), rev.masses.end());
    const MeetRun r = run_meets(s, k), b = run_meets(rev, k);
    meet_tags(s, r);
    const std::size_t until = std::min({first_shared_ball(r), first_shared_ball(b), r.frames.size(), b.frames.size()});
    classify(until < r.frames.size(), "frames left uncompared: a ball in two meets of a frame");
    const auto other = [n](std::uint32_t i) { return static_cast<std::uint32_t>(n - 1 - i); };
    for (std::size_t f = 0; f < until; ++f) {
        // Each ball's events in order, by ball.
        std::vector<std::vector<Event>> want(n), got(n);
        for (Event e : r.frames[f].events) {
            if (e.kind == Event::Kind::overlap) continue;
            e.ball = other(e.ball);
            if (e.kind == Event::Kind::meet) e.index = other(e.index);
            want[e.ball].push_back(e);
        }
        for (const Event& e : b.frames[f].events)
            if (e.kind != Event::Kind::overlap) got[e.ball].push_back(e);
        for (std::size_t i = 0; i < n; ++i)
            if (want[i] != got[i]) {
                std::size_t j = 0;
                while (j < want[i].size() && j < got[i].size() && want[i][j] == got[i][j]) ++j;
                return fail(Check::relabel,
                            fmt::format("with the balls in reverse order, frame {}: ball {}'s event {} should be `{}` "
                                        "(ball {}'s), is `{}`",
                                        f, i, j, j < want[i].size() ? format_event(want[i][j]) : "none",
                                        other(std::uint32_t(i)), j < got[i].size() ? format_event(got[i][j]) : "none"));
            }
    }
    return std::nullopt;
}

/// Simultaneous meets are deterministic: the scene stepped twice, and with no broad phase on one thread against the
/// grid on two threads, prints the same events bit for bit.
std::optional<Failure> same_bits_twice(KernelId k, const Scene& s) {
    const MeetRun r = run_meets(s, k);
    meet_tags(s, r);
    const MeetRun again = run_meets(s, k), other = run_meets(s, k, {.broad_phase = BroadPhase::none, .threads = 1});
    const MeetRun two = run_meets(s, k, {.broad_phase = BroadPhase::grid, .threads = 2});
    using Named = std::pair<const char*, const MeetRun*>;
    for (const auto& [name, x] : {Named{"a second run", &again}, Named{"no broad phase on one thread", &other},
                                  Named{"the grid on two threads", &two}}) {
        if (x->frames.size() != r.frames.size())
            return fail(Check::deterministic,
                        fmt::format("{} runs {} frames, the run {}", name, x->frames.size() - 1, r.frames.size() - 1));
        for (std::size_t f = 0; f < r.frames.size(); ++f) {
            const auto& a = r.frames[f].events;
            const auto& b = x->frames[f].events;
            for (std::size_t i = 0; i < std::max(a.size(), b.size()); ++i)
                if (i >= a.size() || i >= b.size() || !same_bits(a[i], b[i]))
                    return fail(Check::deterministic,
                                fmt::format("{}, frame {}'s event {} is `{}`, the run's `{}`", name, f, i,
                                            i < b.size() ? format_event(b[i]) : "none",
                                            i < a.size() ? format_event(a[i]) : "none"));
        }
    }
    return std::nullopt;
}

/// Two balls whose straight paths through frame 1 cross within S of each other, S or more apart at both its ends
/// (decided exactly; the scene's only balls, no walls): the kernel under test meets them in frame 1, and the lecture
/// kernels, testing for an overlap at the frame's end only, let them through — they print what they print for the
/// scene without `balls collide`, no meet. The second half is the lecture's documented weakness: should it go away,
/// this property says so.
std::optional<Failure> lecture_passes_through(KernelId k, const Scene& s) {
    if (s.balls.size() != 2 || !s.walls.empty() || !s.bumpers.empty() || s.frames < 1) return std::nullopt;
    const Ball& a = s.balls[0];
    const Ball& b = s.balls[1];
    const double ra = a.r, rb = b.r;
    if (!(ra + rb > 0)) return std::nullopt;
    const mpq_class S2 = reach2(ra, rb);
    // D(t) = (B0 − A0) + (v_b − v_a)·t on [0, 1]; its least |D|² at t* = −D·W/(W·W).
    const mpq_class dx = q(b.pos.x) - q(a.pos.x), dy = q(b.pos.y) - q(a.pos.y);
    const mpq_class wx = q(b.vel.x) - q(a.vel.x), wy = q(b.vel.y) - q(a.vel.y), ww = wx * wx + wy * wy;
    if (sgn(ww) == 0) return std::nullopt;
    const mpq_class t = -(dx * wx + dy * wy) / ww;
    const auto d2 = [&](const mpq_class& u) -> mpq_class {
        return (dx + wx * u) * (dx + wx * u) + (dy + wy * u) * (dy + wy * u);
    };
    if (t <= 0 || t >= 1 || d2(0) < S2 || d2(1) < S2 || d2(t) >= S2) return std::nullopt;
    tag("a crossing within one frame");
    const MeetRun r = run_meets(s, k);
    if (r.error || r.frames.size() < 2) return std::nullopt;
    if (r.frames[1].meets.empty())
        return fail(Check::pass_through, fmt::format("balls 0 and 1 cross within R_a + R_b = {} + {} of each other in "
                                                     "frame 1 and do not meet",
                                                     ra, rb));
    Scene apart = s;
    apart.balls_collide = false;
    for (const KernelId lecture : {KernelId::lecture_double, KernelId::lecture_float}) {
        const MeetRun l = run_meets(s, lecture), alone = run_meets(apart, lecture);
        if (l.error || alone.error) continue;
        if (!l.frames[1].meets.empty() || l.frames[1].events != alone.frames[1].events)
            return fail(Check::pass_through,
                        fmt::format("{} met balls 0 and 1, which cross within frame 1 and are apart at its end: the "
                                    "weakness its static test is documented to have is gone",
                                    kernel_name(lecture)));
    }
    return std::nullopt;
}

/// Two balls alone whose straight paths through frame 1 only touch: the least |D + W·u|² over all u is S² exactly,
/// (D × W)² = S²·(W·W), W ≠ 0 (a double root, decided in rationals). A tangent is no meet (docs/scene-log.md "Balls
/// that meet", 2): frame 1 prints none. The same statement as `oracle`'s, which the saved log names.
std::optional<Failure> tangent_no_meet(KernelId k, const Scene& s) {
    if (s.balls.size() != 2 || !s.walls.empty() || !s.bumpers.empty() || s.frames < 1) return std::nullopt;
    const Ball& a = s.balls[0];
    const Ball& b = s.balls[1];
    if (!(a.r + b.r > 0)) return std::nullopt;
    const mpq_class dx = q(b.pos.x) - q(a.pos.x), dy = q(b.pos.y) - q(a.pos.y);
    const mpq_class wx = q(b.vel.x) - q(a.vel.x), wy = q(b.vel.y) - q(a.vel.y), ww = wx * wx + wy * wy;
    const mpq_class cross = dx * wy - dy * wx;
    if (sgn(ww) == 0 || cross * cross != reach2(a.r, b.r) * ww) return std::nullopt;
    // Where along the frame the paths touch: u = −D·W/(W·W).
    const mpq_class u = -(dx * wx + dy * wy) / ww;
    classify(u >= 0 && u <= 1, "a tangent within frame 1");
    const MeetRun r = run_meets(s, k);
    if (r.error || r.frames.size() < 2 || r.frames[1].meets.empty()) return std::nullopt;
    const MeetRecord& m = r.frames[1].meets.front();
    return fail(Check::oracle, fmt::format("balls 0 and 1, whose paths only touch (at u = {}), meet at t = {} in frame "
                                           "1: a tangent is no meet",
                                           qstr(u), m.t));
}

/// Every meeting scene the generators draw.
rc::Gen<Scene> any_meeting_scene() {
    return rc::gen::weightedOneOf<Scene>({{4, gen::meeting_scene(8, 6)},
                                          {1, gen::head_on_scene(6)},
                                          {1, gen::cradle_scene()},
                                          {1, gen::break_shot_scene(6)},
                                          {1, gen::converging_scene(4)},
                                          {1, gen::tangent_scene()}});
}

// ---- the suite --------------------------------------------------------------------------------------------

RICOCHET_PROPERTY_SUITE(Meets);

/// Two balls of equal masses meeting head-on along an axis (in the open or in a corridor) exchange velocities.
TEST_P(Meets, HeadOn) {
    RICOCHET_SKIP_UNLESS_SWEPT(GetParam());
    run_property({"HeadOn", Check::momentum, gen::head_on_scene(8), head_on, 300}, GetParam());
}

/// Off-centre and head-on meets of every mass: the response is the elastic collision along the line of the printed
/// centres (exact: the nearest doubles; robust: within 64 ulps of the speeds).
TEST_P(Meets, Glancing) {
    RICOCHET_SKIP_UNLESS_SWEPT(GetParam());
    run_property(
        {"Glancing", Check::momentum,
         rc::gen::weightedOneOf<Scene>({{3, gen::meeting_scene(8, 4)}, {1, gen::converging_scene(4)}}), glancing, 300},
        GetParam());
}

TEST_P(Meets, NewtonsCradle) {
    RICOCHET_SKIP_UNLESS_SWEPT(GetParam());
    run_property({"NewtonsCradle", Check::momentum, gen::cradle_scene(), cradle, 300}, GetParam());
}

/// A triangle rack broken by a cue ball in a box: no two balls closer than R_i + R_j at a frame's end or a meet.
TEST_P(Meets, BreakShot) {
    RICOCHET_SKIP_UNLESS_SWEPT(GetParam());
    run_property({"BreakShot", Check::ball_overlap, gen::break_shot_scene(8), no_overlap, 200}, GetParam());
}

/// Balls converging on one point at one time, the pairs at one angle meeting at the same exact time and sharing
/// balls: the same bits on every run, broad phase and thread count.
TEST_P(Meets, ThreeAtOnePoint) {
    RICOCHET_SKIP_UNLESS_SWEPT(GetParam());
    run_property({"ThreeAtOnePoint", Check::deterministic, gen::converging_scene(4), same_bits_twice, 150}, GetParam());
}

/// Meets of unequal masses (1/1000 to 1000): momentum and energy within 2^−40.
TEST_P(Meets, UnequalMasses) {
    RICOCHET_SKIP_UNLESS_SWEPT(GetParam());
    run_property({"UnequalMasses", Check::momentum,
                  rc::gen::weightedOneOf<Scene>(
                      {{3, gen::meeting_scene(8, 4)}, {1, gen::converging_scene(4)}, {1, gen::break_shot_scene(4)}}),
                  unequal_masses, 300},
                 GetParam());
}

/// Every meeting scene: no two balls closer than R_i + R_j at a frame's end or a meet, once apart.
TEST_P(Meets, NoOverlapRobust) {
    RICOCHET_SKIP_UNLESS_SWEPT(GetParam());
    run_property({"NoOverlapRobust", Check::ball_overlap, any_meeting_scene(), no_overlap, 400}, GetParam());
}

/// Every meeting scene: no two balls closer than R_i + R_j between printed points either (their paths).
TEST_P(Meets, NoPassThrough) {
    RICOCHET_SKIP_UNLESS_SWEPT(GetParam());
    run_property({"NoPassThrough", Check::pass_through, any_meeting_scene(), no_pass_through, 300}, GetParam());
}

TEST_P(Meets, Mirror) {
    RICOCHET_SKIP_UNLESS_SWEPT(GetParam());
    run_property({"Mirror", Check::symmetry, any_meeting_scene(), mirror, 200}, GetParam());
}

TEST_P(Meets, Relabel) {
    RICOCHET_SKIP_UNLESS_SWEPT(GetParam());
    run_property({"Relabel", Check::relabel, any_meeting_scene(), relabel, 200}, GetParam());
}

/// Fast balls crossing within a frame: met by the kernel under test, let through by lecture-float and lecture-double.
TEST_P(Meets, LecturePassesThrough) {
    RICOCHET_SKIP_UNLESS_SWEPT(GetParam());
    run_property({"LecturePassesThrough", Check::pass_through, gen::crossing_scene(), lecture_passes_through, 200},
                 GetParam());
}

/// Two paths that only touch, at every scale and offset: no meet (the tangent rule), and `oracle` holds.
TEST_P(Meets, Tangent) {
    RICOCHET_SKIP_UNLESS_SWEPT(GetParam());
    const Statement oracle = checked({Check::oracle});
    run_property({"Tangent", Check::oracle, gen::tangent_scene(),
                  [oracle](KernelId k, const Scene& s) {
                      if (auto bad = tangent_no_meet(k, s)) return bad;
                      return oracle(k, s);
                  },
                  150},
                 GetParam());
}

/// Two balls touching at the frame's start and moving nearly square to their line of centres, whether they approach
/// resting on the velocities' last bits: `oracle` (a meet at t = 0 exactly where they approach), `pass-through` and
/// `ball-overlap` hold.
TEST_P(Meets, Grazing) {
    RICOCHET_SKIP_UNLESS_SWEPT(GetParam());
    const Statement check = checked({Check::oracle, Check::pass_through, Check::ball_overlap});
    run_property({"Grazing", Check::oracle, gen::grazing_scene(),
                  [check](KernelId k, const Scene& s) {
                      const MeetRun r = run_meets(s, k);
                      classify(!r.error && r.frames.size() >= 2 && !r.frames[1].meets.empty(), "met at the start");
                      return check(k, s);
                  },
                  150},
                 GetParam());
}

/// Balls converging on one point, pairs sharing a ball meeting at the same exact time: `oracle` holds, so of tied
/// meets the lowest pair is taken first (rule 3), which ThreeAtOnePoint's same bits on every run cannot see.
TEST_P(Meets, LowestPairFirst) {
    RICOCHET_SKIP_UNLESS_SWEPT(GetParam());
    run_property({"LowestPairFirst", Check::oracle, gen::converging_scene(4), checked({Check::oracle}), 150}, GetParam());
}

/// Every meeting scene under the shared checker's checks for meets (meet_checks()).
TEST_P(Meets, MeetChecks) {
    RICOCHET_SKIP_UNLESS_SWEPT(GetParam());
    run_property({"MeetChecks", Check::deterministic, any_meeting_scene(), checked(meet_checks()), 150}, GetParam());
}

}  // namespace
}  // namespace ricochet::props::meets
