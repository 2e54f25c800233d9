// The independent acceptor on its own: for each rule of docs/scene-log.md, a text it accepts and one it
// rejects at the line the spec's diagnostic points at.
#include "acceptor.hpp"

#include <string>

#include <gtest/gtest.h>

namespace {

using ricochet_grammar::accept_scene_log;

const std::string h = "ricochet 1\n";

void accepted(const std::string& text) {
    const auto v = accept_scene_log(text);
    EXPECT_TRUE(v.accepted) << "rejected at line " << v.line << ": " << v.reason << "\n--- text ---\n" << text;
}

void rejected_at(const std::string& text, int line) {
    const auto v = accept_scene_log(text);
    EXPECT_FALSE(v.accepted) << "accepted\n--- text ---\n" << text;
    EXPECT_EQ(v.line, line) << v.reason << "\n--- text ---\n" << text;
    if (!v.accepted) {
        EXPECT_FALSE(v.reason.empty());
    }
}

std::string repeat(const std::string& line, std::size_t n) {
    std::string s;
    s.reserve(line.size() * n);
    for (std::size_t i = 0; i < n; ++i) s += line;
    return s;
}

TEST(GrammarAcceptor, TheSpecExample) {
    accepted("ricochet 1\nfrom property NoTunnelClosedBox seed 1234\nkernel robust\nframes 3\nwall 0 0 0 10\n"
             "wall 0 10 10 10\nwall 10 10 10 0\nwall 10 0 0 0\nball 5 5 7.5 0.1\ncircle 8 5 1\ncheck no-tunnel\n"
             "expect hash 3f29c1a07b5e6d84   # illustrative value\n");
}

TEST(GrammarAcceptor, HeaderFirstAndOnce) {
    accepted("# a comment\n\n  \t\nricochet 1\n");
    rejected_at("wall 0 0 1 1\nricochet 1\n", 1);
    rejected_at("# c\nfrom fuzz x\nricochet 1\n", 2);
    rejected_at(h + "ricochet 1\n", 2);
    rejected_at("ricochet\n", 1);
    rejected_at("ricochet 1 1\n", 1);
}

TEST(GrammarAcceptor, Version) {
    accepted("ricochet 1");
    rejected_at("ricochet 2\n", 1);
    rejected_at("ricochet 0\n", 1);
    rejected_at("ricochet 01\n", 1);
    rejected_at("ricochet one\n", 1);
}

TEST(GrammarAcceptor, EmptyLogPointsAtTheStart) {
    rejected_at("", 1);
    rejected_at("\n\n# only a comment\n\n", 1);
}

TEST(GrammarAcceptor, DirectiveNames) {
    accepted(h + "kernel exact\nframes 2\nwall 0 0 1 1\nball 0 0 1 1\ncircle 0 0 1\nrect 0 0 1 1\ncheck speed\n"
                 "found speed 1 0\nexpect hash 0123456789abcdef\nexpect state 2 0 0 0 1 1\nexpect failure speed 2\n"
                 "from fuzz sweep 3f7a\n");
    rejected_at(h + "wal 0 0 1 1\n", 2);
    rejected_at(h + "Wall 0 0 1 1\n", 2);
    rejected_at(h + "frames 1\nexpect hashes 0123456789abcdef\n", 3);
    rejected_at(h + "expect\n", 2);
}

TEST(GrammarAcceptor, Arities) {
    accepted(h + "wall 0 0 1 1\nball 0 0 1 1\ncircle 0 0 0\nrect 0 0 0 0\n");
    rejected_at(h + "wall 0 0 1\n", 2);
    accepted(h + "ball 0 0 1 1 7\n");  // a disc of radius 7
    accepted(h + "ball 0 0 1 1 7 8\n");  // of mass 8
    rejected_at(h + "ball 0 0 1 1 7 8 9\n", 2);
    rejected_at(h + "bumper 0 0\n", 2);
    rejected_at(h + "bumper 0 0 1 1\n", 2);
    rejected_at(h + "circle 0 0\n", 2);
    rejected_at(h + "rect 0 0 1 1 1\n", 2);
    rejected_at(h + "kernel\n", 2);
    rejected_at(h + "kernel robust exact\n", 2);
    rejected_at(h + "frames\n", 2);
    rejected_at(h + "check speed speed\n", 2);
    rejected_at(h + "expect hash\n", 2);
    rejected_at(h + "expect state 0 0 0 0 0\n", 2);
    rejected_at(h + "check speed\nexpect failure speed\n", 3);
    rejected_at(h + "check speed\nfound speed 0\n", 3);
    rejected_at(h + "check speed\nfound speed 0 0 0\n", 3);
}

TEST(GrammarAcceptor, KernelNames) {
    for (const char* k : {"lecture-float", "lecture-double", "robust", "exact"}) accepted(h + "kernel " + k + "\n");
    rejected_at(h + "kernel fast\n", 2);
    rejected_at(h + "kernel Robust\n", 2);
}

TEST(GrammarAcceptor, CheckNames) {
    std::string all = h;
    for (const char* c : {"no-tunnel", "symmetry", "boundary", "speed", "deterministic", "oracle", "swap", "translation",
                          "broad-phase", "round-trip", "no-escape", "bounce-side", "accuracy", "event-order", "penetration",
                          "ghost-bounce", "plan", "ball-overlap", "pass-through", "momentum", "relabel"})
        all += std::string("check ") + c + "\n";
    accepted(all);
    rejected_at(h + "check speedy\n", 2);
    rejected_at(h + "check grammar\n", 2);
}

TEST(GrammarAcceptor, CheckListedOnce) {
    accepted(h + "check speed\ncheck oracle\n");
    rejected_at(h + "check speed\ncheck oracle\ncheck speed\n", 4);
}

TEST(GrammarAcceptor, DecimalAndHexNumbers) {
    accepted(h + "ball 1 -0.25 1e-300 0x1.8p-3\n");
    accepted(h + "ball -0x1p+0 0X1P3 1. .5\n");
    accepted(h + "ball 1E5 1e+5 0x.8 0xAbC\n");
    accepted(h + "ball 4e-324 0x1p-1074 -0 0x0p0\n");  // subnormals and zeros
    rejected_at(h + "ball 0 0x 1 1\n", 2);
    rejected_at(h + "ball 0 . 1 1\n", 2);
    rejected_at(h + "ball 0 1e 1 1\n", 2);
    rejected_at(h + "ball 0 0x1p 1 1\n", 2);
    rejected_at(h + "ball 0 1p3 1 1\n", 2);   // a binary exponent needs 0x
    rejected_at(h + "ball 0 0x1e3g 1 1\n", 2);
    rejected_at(h + "ball 0 1,5 1 1\n", 2);
}

TEST(GrammarAcceptor, OneLeadingMinusOnly) {
    accepted(h + "wall -1 -0x1p1 -.5 -0\n");
    rejected_at(h + "wall +1 0 1 1\n", 2);
    rejected_at(h + "wall --1 0 1 1\n", 2);
    rejected_at(h + "wall 0 -+1 1 1\n", 2);
    rejected_at(h + "wall 0 0x-1 1 1\n", 2);
    rejected_at(h + "wall 0 -0x-1 1 1\n", 2);
    rejected_at(h + "wall 0 1- 1 1\n", 2);
    rejected_at(h + "wall 0 - 1 1\n", 2);
}

TEST(GrammarAcceptor, InfAndNanAreOutsideTheRange) {
    accepted(h + "ball 0 0 1 1\n");
    for (const char* bad : {"inf", "-inf", "INF", "infinity", "nan", "-nan", "NaN", "nan(12)", "0xinf"})
        rejected_at(h + "ball 0 0 " + bad + " 1\n", 2);
    rejected_at(h + "ball 0 0 1 1\nexpect state 0 0 nan 0 1 1\n", 3);
}

TEST(GrammarAcceptor, RangeIsTwoToThe256Inclusive) {
    // 2^256 exactly, in hex and in decimal, and a decimal just above that rounds to it.
    accepted(h + "wall 0x1p256 -0x1p256 0 0\n");
    accepted(h + "wall 115792089237316195423570985008687907853269984665640564039457584007913129639936 0 0 0\n");
    accepted(h + "wall 115792089237316195423570985008687907853269984665640564039457584007913129639937 0 0 0\n");
    rejected_at(h + "wall 0 0 0x1.0000000000001p256 0\n", 2);
    rejected_at(h + "wall 0 0 1e78 0\n", 2);
    rejected_at(h + "wall 0 0 1e300 0\n", 2);
    rejected_at(h + "frames 0\nball 0 0 1 1\nexpect state 0 0 0 0 -1e78 0\n", 4);
}

TEST(GrammarAcceptor, BeyondADoubleIsARejectionToo) {
    accepted(h + "circle 0 0 1e-320\n");
    rejected_at(h + "wall 0 0 1e400 0\n", 2);
    rejected_at(h + "wall 0 0 -1e400 0\n", 2);
    // A non-zero literal that rounds to zero is out of the range of a double (clarified in the spec).
    rejected_at(h + "wall 0 0 1e-400 0\n", 2);
    rejected_at(h + "wall 0 0 0x1p-1075 0\n", 2);
    accepted(h + "wall 0 0 0x1.8p-1075 0\n");  // rounds up to the smallest subnormal
    accepted(h + "wall 0 0 0e-400 0\n");
}

TEST(GrammarAcceptor, Integers) {
    accepted(h + "frames 10000000\n");
    accepted(h + "frames 007\n");
    accepted(h + "frames -0\n");  // −0 is zero, not negative
    rejected_at(h + "frames 10000001\n", 2);
    rejected_at(h + "frames -3\n", 2);
    rejected_at(h + "frames +3\n", 2);
    rejected_at(h + "frames 3.0\n", 2);
    rejected_at(h + "frames 1e3\n", 2);
    rejected_at(h + "frames 0x10\n", 2);
    rejected_at(h + "frames 99999999999\n", 2);
    rejected_at(h + "frames 1\nball 0 0 0 0\nexpect state 9223372036854775808 0 0 0 0 0\n", 4);
    rejected_at(h + "frames 1\nball 0 0 0 0\nexpect state 1 -1 0 0 0 0\n", 4);
}

TEST(GrammarAcceptor, RadiusNotNegative) {
    accepted(h + "circle 0 0 0\ncircle 0 0 -0\ncircle 0 0 -0x0p0\ncircle 0 0 2\n");
    rejected_at(h + "circle 0 0 -1\n", 2);
    rejected_at(h + "circle 0 0 -4e-324\n", 2);
}

TEST(GrammarAcceptor, DiscsAndBumpers) {
    accepted(h + "ball 0 0 1 1 0\nball 0 0 1 1 -0\nball 0 0 1 1 0.5\nbumper 0 0 0\nbumper 0 0 -0\nbumper 1 1 2\n");
    rejected_at(h + "ball 0 0 1 1 -1\n", 2);
    rejected_at(h + "ball 0 0 1 1 nan\n", 2);
    rejected_at(h + "ball 0 0 1 1 1e78\n", 2);
    rejected_at(h + "bumper 0 0 -4e-324\n", 2);
    // Every check is defined for discs and bumpers.
    accepted(h + "ball 0 0 1 1 0.5\ncheck deterministic\ncheck broad-phase\ncheck round-trip\ncheck event-order\n");
    accepted(h + "bumper 0 0 1\ncheck no-tunnel\ncheck speed\ncheck no-escape\ncheck penetration\ncheck ghost-bounce\ncheck plan\n");
    accepted(h + "ball 0 0 1 1 0.5\ncheck oracle\ncheck symmetry\ncheck swap\ncheck translation\ncheck boundary\n"
                 "check bounce-side\n");
    accepted(h + "check accuracy\nball 0 0 1 1 0.5\n");
    accepted(h + "check round-trip\ncheck oracle\nbumper 0 0 1\ncheck accuracy\n");
    rejected_at(h + "check accuracy\nbumper 0 0 1\nexpect state 0 1 0 0 0 0\n", 4);
}

TEST(GrammarAcceptor, BallsThatMeet) {
    // `balls collide` once, anywhere after the header (before or after the domain lines and the entities).
    accepted(h + "balls collide\nball 0 0 1 0 1\nball 5 0 -1 0 1\n");
    accepted(h + "domain speed 1\nballs collide\nball 0 0 1 0\n");
    accepted(h + "balls collide\ndomain speed 1\nball 0 0 1 0\n");  // it is no entity: a domain line may follow
    accepted(h + "ball 0 0 1 0\nballs collide # solid\n");
    rejected_at(h + "balls collide\nballs collide\n", 3);
    rejected_at(h + "balls\n", 2);
    rejected_at(h + "balls collide x\n", 2);
    rejected_at(h + "balls collides\n", 2);
    rejected_at(h + "balls Collide\n", 2);
    rejected_at(h + "ball collide\n", 2);
    // The mass: the sixth number, 2^−256 ≤ M ≤ 2^256, after R; balls without one have mass 1.
    accepted(h + "ball 0 0 1 0 0 2\nball 0 0 1 0\nball 0 0 1 0 -0 0.5\n");
    accepted(h + "ball 0 0 1 0 1 0x1p-256\nball 0 0 1 0 1 0x1p256\nball 0 0 1 0 1 1e-77\n");
    for (const char* bad : {"0", "-0", "-1", "inf", "nan", "1e300", "4e-324", "0x1p-257", "0x1.0000000000001p256",
                            "8e-78", "1e400", "x"})
        rejected_at(h + "ball 0 0 1 0 1 " + bad + "\n", 2);
    rejected_at(h + "ball 0 0 1 0 -1 1\n", 2);  // a negative radius, mass or not
    // No domain line bounds a mass: it is no length.
    accepted(h + "domain coordinates 1\ndomain no-subnormals\nball 0 0 1 0 1 1e70\n");
    // The new checks are names like any other.
    accepted(h + "balls collide\ncheck ball-overlap\ncheck pass-through\ncheck momentum\ncheck relabel\n");
}

TEST(GrammarAcceptor, RectCorners) {
    accepted(h + "rect 0 0 0 0\nrect -1 -1 1 1\nrect 0 -0 -0 0\n");
    rejected_at(h + "rect 2 0 1 1\n", 2);
    rejected_at(h + "rect 0 2 1 1\n", 2);
}

TEST(GrammarAcceptor, OnceOnlyDirectives) {
    accepted(h + "kernel robust\nframes 1\nexpect hash 0123456789abcdef\ncheck speed\nexpect failure speed 1\n"
                 "found speed 1 0\n");
    rejected_at(h + "kernel robust\nkernel robust\n", 3);
    rejected_at(h + "frames 1\nframes 1\n", 3);
    rejected_at(h + "expect hash 0123456789abcdef\nexpect hash 0123456789abcdef\n", 3);
    rejected_at(h + "check speed\nexpect failure speed 0\nexpect failure speed 0\n", 4);
    rejected_at(h + "check speed\nfound speed 0 0\nfound speed 0 0\n", 4);
}

TEST(GrammarAcceptor, RepeatableDirectives) {
    accepted(h + "frames 1\nwall 0 0 1 1\nwall 0 0 1 1\nball 0 0 1 1\nball 0 0 1 1\ncircle 0 0 1\ncircle 0 0 1\n"
                 "rect 0 0 1 1\nrect 0 0 1 1\nbumper 0 0 1\nbumper 0 0 1\nexpect state 1 1 0 0 0 0\n"
                 "expect state 1 1 0 0 0 0\nfrom a\nfrom a\n");
}

TEST(GrammarAcceptor, ExpectStateNamesAnExistingBallAndFrame) {
    accepted(h + "frames 2\nball 0 0 1 1\nball 0 0 1 1\nexpect state 2 1 0 0 1 1\nexpect state 0 0 0 0 1 1\n");
    // The whole-log check points at the expect line, after every line has been read.
    rejected_at(h + "frames 1\nball 0 0 1 1\nexpect state 1 3 0 0 1 1\n", 4);
    rejected_at(h + "frames 1\nball 0 0 1 1\nexpect state 2 0 0 0 1 1\n", 4);
    rejected_at(h + "expect state 0 0 0 0 1 1\n", 2);  // no ball, frames 0 by default
    rejected_at(h + "expect state 0 0 0 0 1 1\nwal\n", 3);  // a line error comes before
    // Several: the expect state lines in order come first.
    rejected_at(h + "check speed\nexpect failure speed 5\nexpect state 0 0 0 0 1 1\nexpect state 0 9 0 0 1 1\n", 4);
    // A ball index no log can have (≥ the entity limit) is an error on its own line (clarified in the spec).
    rejected_at(h + "expect state 0 100000 0 0 1 1\nwal\n", 2);
}

TEST(GrammarAcceptor, ExpectFailureNeedsItsCheckAndFrame) {
    accepted(h + "frames 3\nexpect failure oracle 3\ncheck oracle\n");
    rejected_at(h + "frames 3\ncheck speed\nexpect failure oracle 3\n", 4);
    rejected_at(h + "frames 3\ncheck oracle\nexpect failure oracle 4\n", 4);
    rejected_at(h + "check oracle\nexpect failure oracles 0\n", 3);
    rejected_at(h + "check oracle\nexpect failure oracle -1\n", 3);
}

TEST(GrammarAcceptor, FoundNeedsItsCheckFrameAndBall) {
    accepted(h + "frames 2\nball 0 0 1 1\nball 0 0 1 1\ncheck speed\nfound speed 2 1\n");
    accepted(h + "check swap\nfound swap 0 0\n");  // ball 0 in a log without balls
    rejected_at(h + "check swap\nfound swap 0 1\n", 3);
    rejected_at(h + "frames 2\nball 0 0 1 1\ncheck speed\nfound oracle 2 0\n", 5);
    rejected_at(h + "frames 2\nball 0 0 1 1\ncheck speed\nfound speed 3 0\n", 5);
    rejected_at(h + "frames 2\nball 0 0 1 1\ncheck speed\nfound speed 1 1\n", 5);
    rejected_at(h + "check speed\nfound speedy 0 0\n", 3);
    // found before expect failure when both are wrong.
    rejected_at(h + "check speed\nexpect failure speed 1\nfound speed 1 0\n", 4);
}

TEST(GrammarAcceptor, Comments) {
    accepted(h + "wall 0 0 1 1 # a wall\n# wall 0 0\nball 0 0 1 1#no space\n");
    rejected_at(h + "wall 0 0 1 # 1\n", 2);
    rejected_at(h + "#\n wall 0 0 1 1 1 #\n", 3);
}

TEST(GrammarAcceptor, SeparatorsTabsAndCarriageReturns) {
    accepted("ricochet 1\r\nwall\t0 0\t1 1\r\n\r\nball 0\r0 1 1\n");
    // A comment holds no CR but a CRLF line end's: an old Mac file's CR-only line ends would let it hide the rest.
    accepted(h + "wall 0 0 1 1 # a wall\r\nball 0 0 1 1 #\r");
    rejected_at("ricochet 1\r# an old Mac file\rwall 0 0 1 1\r", 1);
    rejected_at(h + "# a\rcomment\nwall 0 0 1 1\n", 2);
    rejected_at(h + "wall 0 0 1 1 #\r\r\n", 2);
    rejected_at(h + "wall 0 0 1 1\v\n", 2);  // a vertical tab is no separator
    rejected_at(h + "wall 0 0 1 1\f\n", 2);
}

TEST(GrammarAcceptor, NoByteOrderMark) {
    rejected_at("\xEF\xBB\xBFricochet 1\n", 1);
    rejected_at("\xEF\xBB\xBF# comment\n\nricochet 1\n", 1);
    rejected_at("\xEF\xBB\xBF", 1);
    accepted(h + "from a\xEF\xBB\xBFz\n");  // only at the start of the file
}

TEST(GrammarAcceptor, LineLength) {
    const std::string comment_4096 = "#" + std::string(4095, 'x');
    accepted(h + comment_4096 + "\n");
    accepted(h + comment_4096);
    rejected_at(h + comment_4096 + "x\n", 2);
    // The CR of a CRLF line counts: only the newline is excluded (clarified in the spec).
    rejected_at(h + comment_4096 + "\r\n", 2);
}

TEST(GrammarAcceptor, FileSize) {
    const std::string line = "#" + std::string(4094, 'x') + "\n";  // 4096 bytes with its newline
    const std::string at_limit = h + repeat(line, 4095) + std::string(16 * 1024 * 1024 - h.size() - 4095 * 4096, '\n');
    ASSERT_EQ(at_limit.size(), 16u * 1024 * 1024);
    accepted(at_limit);
    rejected_at(at_limit + "\n", 1);
    rejected_at(at_limit + "wal\n", 1);  // the size is decided first
}

TEST(GrammarAcceptor, EntityCounts) {
    for (const std::string kind : {"wall 0 0 1 1\n", "ball 0 0 1 1\n", "circle 0 0 1\n", "rect 0 0 1 1\n"}) {
        const std::string at_limit = h + repeat(kind, 100'000);
        accepted(at_limit);
        rejected_at(at_limit + kind, 100'002);
    }
}

TEST(GrammarAcceptor, FromLines) {
    accepted(h + repeat("from property NAME seed 1\n", 64));
    rejected_at(h + repeat("from property NAME seed 1\n", 65), 66);
    rejected_at(h + "from\n", 2);
    rejected_at(h + "from # a comment is no word\n", 2);
    accepted(h + "from \xff\xfe words\n");  // verbatim words: the spec asks nothing of their bytes
}

TEST(GrammarAcceptor, NulBytes) {
    accepted(h + "wall 0 0 1 1\n");
    rejected_at(h + std::string("wall 0 0\0" "1 1\n", 13), 2);
    rejected_at(h + std::string("# comment \0\n", 12), 2);
    rejected_at(std::string("\0", 1), 1);
}

TEST(GrammarAcceptor, ExpectHashIsSixteenLowercaseHexDigits) {
    accepted(h + "expect hash 0123456789abcdef\n");
    rejected_at(h + "expect hash 0123456789ABCDEF\n", 2);
    rejected_at(h + "expect hash 12345g7890abcdef\n", 2);
    rejected_at(h + "expect hash 0123456789abcde\n", 2);
    rejected_at(h + "expect hash 0123456789abcdef0\n", 2);
    rejected_at(h + "expect hash 0x23456789abcdef\n", 2);
}

TEST(GrammarAcceptor, DomainLines) {
    accepted(h + "domain coordinates 1e6\ndomain speed 1000\ndomain wall-length 0.5\ndomain no-subnormals\n"
                 "domain waive touching\nwall 0 0 3 4\nball 1 2 3 4 0.5\ncircle 0 0 1\nbumper 0 0 1\nrect 0 0 1 1\n"
                 "check no-tunnel\nexpect state 0 0 1e70 0 0 0\n");
    // Each once, with its bound above 0, before every entity and check.
    rejected_at(h + "domain speed 1\ndomain speed 1\n", 3);
    rejected_at(h + "domain speed 0\n", 2);
    rejected_at(h + "domain speed\n", 2);
    rejected_at(h + "domain no-subnormals 1\n", 2);
    rejected_at(h + "domain waive corners\n", 2);
    rejected_at(h + "domain gravity 1\n", 2);
    rejected_at(h + "domain\n", 2);
    rejected_at(h + "check speed\ndomain speed 1\n", 3);
    rejected_at(h + "wall 0 0 1 1\ndomain speed 1\n", 3);
    // The entities within it.
    rejected_at(h + "domain coordinates 10\nwall 0 0 11 0\n", 3);
    rejected_at(h + "domain coordinates 10\nball 0 0 100 0 11\n", 3);
    accepted(h + "domain coordinates 10\nball 0 0 100 0 10\n");
    rejected_at(h + "domain speed 10\nball 0 0 0 -11\n", 3);
    rejected_at(h + "domain no-subnormals\nbumper 0 0 5e-324\n", 3);
    accepted(h + "domain no-subnormals\nbumper 0 0 -0\nwall 0 0 0x1p-1022 0\n");
    // |(0, 0) -> (3, 4)| = 5: exactly as long is long enough; one ulp shorter is not.
    accepted(h + "domain wall-length 5\nwall 0 0 3 4\n");
    rejected_at(h + "domain wall-length 5\nwall 0 0 3 3.9999999999999996\n", 3);
    rejected_at(h + "domain wall-length 5e-324\nwall 1 1 1 1\n", 3);
    accepted(h + "domain wall-length 5e-324\nwall 0 0 5e-324 0\n");
    accepted(h + "domain wall-length 1e70\nwall -1e70 0 0 0\n");
    // A waived check may not be named.
    rejected_at(h + "domain waive touching\ncheck oracle\n", 3);
    rejected_at(h + "domain waive touching\ncheck boundary\n", 3);
    accepted(h + "domain waive touching\ncheck speed\n");
}

}  // namespace
