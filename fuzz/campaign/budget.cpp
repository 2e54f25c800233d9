// A campaign's clock (budget.hpp).
#include "budget.hpp"

#include <cstdio>
#include <limits>

#include <fmt/format.h>

namespace ricochet::fuzz {

Budget::Budget(Clock::time_point start, double seconds) : start_(start) {
    if (seconds <= 0) return;
    seconds_ = seconds;
    fuzz_end_s_ = (1.0 - k_tail_share) * seconds;
    deadline_ = start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

double Budget::elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

double Budget::left() const {
    if (!deadline_) return std::numeric_limits<double>::max();
    return std::chrono::duration<double>(*deadline_ - Clock::now()).count();
}

Clock::time_point Budget::within(double seconds) const {
    const Clock::time_point t = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
    return deadline_ && *deadline_ < t ? *deadline_ : t;
}

void Budget::say(std::string_view target, std::string_view what) const {
    fmt::print("[{:4.0f}s] {:<7} {}\n", elapsed(), target, what);
    std::fflush(stdout);
}

}  // namespace ricochet::fuzz
