// Moving-scene generator for the properties: any scene with walls and moving balls (single walls, wall
// soups and closed polygons, mixed by weight).
#pragma once

#include <rapidcheck.h>

#include "generators_polygons.hpp"
#include "generators_walls.hpp"
#include "ricochet/scene.hpp"

namespace ricochet::props::gen {

namespace rcg = rc::gen;

/// Any scene with walls and moving balls: single walls, wall soups and closed polygons.
inline rc::Gen<Scene> moving_scene(int max_frames) {
    return rcg::weightedOneOf<Scene>({{3, wall_scene(1, max_frames)},
                                      {2, wall_scene(5, max_frames)},
                                      {2, polygon_scene(true, max_frames)},
                                      {1, polygon_scene(false, max_frames)}});
}

}  // namespace ricochet::props::gen
