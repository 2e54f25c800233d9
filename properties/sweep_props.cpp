// Kernel-level properties of one leg against one wall: symmetry, consistent boundary cases, decisions
// equal to the exact ones, and the bounce's speed. Each statement is a list of checks (checks.hpp).
#include "generators.hpp"
#include "harness.hpp"
#include "sweep_oracle.hpp"

namespace ricochet::props {
namespace {

RICOCHET_PROPERTY_SUITE(Sweep);

/// Reversing the wall flips the side but not whether the ball hits; mirroring across x = 0 flips sides and
/// mirrors t_i, B_i; a quarter turn changes nothing but B_i's turn.
TEST_P(Sweep, SweepSymmetry) {
    run_property({"SweepSymmetry", Check::symmetry, gen::wall_scene(3, 1),
                  checked({Check::symmetry, Check::swap}, classify_legs), 8000},
                 GetParam());
}

/// The sides of Bs and Be and the sweep's decision are the exact ones; a ball on a wall's line never hits
/// it; a leg ending on the wall's line hits it at t = 1, at Be itself.
TEST_P(Sweep, SweepBoundary) {
    run_property({"SweepBoundary", Check::boundary, gen::wall_scene(3, 1),
                  checked({Check::boundary, Check::oracle}, classify_legs), 8000},
                 GetParam());
}

/// Every decision equals the exact one: static tests, sides, and every leg's decisions and first hit.
TEST_P(Sweep, DecisionsEqualExact) {
    const auto g = rc::gen::weightedOneOf<Scene>({{3, gen::wall_scene(3, 1)}, {1, gen::static_scene()}});
    run_property({"DecisionsEqualExact", Check::oracle, g, checked({Check::oracle}, classify_legs), 8000}, GetParam());
}

/// The bounce keeps the speed: one reflection of any velocity about any wall, and every frame with the
/// reflections its kernel made, within the kernel's bound.
TEST_P(Sweep, BounceSpeed) {
    run_property({"BounceSpeed", Check::speed, gen::wall_scene(3, 4), checked({Check::speed}, classify_legs), 3000},
                 GetParam());
}

/// Every well-conditioned hit point is within k_hit_accuracy_ulps·ε·M of the exact crossing of its leg.
TEST_P(Sweep, HitAccuracy) {
    run_property({"HitAccuracy", Check::accuracy, gen::wall_scene(3, 4), checked({Check::accuracy}, classify_legs),
                  3000},
                 GetParam());
}

}  // namespace
}  // namespace ricochet::props
