// Kernel specs: how a command line or an environment variable names a kernel, the one place every harness
// turns one into a KernelId: a registered kernel's name ("robust", a peer's or a loaded plug-in's), or
// plugin:PATH, the plug-in in file PATH (plugin_loader.hpp), loaded on first use. Scene logs name kernels by
// name only (parse_kernel): a log never loads code.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "ricochet/kernel_id.hpp"

namespace ricochet {

/// The prefix of a spec naming a plug-in file: plugin:PATH. No kernel name has a ':' in it.
inline constexpr std::string_view k_plugin_spec_prefix = "plugin:";

/// The kernel spec names, loading a plug-in if it names one. Nothing, and *error (if given) says why, for an
/// unknown name (the registered ones are listed), a kernel this build lacks (absent_kernel_message),
/// `plugin:` without a path, or a plug-in load_plugin refuses.
std::optional<KernelId> resolve_kernel(std::string_view spec, std::string* error = nullptr);

}  // namespace ricochet
