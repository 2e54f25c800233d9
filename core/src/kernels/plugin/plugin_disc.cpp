// A plug-in's discs (plugin.h, ABI version 2): the lecture's disc frame loop (naive_disc_frame.hpp) in double, with
// every contact decision, t_i, B_i and normal from the plug-in's sweep_disc and sweep_disc_bumper, each call under
// the guard and each answer checked against what plugin.h allows; the bounce is its reflect_disc, else robust's
// reflection about the returned normal.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "kernels/naive_disc_frame.hpp"
#include "kernels/plugin/plugin_table.hpp"
#include "kernels/robust/robust_kernel.hpp"

namespace ricochet::detail {
namespace {

using Contact = NaiveContact<double>;

/// The contact a sweep answered, or none for a miss; an answer plugin.h does not allow is reported (op, args).
std::optional<Contact> checked(std::size_t s, PluginOp op, std::initializer_list<double> args,
                               const ricochet_disc_result& r) {
    const auto broke = [&](std::string what) { plugin_broke_header(s, op, args, what); };
    if (r.miss < RICOCHET_HIT || r.miss > RICOCHET_MISS)
        broke(fmt::format("answered miss code {}, which is none of RICOCHET_HIT, RICOCHET_MISS_* and RICOCHET_MISS",
                          r.miss));
    // A miss's t, point and normal mean nothing.
    if (r.miss != RICOCHET_HIT) return std::nullopt;
    if (!(r.t >= 0.0 && r.t <= 1.0)) broke(fmt::format("answered a hit at t = {}, which is not in [0, 1]", r.t));
    if (!std::isfinite(r.point.x) || !std::isfinite(r.point.y))
        broke(fmt::format("answered a hit with its centre at ({}, {}), which is not finite", r.point.x, r.point.y));
    if (!std::isfinite(r.normal.x) || !std::isfinite(r.normal.y) || (r.normal.x == 0.0 && r.normal.y == 0.0))
        broke(fmt::format("answered a hit with the normal ({}, {}), which is {}", r.normal.x, r.normal.y,
                          r.normal.x == 0.0 && r.normal.y == 0.0 ? "zero" : "not finite"));
    return Contact{r.t, {r.point.x, r.point.y}, {r.normal.x, r.normal.y}};
}

/// The plug-in's sweep_disc: the leg bs → bs + v of a disc of radius R against w.
std::optional<Contact> sweep_disc(std::size_t s, Vec2 bs, Vec2 v, double R, const Wall& w) {
    const LoadedPlugin& pl = loaded_plugin(s);
    const ricochet_wall cw{{w.p0.x, w.p0.y}, {w.p1.x, w.p1.y}};
    ricochet_disc_result r{RICOCHET_MISS, 0.0, {0.0, 0.0}, {0.0, 0.0}};
    const auto args = {bs.x, bs.y, v.x, v.y, R, w.p0.x, w.p0.y, w.p1.x, w.p1.y};
    {
        const PluginCall call(s, PluginOp::sweep_disc, args);
        pl.api.sweep_disc(pl.context, {bs.x, bs.y}, {v.x, v.y}, R, &cw, &r);
    }
    return checked(s, PluginOp::sweep_disc, args, r);
}

/// The plug-in's sweep_disc_bumper: the same leg against bumper b.
std::optional<Contact> sweep_disc_bumper(std::size_t s, Vec2 bs, Vec2 v, double R, const Bumper& b) {
    const LoadedPlugin& pl = loaded_plugin(s);
    // Degenerate: no bumpers in this plug-in, so its kernel refuses scenes that have them (steps_bumpers false).
    if (pl.api.sweep_disc_bumper == nullptr) return std::nullopt;
    const ricochet_circle cb{{b.c.x, b.c.y}, b.r};
    ricochet_disc_result r{RICOCHET_MISS, 0.0, {0.0, 0.0}, {0.0, 0.0}};
    const auto args = {bs.x, bs.y, v.x, v.y, R, b.c.x, b.c.y, b.r};
    {
        const PluginCall call(s, PluginOp::sweep_disc_bumper, args);
        pl.api.sweep_disc_bumper(pl.context, {bs.x, bs.y}, {v.x, v.y}, R, &cb, &r);
    }
    return checked(s, PluginOp::sweep_disc_bumper, args, r);
}

/// v′ about the contact normal n: the plug-in's reflect_disc, else robust's reflection.
Vec2 reflect_disc(std::size_t s, Vec2 v, Vec2 n) {
    const LoadedPlugin& pl = loaded_plugin(s);
    if (pl.api.reflect_disc == nullptr) return reflect_about(v, n);
    const PluginCall call(s, PluginOp::reflect_disc, {v.x, v.y, n.x, n.y});
    const ricochet_vec2 r = pl.api.reflect_disc(pl.context, {v.x, v.y}, {n.x, n.y});
    return {r.x, r.y};
}

}  // namespace

FrameStatus step_plugin_disc(std::size_t s, Ball& ball, const Obstacles& obstacles, std::vector<HitEvent>& hits,
                             StepScratch& scratch) {
    // A point ball among bumpers is a disc of radius +0 (a radius of −0 is the point ball too).
    const double R = ball.r > 0.0 ? ball.r : 0.0;
    // Every obstacle of the scene, never a broad phase's candidates: what the plug-in is asked does not depend on
    // the indexes' margins. The trace's decision is the plug-in's answer: a contact or none.
    return step_naive_disc_frame<double>(
        ball, obstacles, hits, scratch,
        [s, R](Vec2 pos, Vec2 d, const Wall& w, const auto& offer) {
            const std::optional<Contact> c = sweep_disc(s, pos, d, R, w);
            if (!c) return Miss::no_reason;
            offer(*c);
            return Miss::none;
        },
        [s, R](Vec2 pos, Vec2 d, const Bumper& b, const auto& offer) {
            if (const std::optional<Contact> c = sweep_disc_bumper(s, pos, d, R, b)) offer(*c);
        },
        [s](Vec2 v, Vec2 n) { return reflect_disc(s, v, n); });
}

}  // namespace ricochet::detail
