// Box2D 2.4.1 through its own API, as a game developer calls it: b2EdgeShape::RayCast for a sweep
// (two-sided edge, the leg as the ray p1 → p2 with maxFraction 1), b2CircleShape / b2PolygonShape
// TestPoint, b2CollideCircles and b2TestOverlap for the static tests. Box2D works in float.
// A disc: b2TimeOfImpact, what Box2D's own continuous collision (b2World::SolveTOI) runs for a bullet against a
// static shape: a b2CircleShape proxy of radius R swept Bs → Be without rotation against each b2EdgeShape
// (two-sided, with Box2D's b2_polygonRadius skin) or b2CircleShape (a bumper); a contact is state e_touching, as
// SolveTOI reads it; the earliest t over the obstacles; the centre where the sweep puts it at t.
#include <limits>

#include <box2d/b2_time_of_impact.h>
#include <box2d/box2d.h>

#include "methods.hpp"

namespace ricochet::bench {
namespace {

b2Vec2 to_b2(Vec2 p) { return {static_cast<float>(p.x), static_cast<float>(p.y)}; }

class Box2dMethod final : public Method {
public:
    std::string name() const override { return "box2d"; }

    SweepAnswer sweep_one(const SweepQuery& q) const override {
        b2EdgeShape edge;
        edge.SetTwoSided(to_b2(q.wall.p0), to_b2(q.wall.p1));
        b2RayCastInput in;
        in.p1 = to_b2(q.bs);
        in.p2 = to_b2(q.bs + q.v);
        in.maxFraction = 1.0f;
        b2Transform xf;
        xf.SetIdentity();
        b2RayCastOutput out;
        if (!edge.RayCast(&out, in, xf, 0)) return {};
        // The ray hits at p1 + fraction·(p2 − p1) (b2_collision.h).
        const b2Vec2 p = in.p1 + out.fraction * (in.p2 - in.p1);
        return {true, true, static_cast<double>(out.fraction), {static_cast<double>(p.x), static_cast<double>(p.y)}};
    }
    void sweep_all(std::span<const SweepQuery> qs, std::span<SweepAnswer> out) const override {
        for (std::size_t i = 0; i < qs.size(); ++i) out[i] = sweep_one(qs[i]);
    }
    bool has_disc() const override { return true; }
    void disc_all(std::span<const DiscQuery> qs, std::span<DiscAnswer> out) const override {
        for (std::size_t i = 0; i < qs.size(); ++i) out[i] = disc_one(qs[i]);
    }
    void static_all(std::span<const StaticQuery> qs, std::span<unsigned char> out) const override {
        b2Transform xf;
        xf.SetIdentity();
        for (std::size_t i = 0; i < qs.size(); ++i) {
            const StaticQuery& q = qs[i];
            bool r = false;
            switch (q.kind) {
                case StaticKind::point_circle: {
                    b2CircleShape c;
                    c.m_p = to_b2(q.a.c);
                    c.m_radius = static_cast<float>(q.a.r);
                    r = c.TestPoint(xf, to_b2(q.p));
                    break;
                }
                case StaticKind::circle_circle: {
                    b2CircleShape a, b;
                    a.m_p = to_b2(q.a.c);
                    a.m_radius = static_cast<float>(q.a.r);
                    b.m_p = to_b2(q.b.c);
                    b.m_radius = static_cast<float>(q.b.r);
                    b2Manifold m;
                    b2CollideCircles(&m, &a, xf, &b, xf);
                    r = m.pointCount > 0;
                    break;
                }
                case StaticKind::point_rect: {
                    // A box as Box2D users make one: half extents about a centre.
                    b2PolygonShape box;
                    const double hx = 0.5 * (q.ra.right - q.ra.left), hy = 0.5 * (q.ra.top - q.ra.bottom);
                    box.SetAsBox(static_cast<float>(hx), static_cast<float>(hy),
                                 to_b2({q.ra.left + hx, q.ra.bottom + hy}), 0.0f);
                    r = box.TestPoint(xf, to_b2(q.p));
                    break;
                }
                case StaticKind::rect_rect: {
                    b2AABB a, b;
                    a.lowerBound = to_b2({q.ra.left, q.ra.bottom});
                    a.upperBound = to_b2({q.ra.right, q.ra.top});
                    b.lowerBound = to_b2({q.rb.left, q.rb.bottom});
                    b.upperBound = to_b2({q.rb.right, q.rb.top});
                    r = b2TestOverlap(a, b);
                    break;
                }
            }
            out[i] = r;
        }
    }

private:
    static DiscAnswer disc_one(const DiscQuery& q) {
        b2CircleShape disc;
        disc.m_p.SetZero();
        disc.m_radius = static_cast<float>(q.R);
        b2TOIInput in;
        in.proxyB.Set(&disc, 0);
        // The obstacles do not move; the disc's body moves from Bs to Be.
        in.sweepA.localCenter.SetZero();
        in.sweepA.c0.SetZero();
        in.sweepA.c.SetZero();
        in.sweepA.a0 = in.sweepA.a = 0.0f;
        in.sweepA.alpha0 = 0.0f;
        in.sweepB = in.sweepA;
        in.sweepB.c0 = to_b2(q.bs);
        in.sweepB.c = to_b2(q.bs + q.v);
        in.tMax = 1.0f;
        DiscAnswer best;
        float best_t = std::numeric_limits<float>::infinity();
        const auto offer = [&](bool bumper, std::uint32_t i) {
            b2TOIOutput o;
            b2TimeOfImpact(&o, &in);
            if (o.state != b2TOIOutput::e_touching || !(o.t < best_t)) return;
            best_t = o.t;
            best = {true, bumper, i, {}};
        };
        for (std::uint32_t i = 0; i < q.nwalls; ++i) {
            b2EdgeShape edge;
            edge.SetTwoSided(to_b2(q.walls[i].p0), to_b2(q.walls[i].p1));
            in.proxyA.Set(&edge, 0);
            offer(false, i);
        }
        if (q.has_bumper) {
            b2CircleShape c;
            c.m_p = to_b2(q.bumper.c);
            c.m_radius = static_cast<float>(q.bumper.r);
            in.proxyA.Set(&c, 0);
            offer(true, 0);
        }
        if (best.hit) {
            b2Transform xf;
            in.sweepB.GetTransform(&xf, best_t);
            best.point = {static_cast<double>(xf.p.x), static_cast<double>(xf.p.y)};
        }
        return best;
    }
};

}  // namespace

std::unique_ptr<Method> make_box2d() { return std::make_unique<Box2dMethod>(); }

}  // namespace ricochet::bench
