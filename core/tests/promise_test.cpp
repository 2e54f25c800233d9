// Promises written in kernel.hpp, limits.hpp, hash.hpp and docs/scene-log.md that no other test pins:
// the accuracy of robust's t_i, B_i and v' against exact for well-conditioned hits, the inclusive range
// limit, the run hash as XXH64 over the documented records (checked against an encoding of its own), and
// the walk-back's rule that a printed piece never passes through a wall, not even exactly through an end.
#include <gtest/gtest.h>

#include <xxhash.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <random>
#include <variant>
#include <vector>

#include "kernels/robust/path.hpp"
#include "ricochet/hash.hpp"
#include "ricochet/kernel.hpp"
#include "ricochet/scene_log_format.hpp"
#include "ricochet/truth.hpp"

namespace ricochet {
namespace {

constexpr double k_eps = 0x1p-53;

/// Well-conditioned, as kernel.hpp means it: |e × d| ≥ |e|∞·|d|∞ / 4 (the leg meets the wall's line at
/// an angle whose sine is at least about 1/4), computed in long double (only a filter for the workload).
bool well_conditioned(const Wall& w, Vec2 d) {
    const long double ex = static_cast<long double>(w.p1.x) - w.p0.x, ey = static_cast<long double>(w.p1.y) - w.p0.y;
    const long double c = std::fabs(ex * d.y - ey * d.x);
    const long double e_inf = std::max(std::fabs(ex), std::fabs(ey));
    const long double d_inf = std::max(std::fabs(static_cast<long double>(d.x)), std::fabs(static_cast<long double>(d.y)));
    return c >= e_inf * d_inf / 4;
}

/// The largest magnitude of any coordinate the leg's decision reads.
double magnitude(Vec2 bs, Vec2 be, const Wall& w) {
    return std::max({std::fabs(bs.x), std::fabs(bs.y), std::fabs(be.x), std::fabs(be.y), std::fabs(w.p0.x),
                     std::fabs(w.p0.y), std::fabs(w.p1.x), std::fabs(w.p1.y)});
}

/// Robust's crossing s = BC(q)/(BC(q) − BC(b)) rounds BC(q) and BC(b), each −e × (p − P0): two products
/// of magnitude ≤ |e|∞·2M and a difference, each with ≤ ε relative error after p − P0 (≤ ε·2M), so each
/// BC is off by ≤ 16ε·|e|∞·M; with |BC(q) − BC(b)| = |e × d| ≥ |e|∞·|d|∞/4 the fraction s is off by
/// ≤ 2·16·4 ε·M/|d|∞ = 128 ε·M/|d|∞ (plus its own rounding), and B_i = q + s·d by ≤ 128 ε·M + 2ε·M.
/// 256 leaves a factor 2 of room: "a few ulps" of the leg's largest coordinate, made precise.
constexpr double k_hit_ulps_of_m = 256.0;

/// A random wall and a leg aimed across it at scale s, on a fixed-seed generator.
struct Case {
    Wall w;
    Vec2 bs, v;
};
Case random_case(std::mt19937_64& rng, double s) {
    std::uniform_real_distribution<double> u(-1.0, 1.0), f(0.0, 1.0);
    Case c;
    c.w = {{u(rng) * s, u(rng) * s}, {u(rng) * s, u(rng) * s}};
    const Vec2 e = c.w.p1 - c.w.p0;
    // A point on the wall, then a start and an end on either side of it.
    const double at = f(rng);
    const Vec2 x{c.w.p0.x + at * e.x, c.w.p0.y + at * e.y};
    const Vec2 off{u(rng) * s, u(rng) * s};
    c.bs = x + off;
    c.v = (1.0 + f(rng)) * Vec2{x.x - c.bs.x, x.y - c.bs.y};
    return c;
}

TEST(Promise, RobustHitTimeAndPointAreWithinAFewUlpsOfExactForWellConditionedHits) {
    std::mt19937_64 rng(20240611);
    const double scales[] = {1.0, 0x1p-30, 0x1p30, 1e15, 0x1p200};
    int checked = 0;
    double worst_b = 0.0, worst_t = 0.0;
    for (double s : scales)
        for (int n = 0; n < 20000; ++n) {
            const Case c = random_case(rng, s);
            const Vec2 be = c.bs + c.v;
            if (c.w.p0 == c.w.p1 || !well_conditioned(c.w, be - c.bs)) continue;
            const Sweep want = sweep(KernelId::exact, c.bs, c.v, c.w);
            const Sweep got = sweep(KernelId::robust, c.bs, c.v, c.w);
            ASSERT_EQ(got.miss, want.miss) << "decisions are exact";
            if (!want.hit()) continue;
            ++checked;
            const double m = magnitude(c.bs, be, c.w);
            const Vec2 d = be - c.bs;
            const double d_inf = std::max(std::fabs(d.x), std::fabs(d.y));
            const double db = std::max(std::fabs(got.point.x - want.point.x), std::fabs(got.point.y - want.point.y));
            const double dt = std::fabs(got.t - want.t);
            worst_b = std::max(worst_b, db / (k_eps * m));
            worst_t = std::max(worst_t, dt * d_inf / (k_eps * m));
            ASSERT_LE(db, k_hit_ulps_of_m * k_eps * m) << "B_i, scale " << s << " case " << n;
            ASSERT_LE(dt * d_inf, k_hit_ulps_of_m * k_eps * m) << "t_i, scale " << s << " case " << n;
        }
    EXPECT_GT(checked, 20000) << "the workload must reach well-conditioned hits";
    std::printf("well-conditioned hits: %d; worst |dB| = %.2f eps*M, worst |dt|*|d| = %.2f eps*M (bound %.0f)\n",
                checked, worst_b, worst_t, k_hit_ulps_of_m);
}

TEST(Promise, TheAccuracyCheckHoldsRobustToTheBoundAndSeesAPointMovedPastIt) {
    // truth::hit_accuracy (the `accuracy` check) on the same workload: robust's B_i is within the bound,
    // the point moved by 300·ε·M in x is not, moved by 100·ε·M it still is.
    std::mt19937_64 rng(20261201);
    int checked = 0;
    for (double s : {1.0, 0x1p-30, 0x1p30, 1e15, 0x1p200})
        for (int n = 0; n < 4000; ++n) {
            const Case c = random_case(rng, s);
            const Vec2 be = c.bs + c.v;
            if (c.w.p0 == c.w.p1 || !well_conditioned(c.w, be - c.bs)) continue;
            const Sweep got = sweep(KernelId::robust, c.bs, c.v, c.w);
            if (!got.hit()) continue;
            const truth::HitAccuracy r = truth::hit_accuracy(c.bs, be, c.w, got.point, 256.0);
            if (!r.conditioned) continue;  // the long-double filter may let a borderline case through
            ++checked;
            ASSERT_TRUE(r.within) << "scale " << s << " case " << n << ": " << r.error << " eps*M";
            const double unit = magnitude(c.bs, be, c.w) * k_eps;
            const double near = truth::hit_accuracy(c.bs, be, c.w, {got.point.x + 100 * unit, got.point.y}, 256.0).error;
            EXPECT_TRUE(truth::hit_accuracy(c.bs, be, c.w, {got.point.x + 100 * unit, got.point.y}, 256.0).within)
                << near;
            EXPECT_FALSE(truth::hit_accuracy(c.bs, be, c.w, {got.point.x + 300 * unit, got.point.y}, 256.0).within);
        }
    EXPECT_GT(checked, 4000);
}

/// One frame, one wall, one ball under kernel k.
struct Frame {
    Ball ball;
    std::vector<HitEvent> hits;
    FrameStatus status;
};
Frame one_frame(KernelId k, Ball b, const Wall& w) {
    BallMemory memory;
    StepScratch scratch;
    std::vector<HitEvent> hits;
    const std::vector<Wall> walls{w};
    const FrameStatus st = step_ball(k, b, memory, walls, hits, scratch);
    return {b, hits, st};
}

TEST(Promise, RobustBounceMatchesExactForWellConditionedHits) {
    // The frame's hit point and v' = v − 2(v·n̂)n̂ against exact's: v' within the per-bounce speed bound of
    // limits.hpp, componentwise (the bound is on |v'|; each component of v' carries the same error terms),
    // and the hit point as in the sweep test above (make_safe may walk it back by 2^-50 of the leg).
    std::mt19937_64 rng(7);
    const double scales[] = {1.0, 0x1p-20, 1e9};
    int checked = 0;
    for (double s : scales)
        for (int n = 0; n < 5000; ++n) {
            const Case c = random_case(rng, s);
            const Vec2 be = c.bs + c.v;
            if (c.w.p0 == c.w.p1 || !well_conditioned(c.w, be - c.bs)) continue;
            const Frame want = one_frame(KernelId::exact, {c.bs, c.v}, c.w);
            const Frame got = one_frame(KernelId::robust, {c.bs, c.v}, c.w);
            ASSERT_EQ(got.hits.size(), want.hits.size()) << "scale " << s << " case " << n;
            if (want.hits.size() != 1) continue;
            ++checked;
            const double m = magnitude(c.bs, be, c.w);
            const Vec2 dp = got.hits[0].point - want.hits[0].point;
            ASSERT_LE(std::max(std::fabs(dp.x), std::fabs(dp.y)), k_hit_ulps_of_m * k_eps * m) << "B_i, case " << n;
            const double speed = std::hypot(c.v.x, c.v.y);
            const double tol = 2.0 * (k_speed_rel_bound * speed + k_speed_abs_bound);
            const Vec2 dv = got.ball.vel - want.ball.vel;
            ASSERT_LE(std::fabs(dv.x), tol) << "v'.x, scale " << s << " case " << n;
            ASSERT_LE(std::fabs(dv.y), tol) << "v'.y, scale " << s << " case " << n;
        }
    EXPECT_GT(checked, 5000);
}

/// A memory with one contact: wall w, met from side.
BallMemory arrived_on(std::uint32_t w, int side) {
    BallMemory m;
    m.contacts[0] = {w, static_cast<std::int8_t>(side)};
    m.count = 1;
    return m;
}

TEST(Promise, APieceThroughAWallsEndPointIsNotAllowed) {
    // q → r crosses the line y = 0 from below to above exactly through P0 = (1, 0), the end of the closed
    // segment: kernel.hpp's no-tunnelling definition counts that, so make_safe may not accept r.
    const std::vector<Wall> walls = {{{1, 0}, {5, 0}}};
    StepScratch scratch;
    const BallMemory none;
    BallMemory arrived;
    EXPECT_FALSE(detail::piece_allowed({0, -1}, {2, 1}, none, walls, nullptr, scratch, arrived));
    EXPECT_TRUE(truth::PathFollower(walls, std::vector<Ball>{{{0, -1}, {}}}).advance(0, {2, 1}) == 0);
    // Just beside the end point it passes beyond the wall: allowed, and no tunnel.
    EXPECT_TRUE(detail::piece_allowed({0, -1}, {1.5, 1}, none, walls, nullptr, scratch, arrived));
    EXPECT_TRUE(truth::PathFollower(walls, std::vector<Ball>{{{0, -1}, {}}}).advance(0, {1.5, 1}) == -1);
    // Through the other end, P1 = (5, 0), and with the wall's ends swapped: the same.
    EXPECT_FALSE(detail::piece_allowed({4, -1}, {6, 1}, none, walls, nullptr, scratch, arrived));
    const std::vector<Wall> swapped = {{{5, 0}, {1, 0}}};
    EXPECT_FALSE(detail::piece_allowed({0, -1}, {2, 1}, none, swapped, nullptr, scratch, arrived));
}

TEST(Promise, AnAllowedPieceSaysWhichWallsItArrivesOn) {
    // The wall y = 0 from (1, 0) to (5, 0): n = (e_y, −e_x) = (0, −4), so q = (3, −1) is on its outer side (+1).
    const std::vector<Wall> walls = {{{1, 0}, {5, 0}}, {{3, 0}, {3, 5}}};
    StepScratch scratch;
    const BallMemory none;
    BallMemory arrived;
    // Ending on the segment, from outside: a contact with the wall, on the side it came from; the second wall's
    // end point (3, 0) is the same point, and q = (3, −1) lies on that wall's line: no contact there.
    ASSERT_TRUE(detail::piece_allowed({3, -1}, {3, 0}, none, walls, nullptr, scratch, arrived));
    ASSERT_EQ(arrived.count, 1);
    EXPECT_EQ(arrived.contacts[0].wall, 0u);
    EXPECT_EQ(arrived.contacts[0].side, 1);
    // Ending on the line beyond the segment's end: no contact.
    ASSERT_TRUE(detail::piece_allowed({7, -1}, {7, 0}, none, walls, nullptr, scratch, arrived));
    EXPECT_EQ(arrived.count, 0);
    // Sliding along the first wall from a contact keeps it; a piece that does not move keeps the memory as it is.
    ASSERT_TRUE(detail::piece_allowed({3, 0}, {4, 0}, arrived_on(0, 1), walls, nullptr, scratch, arrived));
    ASSERT_EQ(arrived.count, 1);
    EXPECT_EQ(arrived.contacts[0].side, 1);
    ASSERT_TRUE(detail::piece_allowed({4, 0}, {4, 0}, arrived_on(1, -1), walls, nullptr, scratch, arrived));
    ASSERT_EQ(arrived.count, 1);
    EXPECT_EQ(arrived.contacts[0].wall, 1u);
    // Sliding along a wall the ball was not on: nothing to remember.
    ASSERT_TRUE(detail::piece_allowed({1.5, 0}, {2.5, 0}, none, walls, nullptr, scratch, arrived));
    EXPECT_EQ(arrived.count, 0);
}

TEST(Promise, TheAcceptedRangeIncludesItsLimit) {
    // kernel.hpp: magnitude at most 2^256, so 2^256 itself is in and the next double is out.
    const double lim = 0x1p256;
    EXPECT_TRUE(in_range(lim));
    EXPECT_TRUE(in_range(-lim));
    EXPECT_FALSE(in_range(std::nextafter(lim, INFINITY)));
    EXPECT_FALSE(in_range(INFINITY));
    EXPECT_FALSE(in_range(std::nan("")));
    // The reader takes the limit and refuses the next double, with the documented message.
    const auto ok = parse_scene_log("ricochet 1\nwall -0x1p256 0 0x1p256 0\nball 0 1 0 -1\n", "t");
    ASSERT_TRUE(std::holds_alternative<Scene>(ok));
    const auto bad = parse_scene_log("ricochet 1\nball 0x1.0000000000001p256 0 0 0\n", "t");
    ASSERT_TRUE(std::holds_alternative<Diagnostic>(bad));
    EXPECT_EQ(std::get<Diagnostic>(bad).col, 6);
    EXPECT_NE(std::get<Diagnostic>(bad).message.find("outside the accepted range"), std::string::npos);
    // A ball at the limit, moving by the limit, steps (the frame stays in range) and hits, inside the wall's
    // segment (not at an end), a wall whose ends lie at the limit.
    Frame f = one_frame(KernelId::robust, {{-lim, 0}, {lim, 0}}, Wall{{-lim, lim}, {lim, -lim}});
    EXPECT_EQ(f.status, FrameStatus::ok);
    ASSERT_EQ(f.hits.size(), 1u);
    EXPECT_EQ(f.hits[0].point, (Vec2{0, 0}));
    // One step past it is refused and changes nothing.
    f = one_frame(KernelId::robust, {{lim, 0}, {lim, 0}}, Wall{{0, 1}, {1, 1}});
    EXPECT_EQ(f.status, FrameStatus::out_of_range);
    EXPECT_EQ(f.ball, (Ball{{lim, 0}, {lim, 0}}));
}

/// hash.hpp's record, written field by field from the table (not from encode_event): little-endian
/// integers, IEEE-754 bit patterns, zero padding.
std::vector<unsigned char> documented_record(const Event& e) {
    std::vector<unsigned char> r(56, 0);
    const auto le = [&](std::size_t at, std::uint64_t v, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) r[at + i] = static_cast<unsigned char>((v >> (8 * i)) & 0xff);
    };
    le(0, static_cast<std::uint8_t>(e.kind), 1);
    le(1, static_cast<std::uint8_t>(e.shape), 1);
    le(4, e.ball, 4);
    le(8, static_cast<std::uint64_t>(e.frame), 8);
    le(16, e.index, 4);
    le(24, std::bit_cast<std::uint64_t>(e.pos.x), 8);
    le(32, std::bit_cast<std::uint64_t>(e.pos.y), 8);
    le(40, std::bit_cast<std::uint64_t>(e.vel.x), 8);
    le(48, std::bit_cast<std::uint64_t>(e.vel.y), 8);
    return r;
}

TEST(Promise, RunHashIsXxh64SeedZeroOverTheDocumentedRecords) {
    std::mt19937_64 rng(3);
    std::vector<Event> events;
    std::vector<unsigned char> bytes;
    // Every field at random (the kinds and shapes the enum has, frames of either sign, −0 and subnormals
    // among the doubles), up to 300 events: past the hasher's 73-record buffer more than once.
    for (int n = 0; n < 300; ++n) {
        Event e;
        e.kind = static_cast<Event::Kind>(rng() % 3);
        e.shape = static_cast<Event::Shape>(rng() % 3);
        e.ball = static_cast<std::uint32_t>(rng());
        e.frame = static_cast<std::int64_t>(rng());
        e.index = static_cast<std::uint32_t>(rng());
        const auto d = [&] {
            const std::uint64_t pick = rng() % 4;
            if (pick == 0) return -0.0;
            if (pick == 1) return 0x1p-1070 * static_cast<double>(rng() % 16);
            return std::ldexp(static_cast<double>(static_cast<std::int64_t>(rng() >> 11)), static_cast<int>(rng() % 200) - 100);
        };
        e.pos = {d(), d()};
        e.vel = {d(), d()};
        unsigned char r[k_event_record_size];
        encode_event(e, r);
        const std::vector<unsigned char> want = documented_record(e);
        ASSERT_TRUE(std::equal(want.begin(), want.end(), r)) << "event " << n;
        events.push_back(e);
        bytes.insert(bytes.end(), want.begin(), want.end());
        ASSERT_EQ(hash_events(events), XXH64(bytes.data(), bytes.size(), 0)) << "after " << n + 1 << " events";
    }
    // Every field reaches the hash: changing any one changes the digest.
    Event base{Event::Kind::hit, 5, 2, Event::Shape::none, 7, {1.5, -2.5}, {0.0, 0.0}};
    const std::uint64_t h = hash_events(std::span(&base, 1));
    std::vector<Event> variants(9, base);
    variants[0].kind = Event::Kind::overlap;
    variants[1].shape = Event::Shape::rect;
    variants[2].ball = 3;
    variants[3].frame = 6;
    variants[4].index = 8;
    variants[5].pos.x = 1.25;
    variants[6].pos.y = -0.5;
    variants[7].vel.x = -0.0;
    variants[8].vel.y = 1.0;
    for (std::size_t i = 0; i < variants.size(); ++i)
        EXPECT_NE(hash_events(std::span(&variants[i], 1)), h) << "field " << i << " is not hashed";
}

}  // namespace
}  // namespace ricochet
