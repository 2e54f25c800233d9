// Plug-in kernels: a shared library implementing ricochet/plugin.h, loaded at run time (dlopen) and entered
// in the kernel registry (kernel.hpp, register_kernel) under the name it declares, so that every harness runs
// against it: `--kernel plugin:PATH` and RICOCHET_KERNEL=plugin:PATH go through resolve_kernel
// (kernel_spec.hpp), `--plugin PATH` through load_plugin. A scene log never loads one: its `kernel NAME` only
// finds a kernel already registered.
//
// What ricochet supplies around a plug-in (plugin.h says it where its author reads):
// - the functions it leaves NULL (reflect, reflect_disc, the static tests) are the robust kernel's, exact decisions;
// - with sweep_disc (plugin.h, ABI version 2) its discs are stepped by the lecture's disc frame loop
//   (naive_disc_frame.hpp, plugin_disc.cpp) over every wall and bumper, each leg traced; without it, and for
//   every version-1 plug-in, a scene with discs or bumpers is refused (sweep_disc_bumper adds bumpers);
// - without a frame step, its frames are stepped by the lecture kernels' loop (naive_frame.hpp) over every
//   wall of the scene (no broad phase: what the plug-in is asked never depends on the grid), its legs traced
//   for the checks; with one, a trace says legs_traced = false and the reflections it reports;
// - its failures are the user's bugs, not documented weaknesses (KernelOps::failures_documented is false):
//   its failure logs carry no `expect failure`, so they fail replay until the bug is fixed, and a campaign
//   that meets a saved one again exits 1;
// - every call into it runs under the guard (plugin_guard.hpp): a crash, a hang or an answer plugin.h does
//   not allow ends the process with a report naming the plug-in and the staged input kept.
// Loading and registering are not synchronized with stepping: load plug-ins at start-up, before any thread
// steps a scene, as register_kernel asks.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "ricochet/kernel_id.hpp"

struct ricochet_plugin;  // ricochet/plugin.h

namespace ricochet {

/// A loaded plug-in kernel.
struct PluginInfo {
    std::string name;             ///< the kernel's name as it declares it (kernel_name of its id)
    std::filesystem::path path;   ///< the file, absolute, symbolic links resolved; empty for a table linked in
    bool frame_step = false;      ///< it steps whole frames itself (plugin.h: step)
    std::uint32_t abi_version = 0;  ///< its table's version: 1 (point balls) or 2
    bool discs = false;           ///< it sweeps discs (plugin.h, version 2: sweep_disc)
    bool bumpers = false;         ///< and bumpers (sweep_disc_bumper, with sweep_disc)
};

/// Loads the plug-in in file and registers its kernel; once per file: loading it again, by any path to it,
/// returns the same id. Nothing, and *error (if given) says why, when the file is missing or not a loadable
/// library (dlerror's words), has no ricochet_plugin_entry, gives an ABI version other than 1 and 2 (which it gives
/// and which this ricochet speaks), a table too short, no sweep, a name that is malformed or taken, init fails, the registry
/// is full, or RICOCHET_PLUGIN_TIMEOUT (seconds per call into a plug-in before it counts as hung; 0: no limit;
/// default k_default_plugin_timeout_s) is not a number from 0 to 86400. The first load installs the guard.
std::optional<KernelId> load_plugin(const std::filesystem::path& file, std::string* error = nullptr);

/// Registers the kernel of a plugin.h table linked into this program, without a shared library or dlopen: the
/// user's own test binary (ricochet/properties.hpp, RICOCHET_TEST_KERNEL) or any program that steps scenes with its
/// own collision code. The table is checked, its init run, its kernel registered and guarded exactly as a loaded
/// plug-in's (load_plugin): the same messages, the same refusals, the same kernel, whose logs name it by the name
/// it declares. table must outlive every use of the kernel (a static is fine); registering the same table again
/// returns the same id. Nothing, and *error says why, where load_plugin would refuse the table.
std::optional<KernelId> register_plugin(const ricochet_plugin& table, std::string* error = nullptr);

/// The plug-in behind kernel k, or null if k is not a plug-in kernel.
const PluginInfo* plugin_info(KernelId k);

}  // namespace ricochet
