// The progress line (progress.hpp).
#include "progress.hpp"

#include <unistd.h>

#include <cstdio>

#include <fmt/format.h>

namespace ricochet::cli {

namespace {

/// Runs shorter than this print no progress at all.
constexpr std::chrono::seconds k_progress_delay{2};
/// The line is rewritten at most this often.
constexpr std::chrono::milliseconds k_progress_period{250};

}  // namespace

Progress::Progress(std::string what, Unit unit, Shown shown)
    : what_(std::move(what)), unit_(unit),
      enabled_(::isatty(STDERR_FILENO) == 1 && (shown == Shown::output_at_end || ::isatty(STDOUT_FILENO) != 1)),
      start_(Clock::now()), next_(start_ + k_progress_delay) {}

Progress::~Progress() { clear(); }

void Progress::clear() {
    // Degenerate: nothing shown (before k_progress_delay, or not a terminal).
    if (!shown_) return;
    // Erase the line: carriage return, then clear to its end; drawn again at the next update.
    fmt::print(stderr, "\r\x1b[K");
    shown_ = false;
    next_ = Clock::now();
}

void Progress::update(std::int64_t done, std::int64_t total) {
    // The clock is read once per 16 frames: a frame can take well under a microsecond.
    if (!enabled_ || (unit_ == Unit::frame && (calls_++ & 15u) != 0)) return;
    const auto now = Clock::now();
    if (now < next_) return;
    next_ = now + k_progress_period;
    const double pct = total > 0 ? 100.0 * static_cast<double>(done) / static_cast<double>(total) : 100.0;
    fmt::print(stderr, "\r{}: {} {} of {} ({:.0f} %)\x1b[K", what_, unit_ == Unit::frame ? "frame" : "log", done, total, pct);
    std::fflush(stderr);
    shown_ = true;
}

void Progress::update(const std::function<std::string()>& text) {
    if (!enabled_) return;
    const auto now = Clock::now();
    if (now < next_) return;
    next_ = now + k_progress_period;
    fmt::print(stderr, "\r{}: {}\x1b[K", what_, text());
    std::fflush(stderr);
    shown_ = true;
}

}  // namespace ricochet::cli
