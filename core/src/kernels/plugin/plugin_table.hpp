// Internal: the loaded plug-ins by slot, as plugin_loader.cpp fills them and the plug-in kernels
// (plugin_kernel.cpp) call them.
#pragma once

#include <cstddef>
#include <vector>

#include "kernels/plugin/plugin_call.hpp"
#include "ricochet/kernel.hpp"
#include "ricochet/plugin.h"
#include "ricochet/plugin_loader.hpp"

namespace ricochet::detail {

/// One loaded plug-in.
struct LoadedPlugin {
    ricochet_plugin api{};    ///< its table, every field past its struct_size absent (NULL, 0)
    void* context = nullptr;  ///< what its init set
    void* handle = nullptr;   ///< dlopen's; null for a table linked in (register_plugin)
    const ricochet_plugin* table = nullptr;  ///< the table register_plugin was given; null for a loaded plug-in
    PluginInfo info;
    KernelId id{};
};

/// Slot slot (the slot-th plug-in loaded, from 0): written once while it loads, before its kernel is registered.
LoadedPlugin& loaded_plugin(std::size_t slot);

/// The registry entry of the plug-in in slot: its functions, and ricochet's where it has none.
KernelOps plugin_kernel_ops(std::size_t slot);

/// One frame of a disc (or a point ball among bumpers) with the plug-in in slot's sweep_disc, sweep_disc_bumper and
/// reflect_disc (plugin_disc.cpp): its kernel's step_disc, for a plug-in that has sweep_disc.
FrameStatus step_plugin_disc(std::size_t slot, Ball& ball, const Obstacles& obstacles, std::vector<HitEvent>& hits,
                             StepScratch& scratch);

}  // namespace ricochet::detail
