// The reports CI reads (docs/cli-reports.md): JUnit XML (`--junit FILE`, through pugixml) and SARIF 2.1.0
// (`--sarif FILE`, through nlohmann-json), both made from one model of what a command ran: suites of test
// cases, each failure naming its check, frame, ball and the log that replays it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ricochet::app {

/// One failure as the reports name it: the check that broke, where, and the saved log that replays it.
struct Finding {
    std::string rule;                   ///< the check's name (SARIF's ruleId), or what went wrong (`expect`, `unreadable`)
    std::optional<std::int64_t> frame;  ///< the first frame it broke in
    std::optional<std::int64_t> ball;   ///< the ball it broke for
    std::string log;                    ///< the log that replays it, as the command names it; empty if none
    /// The log's line and column that matter (a diagnostic's place); unset: its `found` or `expect failure`
    /// line (read_log_mark), else line 1.
    std::optional<int> line, column;
    std::string detail;                 ///< the rest of the story, one line (the check's own message)
};

/// "CHECK broke at frame F ball B: DETAIL (log PATH)", each part only when known: a failure's message in both
/// reports.
std::string finding_text(const Finding& f);

/// What a saved failure log says of its failure: its `found CHECK FRAME BALL` line, else its `expect failure
/// CHECK FRAME` line, and that line's number; check empty if it has neither (or cannot be read), and then the
/// line is that of `check RULE` when rule is given and the log has it, else 1.
struct LogMark {
    std::string check;
    std::optional<std::int64_t> frame, ball;
    int line = 1;
};
LogMark read_log_mark(const std::filesystem::path& log, std::string_view rule = {});

/// A finding for a saved failure log, from its mark (read_log_mark).
Finding finding_of_log(const std::filesystem::path& log);

/// One test case: a log replayed, a kernel, a property, a fuzz target.
struct TestCase {
    enum class Outcome { passed, failed, error, skipped };
    std::string classname;          ///< what holds it (the log's folder, `fuzz.robust`, a GoogleTest suite)
    std::string name;               ///< the log's path, the kernel's, the property's or the target's name
    double seconds = 0;
    Outcome outcome = Outcome::passed;
    std::string message;            ///< why it errored or was skipped; a failure's own message is its findings'
    std::vector<Finding> findings;  ///< a failed (or errored) case's failures: a <failure> each, a SARIF result each
};

/// A suite of cases: a stage of `check`, `replay`, a campaign.
struct TestSuite {
    std::string name;
    double seconds = 0;
    std::vector<TestCase> cases;
};

/// What a command ran, for its reports.
struct Report {
    std::string name;  ///< the command: `ricochet replay`, `ricochet check`, `ricochet fuzz`
    double seconds = 0;
    std::vector<TestSuite> suites;
    /// Other reports to take in whole (`check`'s fuzz campaign writes its own): JUnit documents whose
    /// suites are added after this report's, SARIF documents whose results and rules are.
    std::vector<std::string> junit_parts, sarif_parts;
};

/// The report as a JUnit XML document (the junit-10.xsd form docs/schemas/ holds): <testsuites> of
/// <testsuite>s of <testcase>s; a <failure> per finding of a failed case, an <error> for an errored one
/// (its findings' messages), a <skipped> for a skipped one.
std::string junit_xml(const Report& report);

/// The report as a SARIF 2.1.0 log: one run of the tool `ricochet`, a result per finding of every failed or
/// errored case (level error), pointing at its log's line, the URI relative to project (the project folder)
/// where the log is inside it.
std::string sarif_json(const Report& report, const std::filesystem::path& project);

/// The suites of a JUnit document GoogleTest wrote (--gtest_output=xml:FILE): a case per test, failed with
/// its failure messages; nothing if text is not such a document.
std::vector<TestSuite> read_gtest_xml(const std::string& text);

/// Where a command writes its reports; empty: not asked for.
struct ReportFiles {
    std::string junit;
    std::string sarif;
};

/// "cannot write FILE: WHY" for the first report path that cannot be written ("no such folder: DIR", "it is a
/// folder"), or empty: checked before the command's work, so that a typo costs nothing.
std::string report_files_problem(const ReportFiles& files);

/// Writes the reports asked for in files with write (the core's write_file_atomically: a temporary file renamed
/// over FILE, so never half-written), SARIF's URIs relative to the project folder (project.hpp; the current folder
/// outside a project); false and *error ("cannot write FILE: WHY") if one could not be written.
using WriteFile = bool (*)(const std::filesystem::path&, std::string_view, std::string*);
bool write_reports(const Report& report, const ReportFiles& files, WriteFile write, std::string* error);

}  // namespace ricochet::app
