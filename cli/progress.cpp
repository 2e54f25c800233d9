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

Progress::Progress(std::string what)
    : what_(std::move(what)), enabled_(::isatty(STDERR_FILENO) == 1 && ::isatty(STDOUT_FILENO) != 1),
      start_(Clock::now()), next_(start_ + k_progress_delay) {}

Progress::~Progress() {
    // Erase the line: carriage return, then clear to its end.
    if (shown_) fmt::print(stderr, "\r\x1b[K");
}

void Progress::update(std::int64_t done, std::int64_t total) {
    // The clock is read once per 16 calls: a frame can take well under a microsecond.
    if (!enabled_ || (calls_++ & 15u) != 0) return;
    const auto now = Clock::now();
    if (now < next_) return;
    next_ = now + k_progress_period;
    const double pct = total > 0 ? 100.0 * static_cast<double>(done) / static_cast<double>(total) : 100.0;
    fmt::print(stderr, "\r{}: frame {} of {} ({:.0f} %)\x1b[K", what_, done, total, pct);
    std::fflush(stderr);
    shown_ = true;
}

}  // namespace ricochet::cli
