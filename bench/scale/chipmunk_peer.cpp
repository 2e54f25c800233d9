// The Chipmunk 7 peer (chipmunk_peer.hpp).
#include "chipmunk_peer.hpp"

#include <chipmunk/chipmunk.h>

namespace ricochet::scale {

bool chipmunk_available() { return true; }

struct ChipmunkPeer::Impl {
    cpSpace* space = cpSpaceNew();
    std::vector<cpShape*> shapes;
    ~Impl() {
        for (cpShape* s : shapes) {
            cpSpaceRemoveShape(space, s);
            cpShapeFree(s);
        }
        cpSpaceFree(space);
    }
};

ChipmunkPeer::ChipmunkPeer(std::span<const Wall> walls) : impl_(std::make_unique<Impl>()) {
    cpBody* ground = cpSpaceGetStaticBody(impl_->space);
    impl_->shapes.reserve(walls.size());
    for (const Wall& w : walls) {
        cpShape* s = cpSegmentShapeNew(ground, cpv(w.p0.x, w.p0.y), cpv(w.p1.x, w.p1.y), 0.0);
        cpSpaceAddShape(impl_->space, s);
        impl_->shapes.push_back(s);
    }
}

ChipmunkPeer::~ChipmunkPeer() = default;

namespace {

/// The earliest hit of one query, as the callback sees them.
struct First {
    const cpShape* skip;  // the shape just bounced off
    cpVect v;
    bool found = false;
    cpFloat alpha = 1.0;
    cpVect normal = cpvzero;
    const cpShape* shape = nullptr;
};

void on_hit(cpShape* shape, cpVect /*point*/, cpVect normal, cpFloat alpha, void* data) {
    First& f = *static_cast<First*>(data);
    // The leg starts on the shape it just left, and a shape the ball moves away from is not met.
    if (shape == f.skip || cpvdot(f.v, normal) >= 0.0) return;
    if (!f.found || alpha < f.alpha) {
        f.found = true;
        f.alpha = alpha;
        f.normal = normal;
        f.shape = shape;
    }
}

}  // namespace

void ChipmunkPeer::step(Ball& ball, std::vector<Vec2>* hits) const {
    cpVect p = cpv(ball.pos.x, ball.pos.y), v = cpv(ball.vel.x, ball.vel.y);
    cpFloat rest = 1.0;
    const cpShape* last = nullptr;
    for (int bounce = 0; bounce < 16; ++bounce) {
        const cpVect end = cpvadd(p, cpvmult(v, rest));
        if (cpveql(p, end)) break;
        First f{last, v};
        cpSpaceSegmentQuery(impl_->space, p, end, ball.r, CP_SHAPE_FILTER_ALL, on_hit, &f);
        if (!f.found) {
            p = end;
            break;
        }
        // The centre at the contact, v' = v − 2(v·n)n, the rest of the frame.
        p = cpvlerp(p, end, f.alpha);
        v = cpvsub(v, cpvmult(f.normal, 2.0 * cpvdot(v, f.normal)));
        rest *= 1.0 - f.alpha;
        last = f.shape;
        if (hits != nullptr) hits->push_back({p.x, p.y});
    }
    ball.pos = {p.x, p.y};
    ball.vel = {v.x, v.y};
}

}  // namespace ricochet::scale
