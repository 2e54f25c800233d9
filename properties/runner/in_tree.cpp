// ricochet's own property runner (ricochet_properties): the suite of the ricochet::properties library with the
// source tree's corpus as its replay folder (failures of the built-in kernels are saved there) and the peers
// registered, so that logs naming Box2D or Chipmunk read and RICOCHET_KERNEL=box2d runs them.
#include "harness.hpp"
#include "ricochet_peers/peers.hpp"

namespace {

[[maybe_unused]] const bool g_defaults = [] {
    ricochet::props::set_runner_defaults({RICOCHET_DEFAULT_REPLAY_DIR, &ricochet::peers::register_peer_kernels});
    return true;
}();

}  // namespace
