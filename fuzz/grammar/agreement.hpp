// The grammar oracle of the parser fuzz target and of the agreement test (grammar_agreement_main.cpp):
// the reader (parse_scene_log) accepts a text iff the independent acceptor does, and when both reject they
// name the same line. Header-only, so each binary compiles it with its own flags.
#pragma once

#include <string>
#include <string_view>
#include <variant>

#include <fmt/core.h>

#include "acceptor.hpp"
#include "ricochet/scene_log.hpp"

namespace ricochet_grammar {

/// The reader's verdict in the acceptor's terms.
inline Verdict reader_verdict(const ricochet::SceneOrDiagnostic& parsed) {
    if (const auto* d = std::get_if<ricochet::Diagnostic>(&parsed)) return {false, d->line, d->str()};
    return {true, 0, {}};
}

/// Same acceptance, and the same line when both reject.
inline bool same_verdict(const Verdict& a, const Verdict& b) {
    return a.accepted == b.accepted && (a.accepted || a.line == b.line);
}

/// "accepted" or "rejected at line N: REASON".
inline std::string describe(const Verdict& v) {
    return v.accepted ? std::string("accepted") : fmt::format("rejected at line {}: {}", v.line, v.reason);
}

/// How the reader and the acceptor compare on one text.
struct Comparison {
    Verdict reader;
    Verdict acceptor;     ///< the spec as written
    bool agree = false;   ///< same_verdict(reader, acceptor)
};

/// Compares the reader's verdict on text (parsed = parse_scene_log(text, …)) with the acceptor's.
inline Comparison compare(std::string_view text, const ricochet::SceneOrDiagnostic& parsed) {
    Comparison c{reader_verdict(parsed), accept_scene_log(text)};
    c.agree = same_verdict(c.reader, c.acceptor);
    return c;
}

/// True if the comparison fails the oracle: any disagreement.
inline bool fails(const Comparison& c) { return !c.agree; }

/// Both verdicts, for a failure report.
inline std::string report(const Comparison& c) {
    return fmt::format("the reader and the grammar acceptor disagree\n  reader:   {}\n  acceptor: {}",
                       describe(c.reader), describe(c.acceptor));
}

}  // namespace ricochet_grammar
