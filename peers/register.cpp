// Registering the peer kernels (peers.hpp): those this build has join the kernel registry; the others are
// noted as absent, with why, so that a log naming one gets a clear error instead of "unknown kernel".
#include "ricochet_peers/peers.hpp"

#include "peer_kernels.hpp"

namespace ricochet::peers {

void register_peer_kernels() {
    // Once per process, whoever calls first (a function-local static is initialized exactly once).
    static const bool registered = [] {
#ifdef RICOCHET_HAVE_BOX2D
        register_kernel(box2d_kernel_ops());
#else
        note_absent_kernel("box2d", RICOCHET_BOX2D_ABSENT);
#endif
#ifdef RICOCHET_HAVE_CHIPMUNK
        register_kernel(chipmunk_kernel_ops());
#else
        note_absent_kernel("chipmunk", RICOCHET_CHIPMUNK_ABSENT);
#endif
        return true;
    }();
    (void)registered;
}

}  // namespace ricochet::peers
