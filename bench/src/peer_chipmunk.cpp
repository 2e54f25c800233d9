// Chipmunk 7 through its own API: cpShapeSegmentQuery of the leg against a radius-0 segment shape on a
// static body, cpShapePointQuery for a point against a circle, cpShapesCollide for two circles,
// cpBBContainsVect / cpBBIntersects for rectangles. Chipmunk works in double (cpFloat).
// A disc: cpShapeSegmentQuery(shape, Bs, Be, R) against each radius-0 cpSegmentShape and the bumper's
// cpCircleShape (a query with a radius sweeps a circle of that radius); the smallest alpha; the centre at
// cpvlerp(Bs, Be, alpha).
#include <array>
#include <limits>

#include <chipmunk/chipmunk.h>

#include "methods.hpp"

namespace ricochet::bench {
namespace {

cpVect to_cp(Vec2 p) { return cpv(p.x, p.y); }

class ChipmunkMethod final : public Method {
public:
    ChipmunkMethod() : body_(cpBodyNewStatic()) {}
    ~ChipmunkMethod() override {
        release();
        release_discs();
        cpBodyFree(body_);
    }
    ChipmunkMethod(const ChipmunkMethod&) = delete;
    ChipmunkMethod& operator=(const ChipmunkMethod&) = delete;

    std::string name() const override { return "chipmunk"; }

    SweepAnswer sweep_one(const SweepQuery& q) const override {
        cpShape* seg = cpSegmentShapeNew(body_, to_cp(q.wall.p0), to_cp(q.wall.p1), 0.0);
        cpShapeCacheBB(seg);
        const SweepAnswer a = query(seg, q);
        cpShapeFree(seg);
        return a;
    }
    void prepare(std::span<const SweepQuery> qs) const override {
        // Shapes live in a game's space before it queries them: made here, outside the timed loop.
        release();
        prepared_for_ = qs.data();
        prepared_.resize(qs.size());
        for (std::size_t i = 0; i < qs.size(); ++i) {
            prepared_[i] = cpSegmentShapeNew(body_, to_cp(qs[i].wall.p0), to_cp(qs[i].wall.p1), 0.0);
            cpShapeCacheBB(prepared_[i]);
        }
    }
    void release() const override {
        for (cpShape* s : prepared_) cpShapeFree(s);
        prepared_.clear();
        prepared_for_ = nullptr;
    }
    void sweep_all(std::span<const SweepQuery> qs, std::span<SweepAnswer> out) const override {
        // Shapes made by prepare for exactly these queries, or made (and freed) here.
        const bool mine = prepared_for_ != qs.data() || prepared_.size() != qs.size();
        if (mine) prepare(qs);
        for (std::size_t i = 0; i < qs.size(); ++i) out[i] = query(prepared_[i], qs[i]);
        if (mine) release();
    }
    bool has_disc() const override { return true; }
    void prepare_discs(std::span<const DiscQuery> qs) const override {
        // A game's space holds the shapes before it queries them: made here, outside the timed loop.
        release_discs();
        discs_for_ = qs.data();
        discs_.resize(qs.size());
        for (std::size_t i = 0; i < qs.size(); ++i) {
            const DiscQuery& q = qs[i];
            discs_[i] = {};
            for (std::size_t w = 0; w < q.nwalls; ++w)
                discs_[i][w] = cpSegmentShapeNew(body_, to_cp(q.walls[w].p0), to_cp(q.walls[w].p1), 0.0);
            if (q.has_bumper) discs_[i][2] = cpCircleShapeNew(body_, q.bumper.r, to_cp(q.bumper.c));
            for (cpShape* s : discs_[i])
                if (s != nullptr) cpShapeCacheBB(s);
        }
    }
    void release_discs() const override {
        for (auto& shapes : discs_)
            for (cpShape* s : shapes)
                if (s != nullptr) cpShapeFree(s);
        discs_.clear();
        discs_for_ = nullptr;
    }
    void disc_all(std::span<const DiscQuery> qs, std::span<DiscAnswer> out) const override {
        const bool mine = discs_for_ != qs.data() || discs_.size() != qs.size();
        if (mine) prepare_discs(qs);
        for (std::size_t i = 0; i < qs.size(); ++i) {
            const DiscQuery& q = qs[i];
            const cpVect a = to_cp(q.bs), b = to_cp(q.bs + q.v);
            DiscAnswer best;
            cpFloat best_alpha = std::numeric_limits<cpFloat>::infinity();
            for (std::uint32_t k = 0; k < 3; ++k) {
                const cpShape* s = discs_[i][k];
                cpSegmentQueryInfo info;
                if (s == nullptr || !cpShapeSegmentQuery(s, a, b, q.R, &info) || !(info.alpha < best_alpha)) continue;
                best_alpha = info.alpha;
                const cpVect c = cpvlerp(a, b, info.alpha);
                best = {true, k == 2, k == 2 ? 0u : k, {c.x, c.y}};
            }
            out[i] = best;
        }
        if (mine) release_discs();
    }
    bool has_static(StaticKind) const override { return true; }
    void static_all(std::span<const StaticQuery> qs, std::span<unsigned char> out) const override {
        for (std::size_t i = 0; i < qs.size(); ++i) {
            const StaticQuery& q = qs[i];
            bool r = false;
            switch (q.kind) {
                case StaticKind::point_circle: {
                    cpShape* c = cpCircleShapeNew(body_, q.a.r, to_cp(q.a.c));
                    cpShapeCacheBB(c);
                    cpPointQueryInfo info;
                    // The signed distance from the circle's surface: ≤ 0 on or inside.
                    r = cpShapePointQuery(c, to_cp(q.p), &info) <= 0.0;
                    cpShapeFree(c);
                    break;
                }
                case StaticKind::circle_circle: {
                    cpShape* a = cpCircleShapeNew(body_, q.a.r, to_cp(q.a.c));
                    cpShape* b = cpCircleShapeNew(body_, q.b.r, to_cp(q.b.c));
                    cpShapeCacheBB(a);
                    cpShapeCacheBB(b);
                    r = cpShapesCollide(a, b).count > 0;
                    cpShapeFree(a);
                    cpShapeFree(b);
                    break;
                }
                case StaticKind::point_rect:
                    r = cpBBContainsVect(cpBBNew(q.ra.left, q.ra.bottom, q.ra.right, q.ra.top), to_cp(q.p));
                    break;
                case StaticKind::rect_rect:
                    r = cpBBIntersects(cpBBNew(q.ra.left, q.ra.bottom, q.ra.right, q.ra.top),
                                       cpBBNew(q.rb.left, q.rb.bottom, q.rb.right, q.rb.top));
                    break;
            }
            out[i] = r;
        }
    }

private:
    static SweepAnswer query(const cpShape* seg, const SweepQuery& q) {
        cpSegmentQueryInfo info;
        if (!cpShapeSegmentQuery(seg, to_cp(q.bs), to_cp(q.bs + q.v), 0.0, &info)) return {};
        return {true, true, info.alpha, {info.point.x, info.point.y}};
    }
    cpBody* body_;
    mutable std::vector<cpShape*> prepared_;
    mutable const SweepQuery* prepared_for_ = nullptr;
    mutable std::vector<std::array<cpShape*, 3>> discs_;  // per disc query: its walls, then its bumper (or null)
    mutable const DiscQuery* discs_for_ = nullptr;
};

}  // namespace

std::unique_ptr<Method> make_chipmunk() { return std::make_unique<ChipmunkMethod>(); }

}  // namespace ricochet::bench
