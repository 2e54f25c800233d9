// Internal to reduce_log: its passes. Each tries smaller candidates of the current failing scene
// (Trials::attempt keeps every one that still fails) and returns once it has none left or the tries are
// spent; a pass is deterministic, so the same scene gives the same tries.
#pragma once

#include <vector>

#include "reduce/trials.hpp"

namespace ricochet::detail::reduce {

/// Balls: the failing ball alone, then delta debugging (cut.cpp).
void cut_balls(Trials& trials);
/// Walls: for no-tunnel the wall the path went through alone, then with the walls the failing ball hit in
/// the failing frame, then with every wall any ball hit; then delta debugging (cut.cpp).
void cut_walls(Trials& trials);
/// Circles, then rects, then bumpers: delta debugging (cut.cpp).
void cut_statics(Trials& trials);

/// Frames from the front: every ball started from its state at frame F − L, for L = 0, 1, 2, 4, … below the
/// failing frame F, the first that fails kept (front.cpp).
void cut_front_frames(Trials& trials);

/// Numbers: the masses dropped (every mass 1), then each coordinate of each ball, wall, circle and rect, and
/// each mass, in turn replaced by the first of its simpler numbers that keeps the failure (numbers.cpp).
void simplify_numbers(Trials& trials);

/// The numbers simpler than x, simplest first: fewer characters as the log prints them (shortest round
/// trip), then without a sign, then smaller in magnitude. They are 0, x without its sign, the integers
/// next to x, x to 1..16 significant digits and the dyadic fractions k/2^j (j = 1..16) nearest to x; every
/// one finite and in the accepted range, none equal to x (numbers.cpp).
std::vector<double> simpler_numbers(double x);

}  // namespace ricochet::detail::reduce
