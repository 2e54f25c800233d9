// Chipmunk 7 as a kernel (`--kernel chipmunk`): every test through Chipmunk's own API, in double (cpFloat).
// A wall is a radius-0 cpSegmentShape on a static body; the sweep is cpShapeSegmentQuery of the leg; the
// frame is the loop a Chipmunk user writes around it: query the rest of the frame's leg against every wall,
// take the first hit (smallest alpha), move to its point, reflect v about the normal the query returned,
// spend the rest of the frame. The statics are cpShapePointQuery, cpShapesCollide, cpBBContainsVect and
// cpBBIntersects, as bench's peer calls them. Chipmunk is a peer under test, not code of this project: its
// failures are documented, not fixed.
#include <chipmunk/chipmunk_structs.h>

#include <cstdint>
#include <optional>

#include "peer_kernels.hpp"
#include "peer_trace.hpp"

namespace ricochet::peers {
namespace {

cpVect to_cp(Vec2 p) { return cpv(p.x, p.y); }
Vec2 to_vec(cpVect p) { return {p.x, p.y}; }

/// The static body every wall and bumper hangs on (identity transform). Shapes only read it, so threads may
/// share it; made once and kept for the program's life.
cpBody* static_body() {
    static cpBody* const body = cpBodyNewStatic();
    return body;
}

/// A wall as a Chipmunk user makes one: a radius-0 segment shape on the static body, its bounding box and
/// transformed end points cached. Held in place (chipmunk_structs.h gives the size), not allocated.
class Segment {
public:
    explicit Segment(const Wall& w) {
        cpSegmentShapeInit(&seg_, static_body(), to_cp(w.p0), to_cp(w.p1), 0.0);
        cpShapeCacheBB(shape());
    }
    ~Segment() { cpShapeDestroy(shape()); }
    Segment(const Segment&) = delete;
    Segment& operator=(const Segment&) = delete;
    cpShape* shape() { return &seg_.shape; }

private:
    cpSegmentShape seg_;
};

/// A bumper: a circle shape on the static body, held in place like Segment.
class Bumper {
public:
    explicit Bumper(const Circle& c) {
        cpCircleShapeInit(&circle_, static_body(), c.r, to_cp(c.c));
        cpShapeCacheBB(shape());
    }
    ~Bumper() { cpShapeDestroy(shape()); }
    Bumper(const Bumper&) = delete;
    Bumper& operator=(const Bumper&) = delete;
    cpShape* shape() { return &circle_.shape; }

private:
    cpCircleShape circle_;
};

/// The segment a → b against a wall: Chipmunk's answer (alpha, point, normal), or nothing for no hit.
std::optional<cpSegmentQueryInfo> segment_query(const Wall& w, cpVect a, cpVect b) {
    Segment s(w);
    cpSegmentQueryInfo info;
    if (!cpShapeSegmentQuery(s.shape(), a, b, 0.0, &info)) return std::nullopt;
    return info;
}

/// v' = v − 2(v·n)n with Chipmunk's vector functions.
cpVect bounce(cpVect v, cpVect n) { return cpvsub(v, cpvmult(n, 2.0 * cpvdot(v, n))); }

/// Chipmunk 7 behind the kernel interface: a Kernel (kernel.hpp).
struct ChipmunkKernel {
    /// Double's ε = 2^-53: cpvnormalize's length, reciprocal of |e| + CPFLOAT_MIN and products (≈ 5ε a
    /// component), the reflection (≈ 5ε) and |n|² − 1 doubled (≈ 20ε): about 30ε; 64ε = 2^-47 leaves room,
    /// so only Chipmunk's real losses fail `speed`.
    static constexpr double k_speed_rel_bound = 0x1p-47;
    /// Robust's subnormal part (limits.hpp): each operation errs by up to 2^-1075 absolutely there.
    static constexpr double k_speed_abs_bound = 0x1p-1068;
    /// A peer under test: its failure logs document what it breaks (`expect failure`).
    static constexpr bool k_failures_documented = true;

    static Side classify(Vec2 p, const Wall& w) {
        // BC = n·(p − a), n the segment's unit normal as Chipmunk keeps it
        Segment s(w);
        return side_of(cpvdot(cpSegmentShapeGetNormal(s.shape()), cpvsub(to_cp(p), cpSegmentShapeGetA(s.shape()))));
    }

    static bool point_in_circle(Vec2 p, const Circle& c) {
        Bumper b(c);
        cpPointQueryInfo info;
        // The signed distance from the circle's surface: ≤ 0 on or inside.
        return cpShapePointQuery(b.shape(), to_cp(p), &info) <= 0.0;
    }

    static bool circles_overlap(const Circle& a, const Circle& b) {
        Bumper ba(a), bb(b);
        return cpShapesCollide(ba.shape(), bb.shape()).count > 0;
    }

    static bool point_in_rect(Vec2 p, const Rect& r) {
        return cpBBContainsVect(cpBBNew(r.left, r.bottom, r.right, r.top), to_cp(p));
    }

    static bool rects_overlap(const Rect& a, const Rect& b) {
        return cpBBIntersects(cpBBNew(a.left, a.bottom, a.right, a.top), cpBBNew(b.left, b.bottom, b.right, b.top));
    }

    static Sweep sweep(Vec2 bs, Vec2 v, const Wall& w) {
        // The leg Bs → Be = Bs + v; a ball that does not move makes no query.
        const cpVect a = to_cp(bs), b = cpvadd(a, to_cp(v));
        const auto info = cpveql(a, b) ? std::nullopt : segment_query(w, a, b);
        if (!info) return {Miss::no_reason, 0.0, {}};
        return {Miss::none, info->alpha, to_vec(info->point)};
    }

    static Vec2 reflect(Vec2 v, const Wall& w) {
        Segment s(w);
        return to_vec(bounce(to_cp(v), cpSegmentShapeGetNormal(s.shape())));
    }

    /// One frame: the rest of the frame's leg queried against every wall but the one just bounced off, the hit
    /// with the smallest alpha, bounce, again. Chipmunk remembers nothing between frames: memory is not read or
    /// written.
    static FrameStatus step_ball(Ball& ball, BallMemory& /*memory*/, std::span<const Wall> walls,
                                 std::vector<HitEvent>& hits, StepScratch& scratch, const WallIndex* index) {
        cpVect p = to_cp(ball.pos), v = to_cp(ball.vel);
        cpFloat rest = 1.0, now = 0.0;
        std::optional<std::uint32_t> last;
        FrameStatus status = FrameStatus::ok;
        for (int bounce_count = 0;; ++bounce_count) {
            // The rest of the frame: the segment a → b.
            const cpVect a = p, b = cpvadd(p, cpvmult(v, rest));
            TracedLeg* traced = begin_leg(scratch, to_vec(a), to_vec(b), to_vec(v), last);
            bool found = false;
            std::uint32_t best = 0;
            cpSegmentQueryInfo hit{};
            // A ball that does not move makes no query (cpShapeSegmentQuery would report a shape it lies on).
            const auto tried =
                cpveql(a, b) ? std::span<const std::uint32_t>{} : candidates(walls, index, to_vec(a), to_vec(b), scratch);
            for (std::uint32_t i : tried) {
                // The wall just bounced off: the query starts on it and would hit it again at alpha 0.
                if (last && i == *last) continue;
                const auto info = segment_query(walls[i], a, b);
                decide(scratch, traced, i, info.has_value());
                if (!info) continue;
                if (!found || info->alpha < hit.alpha || (info->alpha == hit.alpha && i < best)) {
                    found = true;
                    best = i;
                    hit = *info;
                }
            }
            if (!found) {
                p = b;
                break;
            }
            if (traced != nullptr) {
                traced->hit = best;
                traced->hit_t = hit.alpha;
            }
            if (bounce_count == k_max_bounces) {
                status = FrameStatus::bounce_limit;
                break;
            }
            if (scratch.trace != nullptr) ++scratch.trace->reflections;
            now = now + rest * hit.alpha;
            // Move to the hit point, reflect v about the returned normal, spend the rest of the frame.
            p = hit.point;
            hits.push_back({best, now, to_vec(p)});
            v = bounce(v, hit.normal);
            rest = rest * (1.0 - hit.alpha);
            last = best;
        }
        ball = {to_vec(p), to_vec(v)};
        return status;
    }
};
static_assert(Kernel<ChipmunkKernel>);

}  // namespace

KernelOps chipmunk_kernel_ops() { return make_kernel_ops<ChipmunkKernel>("chipmunk"); }

}  // namespace ricochet::peers
