// Render: a scene and its run drawn as SVG, so a failure can be looked at rather than read.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "ricochet/checks.hpp"
#include "ricochet/scene.hpp"

namespace ricochet {

/// Which part of the world the picture shows.
enum class RenderView : std::uint8_t {
    failure,  ///< the failing frame with what it failed against: the failing ball's path in it (a disc's
              ///< radius around it), the walls it met, the wall or bumper a disc reached into, with a margin;
              ///< without a frame range, the paths of the frames around it only; an inset at the failure's own
              ///< scale when it is too small to see (the whole scene when the run has no failure)
    all,      ///< every static shape and every path drawn
};

/// What to draw.
struct RenderOptions {
    std::int64_t first_frame = 0;                  ///< paths drawn from this frame's state…
    std::optional<std::int64_t> last_frame;        ///< …to this one's (default: the last frame run)
    int width = 800;                               ///< picture width in pixels
    RenderView view = RenderView::failure;         ///< where the picture looks
    std::uint32_t max_balls = 64;                  ///< paths drawn for at most this many balls (the failing ball always)
    std::uint32_t max_points = 100000;             ///< path points drawn in all, shared by the balls drawn
};

/// A finished picture and what the run it shows found.
struct RenderResult {
    std::string svg;                       ///< the picture
    std::int64_t frames_run = 0;           ///< frames stepped
    std::optional<CheckFailure> failure;   ///< the first broken invariant, as replay finds it
    std::optional<StepError> error;        ///< the run stopped: a ball left the accepted range
};

/// Called with frames done of frames to do, every frame.
using RenderProgress = std::function<void(std::int64_t done, std::int64_t total)>;

/// Runs the scene under kernel with its checks and draws it in one pass over the events, keeping only the
/// drawn balls' points of frames first..last and the failing frame. The run stops after the last frame
/// drawn once the first failure is found (or, with RenderView::all, at the last frame drawn); it goes on
/// past it only to find that failure, so the mark is the one `replay` reports.
RenderResult render_run(const Scene& scene, KernelId kernel, const RenderOptions& options = {},
                        const RenderProgress& progress = {});

/// An SVG picture of a run already made (its events, frame by frame, and its failure): walls (with their
/// outward normals and indices), circles, rects, the drawn balls' paths with their hit points, start and
/// end, and a red marker where run.failure happened (on the wall, where a no-tunnel piece crossed it).
std::string render_svg(const Scene& scene, const CheckedRun& run, const RenderOptions& options = {});

}  // namespace ricochet
