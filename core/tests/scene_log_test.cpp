// Scene logs: write -> read bit for bit, every malformed kind's exact diagnostic, atomic saving.
#include <gtest/gtest.h>

#include <unistd.h>

#include <bit>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include "ricochet/limits.hpp"
#include "ricochet/scene_log.hpp"
#include "scene_text.hpp"

namespace ricochet {
namespace {

using test::parse_ok;
using test::diag;

Scene awkward_scene() {
    Scene s;
    s.kernel = KernelId::lecture_double;
    s.frames = 12;
    s.provenance = {"property NoTunnel seed 7", "fuzz sweep 0123abcd"};
    s.walls = {{{-0.0, 0.1}, {5e-324, 0x1p256}}, {{1e70, -1e-300}, {0.30000000000000004, -0x1p-1074}}};
    s.balls = {{{std::nextafter(1.0, 2.0), -0.0}, {-0x1p256, 1.0 / 3.0}}};
    s.circles = {{{1e9 + 0.125, 2}, 0.0}, {{-3, 4}, -0.0}};
    s.rects = {{-1, -2, -1, 7.5}};
    s.checks = {Check::oracle, Check::no_tunnel, Check::speed};
    s.expect_hash = 0x00ab'cdef'0123'4567ULL;
    s.expect_failure = ExpectFailure{Check::speed, 3};
    s.expect_states = {{0, 0, {{1, 2}, {3, -0.0}}}, {12, 0, {{-5e-324, 1e-310}, {2.5, 0.1}}}};
    return s;
}

TEST(SceneLog, RoundTripIsBitForBit) {
    const Scene s = awkward_scene();
    const std::string text = write_scene_log(s);
    const Scene back = parse_ok(text);
    EXPECT_TRUE(same_bits(s, back)) << text;
    EXPECT_EQ(write_scene_log(back), text);
}

TEST(SceneLog, RoundTripOfRandomBitPatterns) {
    std::mt19937_64 rng(12345);
    Scene s;
    s.frames = 1;
    for (int i = 0; i < 2000; ++i) {
        // Any finite double within the accepted range, sign and subnormals included.
        double v[4];
        for (double& x : v) {
            do x = std::bit_cast<double>(rng());
            while (!in_range(x));
        }
        s.balls.push_back({{v[0], v[1]}, {v[2], v[3]}});
    }
    const Scene back = parse_ok(write_scene_log(s));
    EXPECT_TRUE(same_bits(s, back));
}

TEST(SceneLog, ReadsTheSpecExampleWithCommentsTabsAndHex) {
    const Scene s = parse_ok(
        "# leading comment\n\nricochet 1\r\nfrom property NoTunnelClosedBox seed 1234\nkernel robust\nframes 3\n"
        "wall 0 0 0 10\nwall\t0 10   10 10 # trailing\nball 5 5 7.5 0x1.8p-3\ncircle -0x1p+3 5 0x1p+0 \ncheck no-tunnel\n"
        "expect hash 3f29c1a07b5e6d84   # illustrative value\n");
    EXPECT_EQ(s.kernel, KernelId::robust);
    EXPECT_EQ(s.frames, 3);
    ASSERT_EQ(s.walls.size(), 2u);
    EXPECT_EQ(s.walls[1], (Wall{{0, 10}, {10, 10}}));
    ASSERT_EQ(s.balls.size(), 1u);
    EXPECT_EQ(s.balls[0].vel.y, 0.1875);
    EXPECT_EQ(s.circles.at(0), (Circle{{-8, 5}, 1}));
    EXPECT_EQ(s.provenance, std::vector<std::string>{"property NoTunnelClosedBox seed 1234"});
    EXPECT_EQ(s.expect_hash, 0x3f29c1a07b5e6d84ULL);
}

TEST(SceneLog, NegativeRadiusIsRejectedButMinusZeroIsZero) {
    EXPECT_EQ(diag("ricochet 1\ncircle 0 0 -1e-300\n"), "t.scene:2:12: error: negative radius -1e-300");
    EXPECT_TRUE(std::signbit(parse_ok("ricochet 1\ncircle 0 0 -0\n").circles.at(0).r));
}

struct Bad {
    const char* name;
    std::string text;
    const char* want;
};

TEST(SceneLog, EveryMalformedKindNamesItsPlace) {
    const std::vector<Bad> cases = {
        {"unknown directive", "ricochet 1\nwal 0 0 1 1\n", "2:1: error: unknown directive 'wal'"},
        {"missing token", "ricochet 1\nwall 0 0 1\n", "2:11: error: 'wall' needs X0 Y0 X1 Y1: missing Y1"},
        {"extra token", "ricochet 1\nball 0 0 1 1 1 1 7\n", "2:18: error: unexpected '7' after 'ball' (X Y VX VY [R [M]] expected)"},
        {"bad number", "ricochet 1\nball 0 0x 1 1\n", "2:8: error: bad Y: '0x' is not a number"},
        {"plus sign", "ricochet 1\nball +1 0 1 1\n", "2:6: error: bad X: '+1' is not a number"},
        {"double minus", "ricochet 1\nball --1 0 1 1\n", "2:6: error: bad X: '--1' is not a number"},
        {"nan", "ricochet 1\nball nan 0 1 1\n",
         "2:6: error: X nan is outside the accepted range (finite, magnitude at most 2^256)"},
        {"inf", "ricochet 1\ncircle 0 0 -inf\n",
         "2:12: error: R -inf is outside the accepted range (finite, magnitude at most 2^256)"},
        {"out of range", "ricochet 1\nwall 0 0 1e78 0\n",
         "2:10: error: X1 1e78 is outside the accepted range (finite, magnitude at most 2^256)"},
        {"overflow", "ricochet 1\nwall 0 0 1e400 0\n", "2:10: error: bad X1: '1e400' is out of the range of a double"},
        {"negative radius", "ricochet 1\ncircle 0 0 -1\n", "2:12: error: negative radius -1"},
        {"left > right", "ricochet 1\nrect 2 0 1 1\n", "2:6: error: left 2 is greater than right 1"},
        {"bottom > top", "ricochet 1\nrect 0 2 1 1\n", "2:8: error: bottom 2 is greater than top 1"},
        {"negative frames", "ricochet 1\nframes -3\n", "2:8: error: negative frame count -3"},
        {"absurd frames", "ricochet 1\nframes 99999999999\n",
         "2:8: error: frame count 99999999999 is over the limit of 10000000"},
        {"frames not integer", "ricochet 1\nframes 1.5\n", "2:8: error: bad frame count: '1.5' is not an integer"},
        {"duplicate frames", "ricochet 1\nframes 1\nframes 2\n", "3:1: error: duplicate 'frames'"},
        {"duplicate kernel", "ricochet 1\nkernel exact\nkernel exact\n", "3:1: error: duplicate 'kernel'"},
        {"unknown kernel", "ricochet 1\nkernel fast\n",
         "2:8: error: unknown kernel 'fast' (lecture-float, lecture-double, robust, exact)"},
        {"unknown check", "ricochet 1\ncheck speedy\n",
         "2:7: error: unknown check 'speedy' (no-tunnel, symmetry, boundary, speed, deterministic, oracle, swap, translation, broad-phase, round-trip, no-escape, bounce-side, accuracy, event-order, penetration, ghost-bounce, plan, ball-overlap, pass-through, momentum, relabel, jump-through)"},
        {"duplicate check", "ricochet 1\ncheck speed\ncheck speed\n", "3:7: error: duplicate check 'speed'"},
        {"future version", "ricochet 2\n", "1:10: error: format version 2 is newer than this reader (it reads version 1)"},
        {"bad version", "ricochet one\n", "1:10: error: unknown format version 'one' (this reader reads version 1)"},
        {"missing header", "wall 0 0 1 1\n", "1:1: error: expected the header 'ricochet 1' before 'wall'"},
        {"directive before header", "# c\nkernel robust\nricochet 1\n",
         "2:1: error: expected the header 'ricochet 1' before 'kernel'"},
        {"duplicate header", "ricochet 1\nricochet 1\n", "2:1: error: duplicate header 'ricochet'"},
        {"empty", "", "1:1: error: empty log: expected the header 'ricochet 1'"},
        {"only comments", "# nothing\n\n", "1:1: error: empty log: expected the header 'ricochet 1'"},
        {"nul byte", std::string("ricochet 1\nwall 0 0\0 1 1\n", 24), "2:9: error: NUL byte in the log"},
        {"huge line", "ricochet 1\n#" + std::string(5000, 'x') + "\n",
         "2:4097: error: line is 5001 bytes long, over the limit of 4096"},
        {"huge file", "ricochet 1\n" + std::string(k_max_file_size, '\n'),
         "1:1: error: the file is 16777227 bytes, over the limit of 16777216 bytes"},
        {"bad hash", "ricochet 1\nexpect hash 12345g7890abcdef\n",
         "2:13: error: bad hash '12345g7890abcdef': expected exactly 16 lowercase hex digits"},
        {"short hash", "ricochet 1\nexpect hash abc\n", "2:13: error: bad hash 'abc': expected exactly 16 lowercase hex digits"},
        {"uppercase hash", "ricochet 1\nexpect hash 3F29C1A07B5E6D84\n",
         "2:13: error: bad hash '3F29C1A07B5E6D84': expected exactly 16 lowercase hex digits"},
        {"duplicate hash", "ricochet 1\nexpect hash 0000000000000000\nexpect hash 0000000000000000\n",
         "3:8: error: duplicate 'expect hash'"},
        {"unknown expectation", "ricochet 1\nexpect speed 1\n",
         "2:8: error: unknown expectation 'speed' (hash, state or failure)"},
        {"expect state past the frames", "ricochet 1\nframes 1\nball 0 0 1 1\nexpect state 2 0 0 0 1 1\n",
         "4:14: error: expect state at frame 2 but the log runs 1 frames"},
        {"expect state of a missing ball", "ricochet 1\nframes 1\nball 0 0 1 1\nexpect state 1 3 0 0 1 1\n",
         "4:16: error: expect state for ball 3 but the log has 1 balls"},
        {"expect failure of an unchecked invariant", "ricochet 1\nframes 4\nexpect failure speed 2\n",
         "3:16: error: expect failure of 'speed' but the log has no 'check speed'"},
        {"expect failure unknown check", "ricochet 1\nexpect failure fast 2\n", "2:16: error: unknown check 'fast'"},
        {"from without words", "ricochet 1\nfrom\n", "2:5: error: 'from' needs provenance words: missing provenance"},
    };
    for (const Bad& b : cases) EXPECT_EQ(diag(b.text), std::string("t.scene:") + b.want) << b.name;
}

TEST(SceneLog, ExpectLinesToBeReplacedAreNotCheckedAgainstTheLog) {
    // What `ricochet record` reads: stale expectations (frames lowered, a ball and a check taken out).
    const std::string stale = "ricochet 1\nframes 1\nball 0 0 1 1\ncheck speed\nexpect state 2 0 0 0 1 1\n"
                              "expect state 1 3 0 0 1 1\nexpect failure oracle 5\nexpect hash 0123456789abcdef\n";
    EXPECT_EQ(diag(stale), "t.scene:5:14: error: expect state at frame 2 but the log runs 1 frames");
    auto r = parse_scene_log(stale, "t.scene", ExpectLines::replaced);
    ASSERT_TRUE(std::holds_alternative<Scene>(r)) << std::get<Diagnostic>(r).str();
    const Scene& s = std::get<Scene>(r);
    EXPECT_EQ(s.balls.size(), 1u);
    EXPECT_TRUE(s.expect_states.empty());
    EXPECT_FALSE(s.expect_failure);
    EXPECT_FALSE(s.expect_hash);
    // Each line is still read as strictly as ever, and `found` (which record keeps) still checked.
    const auto replaced = [](std::string_view text) {
        auto p = parse_scene_log(text, "t.scene", ExpectLines::replaced);
        return std::holds_alternative<Diagnostic>(p) ? std::get<Diagnostic>(p).str() : std::string("parsed");
    };
    EXPECT_EQ(replaced("ricochet 1\nexpect hash 3F29C1A07B5E6D84\n"),
              "t.scene:2:13: error: bad hash '3F29C1A07B5E6D84': expected exactly 16 lowercase hex digits");
    EXPECT_EQ(replaced("ricochet 1\nexpect state 0 0 0 0 1\n"),
              "t.scene:2:23: error: 'expect' needs F I X Y VX VY: missing VY");
    EXPECT_EQ(replaced("ricochet 1\nframes 1\ncheck speed\nfound speed 2 0\n"),
              "t.scene:4:13: error: found a failure at frame 2 but the log runs 1 frames");
}

TEST(SceneLog, DiagnosticFormat) {
    EXPECT_EQ((Diagnostic{"a/b.scene", 3, 7, "what"}).str(), "a/b.scene:3:7: error: what");
}

TEST(SceneLog, ReadingAMissingFileIsADiagnostic) {
    auto r = read_scene_log("/nonexistent/x.scene");
    ASSERT_TRUE(std::holds_alternative<Diagnostic>(r));
    EXPECT_EQ(std::get<Diagnostic>(r).str(), "/nonexistent/x.scene:1:1: error: cannot open: No such file or directory");
}

class TempDir : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = std::filesystem::temp_directory_path() /
               ("ricochet-test-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }
    static std::string slurp(const std::filesystem::path& p) {
        std::ifstream in(p, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), {}};
    }
    std::size_t count_files() const {
        return static_cast<std::size_t>(std::distance(std::filesystem::directory_iterator(dir_), {}));
    }
    std::filesystem::path dir_;
};

TEST_F(TempDir, AtomicWriteReplacesAndLeavesNoTemporaryFile) {
    const auto p = dir_ / "a.scene";
    std::string error;
    ASSERT_TRUE(write_file_atomically(p, "first\n", &error)) << error;
    EXPECT_EQ(slurp(p), "first\n");
    ASSERT_TRUE(write_file_atomically(p, "second\n", &error)) << error;
    EXPECT_EQ(slurp(p), "second\n");
    EXPECT_EQ(count_files(), 1u);
}

TEST_F(TempDir, AtomicWriteIntoAMissingFolderFailsAndCreatesNothing) {
    std::string error;
    EXPECT_FALSE(write_file_atomically(dir_ / "no" / "a.scene", "x", &error));
    EXPECT_NE(error.find("cannot create a temporary file"), std::string::npos) << error;
    EXPECT_EQ(count_files(), 0u);
}

TEST_F(TempDir, AtomicWriteGoesThroughASymbolicLink) {
    std::filesystem::create_directories(dir_ / "real");
    const auto target = dir_ / "real" / "a.scene";
    const auto link = dir_ / "link.scene";
    std::string error;
    ASSERT_TRUE(write_file_atomically(target, "first\n", &error)) << error;
    std::filesystem::permissions(target, std::filesystem::perms(0640));
    std::filesystem::create_symlink(std::filesystem::path("real") / "a.scene", link);
    ASSERT_TRUE(write_file_atomically(link, "second\n", &error)) << error;
    EXPECT_TRUE(std::filesystem::is_symlink(link));
    EXPECT_EQ(slurp(target), "second\n");
    EXPECT_EQ(std::filesystem::status(target).permissions(), std::filesystem::perms(0640));
    // No temporary file left on either side.
    EXPECT_EQ(count_files(), 2u);
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir_ / "real"), {}), 1);
    // A dangling link is an error, and nothing is created.
    std::filesystem::create_symlink("nowhere.scene", dir_ / "dangling.scene");
    EXPECT_FALSE(write_file_atomically(dir_ / "dangling.scene", "x", &error));
    EXPECT_NE(error.find("cannot resolve the symbolic link"), std::string::npos) << error;
    EXPECT_EQ(count_files(), 3u);
}

TEST_F(TempDir, AtomicWriteRemovesOnlyTheStaleTemporariesOfItsOwnFile) {
    const auto touch = [&](const std::string& name, bool old) {
        std::ofstream(dir_ / name) << "partial";
        // Set exactly: a file system's own clock may lag the process's by a tick.
        const auto now = std::filesystem::file_time_type::clock::now();
        std::filesystem::last_write_time(dir_ / name, old ? now - std::chrono::hours(1) : now);
    };
    // 2147483647 is past every PID (Linux's pid_max is at most 2^22): its writer is gone.
    const std::string dead = ".a.scene.tmp.2147483647.AbC123";
    const std::string live = fmt::format(".a.scene.tmp.{}.AbC123", ::getppid());  // a running writer's
    const std::string young = ".a.scene.tmp.2147483646.AbC123";                    // made after this process started
    const std::string other = ".b.scene.tmp.2147483647.AbC123";                    // another log's
    const std::string unnamed = ".a.scene.tmp.AbC123";                             // no PID: whose is unknown
    const std::string odd = ".a.scene.tmp.2147483647.AbC12";                      // not mkstemp's six letters
    // Names that only look like a dead writer's: an empty PID, a PID that is not a number, or is followed by
    // more than digits, or is 0; letters outside [0-9a-zA-Z] on each side of the ranges mkstemp draws from.
    const std::vector<std::string> lookalikes = {
        ".a.scene.tmp..AbC123",           ".a.scene.tmp.x2147483647.AbC123", ".a.scene.tmp.2147483647x.AbC123",
        ".a.scene.tmp.0.AbC123",          ".a.scene.tmp.2147483647.AbC-23",  ".a.scene.tmp.2147483647.AbC:23",
        ".a.scene.tmp.2147483647.AbC_23", ".a.scene.tmp.2147483647.AbC{23",
    };
    // This process's own (a writer at work on another thread), and a folder and a link named like a dead one's.
    const std::string own = fmt::format(".a.scene.tmp.{}.AbC123", ::getpid());
    const std::string folder = ".a.scene.tmp.2147483645.AbC123", link = ".a.scene.tmp.2147483644.AbC123";
    touch(dead, true);
    touch(live, true);
    touch(young, false);
    touch(other, true);
    touch(unnamed, true);
    touch(odd, true);
    for (const std::string& name : lookalikes) touch(name, true);
    touch(own, true);
    std::filesystem::create_directory(dir_ / folder);
    std::filesystem::create_symlink(dir_ / live, dir_ / link);
    std::string error;
    ASSERT_TRUE(write_file_atomically(dir_ / "a.scene", "text\n", &error)) << error;
    EXPECT_FALSE(std::filesystem::exists(dir_ / dead));
    std::vector<std::string> kept = {live, young, other, unnamed, odd, own, folder, link};
    kept.insert(kept.end(), lookalikes.begin(), lookalikes.end());
    for (const std::string& name : kept)
        EXPECT_TRUE(std::filesystem::symlink_status(dir_ / name).type() != std::filesystem::file_type::not_found) << name;
    EXPECT_EQ(slurp(dir_ / "a.scene"), "text\n");
    EXPECT_EQ(count_files(), kept.size() + 1);
}

TEST_F(TempDir, TheSameCaseIsNeverSavedTwice) {
    Scene a = awkward_scene();
    Scene b = a;
    b.provenance = {"property Other seed 99"};
    b.expect_states.clear();
    EXPECT_EQ(scene_content_id(a), scene_content_id(b));
    std::string error;
    const auto pa = save_scene_log_once(dir_, "prop", a, &error);
    const auto pb = save_scene_log_once(dir_, "prop", b, &error);
    ASSERT_TRUE(pa && pb) << error;
    EXPECT_TRUE(pa->is_new);
    EXPECT_FALSE(pb->is_new);
    EXPECT_EQ(pa->path, pb->path);
    EXPECT_EQ(count_files(), 1u);
    // The first one saved is kept, untouched.
    EXPECT_EQ(slurp(pa->path), write_scene_log(a));
    b.balls[0].pos.x = 2;
    EXPECT_NE(scene_content_id(a), scene_content_id(b));
}

}  // namespace
}  // namespace ricochet
