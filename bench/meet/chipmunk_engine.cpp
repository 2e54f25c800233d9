// Chipmunk 7 as an Engine (engine.hpp), set up as its manual describes: circle shapes of elasticity 1 and friction 0 on
// bodies of mass 1 that do not turn (infinite moment), segment shapes of radius 0 on the space's static body for the
// walls, no gravity, no damping, sleep off (the default). One cpSpaceStep(space, 1) per frame, in the scene's own
// units (Chipmunk has no limit on a step's translation), 10 iterations (the default). The collision slop, the overlap
// Chipmunk leaves alone, is set to R/50: its default (0.1) is a fifth of these discs' radius.
#include <chipmunk/chipmunk.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include <fmt/format.h>

#include "engine.hpp"

namespace ricochet::meet_bench {
namespace {

/// The frame's contacts as Chipmunk reports them: a pair that begins colliding, and every colliding pair before each
/// solve (preSolve).
struct Contacts {
    std::vector<std::uint8_t> touched;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> met;
};

/// Balls' user data is their index + 1; the walls' is 0 (null).
cpBool note(cpArbiter* arb, cpSpace* /*space*/, cpDataPointer data) {
    Contacts& c = *static_cast<Contacts*>(data);
    CP_ARBITER_GET_SHAPES(arb, a, b);
    const auto ia = reinterpret_cast<std::uintptr_t>(cpShapeGetUserData(a));
    const auto ib = reinterpret_cast<std::uintptr_t>(cpShapeGetUserData(b));
    if (ia != 0) c.touched[ia - 1] = 1;
    if (ib != 0) c.touched[ib - 1] = 1;
    if (ia != 0 && ib != 0) c.met.emplace_back(static_cast<std::uint32_t>(ia - 1), static_cast<std::uint32_t>(ib - 1));
    return cpTrue;
}

class ChipmunkEngine final : public Engine {
public:
    ChipmunkEngine(const MeetScene& s, bool record) : side_(s.side), r_(s.r) {
        cpSpaceSetCollisionSlop(space_, s.r / 50.0);
        cpBody* ground = cpSpaceGetStaticBody(space_);
        const double a = s.side;
        const cpVect corners[4] = {cpv(0, 0), cpv(a, 0), cpv(a, a), cpv(0, a)};
        for (int i = 0; i < 4; ++i) {
            cpShape* w = cpSpaceAddShape(space_, cpSegmentShapeNew(ground, corners[i], corners[(i + 1) % 4], 0.0));
            cpShapeSetElasticity(w, 1.0);
            cpShapeSetFriction(w, 0.0);
            shapes_.push_back(w);
        }
        for (std::size_t i = 0; i < s.balls.size(); ++i) {
            const Ball& ball = s.balls[i];
            cpBody* body = cpSpaceAddBody(space_, cpBodyNew(1.0, INFINITY));
            cpBodySetPosition(body, cpv(ball.pos.x, ball.pos.y));
            cpBodySetVelocity(body, cpv(ball.vel.x, ball.vel.y));
            cpShape* c = cpSpaceAddShape(space_, cpCircleShapeNew(body, s.r, cpvzero));
            cpShapeSetElasticity(c, 1.0);
            cpShapeSetFriction(c, 0.0);
            cpShapeSetUserData(c, reinterpret_cast<cpDataPointer>(static_cast<std::uintptr_t>(i + 1)));
            bodies_.push_back(body);
            shapes_.push_back(c);
        }
        if (record) {
            contacts_.touched.assign(bodies_.size(), 0);
            cpCollisionHandler* h = cpSpaceAddDefaultCollisionHandler(space_);
            h->beginFunc = note;
            h->preSolveFunc = note;
            h->userData = &contacts_;
        }
        read();
    }
    ~ChipmunkEngine() override {
        for (cpShape* s : shapes_) {
            cpSpaceRemoveShape(space_, s);
            cpShapeFree(s);
        }
        for (cpBody* b : bodies_) {
            cpSpaceRemoveBody(space_, b);
            cpBodyFree(b);
        }
        cpSpaceFree(space_);
    }
    ChipmunkEngine(const ChipmunkEngine&) = delete;
    ChipmunkEngine& operator=(const ChipmunkEngine&) = delete;

    void step() override {
        std::fill(contacts_.touched.begin(), contacts_.touched.end(), 0);
        contacts_.met.clear();
        cpSpaceStep(space_, 1.0);
    }
    std::span<const Ball> balls() override {
        read();
        return balls_;
    }
    double side() const override { return side_; }
    FrameRecord frame() override {
        read();
        if (contacts_.touched.empty()) return {balls_, {}, {}, {}};
        return {balls_, {}, contacts_.met, contacts_.touched};
    }
    std::string notes() const override { return fmt::format("collision slop {}", r_ / 50.0); }

private:
    void read() {
        balls_.resize(bodies_.size());
        for (std::size_t i = 0; i < bodies_.size(); ++i) {
            const cpVect p = cpBodyGetPosition(bodies_[i]), v = cpBodyGetVelocity(bodies_[i]);
            balls_[i] = {{p.x, p.y}, {v.x, v.y}, r_};
        }
    }

    double side_, r_;
    cpSpace* space_ = cpSpaceNew();
    std::vector<cpBody*> bodies_;
    std::vector<cpShape*> shapes_;
    std::vector<Ball> balls_;
    Contacts contacts_;
};

}  // namespace

std::unique_ptr<Engine> make_chipmunk(const MeetScene& s, bool record) {
    return std::make_unique<ChipmunkEngine>(s, record);
}

}  // namespace ricochet::meet_bench
