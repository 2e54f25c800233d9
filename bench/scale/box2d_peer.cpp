// The Box2D 2.4.1 peer (box2d_peer.hpp).
#include "box2d_peer.hpp"

#include <box2d/b2_circle_shape.h>
#include <box2d/b2_collision.h>
#include <box2d/b2_distance.h>
#include <box2d/b2_dynamic_tree.h>
#include <box2d/b2_edge_shape.h>
#include <box2d/b2_time_of_impact.h>

#include <cstdint>

namespace ricochet::scale {

bool box2d_available() { return true; }

struct Box2dPeer::Impl {
    b2DynamicTree tree;
    std::vector<b2EdgeShape> edges;
};

Box2dPeer::Box2dPeer(std::span<const Wall> walls) : impl_(std::make_unique<Impl>()) {
    impl_->edges.resize(walls.size());
    for (std::size_t i = 0; i < walls.size(); ++i) {
        b2EdgeShape& e = impl_->edges[i];
        e.SetTwoSided({static_cast<float>(walls[i].p0.x), static_cast<float>(walls[i].p0.y)},
                      {static_cast<float>(walls[i].p1.x), static_cast<float>(walls[i].p1.y)});
        b2AABB box;
        e.ComputeAABB(&box, b2Transform(b2Vec2_zero, b2Rot(0.0f)), 0);
        impl_->tree.CreateProxy(box, reinterpret_cast<void*>(static_cast<std::uintptr_t>(i)));
    }
}

Box2dPeer::~Box2dPeer() = default;

namespace {

/// The nearest edge along the ray, clipping the ray as Box2D's own b2World::RayCast callers do.
struct Nearest {
    const b2DynamicTree* tree;
    const std::vector<b2EdgeShape>* edges;
    b2Transform xf{b2Vec2_zero, b2Rot(0.0f)};
    bool found = false;
    float fraction = 1.0f;
    b2Vec2 normal{0.0f, 0.0f};
    std::uintptr_t skip = ~std::uintptr_t{0};  // the edge just bounced off
    std::uintptr_t hit = 0;

    float RayCastCallback(const b2RayCastInput& input, int32 proxy) {
        const auto i = reinterpret_cast<std::uintptr_t>(tree->GetUserData(proxy));
        // The edge just bounced off is skipped: the ray starts on it, and would hit it again at 0.
        if (i == skip) return input.maxFraction;
        b2RayCastOutput out;
        if (!(*edges)[i].RayCast(&out, input, xf, 0)) return input.maxFraction;
        found = true;
        fraction = out.fraction;
        normal = out.normal;
        hit = i;
        return out.fraction;
    }
};

}  // namespace

void Box2dPeer::step(FloatBall& ball, std::vector<Vec2>* hits) const {
    b2Vec2 p(ball.x, ball.y), v(ball.vx, ball.vy);
    float rest = 1.0f;
    std::uintptr_t last = ~std::uintptr_t{0};
    for (int bounce = 0; bounce < 16; ++bounce) {
        b2RayCastInput input;
        input.p1 = p;
        input.p2 = p + rest * v;
        input.maxFraction = 1.0f;
        if (input.p1 == input.p2) break;
        Nearest cb{&impl_->tree, &impl_->edges};
        cb.skip = last;
        impl_->tree.RayCast(&cb, input);
        if (!cb.found) {
            p = input.p2;
            break;
        }
        // Move to the hit point, reflect v about the edge normal, spend the rest of the frame.
        p = input.p1 + cb.fraction * (input.p2 - input.p1);
        v = v - 2.0f * b2Dot(v, cb.normal) * cb.normal;
        rest *= 1.0f - cb.fraction;
        last = cb.hit;
        if (hits != nullptr) hits->push_back({p.x, p.y});
    }
    ball = {p.x, p.y, v.x, v.y};
}

namespace {

/// The tree's proxies whose boxes meet a query box, as their edges' indices.
struct Candidates {
    const b2DynamicTree* tree;
    std::vector<std::uintptr_t>* out;
    bool QueryCallback(int32 proxy) {
        out->push_back(reinterpret_cast<std::uintptr_t>(tree->GetUserData(proxy)));
        return true;
    }
};

/// A sweep that does not turn: the centre from c0 to c, no rotation.
b2Sweep straight(b2Vec2 c0, b2Vec2 c) {
    b2Sweep s;
    s.localCenter.SetZero();
    s.c0 = c0;
    s.c = c;
    s.a0 = s.a = 0.0f;
    s.alpha0 = 0.0f;
    return s;
}

}  // namespace

void Box2dPeer::step_disc(FloatBall& ball, float r, std::vector<Vec2>* hits) const {
    b2CircleShape circle;
    circle.m_radius = r;
    b2DistanceProxy disc;  // the circle as both queries see it, made once
    disc.Set(&circle, 0);
    const b2Sweep edge_at_rest = straight(b2Vec2_zero, b2Vec2_zero);
    const b2Transform identity(b2Vec2_zero, b2Rot(0.0f));
    b2Vec2 p(ball.x, ball.y), v(ball.vx, ball.vy);
    float rest = 1.0f;
    std::vector<std::uintptr_t> candidates;
    for (int bounce = 0; bounce < 16; ++bounce) {
        const b2Vec2 end = p + rest * v;
        if (p == end) break;
        // The candidates: the edges whose boxes meet the leg's box grown by r (the edges' own boxes carry their
        // polygon radius).
        b2AABB box;
        box.lowerBound = b2Min(p, end) - b2Vec2(r, r);
        box.upperBound = b2Max(p, end) + b2Vec2(r, r);
        candidates.clear();
        Candidates query{&impl_->tree, &candidates};
        impl_->tree.Query(&query, box);
        float first = 1.0f;
        b2Vec2 normal(0.0f, 0.0f);
        bool found = false;
        for (std::uintptr_t i : candidates) {
            b2DistanceProxy edge;
            edge.Set(&impl_->edges[i], 0);
            b2TOIInput in;
            in.proxyA = disc;
            in.proxyB = edge;
            in.sweepA = straight(p, end);
            in.sweepB = edge_at_rest;
            in.tMax = first;
            b2TOIOutput out;
            b2TimeOfImpact(&out, &in);
            // Touching within [0, first]; separated (none), overlapped (already inside: Box2D leaves it to the
            // contact solver, which this loop does not have) and failed are no contact.
            if (out.state != b2TOIOutput::e_touching || out.t >= first) continue;
            // The normal there: from the edge's nearest point to the centre.
            b2DistanceInput d;
            d.proxyA = disc;
            d.proxyB = edge;
            d.transformA = b2Transform(p + out.t * (end - p), b2Rot(0.0f));
            d.transformB = identity;
            d.useRadii = false;
            b2SimplexCache cache;
            cache.count = 0;
            b2DistanceOutput dist;
            b2Distance(&dist, &cache, &d);
            b2Vec2 n = dist.pointA - dist.pointB;
            if (n.Normalize() < b2_epsilon) continue;
            // A leg starting at the edge it just left touches it at t = 0 while moving away: no contact.
            if (b2Dot(v, n) >= 0.0f) continue;
            first = out.t;
            normal = n;
            found = true;
        }
        if (!found) {
            p = end;
            break;
        }
        p = p + first * (end - p);
        v = v - 2.0f * b2Dot(v, normal) * normal;
        rest *= 1.0f - first;
        if (hits != nullptr) hits->push_back({p.x, p.y});
    }
    ball = {p.x, p.y, v.x, v.y};
}

}  // namespace ricochet::scale
