// The peers as kernels: Box2D 2.4.1 (`box2d`) and Chipmunk 7 (`chipmunk`) behind the kernel interface
// (core/include/ricochet/kernel.hpp), so that every harness (properties, fuzz targets, replay) can be pointed
// at them by name. Each is compiled in only where its Debian package was found at build time.
#pragma once

namespace ricochet::peers {

/// Registers the peer kernels this build has (register_kernel) and notes the others as absent
/// (note_absent_kernel: a log or option naming one is told why it is not built in). Idempotent; call it
/// at start-up, before any kernel name is parsed and before any thread steps a scene.
void register_peer_kernels();

}  // namespace ricochet::peers
