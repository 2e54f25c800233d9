// The directive rules of the independent acceptor (acceptor.hpp): docs/scene-log.md's "Directives",
// "Limits", "Order and repetition" and "Diagnostics", over the tokens and numbers of lexical.hpp.
#include "acceptor.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

#include "lexical.hpp"
#include "wall_length.hpp"

namespace ricochet_grammar {
namespace {

constexpr std::size_t k_entity_limit = 100'000;
constexpr std::size_t k_expect_state_limit = 1'000'000;
constexpr std::size_t k_from_limit = 64;
constexpr std::int64_t k_frame_limit = 10'000'000;

constexpr std::array<std::string_view, 4> k_kernels = {"lecture-float", "lecture-double", "robust", "exact"};
constexpr std::array<std::string_view, 22> k_checks = {
    "no-tunnel",   "symmetry",    "boundary",   "speed",     "deterministic", "oracle",   "swap",       "translation",
    "broad-phase", "round-trip",  "no-escape",  "bounce-side", "accuracy",    "event-order", "penetration",
    "ghost-bounce", "plan",       "ball-overlap", "pass-through", "momentum", "relabel", "jump-through"};

template <std::size_t N>
bool one_of(const std::array<std::string_view, N>& names, std::string_view s) {
    return std::find(names.begin(), names.end(), s) != names.end();
}

/// The first error found: its line and why.
struct Rejection {
    int line;
    std::string reason;
};

/// An `expect state`, `expect failure` or `found` line, kept for the checks that need the whole log.
struct Reference {
    int line = 0;
    std::string_view check;
    std::int64_t frame = 0;
    std::int64_t ball = 0;
};

class Acceptor {
public:
    void run(std::string_view text) {
        if (text.size() > k_file_limit) throw Rejection{1, "file over the limit of 16 MiB"};
        // "Lexical rules": no byte order mark at the start (U+FEFF elsewhere is bytes like any other).
        if (text.starts_with("\xEF\xBB\xBF")) throw Rejection{1, "a byte order mark"};
        std::size_t pos = 0;
        Tokens tokens;
        while (pos < text.size()) {
            std::size_t end = text.find('\n', pos);
            if (end == std::string_view::npos) end = text.size();
            ++line_;
            if (std::string why = tokenize(text.substr(pos, end - pos), tokens); !why.empty()) reject(why);
            // "Lexical rules": a comment holds no CR but as its last character (a CRLF line end's).
            const std::string_view l = text.substr(pos, end - pos);
            if (const std::size_t hash = l.find('#'); hash != std::string_view::npos) {
                const std::size_t cr = l.find('\r', hash);
                if (cr != std::string_view::npos && cr + 1 < l.size()) reject("a carriage return inside a comment");
            }
            if (!tokens.empty()) directive(tokens);
            pos = end + 1;
        }
        if (!header_) throw Rejection{1, "empty log: no header"};
        whole_log();
    }

private:
    [[noreturn]] void reject(std::string why) const { throw Rejection{line_, std::move(why)}; }

    // Exactly n arguments after the directive (and its sub-word, for `expect`).
    void arity(const Tokens& t, std::size_t n) const {
        if (t.size() < n + 1) reject("'" + std::string(t[0]) + "': an argument is missing");
        if (t.size() > n + 1) reject("'" + std::string(t[0]) + "': an extra argument");
    }
    double number(std::string_view token) const {
        Number n = read_number(token);
        if (!n.error.empty()) reject(n.error);
        return n.value;
    }
    std::int64_t integer(std::string_view token) const {
        Integer n = read_integer(token);
        if (!n.error.empty()) reject(n.error);
        return n.value;
    }
    void numbers(const Tokens& t, std::size_t n) const {
        arity(t, n);
        for (std::size_t i = 1; i <= n; ++i) number(t[i]);
    }
    void entity(std::size_t& count, std::string_view kind) const {
        if (++count > k_entity_limit) reject("more than 100000 " + std::string(kind));
    }
    std::string_view check_name(std::string_view s) const {
        if (!one_of(k_checks, s)) reject("unknown check '" + std::string(s) + "'");
        return s;
    }
    // A ball index ≥ the entity limit can name no ball: an error on its own line.
    std::int64_t ball_index(std::string_view token) const {
        const std::int64_t b = integer(token);
        if (b >= static_cast<std::int64_t>(k_entity_limit)) reject("ball index over the entity limit");
        return b;
    }
    void hash(std::string_view h) const {
        const auto digit = [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); };
        if (h.size() != 16 || !std::all_of(h.begin(), h.end(), digit)) reject("hash is not 16 lowercase hex digits");
    }

    void directive(const Tokens& t) {
        const std::string_view d = t[0];
        if (!header_) {
            if (d != "ricochet") reject("the header must come first");
            arity(t, 1);
            if (t[1] != "1") reject("format version other than 1");
            header_ = true;
        } else if (d == "ricochet") {
            reject("duplicate header");
        } else if (d == "kernel") {
            once(kernel_, "kernel");
            arity(t, 1);
            if (!one_of(k_kernels, t[1])) reject("unknown kernel");
        } else if (d == "frames") {
            once(frames_seen_, "frames");
            arity(t, 1);
            frames_ = integer(t[1]);
            if (frames_ > k_frame_limit) reject("frames over the limit");
        } else if (d == "domain") {
            domain(t);
        } else if (d == "wall") {
            entity(walls_, "walls");
            numbers(t, 4);
            for (std::size_t i = 1; i <= 4; ++i) in_domain(t[i], false);
            if (wall_length_ && !wall_at_least(number(t[1]), number(t[2]), number(t[3]), number(t[4]), *wall_length_))
                reject("a wall shorter than the domain's wall-length");
        } else if (d == "ball") {
            entity(balls_, "balls");
            // "Discs and bumpers": X Y VX VY and an optional radius R ≥ 0; R > 0 makes the ball a disc.
            // "Balls that meet": then an optional mass M, 2^−256 ≤ M ≤ 2^256, which no domain line bounds.
            if (t.size() >= 6) {
                numbers(t, t.size() == 7 ? 6 : 5);
                if (number(t[5]) < 0.0) reject("negative radius");
                in_domain(t[5], false);
                if (t.size() == 7 && !(number(t[6]) >= 0x1p-256 && number(t[6]) <= 0x1p256))
                    reject("a mass outside [2^-256, 2^256]");
            } else {
                numbers(t, 4);
            }
            in_domain(t[1], false), in_domain(t[2], false), in_domain(t[3], true), in_domain(t[4], true);
        } else if (d == "balls") {
            // "Balls that meet": exactly `balls collide`, once.
            if (t.size() < 2) reject("'balls': the word collide is missing");
            if (t[1] != "collide") reject("'balls' takes only 'collide'");
            once(balls_collide_, "balls collide");
            arity(t, 1);
        } else if (d == "circle") {
            entity(circles_, "circles");
            numbers(t, 3);
            // −0 is zero; any other negative radius is an error.
            if (number(t[3]) < 0.0) reject("negative radius");
            for (std::size_t i = 1; i <= 3; ++i) in_domain(t[i], false);
        } else if (d == "bumper") {
            entity(bumpers_, "bumpers");
            numbers(t, 3);
            if (number(t[3]) < 0.0) reject("negative radius");
            for (std::size_t i = 1; i <= 3; ++i) in_domain(t[i], false);
        } else if (d == "rect") {
            entity(rects_, "rects");
            numbers(t, 4);
            if (number(t[1]) > number(t[3])) reject("LEFT greater than RIGHT");
            if (number(t[2]) > number(t[4])) reject("BOTTOM greater than TOP");
            for (std::size_t i = 1; i <= 4; ++i) in_domain(t[i], false);
        } else if (d == "check") {
            arity(t, 1);
            const std::string_view c = check_name(t[1]);
            if (one_of_listed(c)) reject("check listed twice");
            // "Domain": `waive touching` switches off boundary and oracle, and a log may not name them.
            if (waive_touching_ && (c == "boundary" || c == "oracle")) reject("a check the domain waives");
            after_domain_ = true;
            checks_.push_back(c);
            check_lines_.push_back(line_);
        } else if (d == "expect") {
            expect(t);
        } else if (d == "found") {
            once(found_seen_, "found");
            arity(t, 3);
            found_ = Reference{line_, check_name(t[1]), integer(t[2]), ball_index(t[3])};
        } else if (d == "from") {
            if (t.size() < 2) reject("'from' needs a word");
            if (++froms_ > k_from_limit) reject("more than 64 'from' lines");
        } else {
            reject("unknown directive '" + std::string(d) + "'");
        }
    }

    // "Domain": `domain coordinates C`, `speed V`, `wall-length L` (C, V, L > 0), `no-subnormals`, `waive touching`,
    // each once, before the first wall, ball, circle, rect, bumper and check.
    void domain(const Tokens& t) {
        if (after_domain_) reject("'domain' after an entity or a check");
        if (t.size() < 2) reject("'domain': what it bounds is missing");
        const std::string_view what = t[1];
        const auto bound = [&](std::optional<double>& out) {
            if (out) reject("duplicate 'domain " + std::string(what) + "'");
            arity(t, 2);
            const double x = number(t[2]);
            if (!(x > 0.0)) reject("a domain bound not above 0");
            out = x;
        };
        if (what == "coordinates") {
            bound(coordinates_);
        } else if (what == "speed") {
            bound(speed_);
        } else if (what == "wall-length") {
            bound(wall_length_);
        } else if (what == "no-subnormals") {
            once(no_subnormals_, "domain no-subnormals");
            arity(t, 1);
        } else if (what == "waive") {
            arity(t, 2);
            if (t[2] != "touching") reject("unknown convention");
            once(waive_touching_, "domain waive touching");
        } else {
            reject("unknown domain '" + std::string(what) + "'");
        }
    }
    // An entity's number against the domain: a coordinate or radius (or, speed, a velocity component) within its
    // bound, and not subnormal under no-subnormals. The entity's line settles the domain.
    void in_domain(std::string_view token, bool speed) {
        after_domain_ = true;
        const double x = number(token);
        const std::optional<double>& b = speed ? speed_ : coordinates_;
        if (b && !(std::fabs(x) <= *b)) reject("a number outside the domain");
        if (no_subnormals_ && x != 0.0 && std::fabs(x) < 0x1p-1022) reject("a subnormal number in the domain");
    }

    void expect(const Tokens& t) {
        if (t.size() < 2) reject("'expect': what to expect is missing");
        const std::string_view what = t[1];
        if (what == "hash") {
            once(hash_seen_, "expect hash");
            arity(t, 2);
            hash(t[2]);
        } else if (what == "state") {
            if (++states_seen_ > k_expect_state_limit) reject("more than 1000000 'expect state' lines");
            arity(t, 7);
            Reference r{line_, {}, integer(t[2]), ball_index(t[3])};
            for (std::size_t i = 4; i <= 7; ++i) number(t[i]);
            states_.push_back(r);
        } else if (what == "failure") {
            once(failure_seen_, "expect failure");
            arity(t, 3);
            failure_ = Reference{line_, check_name(t[2]), integer(t[3]), 0};
        } else {
            reject("unknown expectation '" + std::string(what) + "'");
        }
    }

    void once(bool& seen, std::string_view what) const {
        if (seen) reject("duplicate '" + std::string(what) + "'");
        seen = true;
    }
    bool one_of_listed(std::string_view c) const { return std::find(checks_.begin(), checks_.end(), c) != checks_.end(); }

    // The checks that need the whole log, in the order the spec gives (Diagnostics): every `expect state`
    // in order (its frame, then its ball), then `found`, then `expect failure`.
    void whole_log() const {
        for (const Reference& s : states_) {
            if (s.frame > frames_) throw Rejection{s.line, "expect state after the last frame"};
            if (s.ball >= static_cast<std::int64_t>(balls_)) throw Rejection{s.line, "expect state of a missing ball"};
        }
        if (found_) {
            if (!one_of_listed(found_->check)) throw Rejection{found_->line, "found: the check is not listed"};
            if (found_->frame > frames_) throw Rejection{found_->line, "found: after the last frame"};
            if (found_->ball >= static_cast<std::int64_t>(std::max<std::size_t>(balls_, 1)))
                throw Rejection{found_->line, "found: a missing ball"};
        }
        if (failure_) {
            if (!one_of_listed(failure_->check)) throw Rejection{failure_->line, "expect failure: the check is not listed"};
            if (failure_->frame > frames_) throw Rejection{failure_->line, "expect failure: after the last frame"};
        }
    }

    int line_ = 0;
    bool header_ = false, kernel_ = false, frames_seen_ = false, hash_seen_ = false, failure_seen_ = false,
         found_seen_ = false, balls_collide_ = false;
    std::int64_t frames_ = 0;
    std::size_t walls_ = 0, balls_ = 0, circles_ = 0, rects_ = 0, bumpers_ = 0, froms_ = 0, states_seen_ = 0;
    std::vector<std::string_view> checks_;
    std::vector<int> check_lines_;
    std::vector<Reference> states_;
    std::optional<Reference> found_, failure_;
    bool after_domain_ = false, no_subnormals_ = false, waive_touching_ = false;
    std::optional<double> coordinates_, speed_, wall_length_;
};

}  // namespace

Verdict accept_scene_log(std::string_view text) {
    try {
        Acceptor().run(text);
        return {true, 0, {}};
    } catch (const Rejection& r) {
        return {false, r.line, r.reason};
    }
}

}  // namespace ricochet_grammar
