// Batched robust sweep decisions (batch.hpp). Eight lanes at a time (AVX-512F where the CPU has it):
// each lane evaluates the four orientation determinants of the robust kernel's leg test (robust_leg.hpp) with exactly
// the operations of exact::orient's filter (so the certified signs are the same bits); the signs it declines get the
// exact path's second stage (staged_sign.hpp, bounded_det) in the same eight lanes, and a lane whose needed signs
// are still not certified is decided again, alone, by the exact predicates. Every certified sign is the exact one,
// so the decisions are robust's whichever stage certifies them. Without AVX-512F every pair goes through the exact
// predicates one at a time (their own filter first), which gives the same decisions at the scalar robust cost.
#include "ricochet/batch.hpp"

#include <algorithm>
#include <cstdint>

#include "kernels/robust/robust_leg.hpp"
#include "predicates/staged_sign.hpp"
#include "ricochet/predicates.hpp"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define RICOCHET_BATCH_AVX512 1
#endif

namespace ricochet {
namespace {

/// The robust kernel's own leg decision (robust_leg.hpp) for the leg Bs → Bs + v: the fallback, and the
/// definition every lane must agree with. Kept out of line: it is rare, and inlining it into the SIMD loop
/// only bloats it.
[[gnu::noinline]] Miss exact_leg(Vec2 q, Vec2 v, const Wall& w) { return robust::test_leg(q, q + v, w).miss; }

#ifdef RICOCHET_BATCH_AVX512
// The filter constants of predicates.cpp, restated (they must stay equal to those):
// Shewchuk's bound for a 2×2 determinant of differences, |det − fl(det)| ≤ k_ccw·(|l| + |r|).
using exact::k_ccw;
using exact::k_tiny;

/// The filtered sign of l − r in eight lanes: neg where the rounded value is negative, certain where
/// the filter vouches for that sign. exact::orient's filter vouches iff |l − r| > k_ccw·(|l| + |r|) and
/// |l| + |r| ≥ k_tiny; here the two tests are folded into |l − r| > max(k_ccw·(|l| + |r|), k_tiny), which
/// vouches for a subset of those lanes (|l − r| ≤ |l| + |r| and rounding is monotonic, so sum < k_tiny
/// implies |l − r| < k_tiny), never for more. A lane it declines goes to the exact predicates, so the
/// decision is the same either way; NaN lanes compare false and are declined too. A certain value is
/// never zero, so its sign is just neg or not.
struct Signs {
    __mmask8 neg, certain;
};

[[gnu::target("avx512f"), gnu::always_inline]] inline Signs filtered(__m512d l, __m512d r) {
    const __m512d value = _mm512_sub_pd(l, r);
    const __m512d sum = _mm512_add_pd(_mm512_abs_pd(l), _mm512_abs_pd(r));
    const __m512d bound = _mm512_max_pd(_mm512_mul_pd(_mm512_set1_pd(k_ccw), sum), _mm512_set1_pd(k_tiny));
    return {_mm512_cmp_pd_mask(value, _mm512_setzero_pd(), _CMP_LT_OQ),
            _mm512_cmp_pd_mask(_mm512_abs_pd(value), bound, _CMP_GT_OQ)};
}

/// A difference a − b in eight lanes: its rounded head and its exact rounding error (Shewchuk's Two-Diff, exact for
/// every finite a, b whose difference does not overflow; the tail is 0 when the difference is exact).
struct Diff8 {
    __m512d head, tail;
};

[[gnu::target("avx512f"), gnu::always_inline]] inline Diff8 two_diff(__m512d a, __m512d b) {
    const __m512d x = _mm512_sub_pd(a, b);
    const __m512d b_virtual = _mm512_sub_pd(a, x);
    const __m512d a_virtual = _mm512_add_pd(x, b_virtual);
    const __m512d b_round = _mm512_sub_pd(b_virtual, b);
    const __m512d a_round = _mm512_sub_pd(a, a_virtual);
    return {x, _mm512_add_pd(a_round, b_round)};
}

/// staged::bounded_det in eight lanes: sign((A + a)(B + b) − (C + c)(D + d)) with l = fl(A·B), r = fl(C·D), each
/// tail at most ε of its head. The same operations in the same order (le = fma(A, B, −l) is one rounding, as
/// std::fma; l − r = s + t exactly by Two-Diff, as two_sum(l, −r)), so the derivation over bounded_det holds lane by
/// lane: certain where |est| > k_det_tail·(|l| + |r|) with |l| + |r| in [k_tiny, k_stage_huge], never a zero.
[[gnu::target("avx512f"), gnu::always_inline]] inline Signs bounded_det(Diff8 p, Diff8 q, Diff8 u, Diff8 v) {
    // l and r as the filter formed them: the same products of the same heads.
    const __m512d l = _mm512_mul_pd(p.head, q.head), r = _mm512_mul_pd(u.head, v.head);
    const __m512d big = _mm512_add_pd(_mm512_abs_pd(l), _mm512_abs_pd(r));
    const __mmask8 usable = _mm512_cmp_pd_mask(big, _mm512_set1_pd(k_tiny), _CMP_GE_OQ) &
                              _mm512_cmp_pd_mask(big, _mm512_set1_pd(exact::staged::k_stage_huge), _CMP_LE_OQ);
    const __m512d le = _mm512_fmsub_pd(p.head, q.head, l);
    const __m512d re = _mm512_fmsub_pd(u.head, v.head, r);
    const Diff8 st = two_diff(l, r);
    // rest = ((t + le) − re) + ((A·b + a·B) − (C·d + c·D)); est = s + rest.
    const __m512d first = _mm512_sub_pd(_mm512_add_pd(st.tail, le), re);
    const __m512d ab = _mm512_add_pd(_mm512_mul_pd(p.head, q.tail), _mm512_mul_pd(p.tail, q.head));
    const __m512d cd = _mm512_add_pd(_mm512_mul_pd(u.head, v.tail), _mm512_mul_pd(u.tail, v.head));
    const __m512d est = _mm512_add_pd(st.head, _mm512_add_pd(first, _mm512_sub_pd(ab, cd)));
    const __m512d bound = _mm512_mul_pd(_mm512_set1_pd(exact::staged::k_det_tail), big);
    return {_mm512_cmp_pd_mask(est, _mm512_setzero_pd(), _CMP_LT_OQ),
            static_cast<__mmask8>(usable & _mm512_cmp_pd_mask(_mm512_abs_pd(est), bound, _CMP_GT_OQ))};
}

/// s, with the lanes it left uncertain taken from t where t is certain (both exact signs where both are certain).
[[gnu::target("avx512f"), gnu::always_inline]] inline Signs either(Signs s, Signs t) {
    const auto taken = static_cast<__mmask8>(t.certain & ~s.certain);
    return {static_cast<__mmask8>((s.neg & s.certain) | (t.neg & taken)), static_cast<__mmask8>(s.certain | t.certain)};
}

/// The four orientation signs of a leg test (oq, ob: orient(P0, P1, q) and (…, b); o0, o1: orient(q, b, P0) and
/// (…, P1)) and the lanes they decide: the same certified side at both ends decides alone; otherwise all four.
struct LegSigns {
    Signs oq, ob, o0, o1;
    __mmask8 decided() const {
        const __mmask8 inside = static_cast<__mmask8>(~oq.neg & ~ob.neg), outside = oq.neg & ob.neg;
        return oq.certain & ob.certain & (inside | outside | (o0.certain & o1.certain));
    }
};

/// The signs s with those the filter declined decided by stage 2 where it can, for the legs q → b (the differences'
/// tails formed here; their heads are the filter's differences, the same operations on the same inputs).
[[gnu::target("avx512f"), gnu::noinline]] LegSigns second_stage(LegSigns s, __m512d qx, __m512d qy, __m512d bx,
                                                                 __m512d by, __m512d x0, __m512d y0, __m512d x1,
                                                                 __m512d y1) {
    const Diff8 dqx = two_diff(qx, x0), dqy = two_diff(qy, y0), dbx = two_diff(bx, x0), dby = two_diff(by, y0);
    const Diff8 eqx = two_diff(qx, x1), eqy = two_diff(qy, y1), ebx = two_diff(bx, x1), eby = two_diff(by, y1);
    s.oq = either(s.oq, bounded_det(dqx, eqy, dqy, eqx));
    s.ob = either(s.ob, bounded_det(dbx, eby, dby, ebx));
    s.o0 = either(s.o0, bounded_det(dqx, dby, dqy, dbx));
    s.o1 = either(s.o1, bounded_det(eqx, eby, eqy, ebx));
    return s;
}

/// Eight lanes of the leg test; writes eight Miss codes to out and returns the mask of lanes left undecided
/// (their codes are garbage until the caller decides them exactly).
[[gnu::target("avx512f"), gnu::always_inline]] inline __mmask8 lanes(__m512d qx, __m512d qy, __m512d vx, __m512d vy,
                                                                     __m512d x0, __m512d y0, __m512d x1, __m512d y1,
                                                                     Miss* out) {
    // Be = Bs + v, as every kernel computes the leg's end.
    const __m512d bx = _mm512_add_pd(qx, vx), by = _mm512_add_pd(qy, vy);
    // The differences exact::orient's filter forms, (a − c) and (b − c), shared between determinants.
    const __m512d dqx = _mm512_sub_pd(qx, x0), dqy = _mm512_sub_pd(qy, y0);  // q − P0
    const __m512d dbx = _mm512_sub_pd(bx, x0), dby = _mm512_sub_pd(by, y0);  // b − P0
    const __m512d eqx = _mm512_sub_pd(qx, x1), eqy = _mm512_sub_pd(qy, y1);  // q − P1
    const __m512d ebx = _mm512_sub_pd(bx, x1), eby = _mm512_sub_pd(by, y1);  // b − P1
    // orient(P0, P1, q) = (P0 − q) × (P1 − q) = (q − P0) × (q − P1); side(q) = −orient(P0, P1, q).
    const __m512d lq = _mm512_mul_pd(dqx, eqy), rq = _mm512_mul_pd(dqy, eqx);
    const __m512d lb = _mm512_mul_pd(dbx, eby), rb = _mm512_mul_pd(dby, ebx);
    // orient(q, b, P0) = (q − P0) × (b − P0); orient(q, b, P1) = (q − P1) × (b − P1).
    const __m512d l0 = _mm512_mul_pd(dqx, dby), r0 = _mm512_mul_pd(dqy, dbx);
    const __m512d l1 = _mm512_mul_pd(eqx, eby), r1 = _mm512_mul_pd(eqy, ebx);
    LegSigns s{filtered(lq, rq), filtered(lb, rb), filtered(l0, r0), filtered(l1, r1)};
    // Degenerate: a zero-length leg, b = q.
    const __mmask8 still = _mm512_cmp_pd_mask(bx, qx, _CMP_EQ_OQ) & _mm512_cmp_pd_mask(by, qy, _CMP_EQ_OQ);
    // Stage 2 for the lanes the filter declined (a leg ending a rounding away from the wall's line: the end-on-wall
    // lanes), out of line: a batch the filter decides pays a branch for it.
    auto undecided = static_cast<__mmask8>(~(s.decided() | still));
    if (undecided != 0) {
        s = second_stage(s, qx, qy, bx, by, x0, y0, x1, y1);
        undecided = static_cast<__mmask8>(~(s.decided() | still));
    }
    const Signs oq = s.oq, ob = s.ob, o0 = s.o0, o1 = s.o1;
    // On certain lanes (no zeros): side = −orient, so Inside (sq < 0) where orient > 0.
    const __mmask8 inside = static_cast<__mmask8>(~oq.neg & ~ob.neg), outside = oq.neg & ob.neg;
    // before P0 iff sign(orient(q, b, P0)) = −sq = sign(orient(P0, P1, q)); past P1 iff sign(orient(q, b, P1)) = sq.
    const __mmask8 before = static_cast<__mmask8>(~(o0.neg ^ oq.neg));
    const __mmask8 past = o1.neg ^ oq.neg;
    // Lowest priority first, so that each later blend overrides: test_leg's order reversed. (Parallel
    // and leaving need a zero side, which no stage here certifies: those lanes go to the fallback.)
    __m512i code = _mm512_set1_epi64(static_cast<long long>(Miss::none));
    code = _mm512_mask_blend_epi64(past, code, _mm512_set1_epi64(static_cast<long long>(Miss::past_p1)));
    code = _mm512_mask_blend_epi64(before, code, _mm512_set1_epi64(static_cast<long long>(Miss::before_p0)));
    code = _mm512_mask_blend_epi64(outside, code, _mm512_set1_epi64(static_cast<long long>(Miss::both_outside)));
    code = _mm512_mask_blend_epi64(inside, code, _mm512_set1_epi64(static_cast<long long>(Miss::both_inside)));
    code = _mm512_mask_blend_epi64(still, code, _mm512_set1_epi64(static_cast<long long>(Miss::degenerate)));
    _mm_storel_epi64(reinterpret_cast<__m128i*>(out), _mm512_cvtepi64_epi8(code));
    return undecided;
}

// The two AVX-512F loops below run only on a CPU that has it (have_avx512): not on this project's CI
// runners, so the coverage report counts their branches as missed. Where they run, bench/batch_test holds
// every lane to sweep(robust)'s decision, on the inputs where the filter is least sure.
[[gnu::target("avx512f")]] std::size_t many_balls_avx512(const double* x, const double* y, const double* vx,
                                                         const double* vy, std::size_t n, const Wall& w, Miss* out) {
    const __m512d x0 = _mm512_set1_pd(w.p0.x), y0 = _mm512_set1_pd(w.p0.y);
    const __m512d x1 = _mm512_set1_pd(w.p1.x), y1 = _mm512_set1_pd(w.p1.y);
    std::size_t slow = 0, i = 0;
    for (; i + 8 <= n; i += 8) {
        __mmask8 undecided = lanes(_mm512_loadu_pd(x + i), _mm512_loadu_pd(y + i), _mm512_loadu_pd(vx + i),
                                   _mm512_loadu_pd(vy + i), x0, y0, x1, y1, out + i);
        for (; undecided != 0; undecided &= static_cast<__mmask8>(undecided - 1), ++slow) {
            const std::size_t j = i + static_cast<std::size_t>(__builtin_ctz(undecided));
            out[j] = exact_leg({x[j], y[j]}, {vx[j], vy[j]}, w);
        }
    }
    for (; i < n; ++i, ++slow) out[i] = exact_leg({x[i], y[i]}, {vx[i], vy[i]}, w);
    return slow;
}

[[gnu::target("avx512f")]] std::size_t many_walls_avx512(Vec2 bs, Vec2 v, const double* x0, const double* y0,
                                                         const double* x1, const double* y1, std::size_t n, Miss* out) {
    const __m512d qx = _mm512_set1_pd(bs.x), qy = _mm512_set1_pd(bs.y);
    const __m512d vx = _mm512_set1_pd(v.x), vy = _mm512_set1_pd(v.y);
    const auto wall = [&](std::size_t k) { return Wall{{x0[k], y0[k]}, {x1[k], y1[k]}}; };
    std::size_t slow = 0, i = 0;
    for (; i + 8 <= n; i += 8) {
        const __m512d ax0 = _mm512_loadu_pd(x0 + i), ay0 = _mm512_loadu_pd(y0 + i);
        const __m512d ax1 = _mm512_loadu_pd(x1 + i), ay1 = _mm512_loadu_pd(y1 + i);
        __mmask8 undecided = lanes(qx, qy, vx, vy, ax0, ay0, ax1, ay1, out + i);
        // Degenerate: a zero-length wall has no normal; test_leg answers so before anything else.
        const __mmask8 point = _mm512_cmp_pd_mask(ax0, ax1, _CMP_EQ_OQ) & _mm512_cmp_pd_mask(ay0, ay1, _CMP_EQ_OQ);
        for (__mmask8 p = point; p != 0; p &= static_cast<__mmask8>(p - 1))
            out[i + static_cast<std::size_t>(__builtin_ctz(p))] = Miss::degenerate;
        undecided &= static_cast<__mmask8>(~point);
        for (; undecided != 0; undecided &= static_cast<__mmask8>(undecided - 1), ++slow) {
            const std::size_t j = i + static_cast<std::size_t>(__builtin_ctz(undecided));
            out[j] = exact_leg(bs, v, wall(j));
        }
    }
    for (; i < n; ++i, ++slow) out[i] = exact_leg(bs, v, wall(i));
    return slow;
}

bool have_avx512() {
    static const bool yes = __builtin_cpu_supports("avx512f");
    return yes;
}
#endif

}  // namespace

std::size_t sweep_decisions(const BallsSoA& balls, const Wall& w, std::span<Miss> out) {
    const std::size_t n = balls.x.size();
    // Degenerate: a zero-length wall has no normal and is never hit.
    if (w.p0 == w.p1) {
        std::fill_n(out.begin(), n, Miss::degenerate);
        return 0;
    }
#ifdef RICOCHET_BATCH_AVX512
    if (have_avx512()) return many_balls_avx512(balls.x.data(), balls.y.data(), balls.vx.data(), balls.vy.data(), n, w, out.data());
#endif
    for (std::size_t i = 0; i < n; ++i) out[i] = exact_leg({balls.x[i], balls.y[i]}, {balls.vx[i], balls.vy[i]}, w);
    return n;
}

std::size_t sweep_decisions(Vec2 bs, Vec2 v, const WallsSoA& walls, std::span<Miss> out) {
    const std::size_t n = walls.x0.size();
#ifdef RICOCHET_BATCH_AVX512
    if (have_avx512())
        return many_walls_avx512(bs, v, walls.x0.data(), walls.y0.data(), walls.x1.data(), walls.y1.data(), n, out.data());
#endif
    for (std::size_t i = 0; i < n; ++i) out[i] = exact_leg(bs, v, {{walls.x0[i], walls.y0[i]}, {walls.x1[i], walls.y1[i]}});
    return n;
}

}  // namespace ricochet
