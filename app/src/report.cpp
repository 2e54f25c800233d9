// The JUnit and SARIF reports (ricochet_app/report.hpp).
#include "ricochet_app/report.hpp"

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <system_error>

#include <fmt/format.h>
#include <nlohmann/json.hpp>
#ifndef RICOCHET_NO_JUNIT
#include <pugixml.hpp>
#endif

#include "ricochet_app/json.hpp"
#include "ricochet_app/project.hpp"

namespace ricochet::app {

namespace fs = std::filesystem;

namespace {

using Json = nlohmann::ordered_json;

/// The schema a SARIF log names: the OASIS 2.1.0 schema (errata 01), the one docs/schemas/ holds.
constexpr std::string_view k_sarif_schema =
    "https://docs.oasis-open.org/sarif/sarif/v2.1.0/errata01/os/schemas/sarif-schema-2.1.0.json";

/// The base the logs' URIs are relative to (SARIF's originalUriBaseIds).
constexpr std::string_view k_project_base = "PROJECTROOT";

/// What a rule that is not a check stands for (a failure with no check to name).
const std::map<std::string, std::string, std::less<>>& rule_descriptions() {
    static const std::map<std::string, std::string, std::less<>> m = {
        {"expect", "an expect line of the log did not hold (a hash, a state, an expected failure)"},
        {"unreadable", "the log could not be read (a syntax error, a file that cannot be opened)"},
        {"missing", "a path given does not exist"},
        {"over-budget", "the log is over --max-work and was not run"},
        {"unsupported", "the log's kernel cannot step its discs or bumpers"},
        {"property", "a property of the suite failed"},
        {"fuzz", "a fuzz target failed (a sanitizer report, a crash, a hang, a failure not converted yet)"},
        {"error", "the stage could not run"},
    };
    return m;
}

/// The fields of a `found` or `expect failure` line after its directive: CHECK FRAME [BALL].
void read_mark_fields(std::istringstream& in, LogMark& mark) {
    std::int64_t n = 0;
    in >> mark.check;
    if (in >> n) mark.frame = n;
    if (in >> n) mark.ball = n;
}

/// A path as a URI reference: its bytes percent-encoded but for RFC 3986's unreserved characters and `/`.
std::string uri_path(const std::string& path) {
    std::string out;
    for (const char ch : path) {
        const auto c = static_cast<unsigned char>(ch);
        if ((c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '.' || c == '_' ||
            c == '~' || c == '/')
            out += ch;
        else
            out += fmt::format("%{:02X}", c);
    }
    return out;
}

/// A folder as an absolute file URI, ended by `/` (as originalUriBaseIds wants it).
std::string folder_uri(const fs::path& dir) {
    std::string p = dir.generic_string();
    if (p.empty() || p.back() != '/') p += '/';
    return "file://" + uri_path(p);
}

/// path absolute with its links resolved as far as it exists (so that a log and the project compare alike).
fs::path resolved(const fs::path& path) {
    std::error_code ec;
    fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
    return ec ? fs::absolute(path, ec) : p;
}

/// A SARIF artifactLocation for log: relative to the project base where it lies inside the project, else an
/// absolute file URI.
Json artifact_location(const std::string& log, const fs::path& project_abs) {
    const fs::path abs = resolved(log);
    const fs::path rel = abs.lexically_relative(project_abs);
    if (!rel.empty() && *rel.begin() != "..")
        return Json{{"uri", uri_path(rel.generic_string())}, {"uriBaseId", k_project_base}};
    return Json{{"uri", "file://" + uri_path(abs.generic_string())}};
}

#ifndef RICOCHET_NO_JUNIT
/// A time as the XSD's SUREFIRE_TIME takes it: digits, a point, three decimals.
std::string junit_time(double s) { return fmt::format("{:.3f}", s > 0 ? s : 0.0); }

/// Adds name=value to node, as valid UTF-8 on one line: a line end or tab becomes a space (the XML writer leaves
/// out control characters, which would run two words into one).
void attr(pugi::xml_node node, const char* name, std::string_view value) {
    std::string v = valid_utf8(value);
    for (char& c : v)
        if (c == '\n' || c == '\r' || c == '\t') c = ' ';
    node.append_attribute(name).set_value(v.c_str());
}

/// The counts a <testsuite> and <testsuites> carry.
struct Counts {
    int tests = 0, failures = 0, errors = 0, skipped = 0;
    double seconds = 0;
    void add(const Counts& c) {
        tests += c.tests, failures += c.failures, errors += c.errors, skipped += c.skipped;
        seconds += c.seconds;
    }
};

void set_counts(pugi::xml_node node, const Counts& c, bool with_skipped) {
    attr(node, "tests", std::to_string(c.tests));
    attr(node, "failures", std::to_string(c.failures));
    attr(node, "errors", std::to_string(c.errors));
    if (with_skipped) attr(node, "skipped", std::to_string(c.skipped));
    attr(node, "time", junit_time(c.seconds));
}

/// The counts of a <testsuite> element (another report's, taken in whole).
Counts counts_of(pugi::xml_node suite) {
    return {suite.attribute("tests").as_int(), suite.attribute("failures").as_int(), suite.attribute("errors").as_int(),
            suite.attribute("skipped").as_int(), suite.attribute("time").as_double()};
}

/// The line of a GoogleTest failure message that says what failed: the message is `FILE:LINE`, `Failed`, then
/// the assertion's own text.
std::string gtest_summary(std::string_view message) {
    for (std::size_t at = 0; at < message.size();) {
        const std::size_t end = std::min(message.find('\n', at), message.size());
        const std::string_view line = message.substr(at, end - at);
        at = end + 1;
        const std::size_t colon = line.rfind(':');
        const bool file_line = colon != std::string_view::npos && colon + 1 < line.size() &&
                               line.find_first_not_of("0123456789", colon + 1) == std::string_view::npos;
        if (!line.empty() && line != "Failed" && !file_line) return std::string(line);
    }
    return std::string(message);
}

/// Writes one case into suite and returns its counts.
Counts write_case(pugi::xml_node suite, const TestCase& c) {
    using O = TestCase::Outcome;
    pugi::xml_node node = suite.append_child("testcase");
    attr(node, "name", c.name);
    attr(node, "classname", c.classname);
    attr(node, "time", junit_time(c.seconds));
    Counts n;
    n.tests = 1;
    n.seconds = c.seconds;
    if (c.outcome == O::skipped) {
        attr(node.append_child("skipped"), "message", c.message);
        n.skipped = 1;
    } else if (c.outcome == O::error) {
        pugi::xml_node e = node.append_child("error");
        attr(e, "message", c.message);
        for (const Finding& f : c.findings) e.append_child(pugi::node_pcdata).set_value(valid_utf8(finding_text(f) + "\n").c_str());
        n.errors = 1;
    } else if (c.outcome == O::failed) {
        // Every finding a <failure>: a fuzz target that failed three ways says all three.
        for (const Finding& f : c.findings) {
            pugi::xml_node e = node.append_child("failure");
            attr(e, "type", f.rule);
            attr(e, "message", finding_text(f));
            if (!f.detail.empty()) e.append_child(pugi::node_pcdata).set_value(valid_utf8(f.detail).c_str());
        }
        if (c.findings.empty()) attr(node.append_child("failure"), "message", c.message);
        n.failures = 1;
    }
    return n;
}
#endif

}  // namespace

std::string finding_text(const Finding& f) {
    std::string out = f.rule.empty() ? std::string("failed") : f.rule;
    if (f.frame || f.ball) out += " broke";
    if (f.frame) out += fmt::format(" at frame {}", *f.frame);
    if (f.ball) out += fmt::format(" ball {}", *f.ball);
    if (!f.detail.empty()) out += ": " + f.detail;
    if (!f.log.empty()) out += fmt::format(" (log {})", f.log);
    return out;
}

LogMark read_log_mark(const fs::path& log, std::string_view rule) {
    LogMark mark, expect;
    std::ifstream in(log);
    int n = 0;
    for (std::string line; std::getline(in, line);) {
        ++n;
        std::istringstream words(line);
        std::string directive, word;
        words >> directive;
        if (directive == "found") {
            read_mark_fields(words, mark);
            mark.line = n;
            return mark;
        }
        if (directive == "expect" && expect.check.empty() && words >> word && word == "failure") {
            read_mark_fields(words, expect);
            expect.line = n;
        } else if (directive == "check" && expect.check.empty() && expect.line == 1 && !rule.empty() && words >> word &&
                   word == rule) {
            expect.line = n;
        }
    }
    return expect;
}

Finding finding_of_log(const fs::path& log) {
    const LogMark m = read_log_mark(log);
    return {m.check.empty() ? std::string("property") : m.check, m.frame, m.ball, log.string(), m.line, std::nullopt, {}};
}

std::string junit_xml(const Report& report) {
#ifdef RICOCHET_NO_JUNIT
    (void)report;
    return {};
#else
    pugi::xml_document doc;
    pugi::xml_node decl = doc.append_child(pugi::node_declaration);
    decl.append_attribute("version") = "1.0";
    decl.append_attribute("encoding") = "UTF-8";
    pugi::xml_node root = doc.append_child("testsuites");
    attr(root, "name", report.name);
    Counts all;
    for (const TestSuite& s : report.suites) {
        pugi::xml_node suite = root.append_child("testsuite");
        attr(suite, "name", s.name);
        Counts n;
        for (const TestCase& c : s.cases) n.add(write_case(suite, c));
        n.seconds = s.seconds;
        set_counts(suite, n, true);
        all.add(n);
    }
    for (const std::string& part : report.junit_parts) {
        pugi::xml_document other;
        if (!other.load_string(part.c_str())) continue;
        for (pugi::xml_node suite : other.child("testsuites").children("testsuite")) {
            all.add(counts_of(suite));
            root.append_copy(suite);
        }
    }
    all.seconds = report.seconds;
    set_counts(root, all, false);
    std::ostringstream out;
    // Control characters other than tab and newline cannot be in an XML 1.0 document, escaped or not.
    doc.save(out, "  ", pugi::format_default | pugi::format_skip_control_chars, pugi::encoding_utf8);
    return out.str();
#endif
}

std::string sarif_json(const Report& report, const fs::path& project) {
    const fs::path project_abs = resolved(project);
    Json rules = Json::array();
    std::map<std::string, bool, std::less<>> listed;
    const auto add_rule = [&](const std::string& id, const Json& rule) {
        if (listed.emplace(id, true).second) rules.push_back(rule);
    };
    Json results = Json::array();
    for (const TestSuite& s : report.suites)
        for (const TestCase& c : s.cases) {
            if (c.outcome != TestCase::Outcome::failed && c.outcome != TestCase::Outcome::error) continue;
            for (const Finding& f : c.findings) {
                const auto known = rule_descriptions().find(f.rule);
                add_rule(f.rule, Json{{"id", f.rule},
                                      {"shortDescription",
                                       {{"text", known != rule_descriptions().end()
                                                     ? known->second
                                                     : fmt::format("the check {} broke (a ricochet invariant)", f.rule)}}}});
                Json result = {{"ruleId", f.rule}, {"level", "error"}, {"message", {{"text", finding_text(f)}}}};
                if (!f.log.empty()) {
                    Json region = {{"startLine", f.line ? *f.line : read_log_mark(f.log, f.rule).line}};
                    if (f.column) region["startColumn"] = *f.column;
                    result["locations"] = Json::array(
                        {{{"physicalLocation", {{"artifactLocation", artifact_location(f.log, project_abs)}, {"region", region}}}}});
                }
                result["properties"] = {{"testcase", c.name}, {"classname", c.classname}};
                if (f.frame) result["properties"]["frame"] = *f.frame;
                if (f.ball) result["properties"]["ball"] = *f.ball;
                results.push_back(std::move(result));
            }
        }
    // Another report's (a campaign's, run by `check`): its rules and results as they are.
    for (const std::string& part : report.sarif_parts) {
        const Json other = Json::parse(part, nullptr, false);
        if (other.is_discarded() || !other.contains("runs") || other["runs"].empty()) continue;
        const Json& run = other["runs"][0];
        for (const Json& rule : run["tool"]["driver"].value("rules", Json::array())) add_rule(rule.value("id", ""), rule);
        for (const Json& result : run.value("results", Json::array())) results.push_back(result);
    }
    Json sarif = {{"$schema", k_sarif_schema},
                  {"version", "2.1.0"},
                  {"runs", Json::array({{{"tool", {{"driver", {{"name", "ricochet"}, {"rules", rules}}}}},
                                         {"originalUriBaseIds", {{k_project_base, {{"uri", folder_uri(project_abs)}}}}},
                                         {"results", results}}})}};
    return sarif.dump(2, ' ', true, Json::error_handler_t::replace) + "\n";
}

std::vector<TestSuite> read_gtest_xml(const std::string& text) {
    std::vector<TestSuite> out;
#ifdef RICOCHET_NO_JUNIT
    (void)text;
#else
    pugi::xml_document doc;
    if (!doc.load_string(text.c_str())) return out;
    for (pugi::xml_node suite : doc.child("testsuites").children("testsuite")) {
        TestSuite s{suite.attribute("name").value(), suite.attribute("time").as_double(), {}};
        for (pugi::xml_node test : suite.children("testcase")) {
            TestCase c{test.attribute("classname").value(), test.attribute("name").value(), test.attribute("time").as_double(),
                       TestCase::Outcome::passed, {}, {}};
            for (pugi::xml_node failure : test.children("failure")) {
                c.outcome = TestCase::Outcome::failed;
                c.findings.push_back({"property", {}, {}, {}, {}, {}, gtest_summary(failure.attribute("message").value())});
            }
            if (c.outcome == TestCase::Outcome::passed &&
                (test.child("skipped") || std::string_view(test.attribute("result").value()) == "skipped" ||
                 std::string_view(test.attribute("status").value()) == "notrun")) {
                c.outcome = TestCase::Outcome::skipped;
                c.message = test.child("skipped").attribute("message").value();
            }
            s.cases.push_back(std::move(c));
        }
        out.push_back(std::move(s));
    }
#endif
    return out;
}

std::string report_files_problem(const ReportFiles& files) {
    for (const std::string& path : {files.junit, files.sarif}) {
        std::error_code ec;
        if (path.empty()) continue;
        fs::path dir = fs::path(path).parent_path();
        if (dir.empty()) dir = ".";
        if (fs::is_directory(path, ec)) return fmt::format("cannot write {}: it is a folder", path);
        if (!fs::is_directory(dir, ec)) return fmt::format("cannot write {}: no such folder: {}", path, dir.string());
    }
    return {};
}

bool write_reports(const Report& report, const ReportFiles& files, WriteFile write, std::string* error) {
    const auto one = [&](const std::string& path, const std::string& text) {
        if (path.empty()) return true;
        std::string why;
        if (write(path, text, &why)) return true;
        // The writer's message names the file first: said once.
        if (why.starts_with(path + ": ")) why.erase(0, path.size() + 2);
        if (error) *error = fmt::format("cannot write {}: {}", path, why);
        return false;
    };
#ifdef RICOCHET_NO_JUNIT
    if (!files.junit.empty()) {
        if (error) *error = fmt::format("cannot write {}: JUnit reports are not in this build (no pugixml for wasm32)", files.junit);
        return false;
    }
#endif
    std::error_code ec;
    const fs::path here = fs::current_path(ec);
    const fs::path project = here / find_project_root(here).value_or(".");
    return one(files.junit, junit_xml(report)) && one(files.sarif, files.sarif.empty() ? std::string() : sarif_json(report, project));
}

}  // namespace ricochet::app
