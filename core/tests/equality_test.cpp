// Every field of the value types takes part in their ==. The round-trip check (read(write(s)) == s), the
// replay of `expect` lines and the equal-events test of `deterministic` all compare with these operators: a
// field that == left out would let a writer drop it, or a run change it, unseen. Each test changes one field
// at a time from a value equal to the original and expects the two to differ, then restores it.
#include <gtest/gtest.h>

#include <functional>
#include <vector>

#include "ricochet/event.hpp"
#include "ricochet/expect.hpp"
#include "ricochet/scene.hpp"
#include "ricochet/shapes.hpp"

namespace ricochet {
namespace {

/// For each change: a copy of base with that one change differs from base, and base equals itself.
template <class T>
void each_field_counts(const T& base, const std::vector<std::function<void(T&)>>& changes) {
    EXPECT_TRUE(base == base);
    for (std::size_t k = 0; k < changes.size(); ++k) {
        T changed = base;
        changes[k](changed);
        EXPECT_FALSE(changed == base) << "change " << k << " is not seen by ==";
        EXPECT_FALSE(base == changed) << "change " << k << " is not seen by == (swapped)";
    }
}

TEST(Equality, Vec2ComparesBothComponentsInEveryPrecision) {
    each_field_counts<Vec2>({1, 2}, {[](Vec2& v) { v.x = 3; }, [](Vec2& v) { v.y = 3; }});
    each_field_counts<Vec2T<float>>({1, 2}, {[](Vec2T<float>& v) { v.x = 3; }, [](Vec2T<float>& v) { v.y = 3; }});
    // Values, not bits: −0 equals +0 (same_bits is the bitwise comparison).
    EXPECT_TRUE((Vec2{0.0, 1} == Vec2{-0.0, 1}));
}

TEST(Equality, ShapesCompareEveryField) {
    each_field_counts<Circle>({{1, 2}, 3}, {[](Circle& c) { c.c.x = 9; }, [](Circle& c) { c.c.y = 9; },
                                            [](Circle& c) { c.r = 9; }});
    each_field_counts<Rect>({1, 2, 3, 4}, {[](Rect& r) { r.left = 9; }, [](Rect& r) { r.bottom = 9; },
                                           [](Rect& r) { r.right = 9; }, [](Rect& r) { r.top = 9; }});
    each_field_counts<Wall>({{1, 2}, {3, 4}}, {[](Wall& w) { w.p0.x = 9; }, [](Wall& w) { w.p0.y = 9; },
                                               [](Wall& w) { w.p1.x = 9; }, [](Wall& w) { w.p1.y = 9; }});
    each_field_counts<Ball>({{1, 2}, {3, 4}}, {[](Ball& b) { b.pos.x = 9; }, [](Ball& b) { b.pos.y = 9; },
                                               [](Ball& b) { b.vel.x = 9; }, [](Ball& b) { b.vel.y = 9; }});
}

TEST(Equality, ExpectationsCompareEveryField) {
    each_field_counts<ExpectState>({5, 1, {{1, 2}, {3, 4}}},
                                   {[](ExpectState& e) { e.frame = 6; }, [](ExpectState& e) { e.ball = 2; },
                                    [](ExpectState& e) { e.state.pos.x = 9; }, [](ExpectState& e) { e.state.vel.y = 9; }});
    each_field_counts<ExpectFailure>({Check::speed, 5},
                                     {[](ExpectFailure& e) { e.check = Check::boundary; },
                                      [](ExpectFailure& e) { e.frame = 6; }});
    each_field_counts<Found>({Check::speed, 5, 1}, {[](Found& f) { f.check = Check::boundary; },
                                                    [](Found& f) { f.frame = 6; }, [](Found& f) { f.ball = 2; }});
}

TEST(Equality, EventsCompareEveryField) {
    const Event base{Event::Kind::hit, 3, 1, Event::Shape::none, 2, {1, 2}, {3, 4}};
    each_field_counts<Event>(base, {[](Event& e) { e.kind = Event::Kind::state; }, [](Event& e) { e.frame = 4; },
                                    [](Event& e) { e.ball = 2; }, [](Event& e) { e.shape = Event::Shape::rect; },
                                    [](Event& e) { e.index = 3; }, [](Event& e) { e.pos.x = 9; },
                                    [](Event& e) { e.pos.y = 9; }, [](Event& e) { e.vel.x = 9; },
                                    [](Event& e) { e.vel.y = 9; }});
}

TEST(Equality, ScenesCompareEveryField) {
    Scene base;
    base.kernel = KernelId::robust;
    base.frames = 3;
    base.walls = {{{0, 0}, {1, 0}}};
    base.balls = {{{0, 1}, {0, -1}}};
    base.circles = {{{5, 5}, 1}};
    base.rects = {{1, 2, 3, 4}};
    base.checks = {Check::no_tunnel};
    base.expect_hash = 0x1234;
    base.expect_states = {{1, 0, {{0, 0}, {0, 0}}}};
    base.expect_failure = ExpectFailure{Check::speed, 2};
    base.found = Found{Check::speed, 2, 0};
    base.provenance = {"property Example seed 1"};
    each_field_counts<Scene>(base, {
                                       [](Scene& s) { s.kernel = KernelId::exact; },
                                       [](Scene& s) { s.frames = 4; },
                                       [](Scene& s) { s.walls[0].p1.x = 2; },
                                       [](Scene& s) { s.balls[0].vel.y = -2; },
                                       [](Scene& s) { s.circles[0].r = 2; },
                                       [](Scene& s) { s.rects[0].top = 5; },
                                       [](Scene& s) { s.checks.push_back(Check::speed); },
                                       [](Scene& s) { s.expect_hash = 0x1235; },
                                       [](Scene& s) { s.expect_states[0].frame = 2; },
                                       [](Scene& s) { s.expect_failure->frame = 3; },
                                       [](Scene& s) { s.found->ball = 1; },
                                       [](Scene& s) { s.provenance[0] = "fuzz sweep"; },
                                   });
}

}  // namespace
}  // namespace ricochet
