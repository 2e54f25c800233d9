// Equality of core values field by field: operator== (by value, −0 == +0) and same_bits (by bit pattern)
// each tell a change in any one field, and only same_bits tells −0 from +0.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "ricochet/bits.hpp"
#include "ricochet/scene.hpp"
#include "ricochet/scene_log_format.hpp"

namespace ricochet {
namespace {

Scene full_scene() {
    Scene s;
    s.kernel = KernelId::exact;
    s.frames = 4;
    s.walls = {{{0, 1}, {2, 3}}};
    s.balls = {{{4, 5}, {6, 7}}};
    s.circles = {{{8, 9}, 10}};
    s.rects = {{11, 12, 13, 14}};
    s.checks = {Check::speed};
    s.expect_hash = 15;
    s.expect_states = {{1, 0, {{16, 17}, {18, 19}}}};
    s.expect_failure = ExpectFailure{Check::speed, 2};
    s.provenance = {"hand"};
    return s;
}

struct Change {
    std::string what;
    std::function<void(Scene&)> apply;
};

TEST(SceneEquality, AChangeInAnyOneFieldMakesScenesDiffer) {
    const std::vector<Change> changes = {
        {"kernel", [](Scene& s) { s.kernel = KernelId::robust; }},
        {"frames", [](Scene& s) { s.frames = 5; }},
        {"wall", [](Scene& s) { s.walls[0].p1.y = 3.5; }},
        {"ball", [](Scene& s) { s.balls[0].vel.x = 6.5; }},
        {"circle", [](Scene& s) { s.circles[0].r = 10.5; }},
        {"rect", [](Scene& s) { s.rects[0].top = 14.5; }},
        {"checks", [](Scene& s) { s.checks.push_back(Check::oracle); }},
        {"expect hash", [](Scene& s) { s.expect_hash.reset(); }},
        {"expect state frame", [](Scene& s) { s.expect_states[0].frame = 2; }},
        {"expect state ball", [](Scene& s) { s.expect_states[0].ball = 1; }},
        {"expect state", [](Scene& s) { s.expect_states[0].state.pos.x = 16.5; }},
        {"expect failure check", [](Scene& s) { s.expect_failure->check = Check::oracle; }},
        {"expect failure frame", [](Scene& s) { s.expect_failure->frame = 3; }},
        {"provenance", [](Scene& s) { s.provenance[0] = "other"; }},
    };
    const Scene a = full_scene();
    EXPECT_TRUE(a == full_scene());
    EXPECT_TRUE(same_bits(a, full_scene()));
    for (const Change& c : changes) {
        Scene b = full_scene();
        c.apply(b);
        EXPECT_FALSE(a == b) << c.what;
        EXPECT_FALSE(same_bits(a, b)) << c.what;
    }
}

TEST(SceneEquality, MinusZeroIsEqualButNotTheSameBitsInEveryPlace) {
    // Each entity with a +0 put where a −0 was: operator== says equal, same_bits says not.
    Scene zero;
    zero.walls = {{{0, 0}, {0, 0}}};
    zero.balls = {{{0, 0}, {0, 0}}};
    zero.circles = {{{0, 0}, 0}};
    zero.rects = {{0, 0, 0, 0}};
    zero.expect_states = {{0, 0, {{0, 0}, {0, 0}}}};
    const std::vector<Change> flips = {
        {"wall p0.x", [](Scene& s) { s.walls[0].p0.x = -0.0; }},
        {"wall p0.y", [](Scene& s) { s.walls[0].p0.y = -0.0; }},
        {"wall p1.x", [](Scene& s) { s.walls[0].p1.x = -0.0; }},
        {"wall p1.y", [](Scene& s) { s.walls[0].p1.y = -0.0; }},
        {"ball pos", [](Scene& s) { s.balls[0].pos.y = -0.0; }},
        {"ball vel", [](Scene& s) { s.balls[0].vel.x = -0.0; }},
        {"circle centre", [](Scene& s) { s.circles[0].c.x = -0.0; }},
        {"circle radius", [](Scene& s) { s.circles[0].r = -0.0; }},
        {"rect left", [](Scene& s) { s.rects[0].left = -0.0; }},
        {"rect bottom", [](Scene& s) { s.rects[0].bottom = -0.0; }},
        {"rect right", [](Scene& s) { s.rects[0].right = -0.0; }},
        {"rect top", [](Scene& s) { s.rects[0].top = -0.0; }},
        {"expect state", [](Scene& s) { s.expect_states[0].state.vel.y = -0.0; }},
    };
    EXPECT_TRUE(same_bits(zero, zero));
    for (const Change& c : flips) {
        Scene b = zero;
        c.apply(b);
        EXPECT_TRUE(zero == b) << c.what;
        EXPECT_FALSE(same_bits(zero, b)) << c.what;
        EXPECT_FALSE(same_bits(b, zero)) << c.what;
    }
}

TEST(EventEquality, EveryFieldCountsAndOnlyBitsTellTheZeros) {
    const Event a{Event::Kind::hit, 3, 1, Event::Shape::none, 2, {0.5, 0}, {0, 0}};
    const std::vector<std::function<void(Event&)>> changes = {
        [](Event& e) { e.kind = Event::Kind::state; },     [](Event& e) { e.frame = 4; },
        [](Event& e) { e.ball = 2; },                      [](Event& e) { e.shape = Event::Shape::rect; },
        [](Event& e) { e.index = 3; },                     [](Event& e) { e.pos.x = 0.25; },
        [](Event& e) { e.pos.y = 1; },                     [](Event& e) { e.vel.x = 1; },
        [](Event& e) { e.vel.y = 1; },
    };
    for (std::size_t i = 0; i < changes.size(); ++i) {
        Event b = a;
        changes[i](b);
        EXPECT_FALSE(a == b) << i;
        EXPECT_FALSE(same_bits(a, b)) << i;
    }
    EXPECT_TRUE(same_bits(a, a));
    Event z = a;
    z.vel.y = -0.0;
    EXPECT_TRUE(a == z);
    EXPECT_FALSE(same_bits(a, z));
}

TEST(ShapeEquality, EachShapeComparesEveryField) {
    EXPECT_FALSE((Circle{{1, 2}, 3} == Circle{{1, 2}, 4}));
    EXPECT_FALSE((Circle{{1, 2}, 3} == Circle{{1, 5}, 3}));
    EXPECT_TRUE((Circle{{1, 2}, 3} == Circle{{1, 2}, 3}));
    EXPECT_FALSE((Rect{1, 2, 3, 4} == Rect{0, 2, 3, 4}));
    EXPECT_FALSE((Rect{1, 2, 3, 4} == Rect{1, 0, 3, 4}));
    EXPECT_FALSE((Rect{1, 2, 3, 4} == Rect{1, 2, 0, 4}));
    EXPECT_FALSE((Rect{1, 2, 3, 4} == Rect{1, 2, 3, 0}));
    EXPECT_FALSE((Wall{{1, 2}, {3, 4}} == Wall{{1, 2}, {3, 0}}));
    EXPECT_FALSE((Ball{{1, 2}, {3, 4}} == Ball{{1, 2}, {0, 4}}));
    EXPECT_FALSE((ExpectState{1, 2, {}} == ExpectState{1, 3, {}}));
    EXPECT_FALSE((ExpectFailure{Check::speed, 1} == ExpectFailure{Check::speed, 2}));
}

}  // namespace
}  // namespace ricochet
