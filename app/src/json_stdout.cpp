// Standard output under --json (ricochet_app/json_stdout.hpp).
#include "ricochet_app/json_stdout.hpp"

#include <unistd.h>

#include <cstdio>

namespace ricochet::app {

JsonStdout::JsonStdout(bool on) : on_(on) {
    if (!on_) return;
    std::fflush(stdout);
    saved_ = ::dup(STDOUT_FILENO);
    // Degenerate: no descriptor to keep stdout in; then everything stays where it is.
    if (saved_ < 0) return;
    ::dup2(STDERR_FILENO, STDOUT_FILENO);
}

JsonStdout::~JsonStdout() { restore(); }

void JsonStdout::restore() {
    if (saved_ < 0) return;
    std::fflush(stdout);
    ::dup2(saved_, STDOUT_FILENO);
    ::close(saved_);
    saved_ = -1;
}

}  // namespace ricochet::app
