// Ctrl-C (SIGINT) and SIGTERM as a request to stop, not a kill: a command that holds a StopOnSignal checks
// stop_requested() at its frame or log boundaries, prints what it did, leaves no half-written file and
// exits with stop_exit_code() (128 + the signal: 130 for SIGINT, 143 for SIGTERM, as a shell reports it).
#pragma once

#include <sys/types.h>

#include <csignal>

namespace ricochet::app {

/// While in scope, SIGINT and SIGTERM only record the request (SA_RESTART, so blocking calls go on);
/// the previous handlers come back at the end of the scope.
class StopOnSignal {
public:
    StopOnSignal();
    ~StopOnSignal();
    StopOnSignal(const StopOnSignal&) = delete;
    StopOnSignal& operator=(const StopOnSignal&) = delete;

private:
    struct sigaction old_int_ {};
    struct sigaction old_term_ {};
};

/// While in scope, SIGINT and SIGTERM write message (a string literal: it must outlive the scope) and the
/// signal's name on stderr and end the process at once with 128 + the signal. For a phase with nothing to
/// lose, no file being written, that has no boundary to stop at (record's run, a call into the core).
class ExitOnSignal {
public:
    explicit ExitOnSignal(const char* message);
    ~ExitOnSignal();
    ExitOnSignal(const ExitOnSignal&) = delete;
    ExitOnSignal& operator=(const ExitOnSignal&) = delete;

private:
    struct sigaction old_int_ {};
    struct sigaction old_term_ {};
};

/// While in scope, SIGINT and SIGTERM wait (blocked): a file being written is written whole. A signal
/// that arrived meanwhile is handled at the end of the scope.
class HoldSignals {
public:
    HoldSignals();
    ~HoldSignals();
    HoldSignals(const HoldSignals&) = delete;
    HoldSignals& operator=(const HoldSignals&) = delete;

private:
    sigset_t old_{};
};

/// True once SIGINT or SIGTERM arrived under a StopOnSignal.
bool stop_requested();

/// The signal that asked to stop (SIGINT or SIGTERM); 0 if none did.
int stop_signal();

/// "SIGINT" or "SIGTERM", as messages name the signal that stopped a command.
const char* stop_signal_name();

/// 128 + stop_signal(): the exit status of a stopped command.
int stop_exit_code();

/// Seconds a child is given to exit after a stop was passed on to it before it is killed (SIGKILL). A
/// libFuzzer worker's interrupt handler is not async-signal-safe (it builds a std::string and prints): a
/// signal that lands inside malloc can deadlock it, and a stopped command must still end. A worker that
/// does exit takes milliseconds.
inline constexpr double k_stop_grace_s = 10;

/// Waits for the child pid and returns its exit status (128 + signal if a signal ended it, 127 if it
/// cannot be waited for). A stop requested meanwhile is passed on to the child, once, as the same signal,
/// and a child still there k_stop_grace_s later is killed.
int wait_passing_stop(pid_t pid);

}  // namespace ricochet::app
