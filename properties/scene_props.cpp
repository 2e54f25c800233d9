// Scene-level properties: no tunnelling (single walls, wall soups, closed polygons from inside and
// outside), the side a ball leaves a wall on, every frame's decisions against the exact answers,
// symmetry and translation of whole runs, the broad phase, determinism, the event order, accuracy at corners
// and the scene-log round trip.
// Each statement is a list of checks (checks.hpp).
#include <algorithm>

#include "generators.hpp"
#include "harness.hpp"
#include "sweep_oracle.hpp"

namespace ricochet::props {
namespace {

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
        gen::moving_scene(4), gen::static_scene(), rc::gen::container<std::vector<int>>(rc::gen::inRange(0, int(k_all_checks.size()))),
        rc::gen::arbitrary<std::uint64_t>(), rc::gen::arbitrary<bool>(), rc::gen::inRange(0, 5), rc::gen::arbitrary<bool>());
}

/// Moving balls among walls with circles and rects: every kind of event a frame prints.
rc::Gen<Scene> scene_with_statics() {
    return rc::gen::apply(
        [](Scene s, const Scene& statics) {
            s.circles = statics.circles;
            s.rects = statics.rects;
            return s;
        },
        gen::moving_scene(6), gen::static_scene());
}

RICOCHET_PROPERTY_SUITE(Scenes);

/// Each frame's events come in the spec's order and name entities of the scene.
TEST_P(Scenes, EventOrder) {
    run_property({"EventOrder", Check::event_order, scene_with_statics(), checked({Check::event_order}, classify_legs),
                  600},
                 GetParam());
}

TEST_P(Scenes, NoTunnelSingleWall) {
    run_property({"NoTunnelSingleWall", Check::no_tunnel, gen::wall_scene(1, 8), checked({Check::no_tunnel}, classify_legs),
                  4000},
                 GetParam());
}

TEST_P(Scenes, NoTunnelWalls) {
    run_property({"NoTunnelWalls", Check::no_tunnel, gen::wall_scene(6, 8), checked({Check::no_tunnel}, classify_legs),
                  1500},
                 GetParam());
}

/// The path a scene's plan picks (axis-aligned walls: sides by comparison, wall_plan.hpp) prints the events of the
/// general path bit for bit; the generators make horizontal, vertical, sloped and zero-length walls, far or near.
TEST_P(Scenes, PlanChangesNoBits) {
    run_property({"PlanChangesNoBits", Check::plan, gen::moving_scene(6), checked({Check::plan}, classify_legs), 1500},
                 GetParam());
}

/// Balls strictly inside a closed polygon never get out, and never tunnel.
TEST_P(Scenes, NoEscapeClosedPolygon) {
    run_property({"NoEscapeClosedPolygon", Check::no_escape, gen::polygon_scene(true, 24),
                  checked({Check::no_escape, Check::no_tunnel}, classify_legs), 600},
                 GetParam());
}

/// Balls strictly outside a closed box never get in, and never tunnel.
TEST_P(Scenes, NoEntryClosedBox) {
    run_property({"NoEntryClosedBox", Check::no_escape, gen::polygon_scene(false, 24),
                  checked({Check::no_escape, Check::no_tunnel}, classify_legs), 600},
                 GetParam());
}

/// In closed polygons, with balls aimed at their vertices: every hit's t_i and B_i, the bounce off a lone
/// wall, the corner rule at a vertex and the rest of each frame keep to accuracy's bounds.
TEST_P(Scenes, CornerAccuracy) {
    run_property({"CornerAccuracy", Check::accuracy, gen::polygon_scene(true, 24), checked({Check::accuracy}, classify_legs),
                  600},
                 GetParam());
}

/// In closed polygons, with balls aimed at their vertices (to a few ulps, so that crossings of the two walls
/// there are too close for a filter to order): every decision, the first hit and the hits' order are exact.
TEST_P(Scenes, PolygonOracle) {
    run_property({"PolygonOracle", Check::oracle, gen::polygon_scene(true, 24), checked({Check::oracle}, classify_legs),
                  400},
                 GetParam());
}

/// After a bounce the ball stays on the side it came from.
TEST_P(Scenes, BounceSide) {
    run_property({"BounceSide", Check::bounce_side, gen::wall_scene(1, 8), checked({Check::bounce_side}, classify_legs),
                  3000},
                 GetParam());
}

TEST_P(Scenes, FrameOracle) {
    run_property({"FrameOracle", Check::oracle, gen::moving_scene(6), checked({Check::oracle}, classify_legs), 800},
                 GetParam());
}

TEST_P(Scenes, SceneSymmetry) {
    run_property({"SceneSymmetry", Check::symmetry, gen::moving_scene(6), checked({Check::symmetry}, classify_legs),
                  800},
                 GetParam());
}

TEST_P(Scenes, TranslationInvariance) {
    run_property({"TranslationInvariance", Check::translation, gen::moving_scene(1),
                  checked({Check::translation}, classify_legs), 1500},
                 GetParam());
}

TEST_P(Scenes, BroadPhaseSameBits) {
    run_property({"BroadPhaseSameBits", Check::broad_phase, gen::moving_scene(6),
                  checked({Check::broad_phase}, classify_legs), 200},
                 GetParam());
}

TEST_P(Scenes, Determinism) {
    run_property({"Determinism", Check::deterministic, gen::moving_scene(6),
                  checked({Check::deterministic}, classify_legs), 600},
                 GetParam());
}

TEST_P(Scenes, RoundTrip) {
    run_property({"RoundTrip", Check::round_trip, full_scene(), checked({Check::round_trip}), 3000}, GetParam());
}

}  // namespace
}  // namespace ricochet::props
