// Plug-in kernels: KernelOps (plain function pointers, no context) for each plug-in slot, through a type per
// slot whose functions call that slot's plug-in under the guard, converting to and from plugin.h's C types,
// supplying the robust kernel's function where the plug-in has none, and rejecting answers plugin.h does not
// allow. Its discs are plugin_disc.cpp's.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <utility>

#include <fmt/format.h>

#include "kernels/naive_frame.hpp"
#include "kernels/plugin/plugin_table.hpp"
#include "kernels/robust/robust_kernel.hpp"

namespace ricochet::detail {
namespace {

// plugin.h's miss codes are Miss's values, RICOCHET_MISS is Miss::no_reason.
static_assert(RICOCHET_HIT == static_cast<int>(Miss::none) &&
              RICOCHET_MISS_BOTH_INSIDE == static_cast<int>(Miss::both_inside) &&
              RICOCHET_MISS_BOTH_OUTSIDE == static_cast<int>(Miss::both_outside) &&
              RICOCHET_MISS_PARALLEL == static_cast<int>(Miss::parallel) &&
              RICOCHET_MISS_BEFORE_P0 == static_cast<int>(Miss::before_p0) &&
              RICOCHET_MISS_PAST_P1 == static_cast<int>(Miss::past_p1) &&
              RICOCHET_MISS_DEGENERATE == static_cast<int>(Miss::degenerate) &&
              RICOCHET_MISS_LEAVING == static_cast<int>(Miss::leaving) &&
              RICOCHET_MISS == static_cast<int>(Miss::no_reason));
static_assert(RICOCHET_PLUGIN_MAX_BOUNCES == k_max_bounces);
// A frame step reads the scene's walls in place: Wall and ricochet_wall are laid out alike (only C code reads
// them through the C type).
static_assert(std::is_standard_layout_v<Wall> && std::is_standard_layout_v<Vec2> && sizeof(Vec2) == sizeof(ricochet_vec2) &&
              offsetof(Vec2, y) == offsetof(ricochet_vec2, y) && sizeof(Wall) == sizeof(ricochet_wall) &&
              offsetof(Wall, p1) == offsetof(ricochet_wall, p1));

ricochet_vec2 to_c(Vec2 p) { return {p.x, p.y}; }
Vec2 from_c(ricochet_vec2 p) { return {p.x, p.y}; }
ricochet_wall to_c(const Wall& w) { return {to_c(w.p0), to_c(w.p1)}; }
ricochet_circle to_c(const Circle& c) { return {to_c(c.c), c.r}; }
ricochet_rect to_c(const Rect& r) { return {r.left, r.bottom, r.right, r.top}; }

Side classify(std::size_t s, Vec2 p, const Wall& w) {
    const LoadedPlugin& pl = loaded_plugin(s);
    if (pl.api.classify == nullptr) return RobustKernel::classify(p, w);
    const ricochet_wall cw = to_c(w);
    std::int32_t side = 0;
    {
        const PluginCall call(s, PluginOp::classify, {p.x, p.y, w.p0.x, w.p0.y, w.p1.x, w.p1.y});
        side = pl.api.classify(pl.context, to_c(p), &cw);
    }
    return side_from_sign(side > 0 ? 1 : side < 0 ? -1 : 0);
}

bool point_in_circle(std::size_t s, Vec2 p, const Circle& c) {
    const LoadedPlugin& pl = loaded_plugin(s);
    if (pl.api.point_in_circle == nullptr) return RobustKernel::point_in_circle(p, c);
    const ricochet_circle cc = to_c(c);
    const PluginCall call(s, PluginOp::point_in_circle, {p.x, p.y, c.c.x, c.c.y, c.r});
    return pl.api.point_in_circle(pl.context, to_c(p), &cc) != 0;
}

bool circles_overlap(std::size_t s, const Circle& a, const Circle& b) {
    const LoadedPlugin& pl = loaded_plugin(s);
    if (pl.api.circles_overlap == nullptr) return RobustKernel::circles_overlap(a, b);
    const ricochet_circle ca = to_c(a), cb = to_c(b);
    const PluginCall call(s, PluginOp::circles_overlap, {a.c.x, a.c.y, a.r, b.c.x, b.c.y, b.r});
    return pl.api.circles_overlap(pl.context, &ca, &cb) != 0;
}

bool point_in_rect(std::size_t s, Vec2 p, const Rect& r) {
    const LoadedPlugin& pl = loaded_plugin(s);
    if (pl.api.point_in_rect == nullptr) return RobustKernel::point_in_rect(p, r);
    const ricochet_rect cr = to_c(r);
    const PluginCall call(s, PluginOp::point_in_rect, {p.x, p.y, r.left, r.bottom, r.right, r.top});
    return pl.api.point_in_rect(pl.context, to_c(p), &cr) != 0;
}

bool rects_overlap(std::size_t s, const Rect& a, const Rect& b) {
    const LoadedPlugin& pl = loaded_plugin(s);
    if (pl.api.rects_overlap == nullptr) return RobustKernel::rects_overlap(a, b);
    const ricochet_rect ca = to_c(a), cb = to_c(b);
    const PluginCall call(s, PluginOp::rects_overlap,
                          {a.left, a.bottom, a.right, a.top, b.left, b.bottom, b.right, b.top});
    return pl.api.rects_overlap(pl.context, &ca, &cb) != 0;
}

Sweep sweep(std::size_t s, Vec2 bs, Vec2 v, const Wall& w) {
    const LoadedPlugin& pl = loaded_plugin(s);
    const ricochet_wall cw = to_c(w);
    ricochet_sweep_result r{RICOCHET_MISS, 0.0, {0.0, 0.0}};
    const auto args = {bs.x, bs.y, v.x, v.y, w.p0.x, w.p0.y, w.p1.x, w.p1.y};
    {
        const PluginCall call(s, PluginOp::sweep, args);
        pl.api.sweep(pl.context, to_c(bs), to_c(v), &cw, &r);
    }
    if (r.miss < RICOCHET_HIT || r.miss > RICOCHET_MISS)
        plugin_broke_header(s, PluginOp::sweep, args,
                            fmt::format("answered miss code {}, which is none of RICOCHET_HIT, RICOCHET_MISS_* and "
                                        "RICOCHET_MISS",
                                        r.miss));
    const auto miss = static_cast<Miss>(r.miss);
    // A miss's t and point mean nothing: a miss is all there is to compare.
    if (miss != Miss::none) return {miss, 0.0, {}};
    return {Miss::none, r.t, from_c(r.point)};
}

Vec2 reflect(std::size_t s, Vec2 v, const Wall& w) {
    const LoadedPlugin& pl = loaded_plugin(s);
    if (pl.api.reflect == nullptr) return RobustKernel::reflect(v, w);
    const ricochet_wall cw = to_c(w);
    const PluginCall call(s, PluginOp::reflect, {v.x, v.y, w.p0.x, w.p0.y, w.p1.x, w.p1.y});
    return from_c(pl.api.reflect(pl.context, to_c(v), &cw));
}

/// The plug-in's own frame step: its hits and end state, checked against plugin.h's limits; a trace gets what
/// the frame shows (no legs) and the reflections it reports.
FrameStatus step_frame(std::size_t s, Ball& ball, std::span<const Wall> walls, std::vector<HitEvent>& hits,
                       StepScratch& scratch) {
    const LoadedPlugin& pl = loaded_plugin(s);
    ricochet_hit room[RICOCHET_PLUGIN_MAX_BOUNCES] = {};
    ricochet_frame f{};
    f.ball = {to_c(ball.pos), to_c(ball.vel)};
    f.walls = reinterpret_cast<const ricochet_wall*>(walls.data());
    f.wall_count = static_cast<std::uint32_t>(walls.size());
    f.hit_capacity = RICOCHET_PLUGIN_MAX_BOUNCES;
    f.hits = room;
    f.status = RICOCHET_FRAME_OK;
    const auto args = {ball.pos.x, ball.pos.y, ball.vel.x, ball.vel.y, static_cast<double>(walls.size())};
    {
        const PluginCall call(s, PluginOp::step, args);
        pl.api.step(pl.context, &f);
    }
    const auto broke = [&](std::string what) { plugin_broke_header(s, PluginOp::step, args, what); };
    if (f.hit_count > RICOCHET_PLUGIN_MAX_BOUNCES)
        broke(fmt::format("answered {} hits, more than the {} it has room for", f.hit_count, RICOCHET_PLUGIN_MAX_BOUNCES));
    if (f.status != RICOCHET_FRAME_OK && f.status != RICOCHET_FRAME_BOUNCE_LIMIT)
        broke(fmt::format("answered status {}, which is neither RICOCHET_FRAME_OK nor RICOCHET_FRAME_BOUNCE_LIMIT", f.status));
    for (std::uint32_t k = 0; k < f.hit_count; ++k)
        if (room[k].wall >= f.wall_count)
            broke(fmt::format("answered a hit on wall {} of {}", room[k].wall, f.wall_count));
    for (std::uint32_t k = 0; k < f.hit_count; ++k) hits.push_back({room[k].wall, room[k].t, from_c(room[k].point)});
    ball = {from_c(f.ball.pos), from_c(f.ball.vel)};
    if (StepTrace* t = scratch.trace) {
        t->legs_traced = false;
        t->reflections += static_cast<int>(std::min<std::uint32_t>(f.reflections, std::numeric_limits<int>::max() / 2));
    }
    return f.status == RICOCHET_FRAME_BOUNCE_LIMIT ? FrameStatus::bounce_limit : FrameStatus::ok;
}

FrameStatus step_ball(std::size_t s, Ball& ball, std::span<const Wall> walls, std::vector<HitEvent>& hits,
                      StepScratch& scratch) {
    if (loaded_plugin(s).api.step != nullptr) return step_frame(s, ball, walls, hits, scratch);
    // Every wall of the scene, never a broad phase's candidates: what the plug-in is asked does not depend
    // on the grid's margin, whatever precision it computes in.
    return step_naive_frame<double>(
        ball, walls, hits, scratch, nullptr,
        [s](Vec2 pos, Vec2 d, const Wall& w) {
            const Sweep r = sweep(s, pos, d, w);
            return NaiveLeg<double>{r.miss, r.t, r.point};
        },
        [s](Vec2 v, const Wall& w) { return reflect(s, v, w); });
}

/// The kernel of plug-in slot S: KernelOps's functions without a context, so one type per slot.
template <std::size_t S>
struct SlotKernel {
    static Side classify(Vec2 p, const Wall& w) { return detail::classify(S, p, w); }
    static bool point_in_circle(Vec2 p, const Circle& c) { return detail::point_in_circle(S, p, c); }
    static bool circles_overlap(const Circle& a, const Circle& b) { return detail::circles_overlap(S, a, b); }
    static bool point_in_rect(Vec2 p, const Rect& r) { return detail::point_in_rect(S, p, r); }
    static bool rects_overlap(const Rect& a, const Rect& b) { return detail::rects_overlap(S, a, b); }
    static Sweep sweep(Vec2 bs, Vec2 v, const Wall& w) { return detail::sweep(S, bs, v, w); }
    static Vec2 reflect(Vec2 v, const Wall& w) { return detail::reflect(S, v, w); }
    /// Memory is not used (plugin.h has none) and the index is ignored (every wall is tried).
    static FrameStatus step_ball(Ball& ball, BallMemory& /*memory*/, std::span<const Wall> walls,
                                 std::vector<HitEvent>& hits, StepScratch& scratch, const WallIndex* /*index*/) {
        return detail::step_ball(S, ball, walls, hits, scratch);
    }
    /// Discs and bumpers (plugin_disc.cpp); plugin_kernel_ops keeps it only for a plug-in that sweeps discs.
    static FrameStatus step_disc(Ball& ball, BallMemory& /*memory*/, const Obstacles& obstacles,
                                 std::vector<HitEvent>& hits, StepScratch& scratch) {
        return step_plugin_disc(S, ball, obstacles, hits, scratch);
    }
    static constexpr bool k_steps_bumpers = true;
};

template <std::size_t... S>
constexpr std::array<KernelOps, sizeof...(S)> slot_kernels(std::index_sequence<S...>) {
    return {make_kernel_ops<SlotKernel<S>>("")...};
}

/// Every slot's functions; a slot's name and bounds are filled in when a plug-in takes it.
constexpr std::array<KernelOps, k_max_plugins> k_slot_kernels = slot_kernels(std::make_index_sequence<k_max_plugins>{});

}  // namespace

KernelOps plugin_kernel_ops(std::size_t slot) {
    const LoadedPlugin& pl = loaded_plugin(slot);
    KernelOps ops = k_slot_kernels[slot];
    ops.name = pl.info.name;
    // Both 0: no bound stated, so robust's (plugin.h).
    if (pl.api.speed_rel_bound != 0 || pl.api.speed_abs_bound != 0) {
        ops.speed_rel_bound = pl.api.speed_rel_bound;
        ops.speed_abs_bound = pl.api.speed_abs_bound;
    }
    // The user's own code, held to ricochet's guarantees: a saved failure is a regression that fails replay
    // until it is fixed (no `expect failure`), unlike the lecture baselines' and the peers' documented ones.
    ops.failures_documented = false;
    // Discs only with sweep_disc (plugin.h, ABI version 2), bumpers only with sweep_disc_bumper too: else the
    // kernel refuses such scenes (unsupported_scene), as every version-1 plug-in's does.
    if (pl.api.sweep_disc == nullptr) ops.step_disc = nullptr;
    ops.steps_bumpers = ops.step_disc != nullptr && pl.api.sweep_disc_bumper != nullptr;
    return ops;
}

}  // namespace ricochet::detail
