// `ricochet check`: the whole regression gate. Replays the project's corpus (--replay-dir, else
// $RICOCHET_REPLAY_DIR, else replays/ of the project folder: ricochet_app/project.hpp), runs the lecture's
// pinball example, then the property suite if it was built, then a short fuzz campaign if the fuzz targets
// were built (both saving what they find into that same folder); one summary (and, asked for, a JUnit report and a
// SARIF log of every stage: docs/cli-reports.md), non-zero exit if anything failed, 2 if there is no project or a
// report cannot be written. SIGINT or SIGTERM stops it between two stages (a stage's replay between
// two logs, a child program gets the signal too): the summary of what ran, exit 128 + the signal.
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <optional>
#include <variant>

#include <fmt/format.h>

#include "commands.hpp"
#include "number_option.hpp"
#include "ricochet/checks.hpp"
#include "ricochet/domain.hpp"
#include "ricochet/format.hpp"
#include "ricochet/kernel.hpp"
#include "ricochet/plugin_loader.hpp"
#include "ricochet/scene_log.hpp"
#include "ricochet_app/json.hpp"
#include "ricochet_app/json_stdout.hpp"
#include "ricochet_app/project.hpp"
#include "ricochet_app/stop_signal.hpp"

extern char** environ;

namespace ricochet::cli {

namespace {

/// Runs argv (no shell), inheriting stdout/stderr, with env_extra ("NAME=VALUE") added to the environment
/// (replacing a variable of the same name); returns its exit status (127 if it could not start).
int run_program(const std::vector<std::string>& argv, const std::vector<std::string>& env_extra = {}) {
    // Built before fork: the child only calls execve.
    std::vector<char*> args, env;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    for (char** e = environ; *e != nullptr; ++e) {
        const std::string_view var = *e;
        bool replaced = false;
        for (const std::string& x : env_extra) replaced = replaced || var.starts_with(x.substr(0, x.find('=') + 1));
        if (!replaced) env.push_back(*e);
    }
    for (const std::string& x : env_extra) env.push_back(const_cast<char*>(x.c_str()));
    env.push_back(nullptr);
    std::fflush(stdout);
    std::fflush(stderr);
    const pid_t pid = ::fork();
    if (pid < 0) return 127;
    if (pid == 0) {
        ::execve(args[0], args.data(), env.data());
        std::_Exit(127);
    }
    // A SIGINT or SIGTERM that reached check only (not its process group) is passed on.
    return app::wait_passing_stop(pid);
}

std::string self_exe() {
    std::error_code ec;
    const auto p = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? std::string(RICOCHET_BINARY_DIR "/cli/ricochet") : p.string();
}

bool any_fuzz_target_built() {
    const std::filesystem::path dir = std::filesystem::path(RICOCHET_BINARY_DIR) / "fuzz";
    std::error_code ec;
    for (const char* t : {"fuzz_parser", "fuzz_scene", "fuzz_sweep", "fuzz_static"})
        if (std::filesystem::exists(dir / t, ec)) return true;
    return false;
}

/// RICOCHET_CHECK_FUZZ_SECONDS, if set to a number of seconds (0 to 86400): a campaign by time instead of
/// the default fixed count of inputs. −1 if unset; an unusable value is an error at the start of `check`.
int env_fuzz_seconds() {
    const char* env = std::getenv("RICOCHET_CHECK_FUZZ_SECONDS");
    if (!env || !*env) return -1;
    char* end = nullptr;
    const long v = std::strtol(env, &end, 10);
    if (*end != '\0' || v < 0 || v > 86400) {
        fmt::print(stderr, "ricochet check: error: RICOCHET_CHECK_FUZZ_SECONDS='{}' is not a number of seconds (0 to 86400)\n",
                   env);
        throw Exit{2};
    }
    return static_cast<int>(v);
}

/// Every *.scene under dir (recursively), sorted: what a stage saved is what is there after it and not before.
std::vector<std::string> scene_logs_under(const std::filesystem::path& dir) {
    std::vector<std::string> out;
    std::error_code ec;
    for (auto it = std::filesystem::recursive_directory_iterator(dir, ec);
         !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec))
        if (it->is_regular_file() && it->path().extension() == ".scene") out.push_back(it->path().string());
    std::sort(out.begin(), out.end());
    return out;
}

/// The logs in after that were not in before (both sorted).
std::vector<std::string> added(const std::vector<std::string>& before, const std::vector<std::string>& after) {
    std::vector<std::string> out;
    std::set_difference(after.begin(), after.end(), before.begin(), before.end(), std::back_inserter(out));
    return out;
}

/// What the property suite reported through RICOCHET_PROPERTIES_REPORT (properties/harness.cpp): its failed tests
/// and the failure logs it saved.
struct PropertiesReport {
    std::vector<std::string> failed;
    std::vector<std::string> logs;
};

PropertiesReport read_properties_report(const std::filesystem::path& path) {
    PropertiesReport r;
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);) {
        if (line.starts_with("failed ")) r.failed.push_back(line.substr(7));
        else if (line.starts_with("log ")) r.logs.push_back(line.substr(4));
    }
    return r;
}

/// A file of check's own in the temporary folder, for a child to write into; removed at the end of its scope.
class TempFile {
public:
    explicit TempFile(std::string_view stem) {
        std::error_code ec;
        path_ = (std::filesystem::temp_directory_path(ec) / fmt::format("ricochet-check-{}.XXXXXX", stem)).string();
        const int fd = ::mkstemp(path_.data());
        if (fd >= 0) ::close(fd);
        else path_.clear();
    }
    ~TempFile() {
        if (!path_.empty()) ::unlink(path_.c_str());
    }
    TempFile(const TempFile&) = delete;
    TempFile& operator=(const TempFile&) = delete;
    /// Its path; empty if it could not be made.
    const std::string& path() const { return path_; }
    /// What the child wrote into it.
    std::string read() const {
        std::ifstream in(path_);
        return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }

private:
    std::string path_;
};

/// The property suite's cases (GoogleTest's XML), each failed one's findings its saved logs: those named after
/// its property (`NAME-ID.scene`, the suite's failure logs), else the failure GoogleTest reports.
std::vector<app::TestSuite> property_suites(const std::string& gtest_xml, const std::vector<std::string>& saved_logs) {
    std::vector<app::TestSuite> suites = app::read_gtest_xml(gtest_xml);
    for (app::TestSuite& suite : suites)
        for (app::TestCase& c : suite.cases) {
            // GoogleTest's name of a parameterised property: NAME/PARAM.
            const std::string property = c.name.substr(0, c.name.find('/'));
            std::vector<app::Finding> logs;
            for (const std::string& log : saved_logs)
                if (std::filesystem::path(log).filename().string().starts_with(property + "-")) logs.push_back(app::finding_of_log(log));
            if (c.outcome != app::TestCase::Outcome::failed || logs.empty()) continue;
            for (app::Finding& f : logs) f.detail = c.findings.front().detail;
            c.findings = std::move(logs);
        }
    return suites;
}

/// A stage that did not run its cases (skipped, not built, could not start) as a suite of one case.
app::TestSuite stage_case(std::string_view stage, app::TestCase::Outcome outcome, std::string message) {
    app::TestCase c{"check", std::string(stage), 0, outcome, message, {}};
    if (outcome == app::TestCase::Outcome::error) c.findings.push_back({"error", {}, {}, {}, {}, {}, message});
    return {std::string(stage), 0, {std::move(c)}};
}

/// A member holding an array of strings.
void string_array(app::JsonWriter& json, std::string_view name, const std::vector<std::string>& items) {
    json.key(name).begin_array();
    for (const std::string& i : items) json.value(i);
    json.end_array();
}

}  // namespace

void register_check(CLI::App& app) {
    struct Options {
        // The campaign runs a fixed count of inputs per target from a fixed seed, so its verdict does not
        // depend on the machine's speed or load; --fuzz-time (or RICOCHET_CHECK_FUZZ_SECONDS) asks for a
        // campaign by time instead.
        int fuzz_time = -1;
        long fuzz_runs = 10000;
        long fuzz_seed = 1;
        bool no_properties = false;
        std::string replay_dir;
        std::vector<std::string> plugins;
        std::string kernel;
        std::optional<std::string> domain;
        bool json = false;
        app::ReportFiles reports;
        std::uint64_t max_work = k_default_max_work;
    };
    auto opt = std::make_shared<Options>();
    CLI::App* sub = app.add_subcommand(
        "check", "replay the corpus, the lecture's pinball example, the property suite and a short fuzz campaign");
    sub->add_option("--fuzz-runs", opt->fuzz_runs, "inputs per fuzz target at the end (0: no fuzzing; default 10000)")
        ->check(number_in<long>(0, std::numeric_limits<long>::max(), "a count of inputs"));
    sub->add_option("--fuzz-seed", opt->fuzz_seed, "libFuzzer seed of the campaign (default 1)")
        ->check(number_in<long>(1, std::numeric_limits<unsigned>::max(), "a seed"));
    sub->add_option("--fuzz-time", opt->fuzz_time, "fuzz for this many seconds instead of a count of inputs (0: none)")
        ->check(number_in(0, 86400, "a number of seconds"));
    add_max_work_option(*sub, opt->max_work);
    add_plugin_option(*sub, opt->plugins);
    sub->add_option("--kernel", opt->kernel,
                    "run the pinball example, the property suite and the campaign under this kernel alone: a kernel's "
                    "name, or plugin:PATH (ricochet/plugin.h); the corpus's logs run under their own kernels");
    sub->add_option("--domain", opt->domain,
                    "the kernel's world for the property suite and the campaign (RICOCHET_DOMAIN, e.g. "
                    "coordinates=1e6,no-subnormals,waive=touching; docs/scene-log.md \"Domain\")")
        ->type_name("SPEC");
    sub->add_flag("--no-properties", opt->no_properties, "skip the property suite");
    sub->add_option("--replay-dir", opt->replay_dir,
                    "the corpus to replay, and where the properties and the fuzz campaign save failures "
                    "(default $RICOCHET_REPLAY_DIR, else the project folder's replays/)");
    sub->add_flag("--json", opt->json,
                  "print one JSON document (docs/cli-json.md, schema ricochet-check/1) on stdout instead of the summary; "
                  "everything else goes to stderr");
    add_report_options(*sub, opt->reports, "a test case per log replayed, pinball kernel, property and fuzz target", true);
    sub->callback([opt] {
        if (opt->fuzz_time < 0) opt->fuzz_time = env_fuzz_seconds();
        check_report_files_or_exit(opt->reports);
        // The children (properties, fuzz) read the domain from RICOCHET_DOMAIN, inherited.
        if (opt->domain) {
            std::string error;
            if (!parse_domain_spec(*opt->domain, &error)) {
                fmt::print(stderr, "ricochet check: error: --domain: {}\n", error);
                throw Exit{2};
            }
            ::setenv("RICOCHET_DOMAIN", opt->domain->c_str(), 1);
        }
        // Plug-ins before the corpus: their failure logs there name their kernels (the --kernel one's too).
        load_plugins_or_exit(opt->plugins);
        const std::optional<KernelId> kernel = opt->kernel.empty() ? std::nullopt : std::optional(kernel_or_exit(opt->kernel));
        // The children (properties, fuzz) get the kernel as they read it: a plug-in by its absolute path.
        const PluginInfo* plugin = kernel ? plugin_info(*kernel) : nullptr;
        const std::string kernel_spec = !kernel ? std::string()
                                        : plugin != nullptr ? fmt::format("plugin:{}", plugin->path.string())
                                                            : std::string(kernel_name(*kernel));
        const auto project = app::find_project(opt->replay_dir);
        if (!project) {
            fmt::print(stderr, "{}\n", app::no_project_message("check", "run it in a project folder or pass --replay-dir DIR"));
            throw Exit{2};
        }
        const std::filesystem::path replays = project->replay_dir;
        // --replay-dir names the folder failures go to: made if it is not there yet (its parent must be).
        std::error_code made_ec;
        if (!opt->replay_dir.empty() && !std::filesystem::exists(replays, made_ec)) {
            if (!std::filesystem::create_directory(replays, made_ec)) {
                fmt::print(stderr, "ricochet check: error: cannot make the replay folder {}: {}\n", replays.string(),
                           made_ec ? made_ec.message() : "it is not a folder");
                throw Exit{2};
            }
            fmt::print(stderr, "ricochet check: note: made the replay folder {}\n", replays.string());
        }
        // The children (properties, fuzz) get it absolute: they may resolve it from elsewhere.
        std::error_code abs_ec;
        const std::filesystem::path replays_abs = std::filesystem::absolute(replays, abs_ec);
        const bool by_time = opt->fuzz_time >= 0;
        std::vector<std::string> summary;
        bool failed = false;
        const bool reporting = !opt->reports.junit.empty() || !opt->reports.sarif.empty();
        const auto t_check = std::chrono::steady_clock::now();
        app::Report report{"ricochet check", 0, {}, {}, {}};
        // Under --json every stage's output, the children's too, goes to stderr; the document is built as
        // the stages run.
        app::JsonStdout json_out(opt->json);
        app::JsonWriter json;
        json.begin_object().member("schema", fmt::format("ricochet-check/{}", app::k_json_schema_version));
        json.member("replay_dir", replays.string());
        if (kernel)
            json.member("kernel", kernel_name(*kernel));
        else
            json.key("kernel").null();
        json.key("stages").begin_object();
        // stage(NAME, STATUS): opens the stage's object; the caller adds members and closes it.
        const auto stage = [&](std::string_view name, std::string_view status) -> app::JsonWriter& {
            return json.key(name).begin_object().member("status", status);
        };
        // The end, after the last stage or at a SIGINT or SIGTERM between two: the summary (or the
        // document) of the stages that ran, then the exit.
        const app::StopOnSignal stop;
        const auto finish = [&] {
            json.end_object();
            const bool stopped = app::stop_requested();
            int code = stopped ? app::stop_exit_code() : failed ? 1 : 0;
            // The reports before the document and the summary, so that both say the command's exit: 2 if one
            // could not be written.
            report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_check).count();
            if (!write_reports_or_say(report, opt->reports) && !stopped) code = 2;
            if (json_out.on()) {
                json_out.restore();
                write_stdout(json.member("stopped", stopped).member("passed", code == 0).member("exit", code).end_object().str());
                throw Exit{code};
            }
            fmt::print("== summary\n");
            for (const auto& s : summary) fmt::print("{}\n", s);
            fmt::print("{}\n", stopped       ? fmt::format("check stopped by {}", app::stop_signal_name())
                               : code == 2 ? "check FAILED (a report could not be written)"
                               : failed    ? "check FAILED"
                                           : "check passed");
            throw Exit{code};
        };
        const auto timed = [](auto&& f) {
            const auto t0 = std::chrono::steady_clock::now();
            f();
            return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        };

        // 1. The corpus. A folder that holds no log yet (a new project's, made above) is where the properties and
        // the campaign will save their failures: nothing to replay, said so, not a failure.
        fmt::print("== replay {}\n", replays.string());
        if (scene_logs_under(replays).empty()) {
            const std::string none = fmt::format("no scene logs in {} yet", replays.string());
            fmt::print("{}\n", none);
            summary.push_back(fmt::format("replay      skipped ({})", none));
            report.suites.push_back(stage_case("replay", app::TestCase::Outcome::skipped, none));
            stage("replay", "skipped").member("message", none).end_object();
        } else {
            ReplaySummary r;
            const double t_replay = timed([&] { r = replay_paths({replays.string()}, false, opt->max_work); });
            failed = failed || r.failed > 0 || r.bad_input;
            summary.push_back(fmt::format("replay      {} ({:.2f} s)", replay_counts(r, false), t_replay));
            // A log for a kernel this build lacks is skipped, never failed: each reason said once, with its count.
            for (const auto& [reason, n] : r.skip_reasons) summary.push_back(fmt::format("            {} skipped: {}", n, reason));
            stage("replay", r.failed > 0 || r.bad_input ? "failed" : "passed").member("seconds", t_replay);
            report.suites.push_back(replay_suite(r, t_replay));
            write_replay_members(json, r);
            json.end_object();
        }
        if (app::stop_requested()) finish();

        // 2. The lecture's pinball experiment, under every kernel (or --kernel's alone): robust and exact must keep
        // its checks, and so must a --kernel held to the guarantees (a plug-in); the lecture's and the peers' are
        // expected to break.
        const std::filesystem::path pinball = replays / "pinball.scene";
        fmt::print("== lecture pinball example {}\n", pinball.string());
        std::error_code pin_ec;
        auto parsed = read_scene_log(pinball);
        if (!std::filesystem::exists(pinball, pin_ec)) {
            // A project of its own need not carry the lecture's example.
            summary.push_back(fmt::format("pinball     skipped (no {})", pinball.string()));
            report.suites.push_back(stage_case("pinball", app::TestCase::Outcome::skipped, fmt::format("no {}", pinball.string())));
            stage("pinball", "skipped").member("message", fmt::format("no {}", pinball.string())).end_object();
        } else if (auto* d = std::get_if<Diagnostic>(&parsed)) {
            fmt::print(stderr, "{}\n", d->str());
            failed = true;
            summary.push_back("pinball     unreadable");
            report.suites.push_back(stage_case("pinball", app::TestCase::Outcome::error, d->str()));
            stage("pinball", "failed").member("message", d->str()).end_object();
        } else if (const std::string over = work_over_budget(pinball.string(), std::get<Scene>(parsed),
                                                              std::get<Scene>(parsed).frames, opt->max_work);
                   !over.empty()) {
            // The corpus's own log: over the bound only if --max-work was set below it.
            fmt::print(stderr, "ricochet: error: {}\n", over);
            failed = true;
            summary.push_back("pinball     not run (over --max-work)");
            report.suites.push_back(stage_case("pinball", app::TestCase::Outcome::error, over));
            stage("pinball", "failed").member("message", over).end_object();
        } else {
            const Scene& scene = std::get<Scene>(parsed);
            std::string line = "pinball    ";
            bool pinball_failed = false;
            // Its status is known after the kernels: written after them.
            json.key("pinball").begin_object().key("kernels").begin_object();
            CheckOptions quiet;
            quiet.keep_events = false;
            app::TestSuite kernels{"pinball", 0, {}};
            std::vector<KernelId> pinball_kernels(k_all_kernels.begin(), k_all_kernels.end());
            if (kernel) pinball_kernels = {*kernel};
            for (KernelId k : pinball_kernels) {
                const auto t0 = std::chrono::steady_clock::now();
                const CheckedRun run = run_checked(scene, k, scene.frames, scene.checks, quiet);
                const bool ok = !run.failure && !run.error;
                fmt::print("{:15} {}\n", k,
                           ok ? "every check held"
                              : run.failure ? run.failure->str() : run.error->message());
                line += fmt::format(" {}={}", k, ok ? "ok" : "broken");
                json.member(fmt::format("{}", k), ok ? "ok" : "broken");
                // The lecture kernels are expected to break; the robust and exact kernels may not.
                const bool must_hold = !kernel_ops(k).failures_documented;
                if (!ok && must_hold) pinball_failed = true;
                // A case per kernel; the lecture kernels' breaking is what the example shows, not a failure.
                app::TestCase c{"pinball", fmt::format("{}", k),
                                std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
                                app::TestCase::Outcome::passed, {}, {}};
                if (!ok && must_hold) {
                    c.outcome = app::TestCase::Outcome::failed;
                    c.findings.push_back({run.failure ? std::string(check_name(run.failure->check)) : std::string("error"),
                                          run.failure ? std::optional<std::int64_t>(run.failure->frame) : std::nullopt,
                                          run.failure ? std::optional<std::int64_t>(run.failure->ball) : std::nullopt,
                                          pinball.string(), {}, {},
                                          run.failure ? run.failure->message : run.error->message()});
                }
                kernels.seconds += c.seconds;
                kernels.cases.push_back(std::move(c));
            }
            report.suites.push_back(std::move(kernels));
            failed = failed || pinball_failed;
            summary.push_back(line);
            json.end_object().member("status", pinball_failed ? "failed" : "passed").end_object();
        }

        if (app::stop_requested()) finish();

        // 3. The property suite, if this build has it.
        const std::string props = RICOCHET_PROPERTIES_EXE;
        if (opt->no_properties) {
            summary.push_back("properties  skipped (--no-properties)");
            report.suites.push_back(stage_case("properties", app::TestCase::Outcome::skipped, "--no-properties"));
            stage("properties", "skipped").end_object();
        } else if (props.empty() || !std::filesystem::exists(props)) {
            summary.push_back("properties  not built (build target ricochet_properties)");
            report.suites.push_back(stage_case("properties", app::TestCase::Outcome::skipped, "not built"));
            stage("properties", "not-built").end_object();
        } else {
            fmt::print("== properties {}\n", props);
            int rc = 0;
            // What failed and what was saved, told by the suite in a file of our own (removed after); its cases,
            // for the reports, in GoogleTest's XML.
            const TempFile told_file("properties"), gtest_xml("properties-xml");
            std::vector<std::string> argv = {props};
            if (reporting && !gtest_xml.path().empty()) argv.push_back("--gtest_output=xml:" + gtest_xml.path());
            // The suite saves its failures into (and first replays the saved logs of) the same corpus.
            const double t = timed([&] {
                std::vector<std::string> env = {fmt::format("{}={}", app::k_replay_dir_env, replays_abs.string()),
                                                fmt::format("RICOCHET_PROPERTIES_REPORT={}", told_file.path())};
                if (kernel) env.push_back(fmt::format("RICOCHET_KERNEL={}", kernel_spec));
                rc = run_program(argv, env);
            });
            const PropertiesReport told = told_file.path().empty() ? PropertiesReport{} : read_properties_report(told_file.path());
            if (reporting) {
                std::vector<app::TestSuite> suites = property_suites(gtest_xml.read(), told.logs);
                // A suite that ended before writing its XML (a crash): the stage as one case.
                if (suites.empty() && rc != 0)
                    suites.push_back(stage_case("properties", app::TestCase::Outcome::error, fmt::format("the suite exited with status {}", rc)));
                for (app::TestSuite& suite : suites) report.suites.push_back(std::move(suite));
            }
            failed = failed || rc != 0;
            summary.push_back(fmt::format("properties  {} ({:.1f} s)", rc == 0 ? "passed" : fmt::format("FAILED (exit {})", rc), t));
            for (const std::string& f : told.failed) summary.push_back(fmt::format("            failed: {}", f));
            for (const std::string& l : told.logs) summary.push_back(fmt::format("            log: {}", l));
            stage("properties", rc == 0 ? "passed" : "failed").member("exit", rc).member("seconds", t);
            string_array(json, "failed_properties", told.failed);
            string_array(json, "saved_logs", told.logs);
            json.end_object();
        }

        if (app::stop_requested()) finish();

        // 4. A short fuzz campaign through `ricochet fuzz`, if the targets are built.
        if (by_time ? opt->fuzz_time == 0 : opt->fuzz_runs == 0) {
            summary.push_back(by_time ? "fuzz        skipped (--fuzz-time 0)" : "fuzz        skipped (--fuzz-runs 0)");
            report.suites.push_back(stage_case("fuzz", app::TestCase::Outcome::skipped, by_time ? "--fuzz-time 0" : "--fuzz-runs 0"));
            stage("fuzz", "skipped").end_object();
        } else if (!any_fuzz_target_built()) {
            summary.push_back("fuzz        not built (configure with clang-14 and RICOCHET_FUZZ=ON)");
            report.suites.push_back(stage_case("fuzz", app::TestCase::Outcome::skipped, "not built"));
            stage("fuzz", "not-built").end_object();
        } else {
            std::vector<std::string> argv = {self_exe(), "fuzz", "--replay-dir", replays_abs.string()};
            if (kernel) argv.insert(argv.end(), {"--kernel", kernel_spec});
            if (by_time) {
                fmt::print("== fuzz for {} s\n", opt->fuzz_time);
                argv.insert(argv.end(), {"--time", std::to_string(opt->fuzz_time)});
            } else {
                fmt::print("== fuzz: {} inputs per target, seed {}\n", opt->fuzz_runs, opt->fuzz_seed);
                argv.insert(argv.end(), {"--runs", std::to_string(opt->fuzz_runs), "--seed", std::to_string(opt->fuzz_seed)});
            }
            // The campaign's own reports, taken into check's whole.
            const TempFile junit("fuzz-junit"), sarif("fuzz-sarif");
            if (reporting && !junit.path().empty() && !sarif.path().empty())
                argv.insert(argv.end(), {"--junit", junit.path(), "--sarif", sarif.path()});
            int rc = 0;
            // A new failure is a new log in the folder: what is there after the campaign and was not before.
            const std::vector<std::string> before = scene_logs_under(replays_abs);
            const double t = timed([&] { rc = run_program(argv); });
            if (reporting) {
                report.junit_parts.push_back(junit.read());
                report.sarif_parts.push_back(sarif.read());
                // A campaign that stopped before its summary (bad usage, no binaries) wrote no report.
                if (report.junit_parts.back().empty() && rc != 0)
                    report.suites.push_back(stage_case("fuzz", app::TestCase::Outcome::error, fmt::format("ricochet fuzz exited with status {}", rc)));
            }
            const std::vector<std::string> saved = added(before, scene_logs_under(replays_abs));
            failed = failed || rc != 0;
            summary.push_back(fmt::format("fuzz        {} ({:.1f} s)", rc == 0 ? "passed" : fmt::format("FAILED (exit {})", rc), t));
            for (const std::string& l : saved) summary.push_back(fmt::format("            log: {}", l));
            stage("fuzz", rc == 0 ? "passed" : "failed").member("exit", rc).member("seconds", t);
            string_array(json, "saved_logs", saved);
            json.end_object();
        }
        finish();
    });
}

}  // namespace ricochet::cli
