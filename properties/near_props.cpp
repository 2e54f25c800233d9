// Near-degenerate decisions: scenes the predicates' filters cannot decide (generators_near.hpp), so that each exact
// stage behind them decides a side, a leg's Miss or the order of two crossings, judged by the checks in GMP
// rationals. Each statement is a list of checks, so a failure saves a log that `ricochet replay` reproduces.
#include <fmt/format.h>

#include <string_view>

#include "generators_near.hpp"
#include "harness.hpp"
#include "ricochet/predicates.hpp"
#include "ricochet/truth.hpp"
#include "sweep_oracle.hpp"

namespace ricochet::props {
namespace {

/// Which stage of the exact path decided f's call: the counter of FallbackCounts that moved (the filter: none).
template <class F>
void tag_stage(std::string_view what, F&& f) {
    const exact::FallbackCounts before = exact::fallback_counts();
    f();
    const exact::FallbackCounts after = exact::fallback_counts();
    const char* stage = after.gmp != before.gmp             ? "GMP"
                        : after.complete != before.complete ? "stage 3 (complete sum)"
                        : after.bounded != before.bounded   ? "stage 2 (bounded tail)"
                        : after.ordered != before.ordered   ? "stage 1 (ordered products)"
                                                            : "the filter";
    tag(fmt::format("{} decided by {}", what, stage));
}

/// Tags which stage decided each side and end test of every leg against every wall, and for each pair of walls a
/// leg hits, whether the filter ordered their crossings, and whether they tie exactly.
void classify_near(const Scene& s) {
    classify_legs(s);
    for (const Ball& b : s.balls) {
        const Vec2 be = b.pos + b.vel;
        for (const Wall& w : s.walls) {
            if (w.p0 == w.p1 || be == b.pos) continue;
            tag_stage("side of Be", [&] { (void)exact::side(be, w); });
            tag_stage("side of Bs", [&] { (void)exact::side(b.pos, w); });
            tag_stage("leg's line against P0", [&] { (void)exact::orient(b.pos, be, w.p0); });
            classify(truth::side(be, w) == 0 && !(be == w.p0 || be == w.p1), "Be exactly on a wall's line, inexactly");
            classify(truth::orient(b.pos, be, w.p0) == 0 || truth::orient(b.pos, be, w.p1) == 0,
                     "a wall's end exactly on the leg's line");
        }
        for (std::size_t i = 0; i < s.walls.size(); ++i)
            for (std::size_t j = i + 1; j < s.walls.size(); ++j) {
                if (truth::leg_miss(b.pos, be, s.walls[i]) != Miss::none ||
                    truth::leg_miss(b.pos, be, s.walls[j]) != Miss::none)
                    continue;
                int c = 0;
                tag_stage("crossing order", [&] { c = exact::compare_crossings(b.pos, be, s.walls[i], s.walls[j]); });
                classify(c == 0, "two crossings tied exactly");
                classify(c > 0, "the lower-indexed wall crossed later");
            }
    }
}

RICOCHET_PROPERTY_SUITE(Near);

/// Walls and legs with three points collinear, or one of them a few ulps off, on lines through the origin at mixed
/// magnitudes (differences that round) and on lattices far from it (exact differences): every side, Miss and first
/// hit is the exact one, and no leg tunnels.
TEST_P(Near, NearCollinearDecisions) {
    run_property({"NearCollinearDecisions", Check::oracle, gen::near_collinear_scene(),
                  checked({Check::oracle, Check::boundary, Check::no_tunnel}, classify_near), 1500},
                 GetParam());
}

/// One leg and 2–3 walls crossing it at parameters equal or a few ulps apart, some ending on the leg, some
/// crossing it where the hit point rounds: the first hit is the exact first (the lowest index on a tie), and the
/// rounded hit point is never allowed across another wall (no tunnel, the side bounced from kept).
TEST_P(Near, NearTiedCrossings) {
    run_property({"NearTiedCrossings", Check::oracle, gen::crossings_scene(),
                  checked({Check::oracle, Check::no_tunnel, Check::bounce_side}, classify_near), 1500},
                 GetParam());
}

}  // namespace
}  // namespace ricochet::props
