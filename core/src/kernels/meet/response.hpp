// Internal: the response at a meet (docs/scene-log.md, "Balls that meet", 5), the elastic collision along the line
// of the printed centres n = X_a − X_b with the masses:
//   u = (v_a − v_b)·n / (n·n),  v_a′ = v_a − 2·m_b/(m_a + m_b)·u·n,  v_b′ = v_b + 2·m_a/(m_a + m_b)·u·n,
// which keeps momentum m_a·v_a + m_b·v_b and kinetic energy exactly (equal masses exchange their normal components).
#pragma once

#include "ricochet/shapes.hpp"

namespace ricochet::meet {

/// (v_a − v_b)·(X_a − X_b) < 0, exactly: the printed centres approach.
bool approaching(const Ball& a, const Ball& b);

/// robust's response: in doubles where n·n is a normal double and every result finite, else as respond_nearest.
/// Leaves both balls as they are and returns false where the centres do not approach.
bool respond_rounded(Ball& a, Ball& b, double ma, double mb);

/// exact's response: each component the double nearest its exact value. False, nothing changed, where the centres
/// do not approach.
bool respond_nearest(Ball& a, Ball& b, double ma, double mb);

}  // namespace ricochet::meet
