// The plug-in guard (plugin_guard.hpp, plugin_call.hpp). What runs after a fault runs in a signal handler
// (or beside a thread stuck in plug-in code, which may hold any lock): it reads only what was prepared before
// (the plug-ins' names, the staged scene, each thread's call mark) and calls only async-signal-safe functions.
#include "ricochet/plugin_guard.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <mutex>
#include <thread>

#include <fmt/format.h>

#include "kernels/plugin/plugin_call.hpp"
#include "ricochet/bits.hpp"

namespace ricochet {
namespace detail {
namespace {

/// One thread's call mark, set while it is inside plug-in code. Atomics: the watchdog reads other threads' marks.
struct CallMark {
    std::atomic<bool> owned{false};       ///< a thread holds this mark
    std::atomic<bool> active{false};      ///< that thread is inside a plug-in call
    std::atomic<std::uint64_t> calls{0};  ///< calls entered so far: tells a call that is stuck from a new one
    std::atomic<std::uint8_t> slot{0};
    std::atomic<PluginOp> op{PluginOp::load};
    std::atomic<std::uint8_t> arg_count{0};
    std::array<std::atomic<double>, k_max_call_args> args{};
};

/// Threads the watchdog watches; a thread past them is guarded against crashes only.
constexpr std::size_t k_max_marks = 256;
std::array<CallMark, k_max_marks> g_marks;
/// This thread's mark: one of g_marks, else t_own_mark. Constant-initialized, so a signal handler may read it.
thread_local CallMark* t_mark = nullptr;
thread_local CallMark t_own_mark;

/// At a thread's end: gives its mark back and frees its alternate signal stack.
struct ThreadGuard {
    CallMark* mark = nullptr;
    void* stack = nullptr;
    ~ThreadGuard() {
        if (stack != nullptr) {
            stack_t off{};
            off.ss_flags = SS_DISABLE;
            sigaltstack(&off, nullptr);
            std::free(stack);
        }
        // A call after this (a plug-in's destroy at exit) still has a mark, the thread's own.
        t_mark = &t_own_mark;
        if (mark != nullptr) mark->owned.store(false);
    }
};
thread_local ThreadGuard t_guard;

/// Bytes of each alternate signal stack: room for the report and for a sanitizer's handler after it.
constexpr std::size_t k_signal_stack_bytes = std::size_t{1} << 17;

/// A plug-in as the reports name it, copied in before any call into it.
struct PluginName {
    std::array<char, 65> name{};
    std::array<char, 4096> path{};
};
std::array<PluginName, k_max_plugins> g_names{};

/// What the harness staged (plugin_guard.hpp): aside is the temporary file keep is linked from.
struct Staged {
    std::string doing;
    std::string text;
    std::string keep;
    std::string aside;
};
std::atomic<const Staged*> g_stage{nullptr};
/// The current stage and the one before: one is freed only two stages after it was current.
std::array<std::unique_ptr<Staged>, 2> g_stage_store;
std::size_t g_stage_next = 0;
std::mutex g_stage_mutex;

std::atomic<PluginFaultAction> g_action{PluginFaultAction::exit};
std::atomic<bool> g_reporting{false};
double g_timeout_s = 0;
std::array<char, 32> g_timeout_text{};

constexpr std::array<int, 5> k_signals = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};
std::array<struct sigaction, k_signals.size()> g_previous{};

const char* signal_name(int sig) {
    switch (sig) {
        case SIGSEGV: return "SIGSEGV";
        case SIGBUS: return "SIGBUS";
        case SIGFPE: return "SIGFPE";
        case SIGILL: return "SIGILL";
        case SIGABRT: return "SIGABRT";
        default: return "a signal";
    }
}

/// What a report calls op, and how its arguments read: '%' a number, '#' a count.
struct OpText {
    const char* what;
    const char* args;
};

OpText op_text(PluginOp op) {
    switch (op) {
        case PluginOp::load: return {"its constructors (dlopen)", ""};
        case PluginOp::entry: return {"ricochet_plugin_entry or the table it returned", ""};
        case PluginOp::init: return {"its init function", ""};
        case PluginOp::destroy: return {"its destroy function", ""};
        case PluginOp::sweep: return {"its sweep function", "bs (%, %), v (%, %), wall (%, %) -> (%, %)"};
        case PluginOp::reflect: return {"its reflect function", "v (%, %), wall (%, %) -> (%, %)"};
        case PluginOp::classify: return {"its classify function", "p (%, %), wall (%, %) -> (%, %)"};
        case PluginOp::point_in_circle: return {"its point_in_circle function", "p (%, %), circle (%, %) radius %"};
        case PluginOp::circles_overlap:
            return {"its circles_overlap function", "circle (%, %) radius %, circle (%, %) radius %"};
        case PluginOp::point_in_rect: return {"its point_in_rect function", "p (%, %), rect % % % %"};
        case PluginOp::rects_overlap: return {"its rects_overlap function", "rect % % % %, rect % % % %"};
        case PluginOp::step: return {"its step function", "ball (%, %) moving (%, %) among # walls"};
        case PluginOp::sweep_disc:
            return {"its sweep_disc function", "bs (%, %), v (%, %), radius %, wall (%, %) -> (%, %)"};
        case PluginOp::sweep_disc_bumper:
            return {"its sweep_disc_bumper function", "bs (%, %), v (%, %), radius %, bumper (%, %) radius %"};
        case PluginOp::reflect_disc: return {"its reflect_disc function", "v (%, %), normal (%, %)"};
    }
    return {"?", ""};
}

/// Text built without allocating: a fixed buffer, cut at its end.
class Text {
public:
    void clear() { n_ = 0; }
    void put(char c) {
        if (n_ < buf_.size()) buf_[n_++] = c;
    }
    /// s with control bytes shown as '?' (and, for a log's comment, bytes past ASCII too).
    void add(std::string_view s, bool ascii_only = false) {
        for (const char c : s) {
            const auto u = static_cast<unsigned char>(c);
            put(u < 0x20 || u == 0x7f || (ascii_only && u >= 0x80) ? '?' : c);
        }
    }
    void add_count(std::uint64_t v) {
        std::array<char, 20> d{};
        std::size_t k = 0;
        do d[k++] = static_cast<char>('0' + v % 10);
        while ((v /= 10) != 0);
        while (k > 0) put(d[--k]);
    }
    /// x exactly: an integer below 2^53 as one, anything else as a hexadecimal float (0x1.8p-3), as logs read.
    void add_number(double x) {
        if (std::isnan(x)) return add("nan");
        if (std::signbit(x)) put('-');
        x = std::fabs(x);
        if (std::isinf(x)) return add("inf");
        if (x < 0x1p53 && std::trunc(x) == x) return add_count(static_cast<std::uint64_t>(x));
        const auto bits = bits_of(x);
        const auto biased = static_cast<int>(bits >> 52);
        std::uint64_t mantissa = bits & ((std::uint64_t{1} << 52) - 1);
        add(biased == 0 ? "0x0" : "0x1");
        if (mantissa != 0) {
            put('.');
            for (int shift = 48; mantissa != 0; shift -= 4) {
                put("0123456789abcdef"[(mantissa >> shift) & 0xf]);
                mantissa &= (std::uint64_t{1} << shift) - 1;
            }
        }
        const int exponent = biased == 0 ? -1022 : biased - 1023;
        put('p');
        put(exponent < 0 ? '-' : '+');
        add_count(static_cast<std::uint64_t>(exponent < 0 ? -exponent : exponent));
    }
    std::string_view view() const { return {buf_.data(), n_}; }

private:
    std::array<char, 8192> buf_{};
    std::size_t n_ = 0;
};
Text g_line;
Text g_comment;
Text g_note;

void write_all(int fd, std::string_view s) {
    while (!s.empty()) {
        const ssize_t n = ::write(fd, s.data(), s.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return;
        s.remove_prefix(static_cast<std::size_t>(n));
    }
}

bool write_file(int fd, std::string_view a, std::string_view b) {
    for (std::string_view s : {a, b})
        while (!s.empty()) {
            const ssize_t n = ::write(fd, s.data(), s.size());
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) return false;
            s.remove_prefix(static_cast<std::size_t>(n));
        }
    return true;
}

enum class Fault { signal, hang, header };

/// The report of a fault in the call mark describes (sig for a signal, what for a broken header) on stderr,
/// then the staged scene kept. Only one thread gets here (g_reporting).
void report(Fault fault, int sig, const CallMark& mark, std::string_view what) {
    const std::size_t slot = std::min<std::size_t>(mark.slot.load(), k_max_plugins - 1);
    const PluginName& id = g_names[slot];
    const OpText op = op_text(mark.op.load());
    Text& line = g_line;
    line.clear();
    line.add(k_plugin_fault_prefix);
    if (id.name[0] != '\0') {
        line.add("kernel '");
        line.add(id.name.data());
        line.add("' (");
        line.add(id.path.data());
        line.put(')');
    } else {
        line.add(id.path.data());
    }
    switch (fault) {
        case Fault::signal:
            line.add(" crashed: ");
            line.add(signal_name(sig));
            line.add(" in ");
            line.add(op.what);
            break;
        case Fault::hang:
            line.add(" hung: ");
            line.add(op.what);
            line.add(" did not return within ");
            line.add(g_timeout_text.data());
            line.add(" s (RICOCHET_PLUGIN_TIMEOUT)");
            break;
        case Fault::header:
            line.add(" broke ricochet/plugin.h: ");
            line.add(op.what);
            line.put(' ');
            line.add(what);
            break;
    }
    const std::size_t count = std::min<std::size_t>(mark.arg_count.load(), k_max_call_args);
    if (count > 0 && op.args[0] != '\0') {
        line.add(", called with ");
        std::size_t next = 0;
        for (const char* c = op.args; *c != '\0'; ++c) {
            const double x = next < count ? mark.args[next].load(std::memory_order_relaxed) : 0.0;
            if (*c == '%') {
                line.add_number(x), ++next;
            } else if (*c == '#') {
                line.add_count(static_cast<std::uint64_t>(x)), ++next;
            } else {
                line.put(*c);
            }
        }
    }
    const Staged* stage = g_stage.load();
    if (stage != nullptr && !stage->doing.empty()) {
        line.add("; while ");
        line.add(stage->doing);
    }
    line.put('\n');
    write_all(STDERR_FILENO, line.view());
    if (stage == nullptr || stage->text.empty()) return;

    // The staged scene, and the report as a comment (a log's line is at most 4096 bytes, ASCII here).
    Text& comment = g_comment;
    comment.clear();
    comment.add("# ");
    std::string_view said = line.view().substr(std::string_view("ricochet: error: ").size());
    said.remove_suffix(1);  // its newline
    comment.add(said.substr(0, 1000), true);
    comment.put('\n');
    Text& note = g_note;
    note.clear();
    int fd = ::open(stage->aside.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    bool kept = fd >= 0 && write_file(fd, stage->text, comment.view());
    int error = errno;
    if (fd >= 0) ::close(fd);
    bool before = false;
    // link(2) refuses to replace a file: the same case (named by its content) kept before stays as it was.
    if (kept && ::link(stage->aside.c_str(), stage->keep.c_str()) != 0) {
        error = errno;
        before = error == EEXIST;
        kept = before;
    }
    if (fd >= 0) ::unlink(stage->aside.c_str());
    if (kept) {
        note.add(before ? "ricochet: the same scene was kept before as " : "ricochet: the scene is kept as ");
        note.add(stage->keep);
        // A loaded plug-in's path is absolute; a table linked into the program (register_plugin) has none.
        if (id.path[0] == '/') {
            note.add("; replay it: ricochet replay --plugin ");
            note.add(id.path.data());
            note.put(' ');
            note.add(stage->keep);
        } else {
            note.add("; replay it: run this program again (it replays its saved logs first)");
        }
    } else {
        note.add("ricochet: could not keep the scene as ");
        note.add(stage->keep);
        note.add(" (errno ");
        note.add_count(static_cast<std::uint64_t>(error));
        note.put(')');
    }
    note.put('\n');
    write_all(STDERR_FILENO, note.view());
}

/// Hands sig on as if the guard's handler had not been installed.
void pass_on(int sig, siginfo_t* info, void* context) {
    std::size_t i = 0;
    while (i < k_signals.size() && k_signals[i] != sig) ++i;
    if (i < k_signals.size()) {
        const struct sigaction& before = g_previous[i];
        if ((before.sa_flags & SA_SIGINFO) != 0 && before.sa_sigaction != nullptr) {
            before.sa_sigaction(sig, info, context);
            return;
        }
        if ((before.sa_flags & SA_SIGINFO) == 0 && before.sa_handler != SIG_DFL && before.sa_handler != SIG_IGN) {
            before.sa_handler(sig);
            return;
        }
    }
    // The default action: a fault repeats when the handler returns, a raised signal is delivered then.
    struct sigaction dfl{};
    dfl.sa_handler = SIG_DFL;
    sigemptyset(&dfl.sa_mask);
    sigaction(sig, &dfl, nullptr);
    raise(sig);
}

void on_fault(int sig, siginfo_t* info, void* context) {
    const CallMark* mark = t_mark;
    if (mark != nullptr && mark->active.load()) {
        if (!g_reporting.exchange(true)) {
            report(Fault::signal, sig, *mark, {});
            if (g_action.load() == PluginFaultAction::exit) _exit(k_plugin_fault_exit);
        } else if (g_action.load() == PluginFaultAction::exit) {
            // Another thread is reporting and will end the process.
            for (;;) pause();
        }
    }
    pass_on(sig, info, context);
}

/// Ends the process after a hang's or a broken header's report, as the action says.
[[noreturn]] void end_after_report() {
    if (g_action.load() == PluginFaultAction::exit) _exit(k_plugin_fault_exit);
    std::abort();
}

/// Watches every thread's mark: one inside the same call for g_timeout_s is reported as hung.
[[noreturn]] void watch() {
    using Clock = std::chrono::steady_clock;
    const auto timeout = std::chrono::duration<double>(g_timeout_s);
    // Ticks of a quarter of the timeout, 10 to 100 ms: a hang is reported between timeout and timeout + a tick.
    const auto tick = std::clamp(std::chrono::duration_cast<std::chrono::milliseconds>(timeout / 4),
                                 std::chrono::milliseconds(10), std::chrono::milliseconds(100));
    struct Seen {
        bool active = false;
        std::uint64_t calls = 0;
        Clock::time_point since;
    };
    std::array<Seen, k_max_marks> seen{};
    for (;;) {
        std::this_thread::sleep_for(tick);
        const auto now = Clock::now();
        for (std::size_t i = 0; i < k_max_marks; ++i) {
            const CallMark& m = g_marks[i];
            if (!m.owned.load() || !m.active.load()) {
                seen[i].active = false;
                continue;
            }
            const std::uint64_t calls = m.calls.load();
            if (!seen[i].active || seen[i].calls != calls) {
                seen[i] = {true, calls, now};
                continue;
            }
            if (now - seen[i].since < timeout) continue;
            if (g_reporting.exchange(true))
                for (;;) pause();  // another report ends the process
            report(Fault::hang, 0, m, {});
            end_after_report();
        }
    }
}

CallMark* claim_mark() {
    // An alternate stack first, unless the thread has one (a sanitizer's): a stack overflow needs it.
    stack_t old{};
    if (sigaltstack(nullptr, &old) == 0 && (old.ss_flags & SS_DISABLE) != 0) {
        if (void* p = std::malloc(k_signal_stack_bytes)) {
            stack_t ss{};
            ss.ss_sp = p;
            ss.ss_size = k_signal_stack_bytes;
            if (sigaltstack(&ss, nullptr) == 0)
                t_guard.stack = p;
            else
                std::free(p);
        }
    }
    for (CallMark& m : g_marks) {
        bool free = false;
        if (m.owned.compare_exchange_strong(free, true)) {
            t_guard.mark = &m;
            t_mark = &m;
            return &m;
        }
    }
    t_mark = &t_own_mark;
    return t_mark;
}

/// Fills mark with a call's description (before it is marked active).
void describe(CallMark& mark, std::size_t slot, PluginOp op, std::initializer_list<double> args) {
    mark.slot.store(static_cast<std::uint8_t>(slot), std::memory_order_relaxed);
    mark.op.store(op, std::memory_order_relaxed);
    std::size_t n = 0;
    for (const double x : args) {
        if (n == k_max_call_args) break;
        mark.args[n++].store(x, std::memory_order_relaxed);
    }
    mark.arg_count.store(static_cast<std::uint8_t>(n), std::memory_order_relaxed);
}

}  // namespace

void guard_name_plugin(std::size_t slot, std::string_view name, std::string_view path) {
    PluginName& id = g_names[slot];
    id.name.fill('\0');
    id.path.fill('\0');
    std::copy_n(name.data(), std::min(name.size(), id.name.size() - 1), id.name.data());
    std::copy_n(path.data(), std::min(path.size(), id.path.size() - 1), id.path.data());
}

void guard_start(double timeout_s) {
    static std::once_flag once;
    std::call_once(once, [timeout_s] {
        struct sigaction act{};
        act.sa_sigaction = on_fault;
        act.sa_flags = SA_SIGINFO | SA_ONSTACK;
        sigemptyset(&act.sa_mask);
        for (std::size_t i = 0; i < k_signals.size(); ++i) sigaction(k_signals[i], &act, &g_previous[i]);
        if (timeout_s <= 0) return;
        g_timeout_s = timeout_s;
        const auto r = fmt::format_to_n(g_timeout_text.data(), g_timeout_text.size() - 1, "{}", timeout_s);
        *r.out = '\0';
        std::thread(watch).detach();
    });
}

PluginCall::PluginCall(std::size_t slot, PluginOp op, std::initializer_list<double> args) noexcept {
    CallMark* mark = t_mark != nullptr ? t_mark : claim_mark();
    describe(*mark, slot, op, args);
    mark->calls.fetch_add(1);
    mark->active.store(true);
}

PluginCall::~PluginCall() { t_mark->active.store(false); }

void plugin_broke_header(std::size_t slot, PluginOp op, std::initializer_list<double> args, std::string_view what) {
    CallMark* mark = t_mark != nullptr ? t_mark : claim_mark();
    describe(*mark, slot, op, args);
    if (g_reporting.exchange(true))
        for (;;) pause();  // another report ends the process
    report(Fault::header, 0, *mark, what);
    end_after_report();
}

}  // namespace detail

void stage_plugin_input(PluginStage stage) {
    auto staged = std::make_unique<detail::Staged>();
    staged->doing = std::move(stage.doing);
    if (!stage.log_text.empty() && !stage.keep_as.empty()) {
        const std::filesystem::path dir = stage.keep_as.has_parent_path() ? stage.keep_as.parent_path() : ".";
        std::error_code ec;
        std::filesystem::create_directories(dir, ec);
        staged->text = std::move(stage.log_text);
        staged->keep = stage.keep_as.string();
        // write_file_atomically's temporary name (".NAME.tmp.PID.XXXXXX"), so a stale one is cleaned up alike.
        staged->aside = (dir / fmt::format(".{}.tmp.{}.plugin", stage.keep_as.filename().string(), ::getpid())).string();
    }
    const std::lock_guard lock(detail::g_stage_mutex);
    auto& slot = detail::g_stage_store[detail::g_stage_next];
    slot = std::move(staged);
    detail::g_stage.store(slot.get());
    detail::g_stage_next ^= 1;
}

void clear_plugin_stage() { detail::g_stage.store(nullptr); }

void set_plugin_fault_action(PluginFaultAction action) { detail::g_action.store(action); }

}  // namespace ricochet
