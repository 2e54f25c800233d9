// Balls that meet in the format (docs/scene-log.md, "Balls that meet"): `balls collide` and the ball's mass read,
// write and round-trip as specified, each error names its place, a `meet` event prints and hashes as documented,
// and a log without them keeps its bytes and its content id.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "ricochet/bits.hpp"
#include "ricochet/format.hpp"
#include "ricochet/hash.hpp"
#include "ricochet/scene_log.hpp"
#include "scene_text.hpp"

namespace ricochet {
namespace {

using test::diag;
using test::parse_ok;

/// read(text) written back is text, byte for byte, and reads as the same scene bit for bit.
void expect_canonical(const std::string& text) {
    const Scene s = parse_ok(text);
    EXPECT_EQ(write_scene_log(s), text);
    EXPECT_TRUE(same_bits(parse_ok(write_scene_log(s)), s)) << text;
}

TEST(MeetFormat, BallsCollideReadsAndIsWrittenAfterTheDomain) {
    // Anywhere after the header: before the domain lines, after the entities.
    const Scene s = parse_ok("ricochet 1\nballs collide\ndomain speed 8\nframes 2\nball 0 0 1 0 1\ncheck no-tunnel\n");
    EXPECT_TRUE(s.balls_collide);
    EXPECT_TRUE(s.masses.empty());
    EXPECT_FALSE(parse_ok("ricochet 1\nball 0 0 1 0 1\n").balls_collide);
    EXPECT_TRUE(parse_ok("ricochet 1\nball 0 0 1 0 1\nballs collide # solid\n").balls_collide);
    // Written after `frames` and the domain lines, before the walls.
    EXPECT_EQ(write_scene_log(s),
              "ricochet 1\nkernel robust\nframes 2\ndomain speed 8\nballs collide\nball 0 0 1 0 1\ncheck no-tunnel\n");
    expect_canonical("ricochet 1\nkernel exact\nframes 3\ndomain coordinates 100\nballs collide\nwall 0 0 0 10\n"
                     "ball 2 5 1 0 1\nball 8 5 -1 0 1\ncheck no-tunnel\n");
}

TEST(MeetFormat, AMassGivesEveryBallOneThoseBeforeItToo) {
    const Scene s = parse_ok("ricochet 1\nball 0 0 1 0\nball 1 0 1 0 0.5\nball 2 0 1 0 0.5 2.5\nball 3 0 1 0 -0 0x1p-256\n"
                             "ball 4 0 1 0\n");
    ASSERT_EQ(s.balls.size(), 5u);
    EXPECT_EQ(s.masses, (std::vector<double>{1, 1, 2.5, 0x1p-256, 1}));
    EXPECT_EQ(mass_of(s, 0), 1.0);
    EXPECT_EQ(mass_of(s, 2), 2.5);
    // The radius is written on every ball line then, +0 included, and M after it.
    const std::string text = write_scene_log(s);
    EXPECT_EQ(text, "ricochet 1\nkernel robust\nframes 0\nball 0 0 1 0 0 1\nball 1 0 1 0 0.5 1\nball 2 0 1 0 0.5 2.5\n"
                    "ball 3 0 1 0 -0 8.636168555094445e-78\nball 4 0 1 0 0 1\n");
    const Scene back = parse_ok(text);
    EXPECT_TRUE(same_bits(s, back));
    EXPECT_EQ(write_scene_log(back), text);
    // A mass of 1 said is a mass: the scene keeps it, and writes it back.
    const Scene one = parse_ok("ricochet 1\nball 0 0 1 0 0 1\n");
    EXPECT_EQ(one.masses, std::vector<double>{1});
    EXPECT_EQ(write_scene_log(one), "ricochet 1\nkernel robust\nframes 0\nball 0 0 1 0 0 1\n");
}

TEST(MeetFormat, MassesAtTheEndsOfTheirRangeRoundTrip) {
    Scene s;
    s.balls_collide = true;
    const std::vector<double> masses = {0x1p-256, 0x1p256, 1.0 / 3.0, 1e-77, 1e77, 0x1.fffffffffffffp255};
    for (std::size_t i = 0; i < masses.size(); ++i) s.balls.push_back({{double(i), -0.0}, {1, 0}, 0.25 * double(i)});
    s.masses = masses;
    const std::string text = write_scene_log(s);
    const Scene back = parse_ok(text);
    EXPECT_TRUE(same_bits(s, back)) << text;
    EXPECT_EQ(write_scene_log(back), text);
}

TEST(MeetFormat, ABadMassNamesItsPlace) {
    // Column 18: the M of `ball 0 0 1 1 0.5 M`.
    EXPECT_EQ(diag("ricochet 1\nball 0 0 1 1 0.5 0\n"), "t.scene:2:18: error: mass 0 is outside [2^-256, 2^256]");
    EXPECT_EQ(diag("ricochet 1\nball 0 0 1 1 0.5 -0\n"), "t.scene:2:18: error: mass -0 is outside [2^-256, 2^256]");
    EXPECT_EQ(diag("ricochet 1\nball 0 0 1 1 0.5 -1\n"), "t.scene:2:18: error: mass -1 is outside [2^-256, 2^256]");
    EXPECT_EQ(diag("ricochet 1\nball 0 0 1 1 0.5 4e-324\n"),
              "t.scene:2:18: error: mass 4e-324 is outside [2^-256, 2^256]");
    EXPECT_EQ(diag("ricochet 1\nball 0 0 1 1 0.5 0x1p-257\n"),
              "t.scene:2:18: error: mass 0x1p-257 is outside [2^-256, 2^256]");
    EXPECT_EQ(diag("ricochet 1\nball 0 0 1 1 0.5 8e-78\n"), "t.scene:2:18: error: mass 8e-78 is outside [2^-256, 2^256]");
    EXPECT_EQ(diag("ricochet 1\nball 0 0 1 1 0.5 inf\n"),
              "t.scene:2:18: error: M inf is outside the accepted range (finite, magnitude at most 2^256)");
    EXPECT_EQ(diag("ricochet 1\nball 0 0 1 1 0.5 nan\n"),
              "t.scene:2:18: error: M nan is outside the accepted range (finite, magnitude at most 2^256)");
    EXPECT_EQ(diag("ricochet 1\nball 0 0 1 1 0.5 1e300\n"),
              "t.scene:2:18: error: M 1e300 is outside the accepted range (finite, magnitude at most 2^256)");
    EXPECT_EQ(diag("ricochet 1\nball 0 0 1 1 0.5 1e400\n"),
              "t.scene:2:18: error: bad M: '1e400' is out of the range of a double");
    EXPECT_EQ(diag("ricochet 1\nball 0 0 1 1 0.5 heavy\n"), "t.scene:2:18: error: bad M: 'heavy' is not a number");
    // A seventh number is one too many; a bad radius is still the radius's error, mass or not.
    EXPECT_EQ(diag("ricochet 1\nball 0 0 1 1 0.5 2 3\n"),
              "t.scene:2:20: error: unexpected '3' after 'ball' (X Y VX VY [R [M]] expected)");
    EXPECT_EQ(diag("ricochet 1\nball 0 0 1 1 -1 2\n"), "t.scene:2:14: error: negative radius -1");
    // On a later line, after balls without a mass.
    EXPECT_EQ(diag("ricochet 1\nball 0 0 1 1\nball 0 0 1 1 0 2\n\tball 0 0 1 1 0 0\n"),
              "t.scene:4:17: error: mass 0 is outside [2^-256, 2^256]");
}

TEST(MeetFormat, BallsTakesOnlyCollideAndOnlyOnce) {
    EXPECT_EQ(diag("ricochet 1\nballs\n"), "t.scene:2:6: error: 'balls' needs collide: missing the word collide");
    EXPECT_EQ(diag("ricochet 1\nballs # collide\n"), "t.scene:2:7: error: 'balls' needs collide: missing the word collide");
    EXPECT_EQ(diag("ricochet 1\nballs collides\n"), "t.scene:2:7: error: unknown 'collides' after 'balls' (collide)");
    EXPECT_EQ(diag("ricochet 1\nballs  Collide\n"), "t.scene:2:8: error: unknown 'Collide' after 'balls' (collide)");
    EXPECT_EQ(diag("ricochet 1\nballs collide x\n"),
              "t.scene:2:15: error: unexpected 'x' after 'balls' (collide expected)");
    EXPECT_EQ(diag("ricochet 1\nballs collide\nball 0 0 1 0 1\nballs collide\n"),
              "t.scene:4:1: error: duplicate 'balls collide'");
    EXPECT_EQ(diag("ricochet 1\nball collide\n"), "t.scene:2:6: error: bad X: 'collide' is not a number");
    // A log without the header is refused at `balls` as at any directive.
    EXPECT_EQ(diag("balls collide\n"), "t.scene:1:1: error: expected the header 'ricochet 1' before 'balls'");
}

TEST(MeetFormat, NoDomainLineBoundsAMass) {
    // A mass is no length: `domain coordinates` bounds the radius, not M; no-subnormals has nothing to add.
    const Scene s = parse_ok("ricochet 1\ndomain coordinates 1\ndomain speed 1\ndomain no-subnormals\nball 0 0 1 0 1 1e70\n");
    EXPECT_EQ(s.masses, std::vector<double>{1e70});
    EXPECT_EQ(diag("ricochet 1\ndomain coordinates 1\nball 0 0 1 0 2 1\n"),
              "t.scene:3:14: error: R 2 is outside the log's domain (coordinates 1)");
}

TEST(MeetFormat, TheContentIdSeesBallsCollideAndTheMasses) {
    const Scene plain = parse_ok("ricochet 1\nframes 1\nball 0 0 1 0 1\nball 3 0 -1 0 1\n");
    const Scene solid = parse_ok("ricochet 1\nframes 1\nballs collide\nball 0 0 1 0 1\nball 3 0 -1 0 1\n");
    const Scene heavy = parse_ok("ricochet 1\nframes 1\nballs collide\nball 0 0 1 0 1 2\nball 3 0 -1 0 1\n");
    const Scene also = parse_ok("ricochet 1\nfrom property P seed 1\nframes 1\nball 0 0 1 0 1 2\nballs collide\n"
                                "ball 3 0 -1 0 1 1\n");
    EXPECT_NE(scene_content_id(plain), scene_content_id(solid));
    EXPECT_NE(scene_content_id(solid), scene_content_id(heavy));
    // The same case written in another order, with provenance: the same id.
    EXPECT_EQ(scene_content_id(heavy), scene_content_id(also));
}

TEST(MeetFormat, AMeetPrintsAndHashesAsDocumented) {
    const Event meet{Event::Kind::meet, 3, 1, Event::Shape::none, 0, {0.5, -0.0}, {-1, 2.5}};
    EXPECT_EQ(format_event(meet), "meet 3 1 0 0.5 -0 -1 2.5");
    std::string lines = "x\n";
    append_event_line(lines, meet);
    EXPECT_EQ(lines, "x\nmeet 3 1 0 0.5 -0 -1 2.5\n");
    // The record: kind 4, no shape, ball, frame, the other ball as index, the centre and the velocity it leaves with.
    const Event other{Event::Kind::meet, 7, 70000, Event::Shape::none, 65537, {1e300, -2}, {0x1p-1074, -0.0}};
    unsigned char r[k_event_record_size];
    encode_event(other, r);
    EXPECT_EQ(r[0], 4);
    EXPECT_EQ(r[1], 0);
    EXPECT_EQ(r[2] | r[3], 0);
    EXPECT_EQ(r[4] | r[5] << 8 | r[6] << 16 | r[7] << 24, 70000);
    EXPECT_EQ(r[8], 7);
    EXPECT_EQ(r[16] | r[17] << 8 | r[18] << 16 | r[19] << 24, 65537);
    EXPECT_EQ(r[20] | r[21] | r[22] | r[23], 0);
    const auto u64 = [&](int at) {
        std::uint64_t v = 0;
        for (int i = 7; i >= 0; --i) v = v << 8 | r[at + i];
        return v;
    };
    EXPECT_EQ(u64(24), bits_of(1e300));
    EXPECT_EQ(u64(32), bits_of(-2.0));
    EXPECT_EQ(u64(40), bits_of(0x1p-1074));
    EXPECT_EQ(u64(48), bits_of(-0.0));
    // A meet is not a bump at the same place: the kind byte counts.
    Event bump = meet;
    bump.kind = Event::Kind::bump;
    bump.vel = {};
    Event meet_still = meet;
    meet_still.vel = {};
    EXPECT_NE(hash_events(std::vector<Event>{meet_still}), hash_events(std::vector<Event>{bump}));
}

// Every log of the corpus from before balls met keeps its bytes: none of them says `balls collide` or gives a mass,
// so the writer writes what it wrote before, and a saved failure's name, its content id when it was saved, is its content id still.
TEST(MeetFormat, ExistingLogsKeepTheirTextAndTheirIds) {
    const std::regex named(R"(.*-([0-9a-f]{16})\.scene)");
    int logs = 0, named_logs = 0;
    for (const auto& e : std::filesystem::recursive_directory_iterator(RICOCHET_REPLAYS_DIR)) {
        if (e.path().extension() != ".scene") continue;
        const SceneOrDiagnostic parsed = read_scene_log(e.path());
        const Scene* s = std::get_if<Scene>(&parsed);
        if (s == nullptr) continue;  // replays/malformed/ and friends: no scene
        // The logs of balls that meet (replays/meet/) are new: they are written with their directive and masses.
        if (s->balls_collide) continue;
        ++logs;
        SCOPED_TRACE(e.path().string());
        EXPECT_TRUE(s->masses.empty());
        const std::string text = write_scene_log(*s);
        // Every ball line as before masses: X Y VX VY and R only where its bits are not +0.
        for (const Ball& b : s->balls)
            EXPECT_NE(text.find(fmt::format("ball {}\n", b)), std::string::npos) << fmt::format("ball {}", b);
        EXPECT_EQ(text.find("balls collide"), std::string::npos);
        std::smatch m;
        const std::string name = e.path().filename().string();
        if (std::regex_match(name, m, named)) {
            ++named_logs;
            EXPECT_EQ(scene_content_id(*s), m[1].str());
        }
    }
    // A guard against an empty folder proving nothing.
    EXPECT_GT(logs, 50);
    EXPECT_GT(named_logs, 5);
}

}  // namespace
}  // namespace ricochet
