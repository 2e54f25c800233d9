// The scene-log reader's diagnostics no other test pins (docs/scene-log.md, "Diagnostics"):
// FILE:LINE:COL: error: WHAT, COL at the offending token, for numbers that are no numbers, integers out
// of range, the per-log limits, format versions, and the expect/found lines' frames and balls.
#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "ricochet/scene_log.hpp"
#include "ricochet/scene_log_format.hpp"

namespace ricochet {
namespace {

std::string diag(std::string_view text) {
    auto r = parse_scene_log(text, "t.scene");
    if (auto* d = std::get_if<Diagnostic>(&r)) return d->str();
    return "parsed";
}

// Four lines before the line under test, which is line 5.
const std::string k_head = "ricochet 1\nframes 3\nball 0 0 1 0\ncheck speed\n";
std::string at(std::string_view line) { return diag(k_head + std::string(line) + "\n"); }

TEST(SceneLogNumbers, ALoneSignOrAWordIsNotANumber) {
    EXPECT_EQ(at("wall - 0 1 1"), "t.scene:5:6: error: bad X0: '-' is not a number");
    EXPECT_EQ(at("wall 0 abc 1 1"), "t.scene:5:8: error: bad Y0: 'abc' is not a number");
    EXPECT_EQ(at("wall 0 0 -0x 1"), "t.scene:5:10: error: bad X1: '-0x' is not a number");
}

TEST(SceneLogNumbers, ABinaryExponentWithTwoSignsIsNotANumber) {
    // libstdc++ 12's hexadecimal from_chars reads "1p+-3" whole (as 2^-3); the grammar has one sign.
    EXPECT_EQ(at("wall 0x1p+-3 0 1 1"), "t.scene:5:6: error: bad X0: '0x1p+-3' is not a number");
    EXPECT_EQ(at("wall 0 -0X1.8P-+3 1 1"), "t.scene:5:8: error: bad Y0: '-0X1.8P-+3' is not a number");
    EXPECT_EQ(at("wall 0 0 0x1p-3 1"), "parsed");
}

TEST(SceneLogNumbers, AnUpperCaseHexPrefixIsRead) {
    // 0X1p3 = 8, −0X1.8p-1 = −0.75: hexadecimal with either case of prefix (docs/scene-log.md's 0x1.8p-3).
    auto r = parse_scene_log(k_head + "wall 0X1p3 -0X1.8p-1 0 0\n", "t.scene");
    ASSERT_TRUE(std::holds_alternative<Scene>(r)) << std::get<Diagnostic>(r).str();
    const Scene& s = std::get<Scene>(r);
    ASSERT_EQ(s.walls.size(), 1u);
    EXPECT_EQ(s.walls[0].p0, (Vec2{8, -0.75}));
}

TEST(SceneLogIntegers, AnIntegerPastSixtyFourBitsIsOutOfRange) {
    EXPECT_EQ(diag("ricochet 1\nframes 99999999999999999999\n"),
              "t.scene:2:8: error: frame count '99999999999999999999' is out of range");
    EXPECT_EQ(at("expect state 99999999999999999999 0 0 0 0 0"),
              "t.scene:5:14: error: frame '99999999999999999999' is out of range");
}

TEST(SceneLogHeader, AVersionThatIsNoNumberOrNotAboveOneIsUnknown) {
    EXPECT_EQ(diag("ricochet 2x\n"), "t.scene:1:10: error: unknown format version '2x' (this reader reads version 1)");
    EXPECT_EQ(diag("ricochet 0\n"), "t.scene:1:10: error: unknown format version '0' (this reader reads version 1)");
    EXPECT_EQ(diag("ricochet 2\n"),
              "t.scene:1:10: error: format version 2 is newer than this reader (it reads version 1)");
}

TEST(SceneLogLimits, OneWallPastTheLimitIsRefusedAtItsDirective) {
    // k_max_entities walls read; the next one is refused at its 'wall' token (line 1 + k_max_entities + 1).
    std::string text = "ricochet 1\n";
    text.reserve(text.size() + 10 * (k_max_entities + 1));
    for (std::size_t i = 0; i <= k_max_entities; ++i) text += "wall 0 0 1 1\n";
    EXPECT_EQ(diag(text), "t.scene:" + std::to_string(k_max_entities + 2) + ":1: error: too many walls: the limit is " +
                              std::to_string(k_max_entities));
}

TEST(SceneLogLimits, OneFromLinePastTheLimitIsRefused) {
    std::string text = "ricochet 1\n";
    for (std::size_t i = 0; i < k_max_provenance; ++i) text += "from property p seed " + std::to_string(i) + "\n";
    auto r = parse_scene_log(text, "t.scene");
    ASSERT_TRUE(std::holds_alternative<Scene>(r));
    EXPECT_EQ(std::get<Scene>(r).provenance.size(), k_max_provenance);
    text += "  from one more\n";
    EXPECT_EQ(diag(text), "t.scene:" + std::to_string(k_max_provenance + 2) +
                              ":3: error: too many 'from' lines: the limit is " + std::to_string(k_max_provenance));
}

TEST(SceneLogExpect, StateLinesNeedANonNegativeFrameAndABallIndexInRange) {
    EXPECT_EQ(at("expect state -1 0 0 0 1 0"), "t.scene:5:14: error: negative frame -1");
    EXPECT_EQ(at("expect state 0 -1 0 0 1 0"), "t.scene:5:16: error: ball index -1 is out of range");
    EXPECT_EQ(at("expect state 0 " + std::to_string(k_max_entities) + " 0 0 1 0"),
              "t.scene:5:16: error: ball index " + std::to_string(k_max_entities) + " is out of range");
    // One below the limit reads; the whole-log check then says the log has no such ball.
    EXPECT_EQ(at("expect state 0 " + std::to_string(k_max_entities - 1) + " 0 0 1 0"),
              "t.scene:5:16: error: expect state for ball " + std::to_string(k_max_entities - 1) +
                  " but the log has 1 balls");
}

TEST(SceneLogExpect, AFailureLineOnceWithAFrameTheLogRuns) {
    EXPECT_EQ(at("expect failure speed 1\nexpect failure speed 2"), "t.scene:6:8: error: duplicate 'expect failure'");
    EXPECT_EQ(at("expect failure speed -1"), "t.scene:5:22: error: negative frame -1");
    EXPECT_EQ(at("expect failure speed 4"), "t.scene:5:22: error: expect failure at frame 4 but the log runs 3 frames");
    EXPECT_EQ(at("expect failure speed 3"), "parsed");  // the last frame is one the log runs
}

TEST(SceneLogFound, ABallIndexAtTheEntityLimitIsOutOfRange) {
    EXPECT_EQ(at("found speed 1 " + std::to_string(k_max_entities)),
              "t.scene:5:15: error: ball index " + std::to_string(k_max_entities) + " is out of range");
}

}  // namespace
}  // namespace ricochet
