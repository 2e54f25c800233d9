// Plug-in guard: what happens when a plug-in kernel (plugin.h) crashes, hangs or breaks its header. Every
// call ricochet makes into plug-in code (loading it, its entry, init, each kernel function) runs marked as
// such. A crash inside one (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, caught on an alternate stack, so a
// stack overflow is caught too), a call that does not return within the timeout (a watchdog thread), or an
// answer plugin.h does not allow gets one report on stderr,
//
//   ricochet: error: plug-in kernel 'NAME' (PATH) crashed: SIGSEGV in its sweep function, called with
//     bs (1, 2), v (3, 0x1.8p-2), wall (0, 0) -> (5, 5); while replaying x.scene        (one line)
//   ricochet: the scene is kept as DIR/NAME-ID.scene; replay it: ricochet replay --plugin PATH DIR/NAME-ID.scene
//
// (integers printed as such, other numbers as exact hexadecimal floats, which scene logs read), then the
// input staged below is kept, and the process ends with exit status k_plugin_fault_exit: nothing is
// allocated, locked or flushed on the way, only write(2), open(2), link(2) and _exit(2).
// A crash outside plug-in code is passed on as if the guard were not there.
//
// The harness stages what it is about to step before it steps it with a plug-in kernel: the scene as a log
// and where to keep it (a generated case: the property's or fuzz target's own replay folder, named by content
// as saved failures are), or just what it is doing (a log already on disk). Where another crash handler must
// keep the input its own way (libFuzzer writes the crashing input as an artifact), PluginFaultAction::chain
// reports and keeps as above, then hands the signal on to the handler that was there before (a hang: abort()).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace ricochet {

/// The exit status of a process whose plug-in crashed, hung or broke plugin.h (PluginFaultAction::exit).
inline constexpr int k_plugin_fault_exit = 3;
/// How every report's first line starts, for tools that look for it (the fuzz campaign does).
inline constexpr std::string_view k_plugin_fault_prefix = "ricochet: error: plug-in ";
/// Seconds one call into a plug-in may take before it counts as hung, unless RICOCHET_PLUGIN_TIMEOUT says
/// otherwise (plugin_loader.hpp): far above any sweep or frame, below libFuzzer's -timeout=10 of a campaign's
/// workers, so that the report names the plug-in.
inline constexpr double k_default_plugin_timeout_s = 5.0;

/// What the harness is doing with a plug-in kernel, for the report if the plug-in crashes or hangs on it.
struct PluginStage {
    std::string doing;              ///< shown after the report as "while DOING": "replaying x.scene"
    std::string log_text;           ///< the scene being stepped as a scene log to keep; empty: nothing to keep
    std::filesystem::path keep_as;  ///< where to keep log_text: written whole (aside, then linked) or not at all
};

/// Stages stage until the next call or clear_plugin_stage. Call it from the thread that steps, between steps
/// (never while a plug-in call is running); its folder is created here. Cheap: the report is built from it only
/// on a fault.
void stage_plugin_input(PluginStage stage);
/// Nothing staged: a fault reports the plug-in and the call only.
void clear_plugin_stage();

/// What the guard does after its report and keeping the staged input.
enum class PluginFaultAction : std::uint8_t {
    exit,   ///< _exit(k_plugin_fault_exit): the default
    chain,  ///< a crash goes on to the signal handler installed before the guard's (libFuzzer's, a sanitizer's),
            ///< or kills the process by that signal if there was none; a hang or a broken answer calls abort()
};
/// Sets what the guard does after a report (for the whole process).
void set_plugin_fault_action(PluginFaultAction action);

}  // namespace ricochet
