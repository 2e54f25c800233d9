// Render: a scene and its run drawn as SVG, so a failure can be looked at rather than read.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "ricochet/checks.hpp"
#include "ricochet/scene.hpp"

namespace ricochet {

/// What to draw.
struct RenderOptions {
    std::int64_t first_frame = 0;                  ///< paths drawn from this frame's state…
    std::optional<std::int64_t> last_frame;        ///< …to this one's (default: the last frame run)
    int width = 800;                               ///< picture width in pixels
};

/// An SVG picture: walls (with their outward normals and indices), circles, rects, each ball's path over
/// the frames with its hit points, start and end, and a red marker where run.failure happened.
std::string render_svg(const Scene& scene, const CheckedRun& run, const RenderOptions& options = {});

}  // namespace ricochet
