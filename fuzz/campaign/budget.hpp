// A campaign's clock: when the command started, and in a campaign by time the deadline the whole command keeps
// (the workers' fuzzing, then its tail: converting failures into scene logs and merging the corpora).
#pragma once

#include <chrono>
#include <optional>
#include <string_view>

namespace ricochet::fuzz {

/// The clock of progress lines, worker restarts and the time budget.
using Clock = std::chrono::steady_clock;

/// Seconds between progress lines, while the workers fuzz and through the tail.
inline constexpr int k_progress_every_s = 5;

/// The share of a campaign by time kept for its tail: the workers fuzz for the first (1 − k_tail_share)·S of
/// `--time S` and the tail (converting the failures, merging the corpora) has the rest, up to S. What the tail
/// cannot finish by S is left for the next campaign on the cache.
inline constexpr double k_tail_share = 0.2;

/// When a campaign started and, in one by time, when it must end.
class Budget {
public:
    /// A campaign that started at start; seconds > 0 makes it one by time that ends by start + seconds.
    explicit Budget(Clock::time_point start = Clock::now(), double seconds = 0);
    /// Seconds since the start.
    double elapsed() const;
    /// True in a campaign by time.
    bool timed() const { return deadline_.has_value(); }
    /// The deadline of the whole command; none in a campaign by runs.
    std::optional<Clock::time_point> deadline() const { return deadline_; }
    /// Seconds from the start at which the workers stop (a campaign by time; the deadline's share of fuzzing).
    double fuzz_end_s() const { return fuzz_end_s_; }
    /// Seconds from the start to the deadline (0 in a campaign by runs).
    double deadline_s() const { return seconds_; }
    /// Seconds left until the deadline (a great many in a campaign by runs).
    double left() const;
    /// The earlier of the deadline and seconds from now.
    Clock::time_point within(double seconds) const;
    /// Prints one progress line, "[  12s] TARGET  WHAT", on stdout and flushes it.
    void say(std::string_view target, std::string_view what) const;

private:
    Clock::time_point start_;
    double seconds_ = 0;
    double fuzz_end_s_ = 0;
    std::optional<Clock::time_point> deadline_;
};

}  // namespace ricochet::fuzz
