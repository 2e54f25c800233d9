// Stopping on SIGINT and SIGTERM (ricochet_app/stop_signal.hpp).
#include "ricochet_app/stop_signal.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <optional>
#include <thread>

namespace ricochet::app {

namespace {

/// The signal that asked to stop; written only by the handler (async-signal-safe: one store).
volatile std::sig_atomic_t g_stop_signal = 0;

/// How often wait_passing_stop looks at the child and the stop request.
constexpr std::chrono::milliseconds k_wait_poll{20};

extern "C" void record_stop(int sig) { g_stop_signal = sig; }

/// ExitOnSignal's message; set before its handler is installed.
const char* volatile g_exit_message = "";

/// strlen, async-signal-safe.
std::size_t length(const char* s) {
    std::size_t n = 0;
    while (s[n] != '\0') ++n;
    return n;
}

extern "C" void exit_now(int sig) {
    // Only async-signal-safe calls: write(2) and _exit(2).
    const char* msg = g_exit_message;
    const char* name = sig == SIGTERM ? "SIGTERM\n" : "SIGINT\n";
    if (::write(STDERR_FILENO, msg, length(msg)) < 0 || ::write(STDERR_FILENO, name, length(name)) < 0) {
        // Nothing to do: the exit status still says why.
    }
    ::_exit(128 + sig);
}

/// Installs handler for SIGINT and SIGTERM with flags, keeping the dispositions they replace.
void handle_both(void (*handler)(int), int flags, struct sigaction& old_int, struct sigaction& old_term) {
    struct sigaction sa {};
    sa.sa_handler = handler;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = flags;
    sigaction(SIGINT, &sa, &old_int);
    sigaction(SIGTERM, &sa, &old_term);
}

/// Puts back the dispositions handle_both replaced.
void restore_both(const struct sigaction& old_int, const struct sigaction& old_term) {
    sigaction(SIGINT, &old_int, nullptr);
    sigaction(SIGTERM, &old_term, nullptr);
}

}  // namespace

StopOnSignal::StopOnSignal() {
    // Restarted, not failed: a write or a wait interrupted half-way would look like an I/O error.
    handle_both(record_stop, SA_RESTART, old_int_, old_term_);
}

StopOnSignal::~StopOnSignal() { restore_both(old_int_, old_term_); }

ExitOnSignal::ExitOnSignal(const char* message) {
    g_exit_message = message;
    handle_both(exit_now, 0, old_int_, old_term_);
}

ExitOnSignal::~ExitOnSignal() { restore_both(old_int_, old_term_); }

HoldSignals::HoldSignals() {
    sigset_t both;
    sigemptyset(&both);
    sigaddset(&both, SIGINT);
    sigaddset(&both, SIGTERM);
    sigprocmask(SIG_BLOCK, &both, &old_);
}

HoldSignals::~HoldSignals() { sigprocmask(SIG_SETMASK, &old_, nullptr); }

bool stop_requested() { return g_stop_signal != 0; }

int stop_signal() { return g_stop_signal; }

const char* stop_signal_name() { return g_stop_signal == SIGTERM ? "SIGTERM" : "SIGINT"; }

int stop_exit_code() { return 128 + (g_stop_signal != 0 ? static_cast<int>(g_stop_signal) : SIGINT); }

int wait_passing_stop(pid_t pid) {
    using Clock = std::chrono::steady_clock;
    std::optional<Clock::time_point> passed;
    bool killed = false;
    for (;;) {
        int status = 0;
        const pid_t got = ::waitpid(pid, &status, WNOHANG);
        if (got == pid) return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        if (got < 0 && errno != EINTR) return 127;
        if (!passed && stop_requested()) {
            ::kill(pid, stop_signal());
            passed = Clock::now();
        }
        if (passed && !killed && std::chrono::duration<double>(Clock::now() - *passed).count() > k_stop_grace_s) {
            ::kill(pid, SIGKILL);
            killed = true;
        }
        std::this_thread::sleep_for(k_wait_poll);
    }
}

}  // namespace ricochet::app
