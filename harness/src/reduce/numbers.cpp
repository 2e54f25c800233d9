// Simpler numbers in a failing scene (passes.hpp): first every number of a kind at once (all walls' numbers
// rounded to integers, else to 1, 2, … significant digits: one try each, which keeps shared end points
// shared), then, in a scene of at most k_one_by_one_entities entities, each coordinate in turn replaced by
// the simplest number that keeps the failure. Simpler means fewer characters as the log prints the number
// (its shortest round-trip form), then no sign, then a smaller magnitude: a strict order with finitely many
// numbers below each, so a coordinate can be simplified only finitely often.
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <string>
#include <tuple>

#include <fmt/format.h>

#include "reduce/passes.hpp"
#include "ricochet/bits.hpp"
#include "ricochet/from_chars.hpp"
#include "ricochet/limits.hpp"

namespace ricochet::detail::reduce {
namespace {

/// Significant decimal digits tried: up to 17 round-trips every double, so 16 is the last that can be shorter.
constexpr int k_max_digits = 16;
/// Dyadic fractions k/2^j tried, j = 1..k_max_dyadic_bits.
constexpr int k_max_dyadic_bits = 16;
/// Numbers are simplified one by one only in a scene of at most this many entities: about 15 tries per
/// number, so a scene that kept hundreds of walls (a closed chain no-escape needs whole) would spend the
/// budget there; it gets the whole-kind rounding only.
constexpr std::size_t k_one_by_one_entities = 32;

/// The order of simplicity: the printed length, then a sign, then the magnitude.
auto simplicity(double x) { return std::tuple(fmt::format("{}", x).size(), std::signbit(x), std::fabs(x)); }

/// x rounded to digits significant decimal digits.
double to_digits(double x, int digits) {
    const std::string text = fmt::format("{:.{}e}", x, digits - 1);
    double v = x;
    from_chars_double(text.data(), text.data() + text.size(), v);
    return v;
}

/// The entities whose numbers the pass simplifies, each with its numbers' count. A ball's mass is a kind of its
/// own (one number per ball, while the scene has masses): rounding every mass at once is a candidate of its
/// own, and a mass that cannot be rounded does not keep the balls' other numbers from it.
enum class Kind { ball, wall, circle, rect, bumper, mass };
constexpr std::array k_kinds = {Kind::ball, Kind::wall, Kind::circle, Kind::rect, Kind::bumper, Kind::mass};

std::size_t count(const Scene& s, Kind kind) {
    switch (kind) {
        case Kind::ball: return s.balls.size();
        case Kind::wall: return s.walls.size();
        case Kind::circle: return s.circles.size();
        case Kind::rect: return s.rects.size();
        case Kind::bumper: return s.bumpers.size();
        case Kind::mass: return s.masses.size();
    }
    return 0;
}

/// Number j of entity i of kind, in the log's order (`ball X Y VX VY R`, `wall X0 Y0 X1 Y1`, `circle X Y R`,
/// `rect LEFT BOTTOM RIGHT TOP`, `bumper X Y R`, a ball's M); j < arity(kind). A ball's R is 0 for a point
/// ball, which nothing simplifies further.
/// (S: Scene or const Scene.)
template <class S>
auto& number(S& s, Kind kind, std::size_t i, int j) {
    switch (kind) {
        case Kind::ball: {
            auto& b = s.balls[i];
            return j == 0 ? b.pos.x : j == 1 ? b.pos.y : j == 2 ? b.vel.x : j == 3 ? b.vel.y : b.r;
        }
        case Kind::wall: {
            auto& w = s.walls[i];
            return j == 0 ? w.p0.x : j == 1 ? w.p0.y : j == 2 ? w.p1.x : w.p1.y;
        }
        case Kind::circle: {
            auto& c = s.circles[i];
            return j == 0 ? c.c.x : j == 1 ? c.c.y : c.r;
        }
        case Kind::bumper: {
            auto& c = s.bumpers[i];
            return j == 0 ? c.c.x : j == 1 ? c.c.y : c.r;
        }
        case Kind::mass: return s.masses[i];
        case Kind::rect: break;
    }
    auto& r = s.rects[i];
    return j == 0 ? r.left : j == 1 ? r.bottom : j == 2 ? r.right : r.top;
}

int arity(Kind kind) {
    return kind == Kind::mass ? 1 : kind == Kind::circle || kind == Kind::bumper ? 3 : kind == Kind::ball ? 5 : 4;
}

/// True if entity i of kind is one a log may hold: R ≥ 0, LEFT ≤ RIGHT and BOTTOM ≤ TOP, a mass in [2^−256, 2^256]
/// (docs/scene-log.md).
bool valid(const Scene& s, Kind kind, std::size_t i) {
    if (kind == Kind::mass) return s.masses[i] >= 0x1p-256 && s.masses[i] <= 0x1p256;
    if (kind == Kind::circle) return s.circles[i].r >= 0.0;
    if (kind == Kind::bumper) return s.bumpers[i].r >= 0.0;
    if (kind == Kind::ball) return s.balls[i].r >= 0.0;
    if (kind == Kind::rect) return s.rects[i].left <= s.rects[i].right && s.rects[i].bottom <= s.rects[i].top;
    return true;
}

}  // namespace

std::vector<double> simpler_numbers(double x) {
    std::vector<double> out = {0.0, -x, 1.0, -1.0, std::trunc(x), std::round(x), std::floor(x), std::ceil(x)};
    for (int d = 1; d <= k_max_digits; ++d) out.push_back(to_digits(x, d));
    for (int j = 1; j <= k_max_dyadic_bits; ++j) {
        // x·2^j and k/2^j are exact (|x| ≤ 2^256, far from overflow; a power of two scales without rounding
        // unless the result is subnormal, and rounding to an integer first keeps k/2^j ≥ 2^−16 or 0).
        const double scale = std::ldexp(1.0, j);
        out.push_back(std::round(x * scale) / scale);
    }
    const auto below_x = simplicity(x);
    std::erase_if(out, [&](double v) { return !in_range(v) || same_bits(v, x) || !(simplicity(v) < below_x); });
    std::sort(out.begin(), out.end(), [](double a, double b) { return simplicity(a) < simplicity(b); });
    out.erase(std::unique(out.begin(), out.end(), [](double a, double b) { return same_bits(a, b); }), out.end());
    return out;
}

namespace {

/// Every number of kind rounded by round_to (where that is simpler), as one candidate; false if it changes
/// none.
template <class Round>
bool round_all(Scene& s, Kind kind, Round round_to) {
    bool changed = false;
    for (std::size_t i = 0; i < count(s, kind); ++i) {
        for (int j = 0; j < arity(kind); ++j) {
            double& x = number(s, kind, i, j);
            const double v = round_to(x);
            if (in_range(v) && simplicity(v) < simplicity(x)) {
                x = v;
                changed = true;
            }
        }
        if (!valid(s, kind, i)) return false;
    }
    return changed;
}

/// All numbers of kind rounded at once: to integers, else to the fewest significant digits that fail.
void round_kind(Trials& trials, Kind kind) {
    for (int d = 0; d <= k_max_digits; ++d) {
        if (trials.spent()) return;
        Scene candidate = trials.current().scene;
        const bool changed = d == 0 ? round_all(candidate, kind, [](double x) { return std::round(x); })
                                    : round_all(candidate, kind, [d](double x) { return to_digits(x, d); });
        if (changed && trials.attempt(std::move(candidate), "numbers")) return;
    }
}

/// Every mass 1: the scene without masses, a log whose ball lines say none (docs/scene-log.md, "Balls that meet").
void drop_masses(Trials& trials) {
    if (trials.current().scene.masses.empty() || trials.spent()) return;
    Scene candidate = trials.current().scene;
    candidate.masses.clear();
    trials.attempt(std::move(candidate), "numbers");
}

}  // namespace

void simplify_numbers(Trials& trials) {
    drop_masses(trials);
    for (const Kind kind : k_kinds) round_kind(trials, kind);
    if (SceneSize::of(trials.current().scene).entities() > k_one_by_one_entities) return;
    for (const Kind kind : k_kinds) {
        for (std::size_t i = 0; i < count(trials.current().scene, kind); ++i) {
            for (int j = 0; j < arity(kind); ++j) {
                for (const double v : simpler_numbers(number(trials.current().scene, kind, i, j))) {
                    if (trials.spent()) return;
                    Scene candidate = trials.current().scene;
                    number(candidate, kind, i, j) = v;
                    if (!valid(candidate, kind, i)) continue;
                    if (trials.attempt(std::move(candidate), "numbers")) break;
                }
            }
        }
    }
}

}  // namespace ricochet::detail::reduce
