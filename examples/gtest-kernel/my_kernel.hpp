// A game's collision code, as the example's user has it: a point ball's leg against a wall and the bounce, in
// double, written against ricochet/plugin.h's plain C types so that ricochet can run it as a kernel.
#pragma once

#include <ricochet/plugin.h>

namespace my {

/// The kernel's table (ricochet/plugin.h): its name, "my-kernel", its sweep and reflect; ricochet supplies the
/// rest (the static tests, discs are not swept).
const ricochet_plugin& kernel_table();

}  // namespace my
