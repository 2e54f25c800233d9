// Box2D 2.4.1 as an Engine (engine.hpp), set up as its manual asks for fast round bodies: dynamic circle bodies with
// bullet = true (continuous collision among them, not only against the walls), restitution 1 with the restitution
// threshold 0 (every approach bounces, however slow), friction 0, no damping, no sleep, no rotation; the walls four
// two-sided edges on one static body. One b2World::Step of 1 per frame, 8 velocity and 3 position iterations (the
// manual's suggestion).
//
// Units: Box2D moves a body at most b2_maxTranslation (2 m) per step and wants lengths of 0.1 to 10 m, so the scene
// is scaled by the largest power of two s ≤ 1 with s·v_max ≤ 1.5 m per step (a power of two: the scene's
// coordinates, multiples of 2^-14 below 2^9, stay exact in float). A ball sped up past 2 m per step is clamped by
// Box2D; the notes count those frames.
#include <box2d/box2d.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <fmt/format.h>

#include "engine.hpp"

namespace ricochet::meet_bench {
namespace {

/// Balls' user data is their index + 1; the walls' is 0.
constexpr std::uintptr_t k_wall = 0;

/// The frame's contacts, as Box2D reports them: a contact that begins touching, and every touching contact before
/// each solve (PreSolve, also in the bullets' sub-steps).
class Contacts final : public b2ContactListener {
public:
    explicit Contacts(std::size_t n) : touched(n, 0) {}
    void BeginContact(b2Contact* c) override { note(c); }
    void PreSolve(b2Contact* c, const b2Manifold* /*old*/) override { note(c); }
    void clear() {
        std::fill(touched.begin(), touched.end(), 0);
        met.clear();
    }
    std::vector<std::uint8_t> touched;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> met;

private:
    void note(b2Contact* c) {
        if (!c->IsTouching()) return;
        const std::uintptr_t a = c->GetFixtureA()->GetBody()->GetUserData().pointer;
        const std::uintptr_t b = c->GetFixtureB()->GetBody()->GetUserData().pointer;
        if (a != k_wall) touched[a - 1] = 1;
        if (b != k_wall) touched[b - 1] = 1;
        if (a != k_wall && b != k_wall) met.emplace_back(static_cast<std::uint32_t>(a - 1), static_cast<std::uint32_t>(b - 1));
    }
};

class Box2dEngine final : public Engine {
public:
    Box2dEngine(const MeetScene& s, bool record) : world_(b2Vec2(0.0f, 0.0f)) {
        scale_ = 1.0;
        while (scale_ * s.v_max > 1.5) scale_ *= 0.5;
        side_ = static_cast<float>(s.side * scale_);
        world_.SetAllowSleeping(false);
        world_.SetContinuousPhysics(true);
        b2BodyDef ground_def;
        b2Body* ground = world_.CreateBody(&ground_def);
        const float a = static_cast<float>(side_);
        const b2Vec2 corners[4] = {{0.0f, 0.0f}, {a, 0.0f}, {a, a}, {0.0f, a}};
        for (int i = 0; i < 4; ++i) {
            b2EdgeShape e;
            e.SetTwoSided(corners[i], corners[(i + 1) % 4]);
            const b2FixtureDef f = fixture(&e);
            ground->CreateFixture(&f);
        }
        b2CircleShape circle;
        circle.m_radius = static_cast<float>(s.r * scale_);
        r_ = circle.m_radius;
        for (std::size_t i = 0; i < s.balls.size(); ++i) {
            const Ball& ball = s.balls[i];
            b2BodyDef d;
            d.type = b2_dynamicBody;
            d.bullet = true;
            d.fixedRotation = true;
            d.linearDamping = 0.0f;
            d.angularDamping = 0.0f;
            d.position.Set(static_cast<float>(ball.pos.x * scale_), static_cast<float>(ball.pos.y * scale_));
            d.linearVelocity.Set(static_cast<float>(ball.vel.x * scale_), static_cast<float>(ball.vel.y * scale_));
            d.userData.pointer = i + 1;
            b2Body* body = world_.CreateBody(&d);
            b2FixtureDef f = fixture(&circle);
            // Mass 1: density·πr² = 1.
            f.density = static_cast<float>(1.0 / (std::numbers::pi * r_ * r_));
            body->CreateFixture(&f);
            bodies_.push_back(body);
        }
        if (record) {
            contacts_ = std::make_unique<Contacts>(bodies_.size());
            world_.SetContactListener(contacts_.get());
        }
        read();
    }

    void step() override {
        if (contacts_) {
            contacts_->clear();
            speeds_.resize(bodies_.size());
            for (std::size_t i = 0; i < bodies_.size(); ++i) speeds_[i] = bodies_[i]->GetLinearVelocity().LengthSquared();
        }
        world_.Step(1.0f, 8, 3);
        if (contacts_) {
            contact_sum_ += world_.GetContactCount();
            ++steps_;
            // Box2D scales a velocity whose step would move more than b2_maxTranslation down to it, and keeps it: a
            // ball whose speed changed and now lies at the limit was clamped.
            for (std::size_t i = 0; i < bodies_.size(); ++i) {
                const float v2 = bodies_[i]->GetLinearVelocity().LengthSquared();
                if (v2 != speeds_[i] && std::fabs(v2 / b2_maxTranslationSquared - 1.0f) < 1e-5f) ++clamped_;
            }
        }
    }
    std::span<const Ball> balls() override {
        read();
        return balls_;
    }
    double side() const override { return side_; }
    FrameRecord frame() override {
        read();
        if (!contacts_) return {balls_, {}, {}, {}};
        return {balls_, {}, contacts_->met, contacts_->touched};
    }
    std::string notes() const override {
        std::string s = fmt::format("lengths x {} (m)", scale_);
        // Box2D keeps a contact for every pair of overlapping fat boxes (grown by four times a step's displacement):
        // what its bullets' time of impact is searched over.
        if (contacts_ && steps_ > 0)
            s += fmt::format(", {:.0f} contacts a step, {} ball-frames clamped to b2_maxTranslation",
                             static_cast<double>(contact_sum_) / static_cast<double>(steps_), clamped_);
        return s;
    }

private:
    static b2FixtureDef fixture(const b2Shape* shape) {
        b2FixtureDef f;
        f.shape = shape;
        f.friction = 0.0f;
        f.restitution = 1.0f;
        f.restitutionThreshold = 0.0f;
        return f;
    }
    void read() {
        balls_.resize(bodies_.size());
        for (std::size_t i = 0; i < bodies_.size(); ++i) {
            const b2Vec2 p = bodies_[i]->GetPosition(), v = bodies_[i]->GetLinearVelocity();
            balls_[i] = {{p.x, p.y}, {v.x, v.y}, r_};
        }
    }

    double scale_ = 1.0;
    double side_ = 0.0;
    double r_ = 0.0;
    std::unique_ptr<Contacts> contacts_;  // before world_: the listener outlives the world that calls it
    b2World world_;
    std::vector<b2Body*> bodies_;
    std::vector<Ball> balls_;
    std::vector<float> speeds_;
    std::int64_t clamped_ = 0;
    std::int64_t contact_sum_ = 0, steps_ = 0;
};

}  // namespace

std::unique_ptr<Engine> make_box2d(const MeetScene& s, bool record) { return std::make_unique<Box2dEngine>(s, record); }

}  // namespace ricochet::meet_bench
