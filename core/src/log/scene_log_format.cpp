// The scene-log text format (format 1, docs/scene-log.md): the reader and the canonical writer.
#include "ricochet/scene_log_format.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <vector>

#include <fmt/format.h>
#include <xxhash.h>

#include "base/shown_text.hpp"
#include "ricochet/bits.hpp"
#include "ricochet/format.hpp"
#include "ricochet/from_chars.hpp"
#include "ricochet/hash.hpp"
#include "ricochet/limits.hpp"

namespace ricochet {

std::string Diagnostic::str() const { return fmt::format("{}:{}:{}: error: {}", file, line, col, message); }

namespace {

using detail::shown;

/// One token of a line and the 1-based column it starts at.
struct Token {
    std::string_view text;
    int col = 0;
};

/// Thrown inside the parser only; parse_scene_log turns it into a Diagnostic.
struct ParseError {
    int line;
    int col;
    std::string message;
};

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r'; }

/// Reads a double as std::from_chars does, plus a "0x"/"0X" prefix for hexadecimal (docs/scene-log.md's
/// `0x1.8p-3`, which from_chars' hex format reads without the prefix).
std::optional<double> to_double(std::string_view s, std::string& why) {
    bool negative = false;
    std::string_view body = s;
    if (body.starts_with('-')) {
        negative = true;
        body.remove_prefix(1);
    }
    auto format = std::chars_format::general;
    if (body.size() > 2 && body[0] == '0' && (body[1] == 'x' || body[1] == 'X')) {
        body.remove_prefix(2);
        format = std::chars_format::hex;
    }
    // from_chars takes no sign of its own here: a second '-' (or a '+') is not a number.
    if (body.empty() || body.front() == '-' || body.front() == '+') {
        why = fmt::format("'{}' is not a number", shown(s));
        return std::nullopt;
    }
    // Nor is a binary exponent with two signs: libstdc++ 12's hexadecimal from_chars reads "1p+-3" whole, as 2^−3
    // (its decimal one stops at "1e+-3" after the 1, as the grammar has it). Found by the parser fuzz target.
    if (format == std::chars_format::hex) {
        const std::size_t p = body.find_first_of("pP");
        const auto sign = [&](std::size_t i) { return i < body.size() && (body[i] == '+' || body[i] == '-'); };
        if (p != std::string_view::npos && sign(p + 1) && sign(p + 2)) {
            why = fmt::format("'{}' is not a number", shown(s));
            return std::nullopt;
        }
    }
    double v = 0.0;
    const auto [end, ec] = from_chars_double(body.data(), body.data() + body.size(), v, format);
    if (ec == std::errc::result_out_of_range) {
        why = fmt::format("'{}' is out of the range of a double", shown(s));
        return std::nullopt;
    }
    if (ec != std::errc{} || end != body.data() + body.size()) {
        why = fmt::format("'{}' is not a number", shown(s));
        return std::nullopt;
    }
    return negative ? -v : v;
}

class Parser {
public:
    Parser(std::string_view text, ExpectLines expect_lines) : text_(text), expect_lines_(expect_lines) {}

    Scene parse() {
        if (text_.size() > k_max_file_size)
            throw ParseError{1, 1, fmt::format("the file is {} bytes, over the limit of {} bytes", text_.size(),
                                               k_max_file_size)};
        // A BOM would otherwise be the first bytes of the first token, invisible in its message.
        if (text_.starts_with(k_byte_order_mark))
            throw ParseError{1, 1, "a byte order mark (U+FEFF) is not allowed; save the file as UTF-8 without BOM"};
        std::size_t pos = 0;
        int line_no = 0;
        while (pos < text_.size()) {
            std::size_t end = text_.find('\n', pos);
            if (end == std::string_view::npos) end = text_.size();
            ++line_no;
            parse_line(text_.substr(pos, end - pos), line_no);
            pos = end + 1;
        }
        // A log with no directive at all: point at its start.
        if (!seen_header_) throw ParseError{1, 1, "empty log: expected the header 'ricochet 1'"};
        if (any_mass_) scene_.masses = std::move(masses_);
        validate();
        if (expect_lines_ == ExpectLines::replaced) {
            scene_.expect_hash.reset();
            scene_.expect_failure.reset();
            scene_.expect_states.clear();
        }
        return std::move(scene_);
    }

private:
    [[noreturn]] void fail(const Token& t, std::string message) const { throw ParseError{line_, t.col, std::move(message)}; }

    void parse_line(std::string_view line, int line_no) {
        line_ = line_no;
        if (line.size() > k_max_line_length)
            throw ParseError{line_no, static_cast<int>(k_max_line_length) + 1,
                             fmt::format("line is {} bytes long, over the limit of {}", line.size(), k_max_line_length)};
        if (const auto nul = line.find('\0'); nul != std::string_view::npos)
            throw ParseError{line_no, static_cast<int>(nul) + 1, "NUL byte in the log"};
        const std::size_t full_size = line.size();
        // '#' starts a comment to the end of the line. A CR inside it (not its last character, a CRLF's) is an
        // error at its place: an old Mac file's CR-only line ends read as one line, and its first comment would
        // otherwise hide the rest of the log.
        if (const auto hash = line.find('#'); hash != std::string_view::npos) {
            if (const auto cr = line.find('\r', hash); cr != std::string_view::npos && cr + 1 < line.size())
                throw ParseError{line_no, static_cast<int>(cr) + 1,
                                 "a carriage return (CR) inside a comment: lines end with LF or CRLF, and CR-only "
                                 "line ends (an old Mac file?) would let the comment hide the rest of the log"};
            line = line.substr(0, hash);
        }
        tokens_.clear();
        std::size_t i = 0;
        while (i < line.size()) {
            while (i < line.size() && is_space(line[i])) ++i;
            if (i == line.size()) break;
            const std::size_t start = i;
            while (i < line.size() && !is_space(line[i])) ++i;
            tokens_.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
        }
        if (tokens_.empty()) return;
        // Just past the line's last character: the CR of a CRLF line end is no character of the line.
        const bool crlf_end = line.ends_with('\r') && line.size() == full_size;
        end_col_ = static_cast<int>(line.size() - (crlf_end ? 1 : 0)) + 1;
        directive();
    }

    /// The n-th argument (1-based after the directive), or an error at the end of the line.
    const Token& arg(std::size_t n, std::string_view what) {
        if (n >= tokens_.size())
            throw ParseError{line_, end_col_,
                             fmt::format("'{}' needs {}: missing {}", shown(tokens_[0].text), expected_, what)};
        return tokens_[n];
    }
    void no_more(std::size_t n) {
        if (tokens_.size() > n)
            fail(tokens_[n], fmt::format("unexpected '{}' after '{}' ({} expected)", shown(tokens_[n].text),
                                         shown(tokens_[0].text), expected_));
    }

    double number(std::size_t n, std::string_view what) {
        const Token& t = arg(n, what);
        std::string why;
        const auto v = to_double(t.text, why);
        if (!v) fail(t, fmt::format("bad {}: {}", what, why));
        if (!in_range(*v))
            fail(t, fmt::format("{} {} is outside the accepted range (finite, magnitude at most 2^256)", what, shown(t.text)));
        return *v;
    }

    /// A radius R ≥ 0: −0 is zero, any other negative number an error at its token.
    double radius(std::size_t n) {
        const double r = number(n, "R");
        if (std::signbit(r) && r != 0.0) fail(tokens_[n], fmt::format("negative radius {}", shown(tokens_[n].text)));
        return r;
    }

    /// A ball's mass M in [2^−256, 2^256]: neither zero nor negative, and far from the ends of a double, so that
    /// the meet's m_j/(m_i + m_j) neither overflows nor underflows. An error at its token otherwise.
    double mass(std::size_t n) {
        const double m = number(n, "M");
        if (!(m >= 0x1p-256 && m <= 0x1p256))
            fail(tokens_[n], fmt::format("mass {} is outside [2^-256, 2^256]", shown(tokens_[n].text)));
        return m;
    }

    std::int64_t integer(std::size_t n, std::string_view what) {
        const Token& t = arg(n, what);
        std::int64_t v = 0;
        const auto [end, ec] = std::from_chars(t.text.data(), t.text.data() + t.text.size(), v);
        if (ec == std::errc::result_out_of_range) fail(t, fmt::format("{} '{}' is out of range", what, shown(t.text)));
        if (ec != std::errc{} || end != t.text.data() + t.text.size())
            fail(t, fmt::format("bad {}: '{}' is not an integer", what, shown(t.text)));
        return v;
    }

    /// The number at token n as its domain allows it: a coordinate or radius (length) or a velocity component
    /// (speed) within the domain's bound, and not subnormal where the domain says so.
    void in_domain(std::size_t n, double x, bool speed) {
        const Domain& d = scene_.domain;
        const std::optional<double>& bound = speed ? d.speed : d.coordinates;
        if (bound && !(std::fabs(x) <= *bound))
            fail(tokens_[n], fmt::format("{} {} is outside the log's domain ({} {})", expected_word(n),
                                         shown(tokens_[n].text), speed ? "speed" : "coordinates", *bound));
        if (d.no_subnormals && std::fpclassify(x) == FP_SUBNORMAL)
            fail(tokens_[n], fmt::format("{} {} is subnormal, outside the log's domain (no-subnormals)", expected_word(n),
                                         shown(tokens_[n].text)));
    }
    /// The name of argument n in the current directive's expected_ ("X0 Y0 X1 Y1": 1 is X0; "X Y VX VY [R [M]]": 5
    /// is R, 6 is M).
    std::string_view expected_word(std::size_t n) const {
        std::string_view rest = expected_;
        for (std::size_t i = 1; i < n && !rest.empty(); ++i) {
            const auto space = rest.find(' ');
            rest = space == std::string_view::npos ? std::string_view{} : rest.substr(space + 1);
        }
        std::string_view word = rest.substr(0, rest.find(' '));
        // An optional argument's brackets are no part of its name.
        while (word.starts_with('[')) word.remove_prefix(1);
        while (word.ends_with(']')) word.remove_suffix(1);
        return word;
    }
    /// An entity or check line: the domain is settled from here on.
    void settle_domain() { seen_entity_ = true; }

    void domain_line() {
        expected_ = "coordinates C, speed V, wall-length L, no-subnormals or waive touching";
        const Token& d = tokens_[0];
        if (seen_entity_)
            fail(d, "'domain' comes before the first wall, ball, circle, rect, bumper and check (they are read in it)");
        const Token& what = arg(1, "what the domain bounds");
        Domain& dom = scene_.domain;
        const auto duplicate = [&](bool taken) {
            if (taken) fail(what, fmt::format("duplicate 'domain {}'", shown(what.text)));
        };
        const auto bound = [&](std::optional<double>& out) {
            duplicate(out.has_value());
            const double x = number(2, what.text);
            if (!(x > 0)) fail(tokens_[2], fmt::format("domain {} {} is not above 0", what.text, shown(tokens_[2].text)));
            no_more(3);
            out = x;
        };
        if (what.text == "coordinates") {
            bound(dom.coordinates);
        } else if (what.text == "speed") {
            bound(dom.speed);
        } else if (what.text == "wall-length") {
            bound(dom.wall_length);
        } else if (what.text == "no-subnormals") {
            duplicate(dom.no_subnormals);
            no_more(2);
            dom.no_subnormals = true;
        } else if (what.text == "waive") {
            expected_ = "a convention: touching";
            const Token& c = arg(2, "convention");
            if (c.text != "touching") fail(c, fmt::format("unknown convention '{}' (touching)", shown(c.text)));
            duplicate(dom.waive_touching);
            no_more(3);
            dom.waive_touching = true;
        } else {
            fail(what, fmt::format("unknown domain '{}' (coordinates, speed, wall-length, no-subnormals or waive)",
                                   shown(what.text)));
        }
    }

    void count(std::size_t size, std::size_t limit, std::string_view kind) {
        if (size >= limit) fail(tokens_[0], fmt::format("too many {}: the limit is {}", kind, limit));
    }

    void directive() {
        const Token& d = tokens_[0];
        const std::string_view name = d.text;
        if (!seen_header_) {
            if (name != "ricochet")
                fail(d, fmt::format("expected the header 'ricochet 1' before '{}'", shown(name)));
            expected_ = "a format version";
            const Token& v = arg(1, "format version");
            if (v.text != "1") {
                std::int64_t ver = 0;
                const auto [end, ec] = std::from_chars(v.text.data(), v.text.data() + v.text.size(), ver);
                if (ec == std::errc{} && end == v.text.data() + v.text.size() && ver > 1)
                    fail(v, fmt::format("format version {} is newer than this reader (it reads version 1)", shown(v.text)));
                fail(v, fmt::format("unknown format version '{}' (this reader reads version 1)", shown(v.text)));
            }
            no_more(2);
            seen_header_ = true;
            return;
        }
        if (name == "ricochet") fail(d, "duplicate header 'ricochet'");
        if (name == "kernel") {
            expected_ = "a kernel name";
            if (seen_kernel_) fail(d, "duplicate 'kernel'");
            const Token& t = arg(1, "kernel name");
            const auto k = parse_kernel(t.text);
            // A kernel this build knows but lacks (a peer not found at build time) is told apart from a typo.
            if (!k) fail(t, absent_kernel_message(t.text).value_or(
                                fmt::format("unknown kernel '{}' ({})", shown(t.text), kernel_names())));
            no_more(2);
            scene_.kernel = *k;
            seen_kernel_ = true;
        } else if (name == "frames") {
            expected_ = "a frame count";
            if (seen_frames_) fail(d, "duplicate 'frames'");
            const std::int64_t n = integer(1, "frame count");
            if (n < 0) fail(tokens_[1], fmt::format("negative frame count {}", n));
            if (n > k_max_frames)
                fail(tokens_[1], fmt::format("frame count {} is over the limit of {}", n, k_max_frames));
            no_more(2);
            scene_.frames = n;
            seen_frames_ = true;
        } else if (name == "wall") {
            expected_ = "X0 Y0 X1 Y1";
            count(scene_.walls.size(), k_max_entities, "walls");
            Wall w{{number(1, "X0"), number(2, "Y0")}, {number(3, "X1"), number(4, "Y1")}};
            no_more(5);
            settle_domain();
            in_domain(1, w.p0.x, false), in_domain(2, w.p0.y, false), in_domain(3, w.p1.x, false), in_domain(4, w.p1.y, false);
            if (scene_.domain.wall_length && !wall_at_least(w, *scene_.domain.wall_length))
                fail(d, fmt::format("the wall is shorter than the log's domain (wall-length {})", *scene_.domain.wall_length));
            scene_.walls.push_back(w);
        } else if (name == "ball") {
            expected_ = "X Y VX VY [R [M]]";
            count(scene_.balls.size(), k_max_entities, "balls");
            Ball b{{number(1, "X"), number(2, "Y")}, {number(3, "VX"), number(4, "VY")}};
            // The radius is optional: without it the ball is a point, as before radii existed.
            if (tokens_.size() > 5) b.r = radius(5);
            // So is the mass after it (balls that meet): without it the ball's mass is 1.
            const double m = tokens_.size() > 6 ? mass(6) : 1.0;
            no_more(7);
            settle_domain();
            in_domain(1, b.pos.x, false), in_domain(2, b.pos.y, false), in_domain(3, b.vel.x, true), in_domain(4, b.vel.y, true);
            if (tokens_.size() > 5) in_domain(5, b.r, false);
            if (is_disc(b) && !first_disc_) first_disc_ = Place{line_, tokens_[5].col};
            scene_.balls.push_back(b);
            // Every ball's mass, kept until the end: the scene holds them only if some ball line gave one (a ball
            // before the first mass has mass 1 too).
            masses_.push_back(m);
            any_mass_ = any_mass_ || tokens_.size() > 6;
        } else if (name == "balls") {
            expected_ = "collide";
            const Token& what = arg(1, "the word collide");
            if (what.text != "collide") fail(what, fmt::format("unknown '{}' after 'balls' (collide)", shown(what.text)));
            if (scene_.balls_collide) fail(d, "duplicate 'balls collide'");
            no_more(2);
            scene_.balls_collide = true;
        } else if (name == "circle") {
            expected_ = "X Y R";
            count(scene_.circles.size(), k_max_entities, "circles");
            Circle c{{number(1, "X"), number(2, "Y")}, radius(3)};
            no_more(4);
            settle_domain();
            in_domain(1, c.c.x, false), in_domain(2, c.c.y, false), in_domain(3, c.r, false);
            scene_.circles.push_back(c);
        } else if (name == "bumper") {
            expected_ = "X Y R";
            count(scene_.bumpers.size(), k_max_entities, "bumpers");
            Bumper c{{number(1, "X"), number(2, "Y")}, radius(3)};
            no_more(4);
            settle_domain();
            in_domain(1, c.c.x, false), in_domain(2, c.c.y, false), in_domain(3, c.r, false);
            if (!first_bumper_) first_bumper_ = Place{line_, tokens_[0].col};
            scene_.bumpers.push_back(c);
        } else if (name == "rect") {
            expected_ = "LEFT BOTTOM RIGHT TOP";
            count(scene_.rects.size(), k_max_entities, "rects");
            Rect r{number(1, "LEFT"), number(2, "BOTTOM"), number(3, "RIGHT"), number(4, "TOP")};
            if (r.left > r.right)
                fail(tokens_[1], fmt::format("left {} is greater than right {}", shown(tokens_[1].text), shown(tokens_[3].text)));
            if (r.bottom > r.top)
                fail(tokens_[2], fmt::format("bottom {} is greater than top {}", shown(tokens_[2].text), shown(tokens_[4].text)));
            no_more(5);
            settle_domain();
            in_domain(1, r.left, false), in_domain(2, r.bottom, false), in_domain(3, r.right, false), in_domain(4, r.top, false);
            scene_.rects.push_back(r);
        } else if (name == "check") {
            expected_ = "a check name";
            const Token& t = arg(1, "check name");
            const auto c = parse_check(t.text);
            if (!c) {
                // Every name a log may use, from the one list of checks.
                std::string names;
                for (Check k : k_all_checks) names += fmt::format("{}{}", names.empty() ? "" : ", ", check_name(k));
                fail(t, fmt::format("unknown check '{}' ({})", shown(t.text), names));
            }
            for (Check have : scene_.checks)
                if (have == *c) fail(t, fmt::format("duplicate check '{}'", shown(t.text)));
            no_more(2);
            settle_domain();
            for (Check waived : waived_checks(scene_.domain))
                if (waived == *c)
                    fail(t, fmt::format("check '{}' is waived by the log's 'domain waive touching': its kernel does "
                                        "not promise that touching is a hit", shown(t.text)));
            scene_.checks.push_back(*c);
            check_places_.push_back({line_, t.col});
        } else if (name == "expect") {
            expected_ = "hash H, state F I X Y VX VY or failure CHECK F";
            const Token& what = arg(1, "what to expect");
            if (what.text == "hash") {
                expected_ = "16 lowercase hex digits";
                if (scene_.expect_hash) fail(what, "duplicate 'expect hash'");
                const Token& t = arg(2, "hash");
                const auto h = parse_hash(t.text);
                if (!h) fail(t, fmt::format("bad hash '{}': expected exactly 16 lowercase hex digits", shown(t.text)));
                no_more(3);
                scene_.expect_hash = *h;
            } else if (what.text == "state") {
                expected_ = "F I X Y VX VY";
                count(scene_.expect_states.size(), k_max_expect_states, "expect state lines");
                ExpectState e;
                e.frame = integer(2, "frame");
                if (e.frame < 0) fail(tokens_[2], fmt::format("negative frame {}", e.frame));
                const std::int64_t ball = integer(3, "ball index");
                if (ball < 0 || ball >= static_cast<std::int64_t>(k_max_entities))
                    fail(tokens_[3], fmt::format("ball index {} is out of range", ball));
                e.ball = static_cast<std::uint32_t>(ball);
                e.state = {{number(4, "X"), number(5, "Y")}, {number(6, "VX"), number(7, "VY")}};
                no_more(8);
                scene_.expect_states.push_back(e);
                state_places_.push_back({line_, tokens_[2].col, tokens_[3].col});
            } else if (what.text == "failure") {
                expected_ = "CHECK F";
                if (scene_.expect_failure) fail(what, "duplicate 'expect failure'");
                const Token& t = arg(2, "check name");
                const auto c = parse_check(t.text);
                if (!c) fail(t, fmt::format("unknown check '{}'", shown(t.text)));
                const std::int64_t f = integer(3, "frame");
                if (f < 0) fail(tokens_[3], fmt::format("negative frame {}", f));
                no_more(4);
                scene_.expect_failure = ExpectFailure{*c, f};
                failure_place_ = {line_, tokens_[2].col, tokens_[3].col};
            } else {
                fail(what, fmt::format("unknown expectation '{}' (hash, state or failure)", shown(what.text)));
            }
        } else if (name == "found") {
            expected_ = "CHECK F BALL";
            if (scene_.found) fail(d, "duplicate 'found'");
            const Token& t = arg(1, "check name");
            const auto c = parse_check(t.text);
            if (!c) fail(t, fmt::format("unknown check '{}'", shown(t.text)));
            const std::int64_t f = integer(2, "frame");
            if (f < 0) fail(tokens_[2], fmt::format("negative frame {}", f));
            const std::int64_t ball = integer(3, "ball index");
            if (ball < 0 || ball >= static_cast<std::int64_t>(k_max_entities))
                fail(tokens_[3], fmt::format("ball index {} is out of range", ball));
            no_more(4);
            scene_.found = Found{*c, f, static_cast<std::uint32_t>(ball)};
            found_place_ = {line_, tokens_[1].col, tokens_[2].col, tokens_[3].col};
        } else if (name == "domain") {
            domain_line();
        } else if (name == "from") {
            expected_ = "provenance words";
            arg(1, "provenance");
            if (scene_.provenance.size() >= k_max_provenance)
                fail(d, fmt::format("too many 'from' lines: the limit is {}", k_max_provenance));
            // The words verbatim, joined by single spaces.
            std::string words;
            for (std::size_t i = 1; i < tokens_.size(); ++i) {
                if (i > 1) words += ' ';
                words += tokens_[i].text;
            }
            scene_.provenance.push_back(std::move(words));
        } else {
            fail(d, fmt::format("unknown directive '{}'", shown(name)));
        }
    }

    /// Checks that need the whole log, in the spec's order: expect lines must name balls and frames the scene
    /// has, and the failure's check must be one the log asks for; so must `found`. The expect lines' checks
    /// are left out when they are to be replaced (record writes new ones).
    void validate() {
        if (expect_lines_ == ExpectLines::checked) validate_expect_states();
        validate_found();
        if (expect_lines_ == ExpectLines::checked) validate_expect_failure();
    }

    void validate_expect_states() {
        for (std::size_t i = 0; i < scene_.expect_states.size(); ++i) {
            const ExpectState& e = scene_.expect_states[i];
            const Place& p = state_places_[i];
            if (e.frame > scene_.frames)
                throw ParseError{p.line, p.col_a, fmt::format("expect state at frame {} but the log runs {} frames",
                                                              e.frame, scene_.frames)};
            if (e.ball >= scene_.balls.size())
                throw ParseError{p.line, p.col_b, fmt::format("expect state for ball {} but the log has {} balls",
                                                              e.ball, scene_.balls.size())};
        }
    }

    void validate_found() {
        if (scene_.found) {
            const Found& f = *scene_.found;
            const Place& p = found_place_;
            if (std::find(scene_.checks.begin(), scene_.checks.end(), f.check) == scene_.checks.end())
                throw ParseError{p.line, p.col_a,
                                 fmt::format("found a failure of '{}' but the log has no 'check {}'", f.check, f.check)};
            if (f.frame > scene_.frames)
                throw ParseError{p.line, p.col_b, fmt::format("found a failure at frame {} but the log runs {} frames",
                                                              f.frame, scene_.frames)};
            // A failure always names a ball: ball 0 in a log without balls (a static shape against another).
            if (f.ball >= std::max<std::size_t>(scene_.balls.size(), 1))
                throw ParseError{p.line, p.col_c, fmt::format("found a failure for ball {} but the log has {} balls",
                                                              f.ball, scene_.balls.size())};
        }
    }

    void validate_expect_failure() {
        if (scene_.expect_failure) {
            const ExpectFailure& f = *scene_.expect_failure;
            bool listed = false;
            for (Check c : scene_.checks) listed = listed || c == f.check;
            if (!listed)
                throw ParseError{failure_place_.line, failure_place_.col_a,
                                 fmt::format("expect failure of '{}' but the log has no 'check {}'", f.check,
                                             f.check)};
            if (f.frame > scene_.frames)
                throw ParseError{failure_place_.line, failure_place_.col_b,
                                 fmt::format("expect failure at frame {} but the log runs {} frames", f.frame,
                                             scene_.frames)};
        }
    }

    struct Place {
        int line = 0;
        int col_a = 0;
        int col_b = 0;
        int col_c = 0;
    };

    std::string_view text_;
    Scene scene_;
    std::vector<double> masses_;  // every ball's mass so far, 1 where its line gives none
    bool any_mass_ = false;       // some ball line gave a mass: the scene gets masses_
    std::vector<Token> tokens_;
    std::vector<Place> state_places_;
    std::vector<Place> check_places_;    // each `check` line's name token, in scene_.checks' order
    std::optional<Place> first_disc_;    // the first ball with a radius > 0: its R token
    std::optional<Place> first_bumper_;  // the first bumper line
    Place failure_place_;
    Place found_place_;
    std::string_view expected_;
    ExpectLines expect_lines_;
    int line_ = 0;
    int end_col_ = 1;
    bool seen_header_ = false;
    bool seen_kernel_ = false;
    bool seen_frames_ = false;
    bool seen_entity_ = false;  // a wall, ball, circle, rect, bumper or check line: no `domain` line after it
};

}  // namespace

SceneOrDiagnostic parse_scene_log(std::string_view text, std::string_view filename, ExpectLines expect_lines) {
    try {
        return Parser(text, expect_lines).parse();
    } catch (const ParseError& e) {
        return Diagnostic{std::string(filename), e.line, e.col, e.message};
    }
}

namespace {

void write_body(std::string& out, const Scene& s, bool with_provenance_and_expect) {
    auto it = std::back_inserter(out);
    out += "ricochet 1\n";
    if (with_provenance_and_expect)
        for (const std::string& p : s.provenance) fmt::format_to(it, "from {}\n", p);
    fmt::format_to(it, "kernel {}\n", s.kernel);
    fmt::format_to(it, "frames {}\n", s.frames);
    const Domain& d = s.domain;
    if (d.coordinates) fmt::format_to(it, "domain coordinates {}\n", *d.coordinates);
    if (d.speed) fmt::format_to(it, "domain speed {}\n", *d.speed);
    if (d.wall_length) fmt::format_to(it, "domain wall-length {}\n", *d.wall_length);
    if (d.no_subnormals) out += "domain no-subnormals\n";
    if (d.waive_touching) out += "domain waive touching\n";
    if (s.balls_collide) out += "balls collide\n";
    for (const Wall& w : s.walls) fmt::format_to(it, "wall {}\n", w);
    if (s.masses.empty()) {
        for (const Ball& b : s.balls) fmt::format_to(it, "ball {}\n", b);
    } else {
        // With masses every ball line gives R (+0 too: M is the sixth number) and M.
        for (std::size_t i = 0; i < s.balls.size(); ++i) {
            const Ball& b = s.balls[i];
            // A guard: a Scene keeps one mass per ball; one that lost count writes the default for the rest.
            const double m = i < s.masses.size() ? s.masses[i] : 1.0;
            fmt::format_to(it, "ball {} {} {} {} {} {}\n", b.pos.x, b.pos.y, b.vel.x, b.vel.y, b.r, m);
        }
    }
    for (const Circle& c : s.circles) fmt::format_to(it, "circle {}\n", c);
    for (const Rect& r : s.rects) fmt::format_to(it, "rect {}\n", r);
    for (const Bumper& b : s.bumpers) fmt::format_to(it, "bumper {}\n", b);
    for (Check c : s.checks) fmt::format_to(it, "check {}\n", c);
    if (!with_provenance_and_expect) return;
    if (s.found) fmt::format_to(it, "found {} {} {}\n", s.found->check, s.found->frame, s.found->ball);
    if (s.expect_hash) fmt::format_to(it, "expect hash {}\n", format_hash(*s.expect_hash));
    if (s.expect_failure)
        fmt::format_to(it, "expect failure {} {}\n", s.expect_failure->check, s.expect_failure->frame);
    for (const ExpectState& e : s.expect_states) fmt::format_to(it, "expect state {} {} {}\n", e.frame, e.ball, e.state);
}

}  // namespace

std::string write_scene_log(const Scene& scene) {
    std::string out;
    write_body(out, scene, true);
    return out;
}

std::string scene_content_id(const Scene& scene) {
    std::string text;
    write_body(text, scene, false);
    return format_hash(XXH64(text.data(), text.size(), 0));
}

bool same_bits(const Scene& a, const Scene& b) {
    if (!(a == b)) return false;
    const auto all = [](const auto& x, const auto& y) {
        for (std::size_t i = 0; i < x.size(); ++i)
            if (!same_bits(x[i], y[i])) return false;
        return true;
    };
    if (!all(a.walls, b.walls) || !all(a.balls, b.balls) || !all(a.circles, b.circles) || !all(a.rects, b.rects) ||
        !all(a.bumpers, b.bumpers))
        return false;
    for (std::size_t i = 0; i < a.masses.size(); ++i)
        if (!same_bits(a.masses[i], b.masses[i])) return false;
    for (std::size_t i = 0; i < a.expect_states.size(); ++i)
        if (!same_bits(a.expect_states[i].state, b.expect_states[i].state)) return false;
    return true;
}

}  // namespace ricochet
