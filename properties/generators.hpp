// Geometry generators for the properties: values you compose (RapidCheck's map, apply, oneOf, build) so
// that each regime is reached on purpose and every value shrinks toward a simple one.
//
// Numbers: small integers (and −0), dyadic fractions m/2^k, values near zero down to subnormals,
// magnitudes up to about ±1e15, far-from-origin offsets, and anything in between (random mantissa).
// Geometry: points exactly on a circle (Pythagorean triples scaled by powers of two), on a rectangle's
// edge or corner, on a wall's line (axis-aligned and small-integer-slope walls, P0 + t·e with dyadic t)
// and at its end points; end positions a few ulps either side of a wall; velocities parallel or nearly
// parallel to a wall; zero-length walls; zero velocities; closed polygons of walls (convex and concave,
// 2^−40 to 2^40 in size, far from the origin), with balls strictly inside or strictly outside.
// Every generator builds a whole Scene, so a failure is saved as the scene log it came from.
//
// One header per family: generators_numbers.hpp, generators_walls.hpp (walls and the balls aimed at them),
// generators_polygons.hpp, generators_statics.hpp, generators_scenes.hpp (moving_scene). This one
// includes them all.
#pragma once

#include "generators_numbers.hpp"
#include "generators_polygons.hpp"
#include "generators_scenes.hpp"
#include "generators_statics.hpp"
#include "generators_walls.hpp"
