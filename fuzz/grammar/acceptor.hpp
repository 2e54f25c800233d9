// An independent acceptor of the scene-log grammar (format 1), written from docs/scene-log.md alone: no
// ricochet header, no call into the reader (core/src/log/scene_log_format.cpp), standard library only. The
// parser fuzz target asserts that it and the reader accept the same texts and reject at the same line.
#pragma once

#include <string>
#include <string_view>

namespace ricochet_grammar {

/// Whether a text is a scene log, and if not, where the first error is.
struct Verdict {
    bool accepted = false;
    /// On rejection, the 1-based line the diagnostic points at (docs/scene-log.md, "Diagnostics"); 0 if accepted.
    int line = 0;
    /// On rejection, what is wrong (free text, for people); empty if accepted.
    std::string reason;
};

/// Decides text by docs/scene-log.md: lexical rules, directives and their arguments, numbers, limits,
/// order and repetition, and the checks that need the whole log.
Verdict accept_scene_log(std::string_view text);

}  // namespace ricochet_grammar
