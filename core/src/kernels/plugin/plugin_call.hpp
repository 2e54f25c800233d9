// Internal: the guard's side the loader and the plug-in kernels see (plugin_guard.cpp): who the plug-ins are,
// a mark on every call into one, and the report of an answer plugin.h does not allow.
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>

namespace ricochet::detail {

/// The part of a plug-in a call goes to, for the report.
enum class PluginOp : std::uint8_t {
    load,  ///< dlopen, which runs its constructors
    entry,  ///< ricochet_plugin_entry, and reading the table it returns
    init,
    destroy,
    sweep,
    reflect,
    classify,
    point_in_circle,
    circles_overlap,
    point_in_rect,
    rects_overlap,
    step,
    sweep_disc,         ///< ABI version 2
    sweep_disc_bumper,  ///< ABI version 2
    reflect_disc,       ///< ABI version 2
};

/// Most plug-ins a process loads (the registry's room past the four built-in kernels, kernel.hpp).
inline constexpr std::size_t k_max_plugins = 12;
/// Most numbers a call's report shows (sweep_disc's leg, radius and wall).
inline constexpr std::size_t k_max_call_args = 9;

/// Names plug-in slot for the guard's reports (name empty while it is being loaded). Before any call into it.
void guard_name_plugin(std::size_t slot, std::string_view name, std::string_view path);
/// Installs the signal handlers, once, and starts the watchdog with timeout_s per call (0: no watchdog), once:
/// a later call cannot change the timeout. Before the first PluginCall.
void guard_start(double timeout_s);

/// Marks the calling thread as inside plug-in slot's op, called with args (the numbers its report shows, in the
/// order of op's arguments), for the object's lifetime. Not reentrant: one call at a time per thread.
class PluginCall {
public:
    /// Enters the call.
    PluginCall(std::size_t slot, PluginOp op, std::initializer_list<double> args = {}) noexcept;
    /// Leaves it.
    ~PluginCall();
    PluginCall(const PluginCall&) = delete;
    PluginCall& operator=(const PluginCall&) = delete;
};

/// Reports that plug-in slot's op, called with args, answered what plugin.h does not allow (what: "returned
/// miss code 42"), keeps the staged input and ends as the PluginFaultAction says.
[[noreturn]] void plugin_broke_header(std::size_t slot, PluginOp op, std::initializer_list<double> args,
                                      std::string_view what);

}  // namespace ricochet::detail
