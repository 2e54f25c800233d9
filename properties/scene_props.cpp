// Scene-level properties: no tunnelling (single walls, wall soups, closed polygons from inside and
// outside), the side a ball leaves a wall on, the first hit of every frame against the exact answer,
// symmetry and translation of whole runs, determinism and the scene-log round trip.
#include <fmt/format.h>

#include <array>

#include "generators.hpp"
#include "harness.hpp"
#include "oracle.hpp"
#include "ricochet/hash.hpp"
#include "ricochet/parallel.hpp"
#include "ricochet/scene_log.hpp"
#include "ricochet/world.hpp"
#include "sweep_oracle.hpp"

namespace ricochet::props {
namespace {

/// Every event of the scene's run under k, or nothing if a ball left the accepted range (a documented
/// outcome that no property here is about).
std::optional<std::vector<Event>> run(const Scene& s, KernelId k, std::int64_t frames) {
    try {
        return run_scene(s, k, frames);
    } catch (const StepFailure&) {
        tag("a ball left the accepted range");
        return std::nullopt;
    }
}

/// Points of a ball's printed path, in order: hit points and end-of-frame states (frame 0 excluded).
bool on_path(const Event& e) { return e.kind == Event::Kind::hit || (e.kind == Event::Kind::state && e.frame > 0); }

void classify_run(const std::vector<Event>& events) {
    long hits = 0;
    for (const Event& e : events) hits += e.kind == Event::Kind::hit;
    classify(hits == 0, "no hit");
    classify(hits > 0 && hits < 8, "1-7 hits");
    classify(hits >= 8, "8 or more hits");
}

/// No tunnelling, exactly: the printed path of every ball, frame after frame, never goes through a wall
/// (kernel.hpp's definition, followed by PathOracle).
std::optional<Failure> no_tunnel(KernelId k, const Scene& s) {
    classify_legs(s);
    const auto events = run(s, k, s.frames);
    if (!events) return std::nullopt;
    classify_run(*events);
    PathOracle path(s.walls, s.balls);
    for (const Event& e : *events) {
        if (!on_path(e)) continue;
        if (const long w = path.advance(e.ball, e.pos); w >= 0)
            return fail(Check::no_tunnel, fmt::format("frame {}: ball {} tunnels through wall {} ({}) on its way to {}",
                                                      e.frame, e.ball, w, str(s.walls[std::size_t(w)]), str(e.pos)));
    }
    return std::nullopt;
}

/// Balls strictly inside (want = +1) or outside (want = −1) the region the walls enclose never reach the
/// other side of it: every printed point is on the boundary or on the ball's own side (exact even-odd
/// test); and the path never tunnels. A scene whose balls do not start strictly on that side does not
/// apply.
std::optional<Failure> stays(KernelId k, const Scene& s, int want) {
    for (const Ball& b : s.balls)
        if (locate(b.pos, s.walls) != want) {
            tag("not applicable: a ball does not start strictly on its side");
            return std::nullopt;
        }
    classify_legs(s);
    const auto events = run(s, k, s.frames);
    if (!events) return std::nullopt;
    classify_run(*events);
    bool touched = false;
    for (const Event& e : *events) {
        if (!on_path(e)) continue;
        const int where = locate(e.pos, s.walls);
        touched |= where == 0;
        if (where == -want)
            return fail(Check::no_tunnel, fmt::format("frame {}: ball {} {} the closed polygon: {} at {}", e.frame,
                                                      e.ball, want > 0 ? "escapes" : "enters",
                                                      e.kind == Event::Kind::hit ? "hit point" : "end of frame",
                                                      str(e.pos)));
    }
    classify(touched, "a printed point exactly on the boundary");
    return no_tunnel(k, s);
}

/// The bounce leaves on the side it came from: once a ball has hit a wall from one side, no later point
/// of its path lies strictly on the other side of that wall's line (scenes of one wall, where nothing else
/// could bring it round).
std::optional<Failure> bounce_side(KernelId k, const Scene& s) {
    if (s.walls.size() != 1) return std::nullopt;
    classify_legs(s);
    const Wall& w = s.walls[0];
    const auto events = run(s, k, s.frames);
    if (!events) return std::nullopt;
    classify_run(*events);
    std::vector<int> last(s.balls.size()), locked(s.balls.size(), 0);
    for (std::size_t i = 0; i < s.balls.size(); ++i) last[i] = side_oracle(s.balls[i].pos, w);
    for (const Event& e : *events) {
        if (!on_path(e)) continue;
        const int side = side_oracle(e.pos, w);
        if (locked[e.ball] != 0 && side == -locked[e.ball])
            return fail(Check::no_tunnel, fmt::format("frame {}: ball {} hit {} from side {} but is later at {} on "
                                                      "side {}",
                                                      e.frame, e.ball, str(w), locked[e.ball], str(e.pos), side));
        if (e.kind == Event::Kind::hit && last[e.ball] != 0) locked[e.ball] = last[e.ball];
        if (side != 0) last[e.ball] = side;
    }
    return std::nullopt;
}

/// Every frame's first hit equals the exact answer: from the kernel's own state and memory, the exact
/// kernel hits the same wall first (or none); and at a frame that starts with no contact, it is the first
/// wall the leg Bs → Be = Bs + v (as C++ rounds it, kernel.hpp) crosses, by the exact oracle.
std::optional<Failure> frame_oracle(KernelId k, const Scene& s) {
    classify_legs(s);
    World world(s, k);
    std::vector<Event> events;
    world.start(events);
    std::vector<HitEvent> hits;
    StepScratch scratch;
    for (std::int64_t f = 1; f <= s.frames; ++f) {
        const std::vector<Ball> balls(world.balls().begin(), world.balls().end());
        const std::vector<BallMemory> memories(world.memories().begin(), world.memories().end());
        events.clear();
        if (world.step(events)) return std::nullopt;
        for (std::size_t i = 0; i < balls.size(); ++i) {
            long got = -1;
            for (const Event& e : events)
                if (e.kind == Event::Kind::hit && e.ball == i) {
                    got = long(e.index);
                    break;
                }
            if (k != KernelId::exact) {
                Ball b = balls[i];
                BallMemory m = memories[i];
                hits.clear();
                if (step_ball(KernelId::exact, b, m, s.walls, hits, scratch) == FrameStatus::ok) {
                    const long want = hits.empty() ? -1 : long(hits.front().wall);
                    if (got != want)
                        return fail(Check::oracle, fmt::format("frame {} ball {} at {} moving {}: {} hits wall {} "
                                                               "first, the exact kernel wall {} (-1: none)",
                                                               f, i, str(balls[i].pos), str(balls[i].vel),
                                                               kernel_name(k), got, want));
                }
            }
            if (memories[i].count == 0) {
                const Vec2 bs = balls[i].pos, be = bs + balls[i].vel;
                const long want = first_hit_oracle(bs, be, s.walls);
                classify(!sum_exact(bs.x, balls[i].vel.x) || !sum_exact(bs.y, balls[i].vel.y),
                         "a frame whose Bs + v is rounded");
                if (got != want)
                    return fail(Check::oracle, fmt::format("frame {} ball {} at {} moving {} (Be {}): {} hits wall {} "
                                                           "first, exactly wall {} (-1: none)",
                                                           f, i, str(bs), str(balls[i].vel), str(be), kernel_name(k),
                                                           got, want));
            }
        }
    }
    return std::nullopt;
}

/// Mirroring the scene across x = 0 or turning it by 90° (both exact in floating point) mirrors or turns
/// its whole run: the same events, each point and velocity mapped.
std::optional<Failure> scene_symmetry(KernelId k, const Scene& s) {
    classify_legs(s);
    const auto base = run(s, k, s.frames);
    if (!base) return std::nullopt;
    classify_run(*base);
    struct Map {
        const char* name;
        Vec2 (*f)(Vec2);
    };
    for (const Map& m : {Map{"mirroring across x = 0", mirror}, Map{"a quarter turn", rotate90}}) {
        const auto other = run(transform(s, m.f), k, s.frames);
        if (!other || other->size() != base->size())
            return fail(Check::symmetry, fmt::format("{} changes the number of events", m.name));
        for (std::size_t j = 0; j < base->size(); ++j) {
            Event want = (*base)[j];
            want.pos = m.f(want.pos);
            want.vel = m.f(want.vel);
            const Event& got = (*other)[j];
            if (got.kind != want.kind || got.frame != want.frame || got.ball != want.ball || got.index != want.index ||
                got.shape != want.shape || !same_value(got.pos, want.pos) || !same_value(got.vel, want.vel))
                return fail(Check::symmetry, fmt::format("after {}: event {} is `{}`, expected `{}`", m.name, j,
                                                         format_event(got), format_event(want)));
        }
    }
    return std::nullopt;
}

/// Translations tried by TranslationInvariance; one applies when it moves every coordinate (and every
/// Bs + v) without rounding.
constexpr std::array<Vec2, 5> k_translations = {
    {{1, -2}, {1024, 4096}, {-0x1p30 * 3, 0x1p31}, {0x1p40, -0x1p40 * 5}, {0.5, 0.25}}};

/// Translating the scene by an exact amount changes no decision: frame 0's overlaps, and in frame 1 each
/// ball's first hit (wall and t_i) and, for the exact kernel, every hit's wall and t_i.
std::optional<Failure> translation(KernelId k, const Scene& s) {
    classify_legs(s);
    const auto base = run(s, k, 1);
    if (!base) return std::nullopt;
    int applied = 0;
    for (Vec2 t : k_translations) {
        if (!translation_exact(s, t)) continue;
        ++applied;
        const auto other = run(translate(s, t), k, 1);
        if (!other) continue;
        const auto decisions = [&](const std::vector<Event>& ev) {
            std::vector<std::string> out;
            std::vector<int> seen(s.balls.size(), 0);
            for (const Event& e : ev) {
                if (e.kind == Event::Kind::overlap && e.frame == 0)
                    out.push_back(format_event(e));
                else if (e.kind == Event::Kind::hit && (k == KernelId::exact || seen[e.ball]++ == 0))
                    out.push_back(fmt::format("hit ball {} wall {}", e.ball, e.index));
            }
            return out;
        };
        if (decisions(*base) != decisions(*other))
            return fail(Check::symmetry, fmt::format("translating the scene by {} (exactly) changes a decision",
                                                     str(t)));
    }
    classify(applied > 0, "an exact translation applies");
    return std::nullopt;
}

/// The same scene stepped twice, and by two worlds in lockstep, gives the same events and the same hash.
/// The broad phase and threads change nothing: a wall grid, a static-shape index and 2 threads give
/// run_scene's events bit for bit, so the same hash.
std::optional<Failure> broad_phase(KernelId k, const Scene& s) {
    classify_legs(s);
    const auto plain = run(s, k, s.frames);
    if (!plain) return std::nullopt;
    ScaleOptions options{.broad_phase = true, .threads = 2};
    if (k == KernelId::lecture_float) options.grid.margin = k_float_margin;
    std::vector<Event> scaled;
    try {
        scaled = run_scene_scaled(s, k, s.frames, options);
    } catch (const StepFailure& e) {
        return fail(Check::deterministic, fmt::format("with the broad phase the run stopped: {}", e.what()));
    }
    if (scaled != *plain || hash_events(scaled) != hash_events(*plain))
        return fail(Check::deterministic, fmt::format("the broad phase with 2 threads changes the run: hash {} against {}",
                                                      format_hash(hash_events(scaled)), format_hash(hash_events(*plain))));
    return std::nullopt;
}

std::optional<Failure> determinism(KernelId k, const Scene& s) {
    classify_legs(s);
    const auto a = run(s, k, s.frames);
    const auto b = run(s, k, s.frames);
    if (!a || !b) return std::nullopt;
    if (*a != *b || hash_events(*a) != hash_events(*b))
        return fail(Check::deterministic, "two runs of the same scene differ");
    World w1(s, k), w2(s, k);
    std::vector<Event> e1, e2;
    w1.start(e1);
    w2.start(e2);
    RunHasher h;
    h.add(e1);
    for (std::int64_t f = 1; f <= s.frames; ++f) {
        const std::size_t from = e1.size();
        w1.step(e1);
        w2.step(e2);
        h.add(std::span<const Event>(e1).subspan(from));
    }
    if (e1 != *a || e2 != *a) return fail(Check::deterministic, "stepping frame by frame differs from run_scene");
    if (h.digest() != hash_events(*a)) return fail(Check::deterministic, "the streaming hash differs");
    return std::nullopt;
}

/// A scene written as a log and read back is the same scene bit for bit, and writes the same text.
std::optional<Failure> round_trip(KernelId, const Scene& s) {
    const std::string text = write_scene_log(s);
    auto parsed = parse_scene_log(text, "round-trip");
    if (const auto* d = std::get_if<Diagnostic>(&parsed))
        return fail(Check::deterministic, fmt::format("the writer's text does not read back: {}", d->str()));
    const Scene& back = std::get<Scene>(parsed);
    if (!same_bits(back, s)) return fail(Check::deterministic, "the scene read back differs from the one written");
    if (write_scene_log(back) != text) return fail(Check::deterministic, "writing the scene read back changes the text");
    return std::nullopt;
}

/// Scenes with every kind of line a log holds: expectations, checks and provenance as well as entities.
rc::Gen<Scene> full_scene() {
    return rc::gen::apply(
        [](Scene s, const Scene& statics, std::vector<int> checks, std::uint64_t hash, bool with_hash, int fail_frame,
           bool with_fail) {
            s.circles = statics.circles;
            s.rects = statics.rects;
            for (int c : checks) {
                const Check ch = static_cast<Check>(c);
                if (std::find(s.checks.begin(), s.checks.end(), ch) == s.checks.end()) s.checks.push_back(ch);
            }
            if (with_hash) s.expect_hash = hash;
            // A log may only expect the failure of a check it names (the reader rejects anything else).
            if (with_fail && !s.checks.empty()) s.expect_failure = ExpectFailure{s.checks[0], fail_frame % (s.frames + 1)};
            for (std::size_t i = 0; i < s.balls.size(); ++i)
                s.expect_states.push_back({std::int64_t(i) % (s.frames + 1), std::uint32_t(i), s.balls[i]});
            s.provenance = {"property RoundTrip", "fuzz nothing 0"};
            return s;
        },
        gen::moving_scene(4), gen::static_scene(), rc::gen::container<std::vector<int>>(rc::gen::inRange(0, 6)),
        rc::gen::arbitrary<std::uint64_t>(), rc::gen::arbitrary<bool>(), rc::gen::inRange(0, 5), rc::gen::arbitrary<bool>());
}

RICOCHET_PROPERTY_SUITE(Scenes);

TEST_P(Scenes, NoTunnelSingleWall) {
    run_property({"NoTunnelSingleWall", Check::no_tunnel, gen::wall_scene(1, 8), no_tunnel, 4000}, GetParam());
}

TEST_P(Scenes, NoTunnelWalls) {
    run_property({"NoTunnelWalls", Check::no_tunnel, gen::wall_scene(6, 8), no_tunnel, 1500}, GetParam());
}

TEST_P(Scenes, NoEscapeClosedPolygon) {
    run_property({"NoEscapeClosedPolygon", Check::no_tunnel, gen::polygon_scene(true, 24),
                  [](KernelId k, const Scene& s) { return stays(k, s, +1); }, 600},
                 GetParam());
}

TEST_P(Scenes, NoEntryClosedBox) {
    run_property({"NoEntryClosedBox", Check::no_tunnel, gen::polygon_scene(false, 24),
                  [](KernelId k, const Scene& s) { return stays(k, s, -1); }, 600},
                 GetParam());
}

TEST_P(Scenes, BounceSide) {
    run_property({"BounceSide", Check::no_tunnel, gen::wall_scene(1, 8), bounce_side, 3000}, GetParam());
}

TEST_P(Scenes, FrameOracle) {
    run_property({"FrameOracle", Check::oracle, gen::moving_scene(6), frame_oracle, 800}, GetParam());
}

TEST_P(Scenes, SceneSymmetry) {
    run_property({"SceneSymmetry", Check::symmetry, gen::moving_scene(6), scene_symmetry, 800}, GetParam());
}

TEST_P(Scenes, TranslationInvariance) {
    run_property({"TranslationInvariance", Check::symmetry, gen::moving_scene(1), translation, 1500}, GetParam());
}

TEST_P(Scenes, BroadPhaseSameBits) {
    run_property({"BroadPhaseSameBits", Check::deterministic, gen::moving_scene(6), broad_phase, 200}, GetParam());
}

TEST_P(Scenes, Determinism) {
    run_property({"Determinism", Check::deterministic, gen::moving_scene(6), determinism, 600}, GetParam());
}

TEST_P(Scenes, RoundTrip) {
    run_property({"RoundTrip", Check::deterministic, full_scene(), round_trip, 3000}, GetParam());
}

}  // namespace
}  // namespace ricochet::props
