// A disc's first contact with a wall or a circle (core/src/kernels/disc/contact.hpp): the lecture's numbers worked by
// hand for the face, the caps and a bumper; tangents, ties, touching at either end of the leg, degenerate
// inputs; and on random legs the exact decision against the same geometry computed independently in 512-bit
// floating point (skipping the rare leg whose answer that precision cannot separate).
#include <gtest/gtest.h>

#include <gmpxx.h>

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <random>
#include <vector>

#include "kernels/disc/contact.hpp"

namespace ricochet::disc {
namespace {

// A floor from (0, 0) to (10, 0): n = (0, −10), its outside below, its inside (side −1) above.
const Wall k_floor{{0, 0}, {10, 0}};

Obstacle of(const Wall& w) { return {&w, {}, 0.0}; }

TEST(DiscContact, FaceWorkedByHand) {
    // Bs = (2, 3), v = (4, −4), R = 1: n = (0, −10), w = q − P0 = (2, 3), n·w = −30 so s = −1;
    // t_f = (s·n·w − R·|n|)/(−s·n·d) = (30 − 10)/40 = 0.5, B_i = (4, 1): the face line y = 1, one radius above.
    const Leg leg{{2, 3}, {6, -1}, 1.0};
    const auto c = first_contact(leg, k_floor);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->part, Part::face);
    EXPECT_EQ(c->side, -1);
    EXPECT_FALSE(c->at_start);
    EXPECT_EQ(contact_time(leg, of(k_floor), *c), 0.5);
    // The outward normal there is s·n = (0, 10), and the ball moves into it.
    EXPECT_EQ(normal_at({4, 1}, of(k_floor)), (Vec2{0, 10}));
    EXPECT_EQ(normal_sign({4, 1}, {4, -4}, of(k_floor)), -1);
}

TEST(DiscContact, CapWorkedByHand) {
    // Head-on at P0: Bs = (−3, 4), d = (3, −4), R = 1: β = d·(q − P0) = −25, a = 25, γ = 25 − 1 = 24,
    // Δ = β² − aγ = 25, t_c = (−β − √Δ)/a = (25 − 5)/25 = 0.8, B_i = (−0.6, 0.8). The face line y = 1 is
    // reached at t = 0.75, at x = −0.75, before P0: not a face contact.
    const Leg leg{{-3, 4}, {0, 0}, 1.0};
    const auto c = first_contact(leg, k_floor);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->part, Part::cap0);
    EXPECT_NEAR(contact_time(leg, of(k_floor), *c), 0.8, 1e-15);
    // Normal (B_i − P0)/R = (−0.6, 0.8): v = (3, −4) meets it head on, v·n̂ = −5.
    EXPECT_EQ(normal_sign({-0.6, 0.8}, {3, -4}, of(k_floor)), -1);
    // At an angle, 3-4-5: R = 5, the path y = 4 from x = −8: x² + 16 = 25 at x = −3, t = 0.5, while q lies in
    // the band's slab (4 < 5) beyond P0, outside the capsule.
    const Leg slant{{-8, 4}, {2, 4}, 5.0};
    const auto s = first_contact(slant, k_floor);
    ASSERT_TRUE(s);
    EXPECT_EQ(s->part, Part::cap0);
    EXPECT_EQ(contact_time(slant, of(k_floor), *s), 0.5);
    EXPECT_EQ(normal_at({-3, 4}, of(k_floor)), (Vec2{-3, 4}));
}

TEST(DiscContact, BumperWorkedByHand) {
    // A bumper of radius 2 at (10, 0), a disc of radius 1 from (0, 0) moving (10, 0): |X − C| = 3 at x = 7,
    // t = 0.7; a point ball (R = 0) at x = 8, t = 0.8.
    const Leg disc{{0, 0}, {10, 0}, 1.0}, point{{0, 0}, {10, 0}, 0.0};
    const Obstacle bumper{nullptr, {10, 0}, 2.0};
    const auto c = first_contact(disc, bumper.c, bumper.r);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->part, Part::circle);
    EXPECT_NEAR(contact_time(disc, bumper, *c), 0.7, 1e-15);
    const auto p = first_contact(point, bumper.c, bumper.r);
    ASSERT_TRUE(p);
    EXPECT_NEAR(contact_time(point, bumper, *p), 0.8, 1e-15);
    // Passing by exactly 3 from the centre: a tangent, no contact; by a hair less: a contact.
    EXPECT_FALSE(first_contact({{0, 3}, {20, 3}, 1.0}, bumper.c, bumper.r));
    EXPECT_TRUE(first_contact({{0, std::nextafter(3.0, 0.0)}, {20, std::nextafter(3.0, 0.0)}, 1.0}, bumper.c, bumper.r));
    // A point ball never meets a bumper of radius 0, even through its centre (no normal).
    EXPECT_FALSE(first_contact(point, {5, 0}, 0.0));
}

TEST(DiscContact, TangentsAndSlidesAreNoHit) {
    // Sliding along the face at exactly R: parallel, no contact; the path y = 5 tangent to the cap of radius 5.
    EXPECT_FALSE(first_contact({{-8, 5}, {2, 5}, 5.0}, k_floor));
    EXPECT_FALSE(first_contact({{2, 1}, {8, 1}, 1.0}, k_floor));
    // Past the joint onto the next wall of a collinear chain: the joint's caps are met tangentially.
    const Wall next{{10, 0}, {20, 0}};
    EXPECT_FALSE(first_contact({{8, 1}, {12, 1}, 1.0}, next));
    EXPECT_FALSE(first_contact({{8, 1}, {12, 1}, 1.0}, k_floor));
    // The same along a 3-4-5 slope: walls (0,0)→(3,4)→(6,8), R = 5, the centre offset by (4, −3).
    const Wall a{{0, 0}, {3, 4}}, b{{3, 4}, {6, 8}};
    EXPECT_FALSE(first_contact({{4, -3}, {7, 1}, 5.0}, a));
    EXPECT_FALSE(first_contact({{4, -3}, {7, 1}, 5.0}, b));
    // A hair closer and moving along: inside the slab, not entering: still no contact.
    EXPECT_FALSE(first_contact({{2, std::nextafter(1.0, 0.0)}, {8, std::nextafter(1.0, 0.0)}, 1.0}, k_floor));
}

TEST(DiscContact, TouchingAtEitherEnd) {
    // The leg ends exactly one radius above the floor: t = 1.
    const Leg end{{5, 3}, {5, 1}, 1.0};
    const auto c = first_contact(end, k_floor);
    ASSERT_TRUE(c);
    EXPECT_EQ(contact_time(end, of(k_floor), *c), 1.0);
    // Starting there: moving closer is a hit at t = 0; moving away or along is none.
    const auto in = first_contact({{5, 1}, {5, 0.5}, 1.0}, k_floor);
    ASSERT_TRUE(in);
    EXPECT_TRUE(in->at_start);
    EXPECT_FALSE(first_contact({{5, 1}, {5, 2}, 1.0}, k_floor));
    EXPECT_FALSE(first_contact({{5, 1}, {6, 1}, 1.0}, k_floor));
    // Starting overlapping (0.5 above, R = 1) and moving away: no hit this leg.
    EXPECT_FALSE(first_contact({{5, 0.5}, {5, 3}, 1.0}, k_floor));
    EXPECT_TRUE(first_contact({{5, 0.5}, {5, 0.25}, 1.0}, k_floor)->at_start);
    // Overlapping a cap and moving closer to the end point.
    const auto cap = first_contact({{-0.5, 0.5}, {0, 0.25}, 1.0}, k_floor);
    ASSERT_TRUE(cap);
    EXPECT_EQ(cap->part, Part::cap0);
    EXPECT_TRUE(cap->at_start);
}

TEST(DiscContact, DegenerateInputs) {
    // A centre on the segment has no normal; a zero-length leg does not move.
    EXPECT_FALSE(first_contact({{5, 0}, {5, 1}, 1.0}, k_floor));
    EXPECT_FALSE(first_contact({{5, 0}, {5, -1}, 1.0}, k_floor));
    EXPECT_FALSE(first_contact({{5, 3}, {5, 3}, 1.0}, k_floor));
    // A zero-length wall is a point, met by its cap: from (5, 3) down, one radius above it at t = 0.5.
    const Wall dot{{5, 0}, {5, 0}};
    const Leg leg{{5, 3}, {5, -1}, 1.0};
    const auto c = first_contact(leg, dot);
    ASSERT_TRUE(c);
    EXPECT_EQ(c->part, Part::cap0);
    EXPECT_EQ(contact_time(leg, of(dot), *c), 0.5);
}

TEST(DiscContact, TiesAreExact) {
    // Walls sharing P1 = (10, 0): head on at the shared end, both caps at t = 0.8.
    const Wall down{{10, 0}, {10, -10}};
    const Leg leg{{13, 4}, {10, 0}, 1.0};
    const auto a = first_contact(leg, k_floor), b = first_contact(leg, down);
    ASSERT_TRUE(a && b);
    EXPECT_EQ(a->part, Part::cap1);
    EXPECT_EQ(b->part, Part::cap0);
    EXPECT_EQ(compare(leg, of(k_floor), *a, of(down), *b), 0);
    // Straight down onto a chain's joint: both faces (each at its end) and the joint's caps at t = 0.5.
    const Wall next{{10, 0}, {20, 0}};
    const Leg joint{{10, 3}, {10, -1}, 1.0};
    const auto f = first_contact(joint, k_floor), g = first_contact(joint, next);
    ASSERT_TRUE(f && g);
    EXPECT_EQ(f->part, Part::face);
    EXPECT_EQ(g->part, Part::face);
    EXPECT_EQ(compare(joint, of(k_floor), *f, of(next), *g), 0);
    const Contact cap{Part::cap1, 0, false};
    EXPECT_EQ(compare(joint, of(k_floor), *f, of(k_floor), cap), 0);
    // One ulp earlier along the leg is earlier.
    const Wall higher{{0, std::nextafter(0.0, 1.0)}, {10, std::nextafter(0.0, 1.0)}};
    const auto h = first_contact(joint, higher);
    ASSERT_TRUE(h);
    EXPECT_EQ(compare(joint, of(higher), *h, of(k_floor), *f), -1);
    EXPECT_EQ(compare(joint, of(k_floor), *f, of(higher), *h), 1);
}

TEST(DiscContact, AnAcuteWedgeMeetsBothFacesAtOnce) {
    // The wedge (0, 0)→(100, 3) and (100, −3)→(0, 0), a disc of R = 1 down its axis from (90, 0) to (0, 0).
    // A: n = (3, −100), n·(q − P0) = 270, n·d = −270; B: n = (3, 100), n·(q − (100, −3)) = −30 + 300 = 270,
    // n·d = −270: the same t_f = (270 − √10009)/270 ≈ 0.6295 on both faces (x ≈ 33.3, inside both), an exact tie.
    const Wall a{{0, 0}, {100, 3}}, b{{100, -3}, {0, 0}};
    const Leg leg{{90, 0}, {0, 0}, 1.0};
    const auto ca = first_contact(leg, a), cb = first_contact(leg, b);
    ASSERT_TRUE(ca && cb);
    EXPECT_EQ(ca->part, Part::face);
    EXPECT_EQ(cb->part, Part::face);
    EXPECT_EQ(compare(leg, of(a), *ca, of(b), *cb), 0);
    EXPECT_NEAR(contact_time(leg, of(a), *ca), (270 - std::sqrt(10009.0)) / 270, 1e-15);
    // One ulp off the axis (y = 2^−1074 up) reaches the lower face B last: A first.
    const Leg up{{90, 4.9406564584124654e-324}, {0, 4.9406564584124654e-324}, 1.0};
    EXPECT_EQ(compare(up, of(a), *first_contact(up, a), of(b), *first_contact(up, b)), -1);
}

TEST(DiscContact, FarFromTheOriginAndAtExtremeScales) {
    // The face example moved by 2^40 and scaled by 2^±200: the same exact answers (all exact in doubles).
    for (const double scale : {0x1p-200, 1.0, 0x1p200}) {
        for (const double shift : {0.0, 0x1p40}) {
            const auto p = [&](double x, double y) { return Vec2{x * scale + shift * scale, y * scale}; };
            const Wall floor{p(0, 0), p(10, 0)};
            const Leg leg{p(2, 3), p(6, -1), 1.0 * scale};
            const auto c = first_contact(leg, floor);
            ASSERT_TRUE(c) << scale << " " << shift;
            EXPECT_EQ(c->part, Part::face);
            // One ulp more radius than the distance at the leg's end and the start is already in reach.
            EXPECT_FALSE(first_contact({p(2, 3), p(6, 3), 1.0 * scale}, floor));
            const Leg touch{p(5, 1), p(5, 0.5), 1.0 * scale};
            ASSERT_TRUE(first_contact(touch, floor));
            EXPECT_TRUE(first_contact(touch, floor)->at_start);
        }
    }
}

// An independent computation of the first contact in 512-bit floating point: the capsule's entry as the earliest
// of the crossings of the two offset segments P_k ± R·n̂ (clipped to the band) and the entries into the end discs,
// with the entry condition read off the distance's derivative. Returns the time, or a negative number for none,
// or nothing when some quantity lies within 2^−400 of a decision boundary (then the test skips the case).
std::optional<double> brute_force(const Leg& leg, const Wall& w) {
    mpf_set_default_prec(512);
    using F = mpf_class;
    const F qx(leg.q.x), qy(leg.q.y), dx = F(leg.b.x) - qx, dy = F(leg.b.y) - qy, R(leg.R);
    const F ax(w.p0.x), ay(w.p0.y), ex = F(w.p1.x) - ax, ey = F(w.p1.y) - ay;
    const F len = sqrt(ex * ex + ey * ey);
    F tiny(1);
    mpf_div_2exp(tiny.get_mpf_t(), tiny.get_mpf_t(), 400);  // 2^−400
    const auto near = [&](const F& x) { return abs(x) < tiny; };
    std::optional<F> best;
    bool unsure = false;
    // Faces: n̂ = (e_y, −e_x)/|e|; the line n̂·(X − P0) = σR for σ = ±1, entered where the ball comes from.
    const F nx = ey / len, ny = -ex / len;
    const F h0 = nx * (qx - ax) + ny * (qy - ay), nd = nx * dx + ny * dy;
    for (int sigma : {-1, 1}) {
        if (near(h0 - sigma * R)) unsure = true;
        // From the far side of the offset line, moving towards the segment.
        if (sgn(F(sigma * (h0 - sigma * R))) <= 0 || sgn(F(sigma * nd)) >= 0) continue;
        const F t = (sigma * R - h0) / nd;
        if (near(t - 1)) unsure = true;
        if (t > 1) continue;
        const F u = ((qx + t * dx - ax) * ex + (qy + t * dy - ay) * ey) / (len * len);
        if (near(u) || near(u - 1)) unsure = true;
        if (u < 0 || u > 1) continue;
        if (!best || t < *best) best = t;
    }
    for (Vec2 p : {w.p0, w.p1}) {
        const F px = qx - F(p.x), py = qy - F(p.y);
        const F a = dx * dx + dy * dy, beta = dx * px + dy * py, gamma = px * px + py * py - R * R;
        const F disc = beta * beta - a * gamma;
        if (near(gamma) || near(beta) || near(disc)) unsure = true;
        if (gamma <= 0 || beta >= 0 || disc <= 0) continue;
        const F t = (-beta - sqrt(disc)) / a;
        if (near(t - 1)) unsure = true;
        if (t <= 1 && (!best || t < *best)) best = t;
    }
    if (unsure) return std::nullopt;
    return best ? best->get_d() : -1.0;
}

TEST(DiscContact, RandomLegsAgreeWithAnIndependentComputation) {
    std::mt19937_64 rng(99);
    std::uniform_real_distribution<double> coord(-10, 10);
    int compared = 0, hits = 0;
    for (int i = 0; i < 20000; ++i) {
        const Wall w{{coord(rng), coord(rng)}, {coord(rng), coord(rng)}};
        Leg leg{{coord(rng), coord(rng)}, {coord(rng), coord(rng)}, std::fabs(coord(rng)) / 4};
        // Start outside the capsule (the start-in-reach rules are worked by hand above).
        if (!point_clear(leg.q, leg.R, of(w)) || point_clear(leg.q, leg.R, of(w)) != point_clear(leg.q, leg.R * (1 + 1e-9), of(w)))
            continue;
        const auto want = brute_force(leg, w);
        if (!want) continue;
        ++compared;
        const auto got = first_contact(leg, w);
        ASSERT_EQ(got.has_value(), *want >= 0) << i;
        if (!got) continue;
        ++hits;
        EXPECT_NEAR(contact_time(leg, of(w), *got), *want, 1e-12) << i;
    }
    EXPECT_GT(compared, 5000);
    EXPECT_GT(hits, 500);
}

/// x is a double nearest to v: no neighbour of x is closer.
bool is_nearest(double x, const mpf_class& v) {
    const mpf_class d0 = abs(mpf_class(x, 1100) - v);
    for (const double n : {std::nextafter(x, -INFINITY), std::nextafter(x, INFINITY)})
        if (abs(mpf_class(n, 1100) - v) < d0) return false;
    return true;
}

TEST(DiscContact, TheDoubleDoubleContactPointIsTheNearestDoubles) {
    // nearest_contact_fine (the exact kernel's construction without GMP, and robust's where its doubles cannot place
    // t) must answer only with the doubles nearest to t* and q + t*·(b − q), t* from the contact's formula in
    // 1100-bit floating point. Random legs, and legs grazing a 3-4-5 wall's face by ulps (t_f's cancellation).
    mpf_set_default_prec(1100);
    using F = mpf_class;
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> coord(-10, 10);
    int answered = 0, checked = 0;
    const auto check = [&](const Leg& leg, const Wall& w) {
        const auto c = first_contact(leg, w);
        if (!c || c->at_start) return;
        ++checked;
        const auto got = nearest_contact_fine(leg, of(w), *c);
        if (!got) return;
        ++answered;
        const F qx(leg.q.x), qy(leg.q.y), dx = F(leg.b.x) - qx, dy = F(leg.b.y) - qy;
        F t;
        if (c->part == Part::face) {
            const F nx = F(w.p1.y) - F(w.p0.y), ny = F(w.p0.x) - F(w.p1.x);
            const F nw = nx * (qx - F(w.p0.x)) + ny * (qy - F(w.p0.y)), nd = nx * dx + ny * dy;
            t = (c->side * nw - F(leg.R) * sqrt(nx * nx + ny * ny)) / (-c->side * nd);
        } else {
            const Vec2 p = c->part == Part::cap0 ? w.p0 : w.p1;
            const F px = qx - F(p.x), py = qy - F(p.y);
            const F a = dx * dx + dy * dy, beta = dx * px + dy * py, gamma = px * px + py * py - F(leg.R) * F(leg.R);
            t = (-beta - sqrt(beta * beta - a * gamma)) / a;
        }
        EXPECT_TRUE(is_nearest(got->t, t)) << got->t;
        EXPECT_TRUE(is_nearest(got->x.x, qx + t * dx)) << got->x.x;
        EXPECT_TRUE(is_nearest(got->x.y, qy + t * dy)) << got->x.y;
    };
    for (int i = 0; i < 4000; ++i) {
        const Wall w{{coord(rng), coord(rng)}, {coord(rng), coord(rng)}};
        const Leg leg{{coord(rng), coord(rng)}, {coord(rng), coord(rng)}, std::fabs(coord(rng)) / 4};
        if (point_clear(leg.q, leg.R, of(w))) check(leg, w);
    }
    // A 3-4-5 floor from (0, 0) to (40, 30), R = 5 (R·n̂ = (3, −4)): starts on the line shifted by R, moved by
    // ulps, legs one or two ulps from parallel.
    const Wall slope{{0, 0}, {40, 30}};
    for (int k = 1; k < 30; ++k)
        for (int away = 1; away <= 2; ++away)
            for (int skew = 1; skew <= 3; ++skew) {
                Vec2 q{4.0 * k / 3 + 3, static_cast<double>(k) - 4};
                for (int u = 0; u < away; ++u) q.y = std::nextafter(q.y, -INFINITY);
                Vec2 b{q.x + 8, q.y + 6};
                for (int u = 0; u < skew; ++u) b.y = std::nextafter(b.y, INFINITY);
                check({q, b, 5.0}, slope);
            }
    EXPECT_GT(checked, 500);
    EXPECT_GT(answered, checked * 9 / 10);
    fmt::print("double-double contact points: {} of {} answered, each the nearest doubles\n", answered, checked);
}

TEST(DiscContact, ClearanceIsExact) {
    // The piece from (2, 1) to (8, 1) stays exactly R = 1 from the floor: clear; one ulp lower is not.
    EXPECT_TRUE(piece_clear({2, 1}, {8, 1}, 1.0, of(k_floor)));
    EXPECT_FALSE(piece_clear({2, 1}, {8, std::nextafter(1.0, 0.0)}, 1.0, of(k_floor)));
    // A piece far from both ends of its own but crossing the floor is 0 away.
    EXPECT_FALSE(piece_clear({5, 3}, {5, -3}, 1.0, of(k_floor)));
    EXPECT_TRUE(crosses({5, 3}, {5, -3}, k_floor));
    EXPECT_FALSE(crosses({-5, 3}, {-5, -3}, k_floor));
    // touches (a point ball's piece reaching a wall): an end on the segment, along its line, a point on it.
    EXPECT_TRUE(touches({5, 3}, {5, 0}, k_floor));
    EXPECT_FALSE(touches({5, 3}, {5, 4.9406564584124654e-324}, k_floor));
    EXPECT_TRUE(touches({-3, 0}, {0, 0}, k_floor));
    EXPECT_FALSE(touches({-3, 0}, {-4.9406564584124654e-324, 0}, k_floor));
    EXPECT_TRUE(touches({10, 0}, {10, 0}, k_floor));
    EXPECT_FALSE(touches({11, 0}, {11, 0}, k_floor));
    EXPECT_TRUE(touches({11, -1}, {9, 1}, k_floor));
    // Around the end: (−0.6, 0.8) is exactly 1 from P0.
    EXPECT_EQ(point_clear({-0.6, 0.8}, 1.0, of(k_floor)),
              mpq_class(-0.6) * mpq_class(-0.6) + mpq_class(0.8) * mpq_class(0.8) >= 1);
    EXPECT_TRUE(point_clear({-3, 4}, 5.0, of(k_floor)));
    EXPECT_FALSE(point_clear({-3, std::nextafter(4.0, 0.0)}, 5.0, of(k_floor)));
    // A bumper: R + r is not rounded: 0.1 + 0.2 > 0.3 in doubles, the exact sum of the two doubles is what counts.
    const Obstacle b{nullptr, {0, 0}, 0.2};
    EXPECT_EQ(point_clear({0.30000000000000004, 0}, 0.1, b),
              mpq_class(0.30000000000000004) >= mpq_class(0.1) + mpq_class(0.2));
}

TEST(DiscContact, ClearanceAlongAnAxisIsExact) {
    // piece_clear's first test (boxes more than the reach apart along an axis) against the exact answer: a piece
    // parallel to a wall d away, d a few ulps either side of R = 0.1 (where the test leaves it to the decision) and
    // 2^−45 beyond (where it answers), on each side of the wall along each axis; then a bumper, whose R + r is the
    // exact sum.
    const Wall wall_x{{0, 0}, {0, 10}}, wall_y{{0, 0}, {10, 0}};
    const double R = 0.1;
    std::vector<double> ds{R * (1 + 0x1p-45), R * (1 - 0x1p-45)};
    for (double d = R, k = 0; k < 3; ++k) ds.push_back(d = std::nextafter(d, 1.0));
    for (double d = R, k = 0; k < 3; ++k) ds.push_back(d = std::nextafter(d, 0.0));
    ds.push_back(R);
    for (const double d : ds)
        for (const double side : {1.0, -1.0}) {
            const bool want = mpq_class(d) >= mpq_class(R);
            EXPECT_EQ(piece_clear({side * d, 2}, {side * (d + 5), 9}, R, of(wall_x)), want) << d << " " << side;
            EXPECT_EQ(piece_clear({2, side * d}, {9, side * (d + 5)}, R, of(wall_y)), want) << d << " " << side;
        }
    const Obstacle b{nullptr, {0, 0}, 0.2};
    const mpq_class sum = mpq_class(0.1) + mpq_class(0.2);
    for (double x = 0.3, k = 0; k < 6; ++k, x = std::nextafter(x, 1.0))
        EXPECT_EQ(piece_clear({x, -1}, {x, 1}, 0.1, b), mpq_class(x) >= sum) << x;
    EXPECT_TRUE(piece_clear({0.31, -1}, {0.31, 1}, 0.1, b));
}

}  // namespace
}  // namespace ricochet::disc
