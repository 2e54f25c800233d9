// The acceptor's one exact decision (docs/scene-log.md, "Domain"): a wall at least L long, |P1 − P0| ≥ L, decided
// exactly with the standard library alone (never the core's predicates: the acceptor is independent of them).
#pragma once

namespace ricochet_grammar {

/// True if |(x1, y1) − (x0, y0)| ≥ length, exactly; every argument finite.
bool wall_at_least(double x0, double y0, double x1, double y1, double length);

}  // namespace ricochet_grammar
