// Internal: which `expect state` lines `ricochet record` and a failure log write for a run through frame
// `last` (docs/scene-log.md): every frame 0..last while (last + 1) × balls ≤ k_failure_log_all_frames
// (64), else the 8 frames last·k/8, k = 1..8; balls 0 .. k_failure_log_balls − 1 (0..7) only.
#pragma once

#include <algorithm>
#include <cstdint>
#include <set>
#include <span>
#include <utility>
#include <vector>

#include "ricochet/event.hpp"
#include "ricochet/expect.hpp"
#include "ricochet/failure_log.hpp"

namespace ricochet::detail {

/// Keeps the sampled states of a run as its frames go by (feed it CheckOptions::on_frame's events).
class StateSampler {
public:
    /// A run through frame last (nothing is sampled when last < 0) with `balls` balls.
    StateSampler(std::int64_t last, std::size_t balls)
        : balls_(static_cast<std::uint32_t>(std::min<std::size_t>(balls, k_failure_log_balls))) {
        if (last < 0) return;
        if (static_cast<double>(last + 1) * static_cast<double>(balls) <= k_failure_log_all_frames) {
            for (std::int64_t f = 0; f <= last; ++f) frames_.insert(f);
        } else {
            for (std::int64_t k = 1; k <= 8; ++k) frames_.insert(last * k / 8);
        }
    }
    /// Keeps the events' states at sampled frames for the sampled balls, in order.
    void add(std::span<const Event> events) {
        for (const Event& e : events)
            if (e.kind == Event::Kind::state && e.ball < balls_ && frames_.count(e.frame))
                states_.push_back({e.frame, e.ball, Ball{e.pos, e.vel}});
    }
    /// The states kept so far.
    std::vector<ExpectState> take() { return std::move(states_); }

private:
    std::uint32_t balls_;
    std::set<std::int64_t> frames_;
    std::vector<ExpectState> states_;
};

}  // namespace ricochet::detail
