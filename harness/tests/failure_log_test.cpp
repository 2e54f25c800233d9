// Saved failure logs: make_failure_log's log (cut frames, one check, found, expect lines), the `found`
// directive read, written and refused as every directive is, replay's word on a run that differs from
// found, and save_scene_log_once telling a new case from a known one by content.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <variant>

#include <fmt/format.h>

#include "mutant_kernel.hpp"
#include "ricochet/failure_log.hpp"
#include "ricochet/format.hpp"
#include "ricochet/replay.hpp"
#include "ricochet/scene_log.hpp"
#include "scene_text.hpp"

namespace ricochet {
namespace {

using test::parse_ok;
using test::diag;
using test::k_corners;

CheckFailure first_failure(const Scene& s) {
    const CheckedRun run = run_checked(s, s.kernel, s.frames, s.checks);
    EXPECT_TRUE(run.failure.has_value());
    return run.failure.value_or(CheckFailure{});
}

TEST(FailureLog, ALectureFailureIsCutToItsFrameAndExpected) {
    const Scene scene = parse_ok(k_corners);
    const CheckFailure f = first_failure(scene);
    ASSERT_EQ(f.check, Check::oracle);
    ASSERT_EQ(f.frame, 3);
    const FailureLog log = make_failure_log(scene, KernelId::lecture_double, "property Corners seed 7", f);
    const Scene& s = log.scene;
    EXPECT_EQ(s.kernel, KernelId::lecture_double);
    EXPECT_EQ(s.frames, 3);
    EXPECT_EQ(s.checks, std::vector<Check>{Check::oracle});
    EXPECT_EQ(s.provenance, std::vector<std::string>{"property Corners seed 7"});
    ASSERT_TRUE(s.found);
    EXPECT_EQ(*s.found, (Found{Check::oracle, 3, f.ball}));
    ASSERT_TRUE(s.expect_failure);
    EXPECT_EQ(*s.expect_failure, (ExpectFailure{Check::oracle, 3}));
    EXPECT_FALSE(s.expect_hash);
    // Frames 0, 1 and 2 for each of the 4 balls (3 × 4 ≤ 64): the run before the failure, pinned.
    ASSERT_EQ(s.expect_states.size(), 12u);
    for (const ExpectState& e : s.expect_states) EXPECT_LT(e.frame, 3);
    EXPECT_EQ(s.expect_states.front().state, scene.balls[0]);
    EXPECT_TRUE(log.reproduces());
    EXPECT_EQ(log.note, f.message);

    // Replay passes it (the expected failure reproduces); without `expect failure` it fails, at the
    // same check and frame, and says nothing about found (it is what found says).
    const ReplayResult ok = replay_scene(s);
    EXPECT_TRUE(ok.passed) << ok.message;
    Scene bare = s;
    bare.expect_failure.reset();
    const ReplayResult bad = replay_scene(bare);
    EXPECT_FALSE(bad.passed);
    EXPECT_NE(bad.message.find("oracle broke at frame 3"), std::string::npos) << bad.message;
    EXPECT_EQ(bad.message.find("when saved"), std::string::npos) << bad.message;
}

TEST(FailureLog, TextHasTheNoteAsACommentAfterFoundAndReadsBack) {
    const Scene scene = parse_ok(k_corners);
    CheckFailure f = first_failure(scene);
    f.message = "two\nlines";
    FailureLog log = make_failure_log(scene, KernelId::lecture_double, "fuzz scene 0123", f);
    const std::string text = log.text();
    const std::string found = fmt::format("found oracle 3 {}\n# two lines\n", f.ball);
    EXPECT_NE(text.find(found), std::string::npos) << text;
    const Scene back = parse_ok(text);
    EXPECT_TRUE(same_bits(back, log.scene)) << text;
    // The canonical text has no comment; the note is the only difference.
    EXPECT_EQ(write_scene_log(back), write_scene_log(log.scene));
}

TEST(FailureLog, ARobustFailureIsNotExpectedAndAFailureTheLogDoesNotShowIsSaid) {
    // Robust holds on this scene: a failure given for it does not reproduce, and robust's log never
    // expects its failure (a robust failure is a bug: replay fails it until it is fixed).
    Scene scene = parse_ok(k_corners);
    const CheckFailure made_up{Check::oracle, 2, 1, "made up", std::nullopt};
    const FailureLog log = make_failure_log(scene, KernelId::robust, "property P seed 1", made_up);
    EXPECT_EQ(log.scene.kernel, KernelId::robust);
    EXPECT_FALSE(log.scene.expect_failure);
    EXPECT_FALSE(log.replayed);
    EXPECT_FALSE(log.reproduces());
    // Replay passes it (every check holds) and says the found failure is gone.
    const ReplayResult r = replay_scene(log.scene);
    EXPECT_TRUE(r.passed) << r.message;
    EXPECT_NE(r.message.find("found oracle at frame 2 ball 1 when saved, but every check holds now"), std::string::npos)
        << r.message;
}

TEST(FailureLog, ExpectStatesAreCappedAsRecordCapsThem) {
    // 10 balls, failure (made up) at frame 40: 40 × 10 > 64, so 8 spread frames of 0..39, balls 0–7.
    Scene scene = parse_ok(k_corners);
    scene.kernel = KernelId::robust;
    scene.frames = 50;
    while (scene.balls.size() < 10) {
        const Ball copy = scene.balls[scene.balls.size() % 4];
        scene.balls.push_back(copy);
    }
    const FailureLog log =
        make_failure_log(scene, KernelId::robust, "p", CheckFailure{Check::speed, 40, 9, "x", std::nullopt, std::nullopt});
    std::set<std::int64_t> frames;
    std::set<std::uint32_t> balls;
    for (const ExpectState& e : log.scene.expect_states) frames.insert(e.frame), balls.insert(e.ball);
    EXPECT_EQ(frames, (std::set<std::int64_t>{4, 9, 14, 19, 24, 29, 34, 39}));
    EXPECT_EQ(balls.size(), 8u);
    EXPECT_EQ(*balls.rbegin(), 7u);
    EXPECT_EQ(log.scene.expect_states.size(), 64u);
    EXPECT_EQ(log.scene.frames, 40);
    // A failure at frame 0 (a static test) pins no state.
    const FailureLog at0 =
        make_failure_log(scene, KernelId::robust, "p", CheckFailure{Check::boundary, 0, 0, "x", std::nullopt, std::nullopt});
    EXPECT_TRUE(at0.scene.expect_states.empty());
    EXPECT_EQ(at0.scene.frames, 0);
}

/// A bug that acts frames before a check sees it: robust's step, then the ball sinks by 2^−20 in y every frame.
FrameStatus sinking(Ball& ball, BallMemory& memory, std::span<const Wall> walls, std::vector<HitEvent>& hits,
                    StepScratch& scratch, const WallIndex* index) {
    const FrameStatus st = mutant::robust().step_ball(ball, memory, walls, hits, scratch, index);
    ball.pos.y -= 0x1p-20;
    return st;
}

TEST(FailureLog, ABugThatActsBeforeItIsSeenFailsItsLogAndTheFixedKernelPassesIt) {
    // A ball moving along +x at y = 5.5·2^−20 over the wall y = 0, x in [5, 8]. The sinking kernel moves it down
    // every frame, unseen (no check but no-tunnel is asked), until frame 6's piece (5, 0.5·2^−20) → (6, −0.5·2^−20)
    // goes through the wall. Its saved log pins frames 1–5 as the bug ran them.
    const Scene s = parse_ok("ricochet 1\nframes 8\nwall 5 0 8 0\nball 0 0x1.6p-18 1 0\ncheck no-tunnel\n");
    mutant::Mutation m;
    m.ops.step_ball = sinking;
    const CheckedRun bad = run_checked(s, mutant::id(), s.frames, s.checks);
    ASSERT_TRUE(bad.failure);
    EXPECT_EQ(bad.failure->frame, 6);
    const FailureLog log = make_failure_log(s, mutant::id(), "property P seed 1", *bad.failure);
    ASSERT_FALSE(log.scene.expect_states.empty());
    ASSERT_TRUE(log.reproduces());
    // On the kernel that saved it, replay fails it at its found check and frame.
    ReplayResult r = replay_scene(log.scene);
    EXPECT_FALSE(r.passed);
    EXPECT_NE(r.message.find("invariant no-tunnel broke at frame 6 ball 0"), std::string::npos) << r.message;
    // Fixed (robust, which does not sink): every check holds; the states before the failure diverge from frame 1,
    // a note, not a verdict.
    r = replay_scene(log.scene, KernelId::robust);
    EXPECT_TRUE(r.passed) << r.message;
    EXPECT_NE(r.message.find("a note: first diverging frame 1: ball 0"), std::string::npos) << r.message;
    // A log with an expect hash is a recorded regression log: its states are verdicts.
    Scene recorded = log.scene;
    recorded.expect_hash = r.run.hash;
    EXPECT_FALSE(replay_scene(recorded, KernelId::robust).passed);
}

TEST(FailureLog, ReplaySaysWhenTheRunDiffersFromFound) {
    Scene s = parse_ok(k_corners);
    s.checks = {Check::oracle};
    const CheckFailure f = first_failure(s);
    // Another frame: found says 2, the run breaks at 3. The verdict is the usual one (no expect failure:
    // a broken check fails).
    s.found = Found{Check::oracle, 2, f.ball};
    ReplayResult r = replay_scene(s);
    EXPECT_FALSE(r.passed);
    EXPECT_NE(r.message.find(fmt::format("found oracle at frame 2 ball {} when saved, now oracle at frame 3 ball {}",
                                         f.ball, f.ball)),
              std::string::npos)
        << r.message;
    // Another ball.
    s.found = Found{Check::oracle, 3, f.ball + 1};
    r = replay_scene(s);
    EXPECT_NE(r.message.find("when saved, now oracle at frame 3"), std::string::npos) << r.message;
    // With expect failure the verdict follows it; the difference from found is still said.
    s.expect_failure = ExpectFailure{Check::oracle, 3};
    r = replay_scene(s);
    EXPECT_TRUE(r.passed) << r.message;
    EXPECT_NE(r.message.find("when saved, now oracle at frame 3"), std::string::npos) << r.message;
    // The same failure: nothing said.
    s.found = Found{Check::oracle, 3, f.ball};
    r = replay_scene(s);
    EXPECT_TRUE(r.passed);
    EXPECT_EQ(r.message.find("when saved"), std::string::npos) << r.message;
}

TEST(FoundDirective, IsWrittenCanonicallyAfterTheChecksAndIgnoredByTheContentId) {
    const Scene s = parse_ok("ricochet 1\nframes 2\nball 0 0 1 0\ncheck speed\nexpect hash 0000000000000001\n"
                             "  found   speed\t2 0   # a note\n");
    ASSERT_TRUE(s.found);
    EXPECT_EQ(*s.found, (Found{Check::speed, 2, 0}));
    EXPECT_EQ(write_scene_log(s),
              "ricochet 1\nkernel robust\nframes 2\nball 0 0 1 0\ncheck speed\nfound speed 2 0\nexpect hash "
              "0000000000000001\n");
    Scene without = s;
    without.found.reset();
    EXPECT_EQ(scene_content_id(s), scene_content_id(without));
    // A log without balls may name ball 0 (a static shape against another).
    EXPECT_EQ(diag("ricochet 1\ncircle 0 0 1\ncheck oracle\nfound oracle 0 0\n"), "parsed");
}

TEST(FoundDirective, EveryMalformedFoundNamesItsPlace) {
    const std::string head = "ricochet 1\nframes 3\nball 0 0 1 0\nball 1 1 0 0\ncheck speed\n";
    const auto at = [&](std::string_view line) { return diag(head + std::string(line) + "\n"); };
    EXPECT_EQ(at("found"), "t.scene:6:6: error: 'found' needs CHECK F BALL: missing check name");
    EXPECT_EQ(at("found speed"), "t.scene:6:12: error: 'found' needs CHECK F BALL: missing frame");
    EXPECT_EQ(at("found speed 1 # note"), "t.scene:6:15: error: 'found' needs CHECK F BALL: missing ball index");
    EXPECT_EQ(at("found sped 1 0"), "t.scene:6:7: error: unknown check 'sped'");
    EXPECT_EQ(at("found speed x 0"), "t.scene:6:13: error: bad frame: 'x' is not an integer");
    EXPECT_EQ(at("found speed -1 0"), "t.scene:6:13: error: negative frame -1");
    EXPECT_EQ(at("found speed 1 1.5"), "t.scene:6:15: error: bad ball index: '1.5' is not an integer");
    EXPECT_EQ(at("found speed 1 -2"), "t.scene:6:15: error: ball index -2 is out of range");
    EXPECT_EQ(at("found speed 1 0 extra"),
              "t.scene:6:17: error: unexpected 'extra' after 'found' (CHECK F BALL expected)");
    EXPECT_EQ(at("found speed 1 0\nfound speed 1 0"), "t.scene:7:1: error: duplicate 'found'");
    EXPECT_EQ(at("found oracle 1 0"), "t.scene:6:7: error: found a failure of 'oracle' but the log has no 'check oracle'");
    EXPECT_EQ(at("found speed 4 0"), "t.scene:6:13: error: found a failure at frame 4 but the log runs 3 frames");
    EXPECT_EQ(at("found speed 1 2"), "t.scene:6:15: error: found a failure for ball 2 but the log has 2 balls");
    EXPECT_EQ(at("founds speed 1 0"), "t.scene:6:1: error: unknown directive 'founds'");
}

class SaveOnce : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = std::filesystem::temp_directory_path() /
               ("ricochet-failure-log-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }
    static std::string slurp(const std::filesystem::path& p) {
        std::ifstream in(p, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), {}};
    }
    void put(const std::string& name, std::string_view text) const { std::ofstream(dir_ / name) << text; }
    std::size_t count_files() const {
        return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(dir_), {}));
    }
    std::filesystem::path dir_;
};

TEST_F(SaveOnce, KeepsTheLogsCommentsAndSaysNewOrKnown) {
    const Scene scene = parse_ok(k_corners);
    const FailureLog log = make_failure_log(scene, KernelId::lecture_double, "fuzz scene ab", first_failure(scene));
    std::string error;
    const auto first = save_scene_log_once(dir_, "fuzz-scene", log.text(), &error);
    ASSERT_TRUE(first) << error;
    EXPECT_TRUE(first->is_new);
    EXPECT_EQ(first->path.filename().string(), "fuzz-scene-" + scene_content_id(log.scene) + ".scene");
    EXPECT_EQ(slurp(first->path), log.text());
    EXPECT_NE(slurp(first->path).find("\n# "), std::string::npos);
    // The same case again, from another harness with other provenance and expect lines: known.
    Scene other = log.scene;
    other.provenance = {"property Other seed 3"};
    other.expect_states.clear();
    other.found.reset();
    const auto again = save_scene_log_once(dir_, "fuzz-scene", other, &error);
    ASSERT_TRUE(again) << error;
    EXPECT_FALSE(again->is_new);
    EXPECT_EQ(again->path, first->path);
    EXPECT_EQ(count_files(), 1u);
}

TEST_F(SaveOnce, RecognisesTheSameCaseUnderAnyName) {
    Scene s = parse_ok(k_corners);
    // A deliberately malformed log in the folder is no case, and does not stop the search.
    put("broken.scene", "ricochet 1\nwal 0 0 1 1\n");
    put("hand-named.scene", write_scene_log(s));
    std::string error;
    const auto saved = save_scene_log_once(dir_, "Prop", s, &error);
    ASSERT_TRUE(saved) << error;
    EXPECT_FALSE(saved->is_new);
    EXPECT_EQ(saved->path.filename().string(), "hand-named.scene");
    // Another case is new.
    s.balls[0].vel.x = 2;
    const auto fresh = save_scene_log_once(dir_, "Prop", s, &error);
    ASSERT_TRUE(fresh) << error;
    EXPECT_TRUE(fresh->is_new);
    EXPECT_EQ(count_files(), 3u);
}

TEST_F(SaveOnce, TextThatIsNotALogIsRefusedAndNothingIsWritten) {
    std::string error;
    EXPECT_FALSE(save_scene_log_once(dir_, "p", std::string_view("ricochet 1\nfound speed 0 0\n"), &error));
    EXPECT_EQ(error, "not a scene log: p-*.scene:2:7: error: found a failure of 'speed' but the log has no 'check speed'");
    EXPECT_EQ(count_files(), 0u);
}

}  // namespace
}  // namespace ricochet
