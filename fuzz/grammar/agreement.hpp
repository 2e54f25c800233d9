// The grammar oracle of the parser fuzz target and of the agreement test (grammar_agreement_main.cpp):
// the reader (parse_scene_log) accepts a text iff the independent acceptor does, and when both reject they
// name the same line. Header-only, so each binary compiles it with its own flags.
#pragma once

#include <cstdlib>
#include <string>
#include <string_view>
#include <variant>

#include <fmt/core.h>

#include "acceptor.hpp"
#include "ricochet/scene_log.hpp"

namespace ricochet_grammar {

/// Environment variable: when set (to anything but "0"), a known disagreement (Leniency) fails as well.
inline constexpr const char* k_strict_env = "RICOCHET_GRAMMAR_STRICT";

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
    bool known = false;   ///< they disagree, but agree once the acceptor has the reader's known leniencies
};

/// Compares the reader's verdict on text (parsed = parse_scene_log(text, …)) with the acceptor's.
inline Comparison compare(std::string_view text, const ricochet::SceneOrDiagnostic& parsed) {
    Comparison c{reader_verdict(parsed), accept_scene_log(text)};
    c.agree = same_verdict(c.reader, c.acceptor);
    if (!c.agree) {
        // The reader's departures from the spec found so far (fuzz/README.md, "The grammar oracle").
        const Leniency known{.uppercase_hash = true};
        c.known = same_verdict(c.reader, accept_scene_log(text, known));
    }
    return c;
}

/// True if the comparison fails the oracle: a disagreement, unless it is a known one and
/// $RICOCHET_GRAMMAR_STRICT is unset.
inline bool fails(const Comparison& c) {
    if (c.agree) return false;
    const char* strict = std::getenv(k_strict_env);
    return !c.known || (strict != nullptr && std::string_view(strict) != "0");
}

/// Both verdicts, for a failure report.
inline std::string report(const Comparison& c) {
    return fmt::format("the reader and the grammar acceptor disagree{}\n  reader:   {}\n  acceptor: {}",
                       c.known ? " (a known leniency of the reader)" : "", describe(c.reader), describe(c.acceptor));
}

}  // namespace ricochet_grammar
