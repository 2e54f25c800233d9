// The README's speed targets judged on one `ricochet bench` run (bench_targets.hpp).
#include "bench_targets.hpp"

#include <array>
#include <string_view>

#include <fmt/format.h>

namespace ricochet::bench {
namespace {

const Row* find(std::span<const Row> rows, std::string_view workload, std::string_view method) {
    for (const Row& r : rows)
        if (r.workload == workload && r.method == method) return &r;
    return nullptr;
}

/// The peers' ratios on a workload, as "Box2D 1.08×, CGAL 1.21×"; with their tunnels on a closed box.
std::string peers(std::span<const Row> rows, std::string_view workload) {
    constexpr std::array<std::array<std::string_view, 2>, 3> names{
        {{"box2d", "Box2D 2.4.1"}, {"chipmunk", "Chipmunk 7"}, {"cgal", "CGAL 5.5"}}};
    std::string out;
    for (const auto& [method, name] : names)
        if (const Row* r = find(rows, workload, method); r != nullptr && !std::isnan(r->ratio)) {
            out += fmt::format("{}{} {:.2f}×", out.empty() ? "" : ", ", name, r->ratio);
            if (r->tunnels >= 0) out += fmt::format(" ({} tunnels)", r->tunnels);
        }
    return out;
}

/// Robust at most limit times lecture-double on workload.
Verdict ratio_target(std::span<const Row> rows, std::string label, std::string_view workload, double limit,
                     std::string_view unit) {
    Verdict v{.workload = std::move(label), .limit = limit, .target = fmt::format("≤ {}×", limit)};
    if (const Row* r = find(rows, workload, "robust"); r != nullptr && !std::isnan(r->ratio)) {
        v.value = r->ratio;
        v.robust = fmt::format("{:.1f} ns{}", r->ns, unit);
        if (r->tunnels >= 0) v.robust += fmt::format(", {} tunnels", r->tunnels);
        v.ratio = fmt::format("{:.2f}×", r->ratio);
    }
    v.peers = peers(rows, workload);
    return v;
}

/// The batched robust decision at most limit ns per ball-wall pair on workload.
Verdict batch_target(std::span<const Row> rows, std::string label, std::string_view workload, double limit) {
    Verdict v{.workload = std::move(label), .limit = limit, .target = fmt::format("≤ {} ns", limit)};
    if (const Row* r = find(rows, workload, "robust-batch"); r != nullptr && !std::isnan(r->ns)) {
        v.value = r->ns;
        v.robust = fmt::format("{:.1f} ns per pair", r->ns);
        // conv: lanes left to the scalar exact predicates (after both SIMD stages), per mille.
        if (r->conv >= 0)
            v.robust += fmt::format(", {:.1f} % of lanes to the exact predicates", 0.1 * static_cast<double>(r->conv));
    }
    return v;
}

}  // namespace

std::vector<Verdict> bench_targets(std::span<const Row> rows, std::span<const Row> disc_rows) {
    return {
        ratio_target(rows, "sweep, uniform", "uniform", 1.2, ""),
        ratio_target(rows, "sweep, end on the wall", "end-on-wall", 1.5, ""),
        ratio_target(rows, "sweep, at an end point", "at-endpoint", 1.5, ""),
        ratio_target(rows, "static point/circle, boundary-heavy", "point-circle", 3, ""),
        ratio_target(rows, "static circle/circle, boundary-heavy", "circle-circle", 3, ""),
        ratio_target(rows, "closed box", "box", 1.5, " per ball-frame"),
        ratio_target(rows, "closed box, turned", "box-turned", 1.5, " per ball-frame"),
        ratio_target(rows, "closed box, far (1e6)", "box-far-1e6", 1.5, " per ball-frame"),
        batch_target(rows, "batch, uniform pairs", "uniform-pairs", 1.5),
        batch_target(rows, "batch, end-on-wall pairs", "end-on-wall-pairs", 10),
        ratio_target(disc_rows, "discs, uniform", "disc-uniform", 2, ""),
        ratio_target(disc_rows, "discs, grazing", "disc-grazing", 4, ""),
        ratio_target(disc_rows, "discs, caps", "disc-cap", 4, ""),
        ratio_target(disc_rows, "discs among bumpers", "bumper", 4, ""),
    };
}

}  // namespace ricochet::bench
