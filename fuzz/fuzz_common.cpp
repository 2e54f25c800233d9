#include "fuzz_common.hpp"

#include "check_tiers.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include <fmt/core.h>

#include "ricochet/bits.hpp"
#include "ricochet/checks.hpp"
#include "ricochet/failure_log.hpp"
#include "ricochet/kernel_spec.hpp"
#include "ricochet/plugin_guard.hpp"
#include "ricochet/plugin_loader.hpp"
#include "ricochet/scene_log.hpp"
#include "ricochet_peers/peers.hpp"

namespace ricochet::fuzz {

KernelId kernel_under_test() {
    static const KernelId k = [] {
        // The peers join the registry before RICOCHET_KERNEL is read.
        peers::register_peer_kernels();
        const char* name = std::getenv(k_kernel_env);
        if (name == nullptr || *name == '\0') return KernelId::robust;
        std::string error;
        const auto parsed = resolve_kernel(name, &error);
        if (!parsed) {
            fmt::print(stderr, "ricochet fuzz: error: {}: {}\n", k_kernel_env, error);
            std::exit(2);
        }
        // A plug-in's crash goes on to libFuzzer's handler after the guard's report, so that libFuzzer keeps
        // the input as its artifact (plugin_guard.hpp).
        if (plugin_info(*parsed) != nullptr) set_plugin_fault_action(PluginFaultAction::chain);
        return *parsed;
    }();
    return k;
}

std::uint64_t ByteReader::u64() {
    std::uint64_t x = 0;
    for (int i = 0; i < 8; ++i) x |= std::uint64_t{u8()} << (8 * i);
    return x;
}

double clamp_to_range(double x) { return in_range(x) ? x : 0.0; }

double scaled(ByteReader& in, int base, int sign, unsigned span) {
    const double m = 1.0 + in.u8();
    const int e = base + sign * static_cast<int>(in.u8() % span);
    return std::ldexp(m, e);
}

namespace {

// Values where geometry is known to go wrong: zero of both signs, units, non-dyadic decimals,
// the smallest normal and subnormal, the 2^53 integer edge, far offsets and the range limit.
constexpr std::array<double, 24> k_interesting = {
    0.0,     -0.0,   1.0,     -1.0,         0.5,          0.1,           1.0 / 3.0,     3.0,
    1e-9,    1e-300, 5e-324,  0x1p-1022,    0x1p52,       0x1p53,        0x1p53 + 2.0,  1e9,
    1e9 + 0.5, 1e15, -1e15,   1e30,         1e77,         -1e77,         k_coordinate_limit, -k_coordinate_limit};

}  // namespace

double ByteReader::number() {
    switch (u8() % 8) {
        case 0:
        case 1:
        case 2:
            // Small integers: most decisive geometry (boxes, diagonals) lives here.
            return static_cast<double>(static_cast<std::int8_t>(u8()));
        case 3: {
            // Dyadic fractions m/2^k: exact in binary, so points can sit exactly on lines.
            const auto m = static_cast<std::int16_t>(u16());
            return std::ldexp(static_cast<double>(m), -static_cast<int>(u8() % 40));
        }
        case 4: return k_interesting[u8() % k_interesting.size()];
        case 5: {
            // A small integer far from the origin: 1e9 and beyond, where an ulp is large.
            const double base = std::ldexp(1.0, 20 + static_cast<int>(u8() % 40));
            // Read in order (the operands of + are evaluated in an unspecified order).
            const double signed_base = u8() & 1 ? -base : base;
            return signed_base + static_cast<double>(static_cast<std::int8_t>(u8()));
        }
        case 6: {
            // Any double; out of range folds back into it keeping the mantissa.
            const double x = double_of_bits(u64());
            if (in_range(x)) return x;
            if (!std::isfinite(x)) return 0.0;
            int e = 0;
            const double m = std::frexp(x, &e);
            return std::ldexp(m, e % 200);
        }
        default: {
            // A small integer scaled by a power of two, tiny to large.
            const double m = static_cast<double>(static_cast<std::int8_t>(u8()));
            return std::ldexp(m, static_cast<int>(u8() % 128) - 64);
        }
    }
}

double ByteReader::magnitude() { return std::fabs(number()); }

double ByteReader::nudge(double x) {
    const int k = static_cast<int>(u8() % 7) - 3;
    for (int i = 0; i < k; ++i) x = std::nextafter(x, INFINITY);
    for (int i = 0; i > k; --i) x = std::nextafter(x, -INFINITY);
    return clamp_to_range(x);
}

Vec2 ByteReader::point() {
    const unsigned mode = u8() % 8;
    Vec2 p;
    if (mode == 4 && !points_.empty()) {
        // A point seen before: a wall's end, a ball's start, a circle's centre.
        p = points_[u8() % points_.size()];
    } else if (mode == 5 && !walls_.empty()) {
        // On a wall's line: P0 + f·e with f dyadic (inside the segment, at its ends or beyond).
        const Wall& w = walls_[u8() % walls_.size()];
        const double fm = static_cast<std::int8_t>(u8());  // read before the exponent: see number()
        const double f = std::ldexp(fm, -static_cast<int>(u8() % 8));
        p = {clamp_to_range(w.p0.x + f * (w.p1.x - w.p0.x)), clamp_to_range(w.p0.y + f * (w.p1.y - w.p0.y))};
    } else if (mode == 6 && !points_.empty()) {
        // Near a point seen before: a small step away (grazing, corners).
        const Vec2 q = points_[u8() % points_.size()];
        p = {clamp_to_range(q.x + number()), clamp_to_range(q.y + number())};
    } else {
        p = {number(), number()};
    }
    // A few ulps off, one coordinate or both: the end positions where rounding decides.
    if (u8() & 1) p.x = nudge(p.x);
    if (u8() & 1) p.y = nudge(p.y);
    return p;
}

Wall ByteReader::wall() {
    Wall w;
    w.p0 = point();
    remember(w.p0);
    w.p1 = u8() % 16 == 0 ? w.p0 : point();  // sometimes zero-length
    remember(w.p1);
    remember(w);
    return w;
}

Vec2 ByteReader::velocity(Vec2 from) {
    Vec2 v;
    switch (u8() % 4) {
        case 0:
        case 1: {
            // Towards a target point: the leg then ends on or next to a line or a corner.
            const Vec2 to = point();
            v = {clamp_to_range(to.x - from.x), clamp_to_range(to.y - from.y)};
            break;
        }
        case 2:
            if (!walls_.empty()) {
                // Along a wall, or a few ulps off parallel.
                const Wall& w = walls_[u8() % walls_.size()];
                const double km = static_cast<std::int8_t>(u8());  // read before the exponent: see number()
                const double k = std::ldexp(km, -static_cast<int>(u8() % 8));
                v = {nudge(clamp_to_range(k * (w.p1.x - w.p0.x))), nudge(clamp_to_range(k * (w.p1.y - w.p0.y)))};
                break;
            }
            [[fallthrough]];
        default: v = {number(), number()};
    }
    return v;
}

Circle ByteReader::circle() {
    Circle c;
    c.c = point();
    c.r = u8() % 8 == 0 ? 0.0 : magnitude();
    remember(c.c);
    // Points on the circle: the axis extremes, and a 3-4-5 point (exact when r is a multiple of 5).
    remember(Vec2{clamp_to_range(c.c.x + c.r), c.c.y});
    remember(Vec2{c.c.x, clamp_to_range(c.c.y - c.r)});
    remember(Vec2{clamp_to_range(c.c.x + 0.6 * c.r), clamp_to_range(c.c.y + 0.8 * c.r)});
    return c;
}

Rect ByteReader::rect() {
    const Vec2 a = point();
    const Vec2 b = u8() % 8 == 0 ? a : point();  // sometimes zero-size
    const Rect r{std::fmin(a.x, b.x), std::fmin(a.y, b.y), std::fmax(a.x, b.x), std::fmax(a.y, b.y)};
    // Corners, so that later points and rectangles can touch them exactly.
    remember(Vec2{r.left, r.bottom});
    remember(Vec2{r.right, r.top});
    remember(Vec2{r.left, r.top});
    return r;
}

namespace {

/// A near-degenerate scale (1 + 16 bits)·2^e from one of three bands: tiny (2^-1000 and up: GMP decides), near 1,
/// huge (up to 2^229, so that λ·d ≤ 2^250 and 2·Be stay in range). The mantissa is read first.
double near_scale(ByteReader& in) {
    const double m = 1.0 + in.u16();
    const unsigned b = in.u8();
    constexpr int k_base[3] = {-1000, -60, 170};
    const int e = k_base[b % 3] + static_cast<int>((b / 3) % 60) * (b % 3 == 1 ? 2 : 1);
    return std::ldexp(in.u8() & 1 ? -m : m, e);
}

/// A small direction with both components non-zero, each in ±[1, 15].
Vec2 near_direction(ByteReader& in) {
    const unsigned x = in.u8();
    const unsigned y = in.u8();
    return {(x & 16 ? -1.0 : 1.0) * (1 + x % 15), (y & 16 ? -1.0 : 1.0) * (1 + y % 15)};
}

}  // namespace

void ByteReader::near_degenerate(std::vector<Wall>& walls, Ball& ball, bool crossings) {
    const unsigned mode = u8() % 4;
    if (mode == 0 || (mode == 3 && !crossings)) return;
    if (walls.empty()) walls.push_back({});
    if (mode == 1 || mode == 2) {
        // Three points λ·d on one line through the origin, exact (17 + 4 bits); their differences round.
        const Vec2 d = near_direction(*this);
        const double l0 = near_scale(*this);
        const double l1 = near_scale(*this);
        const double l2 = near_scale(*this);
        walls[0] = {l0 * d, l1 * d};
        Vec2 on = l2 * d;
        // k ulps off, in x or y.
        const unsigned k = u8();
        const int ulps = static_cast<int>(k % 7) - 3;
        for (int i = 0; i < ulps; ++i) (k & 8 ? on.y : on.x) = std::nextafter(k & 8 ? on.y : on.x, INFINITY);
        for (int i = 0; i > ulps; --i) (k & 8 ? on.y : on.x) = std::nextafter(k & 8 ? on.y : on.x, -INFINITY);
        // The other end: each coordinate times 0, 1/2, 2 or 1 (different, so off a ray's line); f·x, x − f·x and
        // their sum are exact, so the leg starts or ends exactly at the point on the line.
        constexpr double k_f[4] = {0.0, 0.5, 2.0, 1.0};
        const unsigned f = u8();
        const unsigned fx = f % 4, fy = (f / 4) % 4 == fx ? (fx + 1) % 4 : (f / 4) % 4;
        const Vec2 other{k_f[fx] * on.x, k_f[fy] * on.y};
        ball = mode == 1 ? Ball{other, on - other} : Ball{on, other - on};
        return;
    }
    // A lattice leg Bs → Bs + 2^q·d and two walls crossing it at Bs + j·d and Bs + (j + k)·d: every coordinate an
    // integer below 2^53 (|Bs| < 2^51, 2^q·|d| ≤ 3·2^50, a wall's half ≤ 16·2^10·4), so points and parameters are
    // exact; the whole case times 2^e.
    const int q = 30 + static_cast<int>(u8() % 21);
    const unsigned dy = u8();
    const Vec2 d{1.0 + u8() % 3, (dy & 4 ? -1.0 : 1.0) * (dy % 4)};
    const double r = std::ldexp(1.0, static_cast<int>(u8() % 49));
    const double ox = static_cast<std::int8_t>(u8()) % 8;
    const double oy = static_cast<std::int8_t>(u8()) % 8;
    const Vec2 bs{r * ox, r * oy};
    const std::uint64_t jbits = u64();
    const std::int64_t j0 = static_cast<std::int64_t>(jbits % (std::uint64_t{1} << q));
    const int e = static_cast<int>(u8() % 201) - 100;
    const double scale = std::ldexp(1.0, e);
    if (walls.size() < 2) walls.push_back({});
    for (int i = 0; i < 2; ++i) {
        const unsigned kb = u8();
        const std::int64_t j = i == 0 ? j0 : std::clamp<std::int64_t>(j0 + static_cast<int>(kb % 7) - 3, 0,
                                                                        std::int64_t{1} << q);
        const Vec2 x = bs + static_cast<double>(j) * d;
        const unsigned wb = u8();
        Vec2 w{static_cast<double>(wb % 9) - 4.0, static_cast<double>((wb / 9) % 9) - 4.0};
        if (w.x * d.y == w.y * d.x) w = {-d.y, d.x};  // along the leg: turned a quarter
        const unsigned ab = u8();
        const double len = std::ldexp(1.0, static_cast<int>((ab / 16) % 11));
        // a = 0: the wall ends exactly on the leg; a tilt of one unit moves the crossing off the lattice.
        Vec2 p0 = x - (static_cast<double>(ab % 4) * len) * w;
        if (kb & 8) p0.x += 1.0;
        if (kb & 16) p0.y += 1.0;
        Wall wall{scale * p0, scale * (x + (1.0 + (ab / 4) % 4) * len * w)};
        if (kb & 32) std::swap(wall.p0, wall.p1);
        walls[static_cast<std::size_t>(i)] = wall;
    }
    ball = {scale * bs, scale * (std::ldexp(1.0, q) * d)};
}

/// Before a plug-in kernel steps scene: its guard is told (plugin_guard.hpp), and where the campaign asks for the
/// scene (RICOCHET_FUZZ_SCENE_OUT, when it converts an artifact), the scene is kept there should the plug-in
/// crash or hang on it. Fuzzing, libFuzzer keeps the input itself.
void stage_plugin_case(std::string_view target, const Scene& scene, std::span<const Check> checks) {
    const KernelId k = kernel_under_test();
    if (plugin_info(k) == nullptr) return;
    const char* out = std::getenv(k_scene_out_env);
    if (out == nullptr || *out == '\0') {
        static const bool staged = [&] {
            stage_plugin_input({fmt::format("running fuzz target {}", target), {}, {}});
            return true;
        }();
        (void)staged;
        return;
    }
    const char* sha = std::getenv(k_sha1_env);
    Scene with_checks = scene;
    with_checks.checks.assign(checks.begin(), checks.end());
    const Scene log = plugin_case_log(with_checks, k, fmt::format("fuzz {} {}", target, sha != nullptr && *sha != '\0' ? sha : "unknown"));
    stage_plugin_input({fmt::format("running fuzz target {}", target), write_scene_log(log), out});
}

/// The domain of RICOCHET_DOMAIN (domain.hpp), read once; the full domain if unset. One that does not read ends
/// the worker with status 2 (the campaign checks --domain before it starts any).
const Domain& domain_under_test() {
    static const Domain d = [] {
        const char* env = std::getenv("RICOCHET_DOMAIN");
        if (env == nullptr) return Domain{};
        std::string error;
        const auto parsed = parse_domain_spec(env, &error);
        if (!parsed) {
            fmt::print(stderr, "ricochet fuzz: error: RICOCHET_DOMAIN: {}\n", error);
            std::exit(2);
        }
        return *parsed;
    }();
    return d;
}

void check_scene(std::string_view target, const Scene& decoded, std::span<const Check> checks,
                 std::span<const std::uint8_t> input) {
    // The user's world: the decoded scene brought into it, or the input skipped where it cannot be.
    Scene fitted;
    const Domain& domain = domain_under_test();
    if (!domain.full()) {
        fitted = decoded;
        if (!fit_to_domain(fitted, domain)) return;
    }
    const Scene& scene = domain.full() ? decoded : fitted;
    CheckOptions options;
    options.keep_events = false;
    const std::vector<Check> asked = checks_for(input, checks);
    stage_plugin_case(target, scene, asked);
    const CheckedRun run = run_checked(scene, kernel_under_test(), scene.frames, asked, options);
    if (run.failure) fail(target, scene, *run.failure);
}

void fail(std::string_view target, const Scene& scene, const CheckFailure& failure) {
    const KernelId k = kernel_under_test();
    // kind: what the campaign tells failures apart by (with the check).
    fmt::print(stderr, "{} target={} kernel={} check={} frame={} kind={}\n  {}\n", k_failure_tag, target, kernel_name(k),
               check_name(failure.check), failure.frame, check_name(failure.check), failure.str());
    if (const char* out = std::getenv(k_scene_out_env); out != nullptr && *out != '\0') {
        const char* sha = std::getenv(k_sha1_env);
        const FailureLog log = make_failure_log(
            scene, k, fmt::format("fuzz {} {}", target, sha != nullptr && *sha != '\0' ? sha : "unknown"), failure);
        if (!log.reproduces())
            fmt::print(stderr, "ricochet fuzz: warning: the saved log does not reproduce this failure (its run: {})\n",
                       log.replayed ? log.replayed->str() : std::string("every check holds"));
        std::string error;
        if (!write_file_atomically(out, log.text(), &error)) fmt::print(stderr, "ricochet fuzz: error: {}\n", error);
    }
    std::fflush(stderr);
    std::abort();
}

}  // namespace ricochet::fuzz
