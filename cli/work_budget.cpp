// The bound on a command's work (work_budget.hpp).
#include "work_budget.hpp"

#include <algorithm>
#include <limits>

#include <fmt/format.h>

#include "commands.hpp"
#include "ricochet/wall_grid.hpp"
#include "number_option.hpp"

namespace ricochet::cli {

namespace {

/// a × b, or the largest uint64 if that overflows.
std::uint64_t saturating_mul(std::uint64_t a, std::uint64_t b) {
    constexpr std::uint64_t max = std::numeric_limits<std::uint64_t>::max();
    return b != 0 && a > max / b ? max : a * b;
}

}  // namespace

std::uint64_t estimated_work(const Scene& scene, std::int64_t frames) {
    // The wall index is built even for `frames 0`: at most k_max_references_per_wall references a wall.
    const std::uint64_t index = saturating_mul(scene.walls.size(), k_max_references_per_wall);
    // Degenerate: a negative frame count steps nothing.
    if (frames <= 0) return index;
    const std::uint64_t entities = std::uint64_t{scene.walls.size()} + scene.circles.size() + scene.rects.size() +
                                    scene.bumpers.size() + 1;
    const std::uint64_t steps =
        saturating_mul(saturating_mul(static_cast<std::uint64_t>(frames), scene.balls.size()), entities);
    return steps > std::numeric_limits<std::uint64_t>::max() - index ? std::numeric_limits<std::uint64_t>::max()
                                                                    : steps + index;
}

void add_max_work_option(CLI::App& command, std::uint64_t& max_work) {
    command
        .add_option("--max-work", max_work,
                    fmt::format("refuse a log whose frames × balls × (walls + circles + rects + bumpers + 1) + {} × walls "
                                "is over N (default {}; 0: no bound)",
                                k_max_references_per_wall, k_default_max_work))
        ->option_text("N")
        ->check(number_in<std::uint64_t>(0, std::numeric_limits<std::uint64_t>::max(), "a work bound"));
}

std::string work_over_budget(const std::string& log, const Scene& scene, std::int64_t frames, std::uint64_t max_work) {
    const std::uint64_t work = estimated_work(scene, frames);
    if (max_work == 0 || work <= max_work) return {};
    return fmt::format(
        "{}: too much work: {} frames × {} balls × ({} walls + {} circles + {} rects + {} bumpers + 1) + {} × {} walls "
        "(the wall index) = {} is over the bound of {}; raise it with --max-work N (0: no bound)",
        log, std::max<std::int64_t>(frames, 0), scene.balls.size(), scene.walls.size(), scene.circles.size(),
        scene.rects.size(), scene.bumpers.size(), k_max_references_per_wall, scene.walls.size(), work, max_work);
}

void check_work_or_exit(const std::string& log, const Scene& scene, std::int64_t frames, std::uint64_t max_work) {
    const std::string error = work_over_budget(log, scene, frames, max_work);
    if (error.empty()) return;
    fmt::print(stderr, "ricochet: error: {}\n", error);
    throw Exit{2};
}

}  // namespace ricochet::cli
