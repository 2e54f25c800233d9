// Box2D 2.4.1 as a kernel (`--kernel box2d`): every test through Box2D's own API, in float as its users work.
// The sweep is b2EdgeShape::RayCast of the leg against a two-sided edge; the frame is the loop a Box2D user
// writes for a bouncing bullet around it: cast the rest of the frame's leg at every edge, take the first hit,
// move to it, reflect v about the normal RayCast returned, spend the rest of the frame. The statics are
// b2CircleShape::TestPoint, b2CollideCircles, b2PolygonShape::TestPoint and b2TestOverlap, as bench's peer
// calls them. Box2D is a peer under test, not code of this project: its failures are documented, not fixed.
#include <box2d/box2d.h>

#include <cstdint>
#include <optional>

#include "peer_kernels.hpp"
#include "peer_trace.hpp"

namespace ricochet::peers {
namespace {

/// A double as Box2D holds it: rounded to float (past float's range, ±inf).
b2Vec2 to_b2(Vec2 p) { return {static_cast<float>(p.x), static_cast<float>(p.y)}; }
/// Box2D's float widened to double: exact.
Vec2 to_vec(b2Vec2 p) { return {p.x, p.y}; }

/// Box2D's frame for shapes placed in world coordinates.
b2Transform identity() {
    b2Transform xf;
    xf.SetIdentity();
    return xf;
}

/// A wall as a Box2D user makes one: a two-sided edge from P0 to P1.
b2EdgeShape edge_of(const Wall& w) {
    b2EdgeShape e;
    e.SetTwoSided(to_b2(w.p0), to_b2(w.p1));
    return e;
}

/// The edge's unit normal as RayCast computes it: (e_y, −e_x) normalized; zero for an edge shorter than
/// b2_epsilon (b2Vec2::Normalize leaves it as it is).
b2Vec2 edge_normal(const b2EdgeShape& e) {
    const b2Vec2 d = e.m_vertex2 - e.m_vertex1;
    b2Vec2 n(d.y, -d.x);
    n.Normalize();
    return n;
}

/// The ray p1 → p2 (maxFraction 1) against an edge: Box2D's answer, or nothing for no hit.
std::optional<b2RayCastOutput> ray_cast(const b2EdgeShape& e, b2Vec2 p1, b2Vec2 p2) {
    b2RayCastInput in;
    in.p1 = p1;
    in.p2 = p2;
    in.maxFraction = 1.0f;
    b2RayCastOutput out;
    if (!e.RayCast(&out, in, identity(), 0)) return std::nullopt;
    return out;
}

/// Box2D 2.4.1 behind the kernel interface: a Kernel (kernel.hpp).
struct Box2dKernel {
    /// Float's ε = 2^-24: v rounded to float (ε), Normalize's length, reciprocal and products (≈ 5ε a
    /// component), the reflection's dot, product and subtraction (≈ 5ε), and |n̂|² − 1 doubled (≈ 20ε): about
    /// 32ε = 2^-19 a reflection; 2^-18 leaves room, so only Box2D's real losses fail `speed`.
    static constexpr double k_speed_rel_bound = 0x1p-18;
    /// In float's subnormal range each operation errs by up to 2^-150 absolutely: 64 of them.
    static constexpr double k_speed_abs_bound = 0x1p-144;
    /// A peer under test: its failure logs document what it breaks (`expect failure`).
    static constexpr bool k_failures_documented = true;

    static Side classify(Vec2 p, const Wall& w) {
        // BC = n̂·(p − v1) in float, n̂ the edge normal RayCast uses
        const b2EdgeShape e = edge_of(w);
        return side_of(b2Dot(edge_normal(e), to_b2(p) - e.m_vertex1));
    }

    static bool point_in_circle(Vec2 p, const Circle& c) {
        b2CircleShape s;
        s.m_p = to_b2(c.c);
        s.m_radius = static_cast<float>(c.r);
        return s.TestPoint(identity(), to_b2(p));
    }

    static bool circles_overlap(const Circle& a, const Circle& b) {
        b2CircleShape sa, sb;
        sa.m_p = to_b2(a.c);
        sa.m_radius = static_cast<float>(a.r);
        sb.m_p = to_b2(b.c);
        sb.m_radius = static_cast<float>(b.r);
        b2Manifold m;
        b2CollideCircles(&m, &sa, identity(), &sb, identity());
        return m.pointCount > 0;
    }

    static bool point_in_rect(Vec2 p, const Rect& r) {
        // A box as Box2D users make one: half extents about a centre.
        const double hx = 0.5 * (r.right - r.left), hy = 0.5 * (r.top - r.bottom);
        b2PolygonShape box;
        box.SetAsBox(static_cast<float>(hx), static_cast<float>(hy), to_b2({r.left + hx, r.bottom + hy}), 0.0f);
        return box.TestPoint(identity(), to_b2(p));
    }

    static bool rects_overlap(const Rect& a, const Rect& b) {
        b2AABB ba, bb;
        ba.lowerBound = to_b2({a.left, a.bottom});
        ba.upperBound = to_b2({a.right, a.top});
        bb.lowerBound = to_b2({b.left, b.bottom});
        bb.upperBound = to_b2({b.right, b.top});
        return b2TestOverlap(ba, bb);
    }

    static Sweep sweep(Vec2 bs, Vec2 v, const Wall& w) {
        // The leg Bs → Be = Bs + v, both in float, as the ray p1 → p2; a ball that does not move casts none.
        const b2Vec2 p1 = to_b2(bs), p2 = p1 + to_b2(v);
        const auto out = p1 == p2 ? std::nullopt : ray_cast(edge_of(w), p1, p2);
        if (!out) return {Miss::no_reason, 0.0, {}};
        // The ray hits at p1 + fraction·(p2 − p1) (b2_collision.h).
        return {Miss::none, out->fraction, to_vec(p1 + out->fraction * (p2 - p1))};
    }

    static Vec2 reflect(Vec2 v, const Wall& w) {
        // v' = v − 2(v·n̂)n̂ in float, n̂ the edge normal RayCast returns (up to its sign)
        const b2Vec2 n = edge_normal(edge_of(w)), vf = to_b2(v);
        return to_vec(vf - 2.0f * b2Dot(vf, n) * n);
    }

    /// One frame, the bouncing bullet: the ray from the ball over the rest of the frame at every edge but the
    /// one just bounced off, the nearest hit, bounce, again. Box2D remembers nothing between frames: memory is
    /// not read or written.
    static FrameStatus step_ball(Ball& ball, BallMemory& /*memory*/, std::span<const Wall> walls,
                                 std::vector<HitEvent>& hits, StepScratch& scratch, const WallIndex* index) {
        b2Vec2 p = to_b2(ball.pos), v = to_b2(ball.vel);
        float rest = 1.0f, now = 0.0f;
        std::optional<std::uint32_t> last;
        FrameStatus status = FrameStatus::ok;
        for (int bounce = 0;; ++bounce) {
            // The rest of the frame as a ray p1 → p2; traced as Box2D's floats, widened exactly.
            const b2Vec2 p1 = p, p2 = p + rest * v;
            const Vec2 a = to_vec(p1), b = to_vec(p2);
            TracedLeg* traced = begin_leg(scratch, a, b, to_vec(v), last);
            bool found = false;
            std::uint32_t best = 0;
            b2RayCastOutput hit{};
            // A ball that does not move casts no ray (as bench/scale's Box2D loop does).
            const auto tried = p1 == p2 ? std::span<const std::uint32_t>{} : candidates(walls, index, a, b, scratch);
            for (std::uint32_t i : tried) {
                // The edge just bounced off: the ray starts on it and would hit it again at 0.
                if (last && i == *last) continue;
                const auto out = ray_cast(edge_of(walls[i]), p1, p2);
                decide(scratch, traced, i, out.has_value());
                if (!out) continue;
                if (!found || out->fraction < hit.fraction || (out->fraction == hit.fraction && i < best)) {
                    found = true;
                    best = i;
                    hit = *out;
                }
            }
            if (!found) {
                p = p2;
                break;
            }
            if (traced != nullptr) {
                traced->hit = best;
                traced->hit_t = hit.fraction;
            }
            if (bounce == k_max_bounces) {
                status = FrameStatus::bounce_limit;
                break;
            }
            if (scratch.trace != nullptr) ++scratch.trace->reflections;
            now = now + rest * hit.fraction;
            // Move to the hit point, reflect v about the edge normal, spend the rest of the frame.
            p = p1 + hit.fraction * (p2 - p1);
            hits.push_back({best, now, to_vec(p)});
            v = v - 2.0f * b2Dot(v, hit.normal) * hit.normal;
            rest = rest * (1.0f - hit.fraction);
            last = best;
        }
        ball = {to_vec(p), to_vec(v)};
        return status;
    }
};
static_assert(Kernel<Box2dKernel>);

}  // namespace

KernelOps box2d_kernel_ops() { return make_kernel_ops<Box2dKernel>("box2d"); }

}  // namespace ricochet::peers
