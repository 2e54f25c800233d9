// Internal: the registry entries of the peer kernels this build has (register.cpp registers them).
#pragma once

#include "ricochet/kernel.hpp"

namespace ricochet::peers {

/// Box2D 2.4.1 as the kernel `box2d` (box2d_kernel.cpp; built where Box2D was found).
KernelOps box2d_kernel_ops();
/// Chipmunk 7 as the kernel `chipmunk` (chipmunk_kernel.cpp; built where Chipmunk was found).
KernelOps chipmunk_kernel_ops();

}  // namespace ricochet::peers
