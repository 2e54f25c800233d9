// An event's `ricochet run` line (event.hpp), through its formatter (format.hpp).
#include "ricochet/format.hpp"

#include <iterator>

namespace ricochet {

std::string format_event(const Event& e) { return fmt::format("{}", e); }

void append_event_line(std::string& out, const Event& e) { fmt::format_to(std::back_inserter(out), "{}\n", e); }

}  // namespace ricochet
