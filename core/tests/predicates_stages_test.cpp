// The stages of the predicates' exact path (staged_sign.hpp) against big rationals (base/bignum.hpp): each stage and each early exit reached on
// inputs worked by hand, each stage's answer checked on its own (whenever it answers, it is right) over fixed-seed
// random inputs of every kind (boundary points from Pythagorean triples scaled by powers of two and moved by an
// ulp, magnitudes at the edges of the expansions' range, subnormals, cancellation in every term), and the
// predicates themselves, whose fallback counters show every stage taken.
#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <random>

#include "base/bignum.hpp"
#include "predicates/staged_sign.hpp"
#include "ricochet/predicates.hpp"

namespace ricochet {
namespace {

using exact::FallbackCounts;
using exact::staged::Split;
using exact::staged::two_diff;
using exact::staged::two_sum;

using bignum::Rational;

int sign(const Rational& v) { return bignum::sign(v); }
Rational q(double x) { return bignum::rational(x); }
Rational q(Split s) { return q(s.head) + q(s.tail); }

/// sign((A + a)(B + b) − (C + c)(D + d)) in rationals.
int det_gmp(Split p, Split r, Split u, Split v) { return sign(q(p) * q(r) - q(u) * q(v)); }
/// sign((X + x)² + (Y + y)² − (R + ρ)²) in rationals.
int squares_gmp(Split x, Split y, Split r) { return sign(q(x) * q(x) + q(y) * q(y) - q(r) * q(r)); }

double ulps(double x, int n) {
    for (; n > 0; --n) x = std::nextafter(x, INFINITY);
    for (; n < 0; ++n) x = std::nextafter(x, -INFINITY);
    return x;
}

/// How many calls f's predicates left to the given fallback counter.
template <class F>
unsigned long long calls(unsigned long long FallbackCounts::*counter, F&& f) {
    const auto before = exact::fallback_counts().*counter;
    f();
    return exact::fallback_counts().*counter - before;
}

// --- each stage on its own, worked by hand ---

TEST(PredicateStages, OrderedDecidesExactDifferencesAndTies) {
    // 3·5 − 2·7 = 1: products 15 > 14.
    EXPECT_EQ(exact::staged::ordered({3, 0}, {5, 0}, {2, 0}, {7, 0}, 15, 14), 1);
    EXPECT_EQ(exact::staged::ordered({2, 0}, {7, 0}, {3, 0}, {5, 0}, 14, 15), -1);
    // Overflowed products still order: 2^600·2^600 = +∞ against 1.
    EXPECT_EQ(exact::staged::ordered({0x1p600, 0}, {0x1p600, 0}, {1, 0}, {1, 0}, INFINITY, 1), 1);
    // A tie: (1 + 2^-52)² = 1 + 2^-51 + 2^-104 rounds to 1 + 2^-51 = (1 + 2^-51)·1; the fma errors 2^-104 and 0
    // say +1.
    const double a = 1 + 0x1p-52, c = 1 + 0x1p-51;
    ASSERT_EQ(a * a, c * 1.0);
    EXPECT_EQ(exact::staged::ordered({a, 0}, {a, 0}, {c, 0}, {1, 0}, a * a, c), 1);
    EXPECT_EQ(exact::staged::ordered({c, 0}, {1, 0}, {a, 0}, {a, 0}, c, a * a), -1);
    // An exact tie: 0.
    EXPECT_EQ(exact::staged::ordered({3, 0}, {4, 0}, {2, 0}, {6, 0}, 12, 12), 0);
    // No answer: a tail, a tie below k_tiny (2^-920: its error might not be representable), an infinite tie.
    EXPECT_FALSE(exact::staged::ordered({3, 0x1p-60}, {5, 0}, {2, 0}, {7, 0}, 15, 14));
    EXPECT_FALSE(exact::staged::ordered({0, 0}, {0, 0}, {0, 0}, {5, 0x1p-60}, 0, 0));
    EXPECT_FALSE(exact::staged::ordered({0x1p-460, 0}, {0x1p-460, 0}, {0x1p-460, 0}, {0x1p-460, 0}, 0x1p-920, 0x1p-920));
    EXPECT_FALSE(exact::staged::ordered({0x1p600, 0}, {0x1p600, 0}, {0x1p600, 0}, {0x1p600, 0}, INFINITY, INFINITY));
}

TEST(PredicateStages, BoundedDetDecidesOrDeclines) {
    // (1 + 2^-60)(1 + 2^-60) − 1·1 = 2^-59 + 2^-120 > 0: heads cancel, the first-order tails decide.
    EXPECT_EQ(exact::staged::bounded_det({1, 0x1p-60}, {1, 0x1p-60}, {1, 0}, {1, 0}, 1, 1), 1);
    // Within the bound: the first order cancels ((1 + t)(1 − t) − 1 = −t²) and only −2^-120 is left.
    EXPECT_FALSE(exact::staged::bounded_det({1, 0x1p-60}, {1, -0x1p-60}, {1, 0}, {1, 0}, 1, 1));
    // Guards: L below k_tiny, above k_stage_huge, infinite, NaN (∞·0).
    EXPECT_FALSE(exact::staged::bounded_det({0x1p-460, 0x1p-520}, {0x1p-460, 0}, {0, 0}, {0, 0}, 0x1p-920, 0));
    EXPECT_FALSE(exact::staged::bounded_det({0x1p460, 0x1p400}, {0x1p460, 0}, {0, 0}, {0, 0}, 0x1p920, 0));
    EXPECT_FALSE(exact::staged::bounded_det({0x1p600, 1}, {0x1p600, 0}, {0, 0}, {0, 0}, INFINITY, 0));
    EXPECT_FALSE(exact::staged::bounded_det({INFINITY, NAN}, {0, 0}, {1, 0}, {1, 0}, NAN, 1));
}

TEST(PredicateStages, CompleteDetNeedsEveryTerm) {
    // Every order cancels but the second: heads 1, first order (b − d) + (a − c) = 0 with c = a + δ, d = b − δ,
    // second order a·b − c·d = δ(a − b + δ) = 2^-62·3·2^-62 > 0.
    const double a = 0x1p-60, b = 0x1p-61, dl = 0x1p-62;
    const Split p{1, a}, r{1, b}, u{1, a + dl}, v{1, b - dl};
    EXPECT_FALSE(exact::staged::bounded_det(p, r, u, v, 1, 1));
    EXPECT_EQ(exact::staged::complete_det(p, r, u, v), 1);
    EXPECT_EQ(exact::staged::complete_det(u, v, p, r), -1);
    EXPECT_EQ(det_gmp(p, r, u, v), 1);
    // Exactly zero with every tail non-zero.
    EXPECT_EQ(exact::staged::complete_det({0.75, 0x1p-58}, {3, -0x1p-55}, {0.75, 0x1p-58}, {3, -0x1p-55}), 0);
}

TEST(PredicateStages, SquaresStagesDecideOrDecline) {
    // 3² + 4² − 5² = 0 and first order 2(3·x + 4·y − 5·ρ) = 2(3·5t − 5·3t) = 0 with x = 5t, y = 0, ρ = 3t:
    // only the second order x² − ρ² = 16t² > 0 is left, for the complete sum to find.
    const double t = 0x1p-60;
    EXPECT_FALSE(exact::staged::bounded_squares({3, 5 * t}, {4, 0}, {5, 3 * t}));
    EXPECT_EQ(exact::staged::complete_squares({3, 5 * t}, {4, 0}, {5, 3 * t}), 1);
    EXPECT_EQ(exact::staged::complete_squares({3, 3 * t}, {4, 0}, {5, 5 * t}), -1);
    EXPECT_EQ(exact::staged::complete_squares({3, 0}, {4, 0}, {5, 0}), 0);
    // A first-order tail decides: 3² + 4² − (5 − t)² = 10t − t² > 0.
    EXPECT_EQ(exact::staged::bounded_squares({3, 0}, {4, 0}, {5, -t}), 1);
    EXPECT_EQ(exact::staged::bounded_squares({3, 0}, {4, 0}, {5, t}), -1);
    // The heads' rounding errors decide: 3·(1 + 2^-52) squared is 9 + 18·2^-52 + 9·2^-104, rounded to
    // 9 + 18·2^-52 with error 9·2^-104; against R = 3(1 + 2^-52) rounded the same way, Y = 2^-60: Y² = 2^-120 and
    // 9·2^-104 − 9·2^-104 = 0, so +2^-120 is what is left; too small for the bound: the complete sum says +1.
    const double h = 3 * (1 + 0x1p-52);
    EXPECT_FALSE(exact::staged::bounded_squares({h, 0}, {0x1p-60, 0}, {h, 0}));
    EXPECT_EQ(exact::staged::complete_squares({h, 0}, {0x1p-60, 0}, {h, 0}), 1);
    // Guards: M below k_tiny, above k_stage_huge, infinite; a non-zero head too small for an exact square error
    // (2^-486 < k_square_min) though M ≈ 2 is fine and (2^-486)² + (1 + 2^-60)² − 1 ≈ 2^-59 is clear, and the same
    // with the head at k_square_min, which answers.
    EXPECT_FALSE(exact::staged::bounded_squares({0x1p-460, 0}, {0, 0}, {0, 0}));
    EXPECT_FALSE(exact::staged::bounded_squares({0x1p460, 0}, {0, 0}, {0, 0}));
    EXPECT_FALSE(exact::staged::bounded_squares({INFINITY, NAN}, {0, 0}, {1, 0}));
    EXPECT_FALSE(exact::staged::bounded_squares({0x1p-486, 0}, {1, 0x1p-60}, {1, 0}));
    EXPECT_FALSE(exact::staged::bounded_squares({1, 0x1p-60}, {0x1p-486, 0}, {1, 0}));
    EXPECT_FALSE(exact::staged::bounded_squares({1, 0x1p-60}, {0, 0}, {0x1p-486, 0}));
    EXPECT_EQ(exact::staged::bounded_squares({0x1p-485, 0}, {1, 0x1p-60}, {1, 0}), 1);
}

// --- each stage against GMP over random inputs of every kind (fixed seed) ---

struct Rng {
    std::mt19937_64 rng{20261202};
    double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
    int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
    bool coin() { return rng() % 2 == 0; }
    /// A random double of magnitude in [2^lo, 2^hi), either sign.
    double magnitude(int lo, int hi) { return (coin() ? 1 : -1) * std::ldexp(uniform(1, 2), integer(lo, hi - 1)); }
};

TEST(PredicateStages, SquareErrorIsExactInItsRange) {
    // Dekker's square error against the correctly rounded fma, which gives x² − fl(x²) exactly when it is
    // representable (as it is here): random mantissas at every exponent of the range, and its two ends.
    Rng g;
    for (int e = -485; e <= 451; ++e)
        for (int i = 0; i < 20; ++i) {
            const double x = std::ldexp(g.uniform(1, 2), e) * (g.coin() ? 1 : -1);
            ASSERT_EQ(exact::staged::square_error(x, x * x), std::fma(x, x, -(x * x))) << x;
        }
    for (const double x : {0x1p-485, 0x1.fffffffffffffp-485, 0x1.fffffffffffffp451, 0x1p451, 0.0, -0.0}) {
        ASSERT_EQ(exact::staged::square_error(x, x * x), std::fma(x, x, -(x * x))) << x;
    }
}

/// Stage 3's precondition: each head and tail 0, or a multiple of 2^-502 of magnitude at most 2^451.
bool in_stage3_range(std::initializer_list<Split> xs) {
    for (const Split& s : xs)
        for (double x : {s.head, s.tail})
            if (x != 0.0 && !(std::fabs(x) <= 0x1p451 && std::ldexp(x, 502) == std::trunc(std::ldexp(x, 502)))) return false;
    return true;
}

/// Checks every stage that answers against GMP (stage 3 where its precondition holds), and counts the cases each
/// stage was the first to answer (left: neither stage 1 nor 2 answered, and stage 3's precondition fails).
struct StageCheck {
    int ordered = 0, bounded = 0, complete = 0, left = 0;

    void det(Split p, Split r, Split u, Split v) {
        const int want = det_gmp(p, r, u, v);
        const double l = p.head * r.head, rr = u.head * v.head;
        const auto s1 = exact::staged::ordered(p, r, u, v, l, rr);
        if (s1) {
            ASSERT_EQ(*s1, want) << p.head << ' ' << r.head << ' ' << u.head << ' ' << v.head;
        }
        const auto s2 = exact::staged::bounded_det(p, r, u, v, l, rr);
        if (s2) {
            ASSERT_EQ(*s2, want) << p.head << ' ' << p.tail << ' ' << r.head << ' ' << r.tail;
        }
        const bool s3 = in_stage3_range({p, r, u, v});
        if (s3) {
            ASSERT_EQ(exact::staged::complete_det(p, r, u, v), want) << p.head << ' ' << r.head << ' ' << u.head;
        }
        count(s1.has_value(), s2.has_value(), s3);
    }
    void squares(Split x, Split y, Split r) {
        const int want = squares_gmp(x, y, r);
        const auto s2 = exact::staged::bounded_squares(x, y, r);
        if (s2) {
            ASSERT_EQ(*s2, want) << x.head << ' ' << x.tail << ' ' << y.head << ' ' << r.head << ' ' << r.tail;
        }
        const bool s3 = in_stage3_range({x, y, r});
        if (s3) {
            ASSERT_EQ(exact::staged::complete_squares(x, y, r), want) << x.head << ' ' << y.head << ' ' << r.head;
        }
        count(false, s2.has_value(), s3);
    }
    void count(bool s1, bool s2, bool s3) { ++(s1 ? ordered : s2 ? bounded : s3 ? complete : left); }
};

/// A Pythagorean triple (m² − n², 2mn, m² + n²), 1 ≤ n < m ≤ 64.
void triple(Rng& g, double& a, double& b, double& c) {
    const int m = g.integer(2, 64), n = g.integer(1, m - 1);
    a = m * m - n * n;
    b = 2.0 * m * n;
    c = m * m + n * n;
}

TEST(PredicateStages, EachStageAgreesWithGmpOnRandomInputs) {
    Rng g;
    StageCheck det, sq;
    for (int i = 0; i < 20000; ++i) {
        // Boundary points from Pythagorean triples at scales 2^k across the expansions' range (2^-450 .. 2^450,
        // the triples reaching 2^13), around a centre that makes the differences exact (a power of two at the same
        // scale) or not (any double up to 2^6 times the scale), moved by −1, 0 or +1 ulp.
        double a, b, c;
        triple(g, a, b, c);
        const int k = g.integer(-440, 430);
        const double s = std::ldexp(1.0, k);
        const Vec2 ctr = g.coin() ? Vec2{s * g.integer(-8, 8), s * g.integer(-8, 8)}
                                  : Vec2{g.uniform(-64, 64) * s, g.uniform(-64, 64) * s};
        const Vec2 p{ulps(ctr.x + a * s, g.integer(-1, 1)), ulps(ctr.y + b * s, g.integer(-1, 1))};
        const double r = ulps(c * s, g.integer(-1, 1));
        ASSERT_NO_FATAL_FAILURE(sq.squares(two_diff(p.x, ctr.x), two_diff(p.y, ctr.y), {r, 0}));
        // The radius as a sum of two, exact or not.
        const double ra = g.coin() ? std::ldexp(std::floor(c / 3), k) : r * g.uniform(0, 1);
        const double rb = ulps(r - ra, g.integer(-1, 1));
        ASSERT_NO_FATAL_FAILURE(sq.squares(two_diff(p.x, ctr.x), two_diff(p.y, ctr.y), two_sum(ra, rb)));
        // The same points as a determinant: (p − ctr) × (q − ctr) with q on the ray through p (exact zero up to
        // the ulps), or q from another triple.
        const double t = g.coin() ? 2.0 : g.uniform(-3, 3);
        const Vec2 qq{ulps(ctr.x + t * (p.x - ctr.x), g.integer(-1, 1)), ulps(ctr.y + t * (p.y - ctr.y), g.integer(-1, 1))};
        ASSERT_NO_FATAL_FAILURE(
            det.det(two_diff(p.x, ctr.x), two_diff(qq.y, ctr.y), two_diff(p.y, ctr.y), two_diff(qq.x, ctr.x)));
    }
    for (int i = 0; i < 20000; ++i) {
        // Cancellation in every term: points on the line y = 2^j·x (exactly collinear, their differences
        // inexact), centres and radii of circles whose touching is exact in reals though every sum rounds
        // (0.1 + 0.2 against 0.1 − (−0.2), scaled), at magnitudes at the edges of the range and subnormal.
        const int j = g.integer(-3, 3);
        const int lo = i % 3 == 0 ? -450 : i % 3 == 1 ? 440 : -10;
        const double u = g.magnitude(lo, lo + 10), v = g.magnitude(lo, lo + 10), w = g.magnitude(lo, lo + 10);
        const Vec2 pa{u, std::ldexp(u, j)}, pb{v, std::ldexp(v, j)}, pc{w, std::ldexp(w, j)};
        ASSERT_NO_FATAL_FAILURE(
            det.det(two_diff(pa.x, pc.x), two_diff(pb.y, pc.y), two_diff(pa.y, pc.y), two_diff(pb.x, pc.x)));
        const double s = std::ldexp(1.0, g.integer(lo, lo + 8));
        const double r1 = ulps(0.1 * s, g.integer(-1, 1)), r2 = 0.2 * s;
        const double cx = ulps(-0.2 * s, g.integer(-1, 1));
        ASSERT_NO_FATAL_FAILURE(sq.squares(two_diff(0.1 * s, cx), {0, 0}, two_sum(r1, r2)));
        ASSERT_NO_FATAL_FAILURE(sq.squares(two_diff(0.1 * s, cx), two_diff(r1, r2), two_sum(r1 * 0.75, r2)));
    }
    for (int i = 0; i < 20000; ++i) {
        // The first order cancelled by construction, leaving the rounding of the estimate and the dropped second
        // order to fight over the sign: exactly where stage 2's bound must hold it back. Determinants with equal
        // heads, A·B − A·B = 0, and d solving A·(b − d) + B·(a − c) = 0 in doubles; sums of squares with heads
        // from a Pythagorean triple, X² + Y² − R² = 0, and ρ solving X·x + Y·y − R·ρ = 0. Tails up to ε/4 of
        // their heads, so that the solved one stays within ε of its own.
        const double s = std::ldexp(1.0, g.integer(-400, 380));
        const double A = g.uniform(1, 2) * s, B = g.uniform(1, 2) * s;
        const auto tail = [&](double head) { return std::ldexp(g.uniform(-1, 1) * head, -55); };
        const double a = tail(A), b = tail(B), c = tail(A);
        const double d = b + B * (a - c) / A;
        ASSERT_NO_FATAL_FAILURE(det.det({A, a}, {B, b}, {A, c}, {B, d}));
        double X, Y, R;
        triple(g, X, Y, R);
        X *= s, Y *= s, R *= s;
        const double x = tail(X), y = tail(Y);
        const double rho = (X * x + Y * y) / R;
        ASSERT_NO_FATAL_FAILURE(sq.squares({X, x}, {Y, y}, {R, rho}));
    }
    // Every stage answered first, and often (the counts are fixed by the seed).
    // Measured with this seed: determinants 12187 ordered, 9804 bounded, 36282 complete, 1727 left to GMP;
    // squares 74186 bounded, 22663 complete, 3151 left.
    EXPECT_GT(det.ordered, 10000);
    EXPECT_GT(det.bounded, 8000);
    EXPECT_GT(det.complete, 30000);
    EXPECT_GT(det.left, 1400);
    EXPECT_GT(sq.bounded, 60000);
    EXPECT_GT(sq.complete, 18000);
    EXPECT_GT(sq.left, 2500);
}

// --- the predicates: every stage taken, every answer GMP's ---

TEST(PredicateStages, PredicatesTakeEveryStage) {
    // orient, exact differences, a sliver the filter cannot decide: (0, 0), (2^52, 1), (2^53 + 2, 2):
    // (b − a) × (c − a) = 2^52·2 − 1·(2^53 + 2) = −2 < 0, clockwise.
    int o = 2;
    EXPECT_EQ(calls(&FallbackCounts::ordered, [&] { o = exact::orient({0, 0}, {0x1p52, 1}, {0x1p53 + 2, 2}); }), 1u);
    EXPECT_EQ(o, -1);
    // orient, a tie of the rounded products: with c = 0, a = (1 + 2^-52, 1 + 2^-51), b = (1, 1 + 2^-52),
    // (a − c) × (b − c) = (1 + 2^-52)² − (1 + 2^-51) = 2^-104 > 0, and both products round to 1 + 2^-51.
    const double e1 = 1 + 0x1p-52, e2 = 1 + 0x1p-51;
    EXPECT_EQ(calls(&FallbackCounts::ordered, [&] { o = exact::orient({e1, e2}, {1, e1}, {0, 0}); }), 1u);
    EXPECT_EQ(o, 1);
    // orient, inexact differences: a = (0.1, 0.3), b = (0.7, 2.1), c = (−0.3, −0.9), near the line y = 3x (each
    // decimal rounded): the leading terms and the tails decide.
    const Vec2 a{0.1, 0.3}, b{0.7, 2.1}, c{-0.3, -0.9};
    const int want = sign((q(b.x) - q(a.x)) * (q(c.y) - q(a.y)) - (q(b.y) - q(a.y)) * (q(c.x) - q(a.x)));
    EXPECT_EQ(calls(&FallbackCounts::bounded, [&] { o = exact::orient(a, b, c); }), 1u);
    EXPECT_EQ(o, want);
    // orient, exactly collinear with inexact differences: on y = 2x, only the complete sum says 0.
    EXPECT_EQ(calls(&FallbackCounts::complete, [&] { o = exact::orient({0.1, 0.2}, {0.7, 1.4}, {-0.3, -0.6}); }), 1u);
    EXPECT_EQ(o, 0);
    // direction_side, inexact e: wall (0.1, 0) → (0.7, 0.9), whose e_x = 0.7 − 0.1 rounds, and d = (0.6, 0.9)
    // nearly along it.
    const Wall w{{0.1, 0}, {0.7, 0.9}};
    const Vec2 d{0.6, 0.9};
    const int dwant = sign((q(w.p1.y) - q(w.p0.y)) * q(d.x) - (q(w.p1.x) - q(w.p0.x)) * q(d.y));
    EXPECT_EQ(calls(&FallbackCounts::bounded, [&] { o = exact::direction_side(d, w); }), 1u);
    EXPECT_EQ(o, dwant);
    // direction_side, exact differences on a tie: e = (3, 4) − (0, 0), d = (3, 4): e × d = 0, products 12 = 12,
    // errors 0 = 0.
    EXPECT_EQ(calls(&FallbackCounts::ordered, [&] { o = exact::direction_side({3, 4}, Wall{{0, 0}, {3, 4}}); }), 1u);
    EXPECT_EQ(o, 0);
    // point_circle: exactly on (3-4-5 scaled by 2^-400: the complete sum), an ulp off (the bounded stage).
    const Vec2 p{3 * 0x1p-400, 4 * 0x1p-400};
    EXPECT_EQ(calls(&FallbackCounts::complete, [&] { o = exact::point_circle(p, {{0, 0}, 5 * 0x1p-400}); }), 1u);
    EXPECT_EQ(o, 0);
    EXPECT_EQ(calls(&FallbackCounts::bounded, [&] { o = exact::point_circle(p, {{0, 0}, ulps(5 * 0x1p-400, 1)}); }), 1u);
    EXPECT_EQ(o, -1);
    // circle_circle: 0.1 − (−0.2) and 0.1 + 0.2 round to the same double and are the same real: touching, only
    // the complete sum can tell; with the centre an ulp further, apart (the bounded stage).
    EXPECT_EQ(calls(&FallbackCounts::complete, [&] { o = exact::circle_circle({{0.1, 0}, 0.1}, {{-0.2, 0}, 0.2}); }), 1u);
    EXPECT_EQ(o, 0);
    const Circle further{{ulps(-0.2, -1), 0}, 0.2};
    EXPECT_EQ(calls(&FallbackCounts::bounded, [&] { o = exact::circle_circle({{0.1, 0}, 0.1}, further); }), 1u);
    EXPECT_EQ(o, 1);
}

TEST(PredicateStages, CirclesAgreeWithGmpNearTheirBoundary) {
    // The bench's workload, and Pythagorean boundaries at every scale: centre, radius, a point on the circle
    // rounded and moved by up to 2 ulps; two circles touching likewise. Every answer against GMP.
    Rng g;
    const auto before = exact::fallback_counts();
    for (int i = 0; i < 50000; ++i) {
        Circle c;
        Vec2 p;
        if (i % 2 == 0) {
            c = {{g.uniform(-100, 100), g.uniform(-100, 100)}, g.uniform(0, 10)};
            const double th = g.uniform(0, 6.283185307179586);
            p = {c.c.x + c.r * std::cos(th), c.c.y + c.r * std::sin(th)};
        } else {
            double a, b, r;
            triple(g, a, b, r);
            const double s = std::ldexp(1.0, g.integer(-440, 430));
            c = {{s * g.integer(-100, 100), s * (g.coin() ? g.integer(-100, 100) : g.uniform(-100, 100))}, r * s};
            p = {c.c.x + (g.coin() ? a : -b) * s, c.c.y + (g.coin() ? b : -a) * s};
        }
        if (g.coin()) p = {ulps(p.x, g.integer(-2, 2)), ulps(p.y, g.integer(-2, 2))};
        const Rational dx = q(p.x) - q(c.c.x), dy = q(p.y) - q(c.c.y);
        ASSERT_EQ(exact::point_circle(p, c), sign(dx * dx + dy * dy - q(c.r) * q(c.r))) << i;
        // A second circle touching c at p: centre p + rb·(p − c)/|p − c| rounded, radius rb.
        const double rb = c.r * g.uniform(0, 2);
        const double len = std::sqrt(static_cast<double>(bignum::to_double(dx) * bignum::to_double(dx) + bignum::to_double(dy) * bignum::to_double(dy)));
        if (!(len > 0)) continue;
        const Circle b{{ulps(p.x + rb * bignum::to_double(dx) / len, g.integer(-1, 1)),
                        ulps(p.y + rb * bignum::to_double(dy) / len, g.integer(-1, 1))},
                       rb};
        const Rational ex = q(c.c.x) - q(b.c.x), ey = q(c.c.y) - q(b.c.y), rs = q(c.r) + q(b.r);
        ASSERT_EQ(exact::circle_circle(c, b), sign(ex * ex + ey * ey - rs * rs)) << i;
    }
    const auto after = exact::fallback_counts();
    EXPECT_GT(after.bounded - before.bounded, 5000u);
    EXPECT_GT(after.complete - before.complete, 1000u);
}

}  // namespace
}  // namespace ricochet
