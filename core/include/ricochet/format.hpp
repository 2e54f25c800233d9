// How the core's types print: one fmt::formatter each, numbers in shortest round-trip form (`{}`),
// so a printed value reads back bit for bit. Every printer in core/ and cli/ goes through these.
//
//   Vec2     (x, y)             a NaN as nan, without its sign (the processor's)
//   Wall     x0 y0 x1 y1        the scene-log `wall` arguments (docs/scene-log.md)
//   Ball     x y vx vy [r]      the `ball` arguments; r only when its bits are not +0 (a point ball prints
//                               as before radii existed, and an `expect state` has no radius)
//   Circle   x y r              the `circle` arguments
//   Bumper   x y r              the `bumper` arguments
//   Rect     left bottom right top
//   Event    its `ricochet run` line, no newline: state F I X Y VX VY | hit F I W X Y | bump F I K X Y |
//            meet F I J X Y VX VY | overlap F I circle|rect K
//   Side     outside | inside | on
//   KernelId, Miss, Check       kernel_name, miss_name, check_name (width and fill specs work: "{:15}")
#pragma once

#include <cmath>
#include <string_view>

#include <fmt/format.h>

#include "ricochet/check.hpp"
#include "ricochet/event.hpp"
#include "ricochet/kernel_id.hpp"
#include "ricochet/line.hpp"
#include "ricochet/shapes.hpp"
#include "ricochet/sweep.hpp"

namespace ricochet::detail {

/// A formatter that takes no format spec: every number is printed with `{}`, which round-trips.
struct PlainFormatter {
    /// Accepts only `{}`.
    constexpr auto parse(fmt::format_parse_context& ctx) -> decltype(ctx.begin()) {
        auto it = ctx.begin();
        if (it != ctx.end() && *it != '}') ctx.on_error("ricochet values take no format spec: use {}");
        return it;
    }
};

/// A formatter that prints a name, with string_view's specs (width, fill, alignment).
template <class T, std::string_view (*Name)(T)>
struct NameFormatter : fmt::formatter<std::string_view> {
    /// Name(value), formatted as a string.
    template <class Context>
    auto format(T value, Context& ctx) const {
        return fmt::formatter<std::string_view>::format(Name(value), ctx);
    }
};

/// "outside", "inside" or "on", by the side's sign.
constexpr std::string_view side_name(Side s) {
    const int sign = sign_of(s);
    return sign > 0 ? "outside" : sign < 0 ? "inside" : "on";
}

}  // namespace ricochet::detail

/// (x, y).
template <>
struct fmt::formatter<ricochet::Vec2> : ricochet::detail::PlainFormatter {
    template <class Context>
    auto format(const ricochet::Vec2& p, Context& ctx) const {
        // A NaN prints as nan whatever its sign bit: the sign of an invalid operation's NaN is the processor's
        // (negative on x86, positive on ARM and s390x), and a message must read the same on every platform.
        const auto plain = [](double v) { return std::isnan(v) ? std::fabs(v) : v; };
        return fmt::format_to(ctx.out(), "({}, {})", plain(p.x), plain(p.y));
    }
};

/// x0 y0 x1 y1.
template <>
struct fmt::formatter<ricochet::Wall> : ricochet::detail::PlainFormatter {
    template <class Context>
    auto format(const ricochet::Wall& w, Context& ctx) const {
        return fmt::format_to(ctx.out(), "{} {} {} {}", w.p0.x, w.p0.y, w.p1.x, w.p1.y);
    }
};

/// x y vx vy, then r unless it is +0 (so a point ball and a state print as they always did; −0 is kept).
template <>
struct fmt::formatter<ricochet::Ball> : ricochet::detail::PlainFormatter {
    template <class Context>
    auto format(const ricochet::Ball& b, Context& ctx) const {
        auto out = fmt::format_to(ctx.out(), "{} {} {} {}", b.pos.x, b.pos.y, b.vel.x, b.vel.y);
        if (b.r != 0.0 || std::signbit(b.r)) out = fmt::format_to(out, " {}", b.r);
        return out;
    }
};

/// x y r.
template <>
struct fmt::formatter<ricochet::Bumper> : ricochet::detail::PlainFormatter {
    template <class Context>
    auto format(const ricochet::Bumper& c, Context& ctx) const {
        return fmt::format_to(ctx.out(), "{} {} {}", c.c.x, c.c.y, c.r);
    }
};

/// x y r.
template <>
struct fmt::formatter<ricochet::Circle> : ricochet::detail::PlainFormatter {
    template <class Context>
    auto format(const ricochet::Circle& c, Context& ctx) const {
        return fmt::format_to(ctx.out(), "{} {} {}", c.c.x, c.c.y, c.r);
    }
};

/// left bottom right top.
template <>
struct fmt::formatter<ricochet::Rect> : ricochet::detail::PlainFormatter {
    template <class Context>
    auto format(const ricochet::Rect& r, Context& ctx) const {
        return fmt::format_to(ctx.out(), "{} {} {} {}", r.left, r.bottom, r.right, r.top);
    }
};

/// The event's `ricochet run` line, without the newline.
template <>
struct fmt::formatter<ricochet::Event> : ricochet::detail::PlainFormatter {
    template <class Context>
    auto format(const ricochet::Event& e, Context& ctx) const {
        using Kind = ricochet::Event::Kind;
        if (e.kind == Kind::state)
            return fmt::format_to(ctx.out(), "state {} {} {} {} {} {}", e.frame, e.ball, e.pos.x, e.pos.y, e.vel.x, e.vel.y);
        if (e.kind == Kind::hit)
            return fmt::format_to(ctx.out(), "hit {} {} {} {} {}", e.frame, e.ball, e.index, e.pos.x, e.pos.y);
        if (e.kind == Kind::bump)
            return fmt::format_to(ctx.out(), "bump {} {} {} {} {}", e.frame, e.ball, e.index, e.pos.x, e.pos.y);
        // Ball I met ball J (index) with its centre at pos, and left with vel.
        if (e.kind == Kind::meet)
            return fmt::format_to(ctx.out(), "meet {} {} {} {} {} {} {}", e.frame, e.ball, e.index, e.pos.x, e.pos.y,
                                  e.vel.x, e.vel.y);
        return fmt::format_to(ctx.out(), "overlap {} {} {} {}", e.frame, e.ball,
                              e.shape == ricochet::Event::Shape::circle ? "circle" : "rect", e.index);
    }
};

/// outside, inside or on.
template <>
struct fmt::formatter<ricochet::Side> : ricochet::detail::NameFormatter<ricochet::Side, ricochet::detail::side_name> {};
/// kernel_name.
template <>
struct fmt::formatter<ricochet::KernelId>
    : ricochet::detail::NameFormatter<ricochet::KernelId, ricochet::kernel_name> {};
/// miss_name.
template <>
struct fmt::formatter<ricochet::Miss> : ricochet::detail::NameFormatter<ricochet::Miss, ricochet::miss_name> {};
/// check_name.
template <>
struct fmt::formatter<ricochet::Check> : ricochet::detail::NameFormatter<ricochet::Check, ricochet::check_name> {};
