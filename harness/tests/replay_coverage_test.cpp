// replay_scene's messages no other test pins (docs/scene-log.md, "What replay asserts" and "Saved
// failure logs"): a log with nothing to print, a run that leaves the range, an expected failure of
// another check, a hash with no expect state to place its divergence, a `found` naming another check;
// and FailureLog's own verdict (reproduces) and text for every way found, replayed and note can differ.
#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "ricochet/failure_log.hpp"
#include "ricochet/replay.hpp"
#include "ricochet/scene_log.hpp"
#include "scene_text.hpp"

namespace ricochet {
namespace {

using test::parse_ok;
using test::k_corners;

bool has(const std::string& message, std::string_view part) { return message.find(part) != std::string::npos; }

TEST(ReplayMessages, ALogWithNothingInItPrintsNoEventAndHashesTheEmptyInput) {
    // No ball and no shape: every frame is empty, and the run hash is XXH64 (seed 0) of no bytes,
    // ef46db3751d8e999. The expect state lines cannot name a ball, so there are none to compare.
    const ReplayResult r = replay_scene(parse_ok("ricochet 1\nframes 3\nwall 0 0 1 0\nexpect hash ef46db3751d8e999\n"));
    EXPECT_TRUE(r.passed) << r.message;
    EXPECT_TRUE(has(r.message, "hash ef46db3751d8e999")) << r.message;
}

TEST(ReplayMessages, ARunThatLeavesTheRangeFailsWithItsErrorAndNoHashComplaint) {
    // From x = 2^255 moving 2^255 a frame: 2^256 after frame 1 (the range's edge, still in it), 1.5·2^256
    // at frame 2, out of it. The run stops there; its hash is not the log's, but the error says why, so
    // no hash problem is added.
    const Scene s = parse_ok("ricochet 1\nframes 3\nball 0x1p255 0 0x1p255 0\nexpect hash 0000000000000001\n");
    const ReplayResult r = replay_scene(s);
    EXPECT_FALSE(r.passed);
    ASSERT_TRUE(r.run.error) << r.message;
    EXPECT_EQ(r.message, r.run.error->message());
    EXPECT_TRUE(has(r.message, "frame 2")) << r.message;
    EXPECT_FALSE(has(r.message, "hash expected")) << r.message;
}

TEST(ReplayMessages, AWrongHashWithoutExpectStatesSaysNoStateCanNameTheFrame) {
    const ReplayResult r = replay_scene(parse_ok("ricochet 1\nframes 2\nball 0 0 1 0\nexpect hash 0000000000000001\n"));
    EXPECT_FALSE(r.passed);
    EXPECT_TRUE(has(r.message, "hash expected 0000000000000001, got ")) << r.message;
    EXPECT_TRUE(has(r.message, " (no expect state to name the frame)")) << r.message;
}

TEST(ReplayMessages, AnExpectedFailureOfAnotherCheckAtTheSameFrameFails) {
    Scene s = parse_ok(k_corners);
    const ReplayResult plain = replay_scene(s);
    ASSERT_TRUE(plain.run.failure);
    ASSERT_EQ(plain.run.failure->check, Check::oracle);
    ASSERT_EQ(plain.run.failure->frame, 3);
    s.expect_failure = ExpectFailure{Check::speed, 3};
    const ReplayResult r = replay_scene(s);
    EXPECT_FALSE(r.passed);
    EXPECT_EQ(r.message, "expected speed to break first at frame 3, got " + plain.run.failure->str());
}

TEST(ReplayMessages, AFoundNamingAnotherCheckIsSaidAsADrift) {
    Scene s = parse_ok(k_corners);
    const CheckFailure f = *replay_scene(s).run.failure;
    s.found = Found{Check::speed, 3, f.ball};
    s.expect_failure = ExpectFailure{Check::oracle, 3};
    const ReplayResult r = replay_scene(s);
    EXPECT_TRUE(r.passed) << r.message;  // the verdict follows expect failure; found is a record only
    const std::string ball = std::to_string(f.ball);
    EXPECT_TRUE(has(r.message, "; found speed at frame 3 ball " + ball + " when saved, now oracle at frame 3 ball " + ball))
        << r.message;
}

TEST(FailureLogVerdict, ReproducesOnlyWhenCheckFrameAndBallAllAgree) {
    FailureLog log;
    EXPECT_FALSE(log.reproduces());  // nothing replayed, nothing found
    log.replayed = CheckFailure{Check::speed, 4, 1, "m", std::nullopt, std::nullopt};
    EXPECT_FALSE(log.reproduces());  // replayed, but no found
    log.scene.found = Found{Check::speed, 4, 1};
    EXPECT_TRUE(log.reproduces());
    log.scene.found = Found{Check::oracle, 4, 1};
    EXPECT_FALSE(log.reproduces());  // another check
    log.scene.found = Found{Check::speed, 5, 1};
    EXPECT_FALSE(log.reproduces());  // another frame
    log.scene.found = Found{Check::speed, 4, 0};
    EXPECT_FALSE(log.reproduces());  // another ball
}

TEST(FailureLogText, TheNoteIsOneCommentLineAfterFoundAndOnlyWithBoth) {
    FailureLog log;
    log.scene = parse_ok("ricochet 1\nframes 2\nball 0 0 1 0\ncheck speed\n");
    log.note = "a note";
    // No found: the canonical text alone.
    EXPECT_EQ(log.text(), write_scene_log(log.scene));
    // Found but no note: the canonical text alone too.
    log.scene.found = Found{Check::speed, 2, 0};
    log.note.clear();
    EXPECT_EQ(log.text(), write_scene_log(log.scene));
    // Both: CR and LF in the note become spaces, so the comment cannot end early.
    log.note = "one\r\ntwo\rthree";
    EXPECT_EQ(log.text(),
              "ricochet 1\nkernel robust\nframes 2\nball 0 0 1 0\ncheck speed\nfound speed 2 0\n# one  two three\n");
    EXPECT_EQ(parse_ok(log.text()), log.scene);  // the comment reads back as nothing
}

}  // namespace
}  // namespace ricochet
