// A scene's domain (domain.hpp): what lies outside it, how a drawn scene is brought inside, the checks it waives,
// and its spelling in RICOCHET_DOMAIN and --domain.
#include "ricochet/domain.hpp"

#include <array>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "base/shown_text.hpp"
#include "ricochet/format.hpp"
#include "ricochet/from_chars.hpp"
#include "ricochet/limits.hpp"
#include "ricochet/predicates.hpp"
#include "ricochet/scene.hpp"

namespace ricochet {
namespace {

constexpr std::array<Check, 2> k_touching_checks = {Check::boundary, Check::oracle};

bool subnormal(double x) { return std::fpclassify(x) == FP_SUBNORMAL; }

/// Every number of the scene that is a coordinate or a radius (what `coordinates` bounds), with its name.
template <class F>
void each_length(const Scene& s, F&& f) {
    for (std::size_t i = 0; i < s.walls.size(); ++i) {
        const Wall& w = s.walls[i];
        f(w.p0.x, "wall", i, "X0"), f(w.p0.y, "wall", i, "Y0"), f(w.p1.x, "wall", i, "X1"), f(w.p1.y, "wall", i, "Y1");
    }
    for (std::size_t i = 0; i < s.balls.size(); ++i) {
        const Ball& b = s.balls[i];
        f(b.pos.x, "ball", i, "X"), f(b.pos.y, "ball", i, "Y"), f(b.r, "ball", i, "R");
    }
    for (std::size_t i = 0; i < s.circles.size(); ++i)
        f(s.circles[i].c.x, "circle", i, "X"), f(s.circles[i].c.y, "circle", i, "Y"), f(s.circles[i].r, "circle", i, "R");
    for (std::size_t i = 0; i < s.bumpers.size(); ++i)
        f(s.bumpers[i].c.x, "bumper", i, "X"), f(s.bumpers[i].c.y, "bumper", i, "Y"), f(s.bumpers[i].r, "bumper", i, "R");
    for (std::size_t i = 0; i < s.rects.size(); ++i) {
        const Rect& r = s.rects[i];
        f(r.left, "rect", i, "LEFT"), f(r.bottom, "rect", i, "BOTTOM"), f(r.right, "rect", i, "RIGHT"), f(r.top, "rect", i, "TOP");
    }
}

/// The number of doublings to undo so that every |x| of the values fits within bound: the least k ≥ 0 with
/// max|x|·2^−k ≤ bound.
int halvings(double largest, double bound) {
    int k = 0;
    while (std::ldexp(largest, -k) > bound) ++k;
    return k;
}

}  // namespace

// |p1 − p0|² ≥ length², decided exactly: p1 on or outside the circle of radius length about p0.
bool wall_at_least(const Wall& w, double length) { return exact::point_circle(w.p1, Circle{w.p0, length}) >= 0; }

std::span<const Check> waived_checks(const Domain& domain) {
    if (domain.waive_touching) return k_touching_checks;
    return {};
}

std::optional<std::string> outside_domain(const Scene& s, const Domain& d) {
    std::optional<std::string> why;
    const auto note = [&](std::string text) {
        if (!why) why = std::move(text);
    };
    each_length(s, [&](double x, const char* kind, std::size_t i, const char* name) {
        if (d.coordinates && !(std::fabs(x) <= *d.coordinates))
            note(fmt::format("{} {}'s {} {} is outside the domain's coordinates {}", kind, i, name, x, *d.coordinates));
        if (d.no_subnormals && subnormal(x)) note(fmt::format("{} {}'s {} {} is subnormal", kind, i, name, x));
    });
    for (std::size_t i = 0; i < s.balls.size(); ++i)
        for (const auto& [v, name] : {std::pair{s.balls[i].vel.x, "VX"}, std::pair{s.balls[i].vel.y, "VY"}}) {
            if (d.speed && !(std::fabs(v) <= *d.speed))
                note(fmt::format("ball {}'s {} {} is outside the domain's speed {}", i, name, v, *d.speed));
            if (d.no_subnormals && subnormal(v)) note(fmt::format("ball {}'s {} {} is subnormal", i, name, v));
        }
    if (d.wall_length)
        for (std::size_t i = 0; i < s.walls.size(); ++i)
            if (!wall_at_least(s.walls[i], *d.wall_length))
                note(fmt::format("wall {} is shorter than the domain's wall-length {}", i, *d.wall_length));
    return why;
}

bool fit_to_domain(Scene& s, const Domain& d) {
    s.domain = d;
    if (d.coordinates) {
        double largest = 0;
        each_length(s, [&](double x, const char*, std::size_t, const char*) { largest = std::max(largest, std::fabs(x)); });
        if (const int k = halvings(largest, *d.coordinates); k > 0) {
            // Every length halved k times, velocities too: the same scene at another scale.
            const auto h = [k](double& x) { x = std::ldexp(x, -k); };
            for (Wall& w : s.walls) h(w.p0.x), h(w.p0.y), h(w.p1.x), h(w.p1.y);
            for (Ball& b : s.balls) h(b.pos.x), h(b.pos.y), h(b.vel.x), h(b.vel.y), h(b.r);
            for (Circle& c : s.circles) h(c.c.x), h(c.c.y), h(c.r);
            for (Bumper& c : s.bumpers) h(c.c.x), h(c.c.y), h(c.r);
            for (Rect& r : s.rects) h(r.left), h(r.bottom), h(r.right), h(r.top);
        }
    }
    if (d.speed) {
        double largest = 0;
        for (const Ball& b : s.balls) largest = std::max({largest, std::fabs(b.vel.x), std::fabs(b.vel.y)});
        if (const int k = halvings(largest, *d.speed); k > 0)
            for (Ball& b : s.balls) b.vel = {std::ldexp(b.vel.x, -k), std::ldexp(b.vel.y, -k)};
    }
    return !outside_domain(s, d);
}

std::optional<Domain> parse_domain_spec(std::string_view spec, std::string* error) {
    Domain d;
    const auto refuse = [&](std::string why) -> std::optional<Domain> {
        *error = std::move(why);
        return std::nullopt;
    };
    std::vector<std::string_view> seen;
    while (!spec.empty()) {
        const auto comma = spec.find(',');
        const std::string_view item = spec.substr(0, comma);
        spec = comma == std::string_view::npos ? std::string_view{} : spec.substr(comma + 1);
        const auto eq = item.find('=');
        const std::string_view key = item.substr(0, eq);
        const std::string_view value = eq == std::string_view::npos ? std::string_view{} : item.substr(eq + 1);
        for (const std::string_view k : seen)
            if (k == key) return refuse(fmt::format("'{}' is given twice", detail::shown(key)));
        seen.push_back(key);
        const auto bound = [&](std::optional<double>& out) -> bool {
            double x = 0;
            const auto [end, ec] = from_chars_double(value.data(), value.data() + value.size(), x);
            if (value.empty() || ec != std::errc{} || end != value.data() + value.size() || !(x > 0) || !in_range(x)) {
                *error = fmt::format("'{}' needs a number above 0 and at most 2^256: {}={}", detail::shown(key),
                                     detail::shown(key), value.empty() ? "X" : detail::shown(value));
                return false;
            }
            out = x;
            return true;
        };
        if (key == "coordinates") {
            if (!bound(d.coordinates)) return std::nullopt;
        } else if (key == "speed") {
            if (!bound(d.speed)) return std::nullopt;
        } else if (key == "wall-length") {
            if (!bound(d.wall_length)) return std::nullopt;
        } else if (key == "no-subnormals" && eq == std::string_view::npos) {
            d.no_subnormals = true;
        } else if (key == "waive" && value == "touching") {
            d.waive_touching = true;
        } else {
            return refuse(fmt::format("unknown domain item '{}' (coordinates=C, speed=V, wall-length=L, no-subnormals, "
                                      "waive=touching)", detail::shown(item)));
        }
    }
    return d;
}

std::string domain_spec(const Domain& d) {
    std::vector<std::string> items;
    if (d.coordinates) items.push_back(fmt::format("coordinates={}", *d.coordinates));
    if (d.speed) items.push_back(fmt::format("speed={}", *d.speed));
    if (d.wall_length) items.push_back(fmt::format("wall-length={}", *d.wall_length));
    if (d.no_subnormals) items.emplace_back("no-subnormals");
    if (d.waive_touching) items.emplace_back("waive=touching");
    return fmt::format("{}", fmt::join(items, ","));
}

}  // namespace ricochet
