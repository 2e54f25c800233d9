// What a diagnostic shows of the log (docs/scene-log.md, "Diagnostics"): quoted text escaped and cut short,
// a byte order mark named, columns of CRLF files the same as of LF files.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "scene_text.hpp"

namespace ricochet {
namespace {

using test::diag;

// The diagnostic of an unknown directive spelled `name`: the quotation under test.
std::string unknown(const std::string& name) { return diag("ricochet 1\n" + name + " 0\n"); }

TEST(SceneLogDiagnostics, EscapeSequencesCannotReachTheTerminal) {
    // An OSC sequence that would retitle the window, and a CSI one that would recolour the output.
    EXPECT_EQ(unknown("wal\x1b]0;pwned\x07"), "t.scene:2:1: error: unknown directive 'wal\\x1b]0;pwned\\x07'");
    EXPECT_EQ(diag("ricochet 1\nball 0 0\x1b[31m 1 1\n"), "t.scene:2:8: error: bad Y: '0\\x1b[31m' is not a number");
    EXPECT_EQ(diag("ricochet 1\nkernel \x7f\x08\n"),
              "t.scene:2:8: error: unknown kernel '\\x7f\\x08' (lecture-float, lecture-double, robust, exact)");
    // A lone CR inside a token is a separator, never shown: the token is cut there.
    EXPECT_EQ(diag("ricochet 1\nball 0 0 1 1 1 1\r7\n"),
              "t.scene:2:18: error: unexpected '7' after 'ball' (X Y VX VY [R [M]] expected)");
}

TEST(SceneLogDiagnostics, ValidUtf8IsKeptEverythingElseEscaped) {
    EXPECT_EQ(unknown("wäll→😀"), "t.scene:2:1: error: unknown directive 'wäll→😀'");
    // Not UTF-8: a stray continuation byte, an invalid lead, an overlong '/', a surrogate, past U+10FFFF,
    // a sequence cut short by the end of the token.
    EXPECT_EQ(unknown("a\x80" "b\xff" "c\xc0\xaf" "d\xed\xa0\x80" "e\xf4\x90\x80\x80" "f\xe2\x82"),
              "t.scene:2:1: error: unknown directive "
              "'a\\x80b\\xffc\\xc0\\xafd\\xed\\xa0\\x80e\\xf4\\x90\\x80\\x80f\\xe2\\x82'");
    // Valid UTF-8 that would hide or reorder text: a C1 control (CSI), RIGHT-TO-LEFT OVERRIDE, a BOM
    // inside a line, LINE SEPARATOR.
    EXPECT_EQ(unknown("a\xc2\x9b" "b\xe2\x80\xae" "c\xef\xbb\xbf" "d\xe2\x80\xa8"),
              "t.scene:2:1: error: unknown directive 'a\\xc2\\x9bb\\xe2\\x80\\xaec\\xef\\xbb\\xbfd\\xe2\\x80\\xa8'");
}

TEST(SceneLogDiagnostics, EachRangeEndsWhereRfc3629AndTheHiddenListSay) {
    // Three-byte forms: E0 needs A0–BF next (E0 80 80 would be an overlong U+0000), U+0800 is the first;
    // the third byte must be a continuation (41 is below 80, C0 above BF). A byte that starts no sequence
    // stands alone, so the rest of the cut sequence is judged byte by byte.
    EXPECT_EQ(unknown("a\xe0\x80\x80" "b\xe0\xa0\x80" "c\xe1\x80\x41" "d\xe1\x80\xc0"),
              "t.scene:2:1: error: unknown directive 'a\\xe0\\x80\\x80b\xe0\xa0\x80"
              "c\\xe1\\x80Ad\\xe1\\x80\\xc0'");
    // The hidden characters at each end of their ranges, and the characters just outside them kept:
    // U+0080 and U+009F (C1) hidden, U+00A0 kept; U+200E, U+200F hidden; U+2027 kept, U+2028, U+2029
    // hidden; U+202A, U+202E hidden, U+202F kept; U+2065 kept, U+2066, U+2069 hidden, U+206A kept.
    EXPECT_EQ(unknown("\xc2\x80" "\xc2\x9f" "\xc2\xa0" "\xe2\x80\x8e" "\xe2\x80\x8f" "\xe2\x80\xa7" "\xe2\x80\xa9"),
              "t.scene:2:1: error: unknown directive '\\xc2\\x80\\xc2\\x9f\xc2\xa0\\xe2\\x80\\x8e\\xe2\\x80\\x8f"
              "\xe2\x80\xa7\\xe2\\x80\\xa9'");
    EXPECT_EQ(unknown("\xe2\x80\xaa" "\xe2\x80\xae" "\xe2\x80\xaf" "\xe2\x81\xa5" "\xe2\x81\xa6" "\xe2\x81\xa9"
                      "\xe2\x81\xaa"),
              "t.scene:2:1: error: unknown directive '\\xe2\\x80\\xaa\\xe2\\x80\\xae\xe2\x80\xaf\xe2\x81\xa5"
              "\\xe2\\x81\\xa6\\xe2\\x81\\xa9\xe2\x81\xaa'");
}

TEST(SceneLogDiagnostics, LongTokensAreCutAtACharacter) {
    const std::string x64(64, 'x');
    EXPECT_EQ(unknown(x64), "t.scene:2:1: error: unknown directive '" + x64 + "'");
    EXPECT_EQ(unknown(x64 + "y"), "t.scene:2:1: error: unknown directive '" + x64 + "…'");
    // A two-byte character across the limit is left out whole; escapes count the bytes they stand for.
    EXPECT_EQ(unknown(std::string(63, 'x') + "é"), "t.scene:2:1: error: unknown directive '" + std::string(63, 'x') + "…'");
    EXPECT_EQ(unknown(std::string(64, '\x01') + "z"),
              "t.scene:2:1: error: unknown directive '" + [] {
                  std::string s;
                  for (int i = 0; i < 64; ++i) s += "\\x01";
                  return s;
              }() + "…'");
    // A 4000-byte number.
    EXPECT_EQ(diag("ricochet 1\nframes " + std::string(4000, '9') + "\n"),
              "t.scene:2:8: error: frame count '" + std::string(64, '9') + "…' is out of range");
}

TEST(SceneLogDiagnostics, AByteOrderMarkHasItsOwnError) {
    const std::string bom = "t.scene:1:1: error: a byte order mark (U+FEFF) is not allowed; save the file as UTF-8 without BOM";
    EXPECT_EQ(diag("\xEF\xBB\xBFricochet 1\n"), bom);
    EXPECT_EQ(diag("\xEF\xBB\xBF# comment\nricochet 1\n"), bom);
    EXPECT_EQ(diag("\xEF\xBB\xBF"), bom);
    // Only at the start of the file: inside a `from` word U+FEFF is a character like any other.
    EXPECT_EQ(diag("ricochet 1\nfrom a\xEF\xBB\xBFz\n"), "parsed");
}

TEST(SceneLogDiagnostics, CrlfColumnsAreLfColumns) {
    // A missing argument points just past the line's last character; the CR of the line end is none.
    EXPECT_EQ(diag("ricochet 1\r\nwall 0 0 1\r\n"), "t.scene:2:11: error: 'wall' needs X0 Y0 X1 Y1: missing Y1");
    EXPECT_EQ(diag("ricochet 1\r\nexpect state 0 0 1.5 -2.25 0.125\r\n"),
              "t.scene:2:33: error: 'expect' needs F I X Y VX VY: missing VY");
    EXPECT_EQ(diag("ricochet 1\r\nrect 0 0 1\t\r\n"),
              "t.scene:2:12: error: 'rect' needs LEFT BOTTOM RIGHT TOP: missing TOP");  // the tab is a character
    EXPECT_EQ(diag("ricochet 1\r\nwall 0 0 1 # c\r\n"), "t.scene:2:12: error: 'wall' needs X0 Y0 X1 Y1: missing Y1");
    // Late in a line, on the last line without a line end, and at a token.
    EXPECT_EQ(diag("ricochet 1\r\nball 0 0 1 1 1 1 7\r\n"),
              "t.scene:2:18: error: unexpected '7' after 'ball' (X Y VX VY [R [M]] expected)");
    EXPECT_EQ(diag("ricochet 1\r\nwall 0 0 1\r"), "t.scene:2:11: error: 'wall' needs X0 Y0 X1 Y1: missing Y1");
    // A lone CR before a comment ends no line: it is a separator, a character of the line like the tab.
    EXPECT_EQ(diag("ricochet 1\nwall 0 0 1\r# c\n"), "t.scene:2:12: error: 'wall' needs X0 Y0 X1 Y1: missing Y1");
}

TEST(SceneLogDiagnostics, EveryLfDiagnosticIsTheCrlfOne) {
    const std::vector<std::string> logs = {
        "ricochet 1\nwall 0 0 1\n",         "ricochet 1\nball 0 0 1 1 1 7\n",      "ricochet 1\nball 0 0x 1 1\n",
        "ricochet 1\nframes\n",             "ricochet 1\nexpect\n",              "ricochet 1\nexpect hash\n",
        "ricochet 1\nexpect failure speed\n", "ricochet 1\nfound speed 0\n",    "ricochet 1\nfrom\n",
        "ricochet 1\ncircle 0 0 -1\n",      "ricochet 1\nframes 1\nball 0 0 1 1\nexpect state 2 0 0 0 1 1\n",
        "ricochet\n",                       "# c\nkernel robust\nricochet 1\n",
    };
    for (const std::string& lf : logs) {
        std::string crlf;
        for (char c : lf) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
        EXPECT_EQ(diag(crlf), diag(lf)) << lf;
    }
}

}  // namespace
}  // namespace ricochet
