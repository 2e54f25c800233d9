// Disc and bumper properties: R = 0 is the point ball bit for bit; whole runs are symmetric under mirrors, quarter
// turns and ball order; every check read for discs (oracle, boundary, bounce-side, symmetry, swap, translation)
// on discs starting exactly touching what they meet; no tunnelling, no escape and penetration within δ = 0 in closed polygons
// and through chains of walls; no ghost bounce at the joints of a straight chain; a disc meeting a bumper
// head-on comes straight back. Generators: generators_discs.hpp.
//
// A kernel that refuses discs or bumpers (UnsupportedScene, world.hpp) cannot be asked any of these but the first:
// each such test is skipped with the kernel's own refusal as its reason (GTEST_SKIP, which CTest reports as
// skipped), never passed having checked nothing.
#include <algorithm>
#include <map>

#include <fmt/format.h>

#include "generators.hpp"
#include "generators_discs.hpp"
#include "harness.hpp"
#include "ricochet/bits.hpp"
#include "ricochet/checks.hpp"
#include "ricochet/scene_log_format.hpp"
#include "ricochet/truth.hpp"

namespace ricochet::props {
namespace {

/// Why kernel k refuses a scene with a disc (and a bumper, if bumpers), or nothing if it steps one.
std::optional<std::string> disc_refusal(KernelId k, bool bumpers) {
    Scene probe;
    probe.walls = {{{0, 0}, {1, 0}}};
    probe.balls = {{{0.5, 1}, {0, -1}, 0.25}};
    if (bumpers) probe.bumpers = {{{3, 3}, 1}};
    probe.frames = 1;
    return refusal(probe, k);
}

/// Skips the current test, with the kernel's refusal as the reason, unless kernel k steps discs (and bumpers).
#define RICOCHET_SKIP_UNLESS_DISCS(k, bumpers)                                                                  \
    if (const auto why = disc_refusal((k), (bumpers)))                                                          \
    GTEST_SKIP() << fmt::format("this kernel refuses scenes with {}: {}", (bumpers) ? "discs and bumpers" : "discs", *why)

/// One run's events (states, hits, bumps) and whether it left the accepted range.
struct Run {
    std::vector<Event> events;
    bool error = false;
    std::uint64_t hash = 0;
};

Run run(const Scene& s, KernelId k) {
    // The world's default options, as checked() and replay step a scene (properties/harness.cpp).
    const CheckedRun r = run_checked(s, k, s.frames, {});
    return {r.events, r.error.has_value(), r.hash};
}

/// Each ball's events in order (hits, bumps and states; overlaps left out: these scenes have no sensors).
std::map<std::uint32_t, std::vector<Event>> by_ball(const std::vector<Event>& events) {
    std::map<std::uint32_t, std::vector<Event>> out;
    for (const Event& e : events)
        if (e.kind != Event::Kind::overlap) out[e.ball].push_back(e);
    return out;
}

std::string str(const Event& e) { return format_event(e); }

/// The same event, its numbers bit for bit.
bool same_event_bits(const Event& a, const Event& b) {
    return a.kind == b.kind && a.frame == b.frame && a.ball == b.ball && a.shape == b.shape && a.index == b.index &&
           ricochet::same_bits(a.pos, b.pos) && ricochet::same_bits(a.vel, b.vel);
}

/// Labels for the classification table: the radii drawn, bumpers, and discs that start within reach of a wall.
void disc_tags(const Scene& s) {
    for (const Ball& b : s.balls) {
        classify(!is_disc(b), "a point ball (R = 0)");
        classify(is_disc(b) && b.r < 0x1p-1022, "a subnormal radius");
        classify(is_disc(b) && b.r >= 0x1p-1022 && b.r < 0x1p-40, "a tiny radius (< 2^-40)");
        classify(b.r >= 0x1p30, "a huge radius (>= 2^30)");
        for (const Wall& w : s.walls) {
            // |b.pos − P0| ≤ R at an end point, a rough sign of a disc starting in reach (for the table only).
            const Vec2 d = b.pos - w.p0;
            classify(is_disc(b) && d.x * d.x + d.y * d.y <= b.r * b.r, "a disc starting within R of a wall's end");
        }
    }
    classify(!s.bumpers.empty(), "bumpers");
    classify(s.walls.empty(), "no walls");
}

// ---- R = 0 ----------------------------------------------------------------------------------------------

/// Point-ball scenes whose balls carry a radius of +0 or −0, as `ball X Y VX VY 0` and `… -0` write them.
rc::Gen<Scene> zero_radius_scene() {
    return rc::gen::apply(
        [](Scene s, const std::vector<int>& zeros) {
            for (std::size_t i = 0; i < s.balls.size(); ++i) s.balls[i].r = zeros[i % zeros.size()] == 0 ? 0.0 : -0.0;
            return s;
        },
        gen::moving_scene(6), rc::gen::container<std::vector<int>>(3, gen::upto(1)));
}

/// R = 0 is the point ball: the scene's log read back, and the scene with every radius dropped, step to the same
/// events and hash bit for bit; and, where the kernel steps discs, discs added after the point balls change none
/// of the point balls' events (discs among walls alone never touch how a point ball is stepped).
std::optional<Failure> radius_zero(KernelId k, const Scene& s) {
    if (has_discs_or_bumpers(s)) return std::nullopt;  // the statement is about point balls
    Scene bare = s;
    for (Ball& b : bare.balls) b.r = 0.0;
    auto parsed = parse_scene_log(write_scene_log(s), "written");
    if (const auto* d = std::get_if<Diagnostic>(&parsed))
        return fail(Check::round_trip, fmt::format("the scene's log does not read back: {}", d->str()));
    const Scene& back = std::get<Scene>(parsed);
    const Run want = run(bare, k);
    for (const auto& [name, other] : {std::pair<const char*, const Scene*>{"the scene with radii ±0", &s},
                                      std::pair<const char*, const Scene*>{"its log read back", &back}}) {
        const Run got = run(*other, k);
        if (got.hash != want.hash || got.events.size() != want.events.size())
            return fail(Check::deterministic, fmt::format("{} hashes {:016x} ({} events), the point balls {:016x} ({} events)",
                                                          name, got.hash, got.events.size(), want.hash, want.events.size()));
    }
    if (disc_refusal(k, false)) return std::nullopt;
    // Discs after the point balls, one per point ball (its copy with radius 1/4 of its speed, or 1/4).
    Scene mixed = bare;
    for (const Ball& b : bare.balls) {
        const double speed = std::fmax(std::fabs(b.vel.x), std::fabs(b.vel.y));
        mixed.balls.push_back({b.pos, b.vel, speed > 0 && std::isfinite(speed / 4) && speed / 4 > 0 ? speed / 4 : 0.25});
    }
    tag("discs added after the point balls");
    const Run with_discs = run(mixed, k);
    if (want.error || with_discs.error) return std::nullopt;  // a run that stops early is not compared
    const auto a = by_ball(want.events), b = by_ball(with_discs.events);
    for (const auto& [ball, events] : a) {
        const auto it = b.find(ball);
        const std::size_t n = it == b.end() ? 0 : it->second.size();
        for (std::size_t i = 0; i < events.size(); ++i)
            if (i >= n || !same_event_bits(events[i], it->second[i]))
                return fail(Check::deterministic,
                            fmt::format("point ball {}'s event {} is `{}` alone but `{}` with discs in the scene", ball, i,
                                        str(events[i]), i < n ? str(it->second[i]) : std::string("missing")));
    }
    return std::nullopt;
}

// ---- symmetry -------------------------------------------------------------------------------------------

/// A map of the plane exact on doubles (negations and swaps of coordinates) or of the scene's order. (Walls walked
/// the other way keep only a disc's decisions, not its rounded contact points: the `swap` check, DiscEveryCheck.)
enum class Transform { mirror_x, mirror_y, turn, reverse_balls };
constexpr Transform k_transforms[] = {Transform::mirror_x, Transform::mirror_y, Transform::turn, Transform::reverse_balls};

const char* name(Transform t) {
    switch (t) {
        case Transform::mirror_x: return "mirrored in x";
        case Transform::mirror_y: return "mirrored in y";
        case Transform::turn: return "turned 90 degrees";
        default: return "with its balls in reverse order";
    }
}

/// Where t takes a point (and a velocity: these maps are linear).
Vec2 map(Transform t, Vec2 p) {
    switch (t) {
        case Transform::mirror_x: return {-p.x, p.y};
        case Transform::mirror_y: return {p.x, -p.y};
        case Transform::turn: return {-p.y, p.x};
        default: return p;
    }
}

Scene transformed(const Scene& s, Transform t) {
    Scene out = s;
    for (Wall& w : out.walls) w = {map(t, w.p0), map(t, w.p1)};
    for (Ball& b : out.balls) b = {map(t, b.pos), map(t, b.vel), b.r};
    for (Bumper& u : out.bumpers) u.c = map(t, u.c);
    if (t == Transform::reverse_balls) std::reverse(out.balls.begin(), out.balls.end());
    return out;
}

/// Every transform gives the transformed run: ball i's events, mapped, are ball π(i)'s, compared by value
/// (−0 = +0, as the point balls' `symmetry` check compares). Decisions are exact and the constructions round the
/// same numbers up to sign and order, so this holds bit for bit but for the sign of zero.
std::optional<Failure> symmetric(KernelId k, const Scene& s) {
    disc_tags(s);
    const Run base = run(s, k);
    classify(std::any_of(base.events.begin(), base.events.end(), [](const Event& e) { return e.kind == Event::Kind::hit; }), "a hit");
    classify(std::any_of(base.events.begin(), base.events.end(), [](const Event& e) { return e.kind == Event::Kind::bump; }), "a bump");
    const auto want = by_ball(base.events);
    for (const Transform t : k_transforms) {
        const Run other = run(transformed(s, t), k);
        if (base.error || other.error) {
            if (base.error != other.error)
                return fail(Check::symmetry, fmt::format("{}, the run {} the accepted range, the scene's {}", name(t),
                                                         other.error ? "leaves" : "stays in", base.error ? "leaves it" : "does not"));
            continue;
        }
        const auto got = by_ball(other.events);
        const std::uint32_t n = std::uint32_t(s.balls.size());
        for (const auto& [ball, events] : want) {
            const std::uint32_t to = t == Transform::reverse_balls ? n - 1 - ball : ball;
            const auto it = got.find(to);
            const std::size_t m = it == got.end() ? 0 : it->second.size();
            for (std::size_t i = 0; i < std::max(events.size(), m); ++i) {
                Event e = i < events.size() ? events[i] : Event{};
                e.ball = to;
                e.pos = map(t, e.pos);
                e.vel = map(t, e.vel);
                const bool same = i < events.size() && i < m && e == it->second[i];
                if (!same)
                    return fail(Check::symmetry, fmt::format("{}: ball {}'s event {} should be `{}`, is `{}`", name(t), ball, i,
                                                             i < events.size() ? str(e) : std::string("none"),
                                                             i < m ? str(it->second[i]) : std::string("none")));
            }
        }
    }
    return std::nullopt;
}

// ---- no ghost bounce ------------------------------------------------------------------------------------

/// a − b, and whether it is exact (its rounding error, by TwoSum, is zero).
std::pair<double, bool> exact_difference(double a, double b) {
    const double s = a - b, bb = s - a;
    const double err = (a - (s - bb)) + (-b - bb);
    return {s, err == 0};
}

/// A disc sliding along an axis-aligned chain of collinear walls at exactly its radius, parallel to it, meets each
/// joint's caps tangentially: no hit, no bump, its velocity never changes and its distance to the chain's line
/// stays exactly R at every printed point. Balls not so placed (the precondition, decided exactly) are not judged.
std::optional<Failure> no_ghost_bounce(KernelId k, const Scene& s) {
    if (s.walls.empty() || !s.bumpers.empty()) return std::nullopt;
    // Axis-aligned and collinear: every end point on one horizontal (axis 1) or vertical (axis 0) line.
    const auto coord = [](Vec2 p, int axis) { return axis == 0 ? p.x : p.y; };
    int axis = -1;
    for (int a = 0; a < 2 && axis < 0; ++a) {
        const double line = coord(s.walls[0].p0, a);
        if (std::all_of(s.walls.begin(), s.walls.end(), [&](const Wall& w) { return coord(w.p0, a) == line && coord(w.p1, a) == line; }))
            axis = a;
    }
    if (axis < 0) return std::nullopt;
    const double line = coord(s.walls[0].p0, axis);
    std::vector<bool> sliding(s.balls.size());
    for (std::size_t i = 0; i < s.balls.size(); ++i) {
        const Ball& b = s.balls[i];
        const auto [d, exact] = exact_difference(coord(b.pos, axis), line);
        sliding[i] = is_disc(b) && coord(b.vel, axis) == 0 && exact && std::fabs(d) == b.r;
    }
    if (std::none_of(sliding.begin(), sliding.end(), [](bool x) { return x; })) return std::nullopt;
    tag("a disc sliding at its radius");
    const Run r = run(s, k);
    // Whether a sliding disc's path passes a joint (an end point's coordinate along the chain), for the table.
    for (const Event& e : r.events)
        if (e.kind == Event::Kind::state && sliding[e.ball]) {
            const double from = coord(s.balls[e.ball].pos, 1 - axis), to = coord(e.pos, 1 - axis);
            for (const Wall& w : s.walls)
                for (const Vec2 p : {w.p0, w.p1})
                    classify(std::fmin(from, to) <= coord(p, 1 - axis) && coord(p, 1 - axis) <= std::fmax(from, to),
                             "a sliding disc passes an end point");
        }
    for (const Event& e : r.events) {
        if (e.kind == Event::Kind::overlap || !sliding[e.ball]) continue;
        const Ball& b = s.balls[e.ball];
        if (e.kind == Event::Kind::hit || e.kind == Event::Kind::bump)
            return fail(Check::ghost_bounce, fmt::format("ghost bounce: ball {} (radius {}) sliding at its radius along the "
                                                         "chain hits at frame {}: `{}`", e.ball, b.r, e.frame, str(e)));
        if (coord(e.pos, axis) != coord(b.pos, axis) || !(e.vel == b.vel))
            return fail(Check::ghost_bounce, fmt::format("ball {} sliding at its radius {} along the chain left its line or "
                                                         "changed its velocity at frame {}: `{}`", e.ball, b.r, e.frame, str(e)));
    }
    return std::nullopt;
}

// ---- bumpers head-on ------------------------------------------------------------------------------------

/// One disc and one bumper, the disc moving along an axis straight at the bumper's centre (decided exactly):
/// every printed point stays on that line, and every velocity is +v or −v exactly (the normal at the contact is
/// along the axis, so the reflection is exact), and once it has bumped it moves away.
std::optional<Failure> head_on(KernelId k, const Scene& s) {
    if (s.balls.size() != 1 || s.bumpers.size() != 1 || !s.walls.empty()) return std::nullopt;
    const Ball& b = s.balls[0];
    const Bumper& u = s.bumpers[0];
    int axis = -1;  // the coordinate that moves
    if (b.vel.y == 0 && b.vel.x != 0 && b.pos.y == u.c.y) axis = 0;
    if (b.vel.x == 0 && b.vel.y != 0 && b.pos.x == u.c.x) axis = 1;
    if (axis < 0 || u.r <= 0) return std::nullopt;
    tag("head-on");
    const Run r = run(s, k);
    if (r.error) return std::nullopt;
    classify(std::any_of(r.events.begin(), r.events.end(), [](const Event& e) { return e.kind == Event::Kind::bump; }),
             "bumped");
    const Vec2 back{-b.vel.x, -b.vel.y};
    bool bumped = false;
    for (const Event& e : r.events) {
        const bool off_line = axis == 0 ? e.pos.y != b.pos.y : e.pos.x != b.pos.x;
        if (e.kind != Event::Kind::overlap && off_line)
            return fail(Check::speed, fmt::format("head-on: the disc left its line at frame {}: `{}`", e.frame, str(e)));
        if (e.kind == Event::Kind::hit)
            return fail(Check::speed, fmt::format("head-on: a hit without walls at frame {}: `{}`", e.frame, str(e)));
        bumped |= e.kind == Event::Kind::bump;
        if (e.kind == Event::Kind::state && !(e.vel == b.vel || e.vel == back))
            return fail(Check::speed, fmt::format("head-on: the velocity at frame {} is not ±v exactly: `{}`", e.frame, str(e)));
        if (e.kind == Event::Kind::state && bumped && !(e.vel == back))
            return fail(Check::speed, fmt::format("head-on: after the bump, frame {}'s velocity is not −v: `{}`", e.frame, str(e)));
    }
    return std::nullopt;
}

// ---- the suite ------------------------------------------------------------------------------------------

RICOCHET_PROPERTY_SUITE(Discs);

TEST_P(Discs, RadiusZeroIsThePointBall) {
    run_property({"RadiusZeroIsThePointBall", Check::deterministic, zero_radius_scene(), radius_zero, 1000}, GetParam());
}

/// Inside closed convex and concave polygons (with bumpers where the kernel steps them): the centre never leaves,
/// never crosses a wall, never comes closer than R to a wall (R + r to a bumper) it was clear of, and keeps its speed.
TEST_P(Discs, DiscNoEscapeClosedPolygon) {
    RICOCHET_SKIP_UNLESS_DISCS(GetParam(), false);
    const bool bumpers = !disc_refusal(GetParam(), true);
    run_property({"DiscNoEscapeClosedPolygon", Check::no_escape, gen::disc_polygon_scene(true, 16, bumpers),
                  checked({Check::no_escape, Check::no_tunnel, Check::penetration, Check::speed, Check::accuracy}, disc_tags), 1000},
                 GetParam());
}

/// Outside a closed polygon: never in, never through, never within R.
TEST_P(Discs, DiscNoEntryClosedPolygon) {
    RICOCHET_SKIP_UNLESS_DISCS(GetParam(), false);
    run_property({"DiscNoEntryClosedPolygon", Check::no_escape, gen::disc_polygon_scene(false, 16, false),
                  checked({Check::no_escape, Check::no_tunnel, Check::penetration, Check::speed, Check::accuracy}, disc_tags), 300},
                 GetParam());
}

/// Discs aimed at the joints of straight and bent chains of walls, from either side: never through, never within R.
TEST_P(Discs, DiscNoTunnelChains) {
    RICOCHET_SKIP_UNLESS_DISCS(GetParam(), false);
    run_property({"DiscNoTunnelChains", Check::no_tunnel, gen::chain_scene(8),
                  checked({Check::no_tunnel, Check::penetration, Check::speed, Check::accuracy}, disc_tags), 2000},
                 GetParam());
}

/// A disc sliding at its radius along a straight chain passes every joint: no hit, no bump, no change. Its own
/// oracle; what the run breaks is saved as the shared check `ghost-bounce`, which replay asserts.
TEST_P(Discs, DiscNoGhostBounce) {
    RICOCHET_SKIP_UNLESS_DISCS(GetParam(), false);
    run_property({"DiscNoGhostBounce", Check::ghost_bounce, gen::sliding_chain_scene(8), no_ghost_bounce, 2000}, GetParam());
}

/// Mirrors in x and y, quarter turns and the balls' order give the mapped run.
TEST_P(Discs, DiscSymmetry) {
    RICOCHET_SKIP_UNLESS_DISCS(GetParam(), false);
    run_property({"DiscSymmetry", Check::symmetry, gen::disc_scene(6, !disc_refusal(GetParam(), true)), symmetric, 600},
                 GetParam());
}

TEST_P(Discs, BumperSymmetry) {
    RICOCHET_SKIP_UNLESS_DISCS(GetParam(), true);
    run_property({"BumperSymmetry", Check::symmetry,
                  rc::gen::oneOf(gen::bumper_scene(6, false), gen::bumper_scene(6, true)), symmetric, 600},
                 GetParam());
}

TEST_P(Discs, BumperHeadOn) {
    RICOCHET_SKIP_UNLESS_DISCS(GetParam(), true);
    run_property({"BumperHeadOn", Check::speed, gen::bumper_scene(8, false, 1), head_on, 2000}, GetParam());
}

/// Bumpers among walls: no tunnelling, no penetration, the speed bound.
TEST_P(Discs, BumperNoTunnel) {
    RICOCHET_SKIP_UNLESS_DISCS(GetParam(), true);
    run_property({"BumperNoTunnel", Check::penetration, gen::bumper_scene(8, true),
                  checked({Check::no_escape, Check::no_tunnel, Check::penetration, Check::speed, Check::accuracy}, disc_tags), 1000},
                 GetParam());
}

/// The checks read for discs: every contact decision and first contact is the exact one (oracle), its time, point and
/// bounce within their bounds of the exact ones (accuracy); a scene mirrored,
/// turned, with its balls reversed or its walls walked the other way runs as the image of the run (symmetry, swap);
/// moved by an exact offset it meets the same obstacles first (translation); a disc that starts touching an
/// obstacle and moves closer meets it at once (boundary); a disc bounced off a face stays on its side until its
/// next contact (bounce-side). Discs starting exactly touching a wall's face, a cap or a bumper, and every disc
/// scene.
/// disc_tags, and how each ball starts against the obstacles: exactly touching one (decided exactly), moving closer,
/// along or away.
void touch_tags(const Scene& s) {
    disc_tags(s);
    for (const Ball& b : s.balls) {
        const double R = b.r > 0 ? b.r : 0.0;
        const Vec2 be = b.pos + b.vel;
        const auto approach = [](int sign) { return sign < 0 ? "closer" : sign == 0 ? "along or not at all" : "away"; };
        for (const Wall& w : s.walls)
            if (R > 0 && truth::wall_reach_side(b.pos, w, R) == 0)
                tag(fmt::format("a disc starting exactly touching a wall, moving {}",
                                approach(truth::wall_approach_sign(b.pos, be, w))));
        for (const Bumper& u : s.bumpers)
            if (truth::circle_reach_side(b.pos, u.c, R, u.r) == 0)
                tag(fmt::format("a ball starting exactly touching a bumper, moving {}",
                                approach(truth::circle_approach_sign(b.pos, be, u.c))));
    }
}

TEST_P(Discs, DiscEveryCheck) {
    RICOCHET_SKIP_UNLESS_DISCS(GetParam(), false);
    const bool bumpers = !disc_refusal(GetParam(), true);
    run_property({"DiscEveryCheck", Check::boundary,
                  rc::gen::weightedOneOf<Scene>({{2, gen::touching_scene(4)}, {1, gen::disc_scene(4, bumpers)}}),
                  [bumpers](KernelId k, const Scene& s) -> std::optional<Failure> {
                      if (!bumpers && !s.bumpers.empty()) return std::nullopt;  // a kernel of discs among walls
                      return checked({Check::oracle, Check::accuracy, Check::boundary, Check::bounce_side,
                                      Check::symmetry, Check::swap, Check::translation},
                                     touch_tags)(k, s);
                  },
                  400},
                 GetParam());
}

/// A disc's contact time and printed contact point within k_disc_accuracy_ulps of the exact contact, its bounce within
/// the speed bound of the exact reflection about the normal at the printed point, each leg the rest of the frame
/// (accuracy): discs among walls and bumpers, at every scale the generator draws.
TEST_P(Discs, DiscAccuracy) {
    RICOCHET_SKIP_UNLESS_DISCS(GetParam(), false);
    run_property({"DiscAccuracy", Check::accuracy, gen::disc_scene(6, !disc_refusal(GetParam(), true)),
                  checked({Check::accuracy}, disc_tags), 600},
                 GetParam());
}

/// The rest of what a disc log can name: the same bits twice, the event order, the log's round trip and the broad
/// phase's bits.
TEST_P(Discs, DiscDeterminism) {
    RICOCHET_SKIP_UNLESS_DISCS(GetParam(), false);
    run_property({"DiscDeterminism", Check::deterministic, gen::disc_scene(6, !disc_refusal(GetParam(), true)),
                  checked({Check::deterministic, Check::event_order, Check::round_trip, Check::broad_phase}, disc_tags), 600},
                 GetParam());
}

}  // namespace
}  // namespace ricochet::props
