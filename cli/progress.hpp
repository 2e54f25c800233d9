// A progress line on stderr for a command that runs longer than a couple of seconds, rewritten in place
// with \r. Shown only when stderr is a terminal and stdout is not (there the output itself scrolls by), or,
// for a command that writes its output only at its end (reduce), whenever stderr is a terminal; silent
// otherwise, so logs and CI output never see it.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <string>

namespace ricochet::cli {

/// "WHAT: frame DONE of TOTAL (P %)" (or "log DONE of TOTAL"), from k_progress_delay on, at most 4 times a second.
class Progress {
public:
    /// What is counted: frames (cheap, many: the clock is read every 16th call) or logs (every call).
    enum class Unit { frame, log };
    /// Who sees it: stderr a terminal and stdout not, or stderr a terminal (output only at the end).
    enum class Shown { output_elsewhere, output_at_end };
    /// what: the line's prefix ("ricochet run LOG").
    explicit Progress(std::string what, Unit unit = Unit::frame, Shown shown = Shown::output_elsewhere);
    /// Clears the line if one was shown.
    ~Progress();
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;

    /// Reports done of total frames; cheap enough to call every frame.
    void update(std::int64_t done, std::int64_t total);
    /// Shows "WHAT: TEXT" instead of a count (text() is called only when the line is redrawn); reads the
    /// clock, so call it per unit of work that takes a microsecond or more.
    void update(const std::function<std::string()>& text);
    /// Erases the line, if one is shown, before something else is printed on stderr; the next update
    /// draws it again.
    void clear();

private:
    using Clock = std::chrono::steady_clock;
    std::string what_;
    Unit unit_;
    bool enabled_ = false;
    bool shown_ = false;
    std::uint32_t calls_ = 0;
    Clock::time_point start_;
    Clock::time_point next_;
};

}  // namespace ricochet::cli
