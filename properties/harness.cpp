// The property harness (harness.hpp).
//
// Why we record the failing case ourselves: RapidCheck calls the property again for every shrink it
// tries, so writing a log from inside the property would save every intermediate case. Its shrinker
// keeps the current counterexample and tries its shrinks in turn; a shrink that still fails becomes the
// new current one; it stops when every shrink of the current one passes. The failing calls therefore
// come in order of ever smaller cases and the last failing call is the minimal one (this version also
// replays that minimal case once more at the end, see rapidcheck/BeforeMinimalTestCase.h). So the
// property only remembers its latest failing scene, and run_property saves that one after
// checkProperty has returned, reduced first (reduce.hpp: RapidCheck shrinks the generated values, the
// reducer the scene itself), then reads the saved log back and checks that it still fails.
#include "harness.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string_view>

#include "ricochet/checks.hpp"
#include "ricochet/failure_log.hpp"
#include "ricochet/reduce.hpp"
#include "ricochet/kernel_spec.hpp"
#include "ricochet/plugin_guard.hpp"
#include "ricochet/plugin_loader.hpp"
#include "ricochet/replay.hpp"
#include "ricochet/scene_log.hpp"

namespace ricochet {

void showValue(const Scene& scene, std::ostream& os) { os << "\n" << write_scene_log(scene); }

void PrintTo(KernelId k, std::ostream* os) { *os << kernel_name(k); }

}  // namespace ricochet

namespace ricochet::props {
namespace {

std::atomic<long long> g_total_cases{0};
/// The logs this run saved (or found already saved) for its failures, for RICOCHET_PROPERTIES_REPORT.
std::vector<std::string> g_saved_logs;

/// Writes RICOCHET_PROPERTIES_REPORT, if set: a line `failed TEST` per failed test (its full GoogleTest name)
/// and `log PATH` per failure log saved, for `ricochet check --json`.
void write_report() {
    const char* path = std::getenv("RICOCHET_PROPERTIES_REPORT");
    if (path == nullptr || *path == '\0') return;
    std::ofstream out(path, std::ios::trunc);
    const ::testing::UnitTest& run = *::testing::UnitTest::GetInstance();
    for (int i = 0; i < run.total_test_suite_count(); ++i) {
        const ::testing::TestSuite& suite = *run.GetTestSuite(i);
        for (int j = 0; j < suite.total_test_count(); ++j)
            if (const ::testing::TestInfo& test = *suite.GetTestInfo(j); test.result() != nullptr && test.result()->Failed())
                out << "failed " << suite.name() << "." << test.name() << "\n";
    }
    for (const std::string& log : g_saved_logs) out << "log " << log << "\n";
}
/// The labels of the case being generated, or nullptr outside one.
thread_local std::set<std::string>* g_case_tags = nullptr;

/// Prints the total number of generated cases when the test program ends.
class CaseCounter : public ::testing::Environment {
public:
    void TearDown() override {
        fmt::print("ricochet properties: {} cases generated in total (kernels:", total_cases());
        for (KernelId k : kernels_under_test()) fmt::print(" {}", kernel_name(k));
        fmt::print(")\n");
        // The line CTest's SKIP_REGULAR_EXPRESSION looks for (CMakeLists.txt, kernel_env_tests.cmake.in): only when
        // nothing ran, so that a test with one failing kernel and one refusing kernel still fails.
        const ::testing::UnitTest& run = *::testing::UnitTest::GetInstance();
        if (run.skipped_test_count() > 0 && run.successful_test_count() == 0 && run.failed_test_count() == 0)
            fmt::print("ricochet properties: every test was skipped\n");
        write_report();
    }
};
[[maybe_unused]] ::testing::Environment* const g_counter = ::testing::AddGlobalTestEnvironment(new CaseCounter);

/// The seed every property runs with when RC_PARAMS names none.
constexpr std::uint64_t k_default_seed = 1;

/// RC_PARAMS as the user set it, read once, before pin_rapidcheck_seed adds the harness's seed to it.
const std::string& user_rc_params() {
    static const std::string params = [] {
        const char* env = std::getenv("RC_PARAMS");
        return std::string(env != nullptr ? env : "");
    }();
    return params;
}

/// True if the user's RC_PARAMS sets key (then RapidCheck's configuration wins over our default).
bool rc_params_set(std::string_view key) { return user_rc_params().find(key) != std::string::npos; }

/// Puts the seed the properties run with into RC_PARAMS before RapidCheck reads it (once, at its first
/// configuration()): RapidCheck would otherwise draw a random seed of its own and print it ("Using configuration:
/// seed=…"), a second seed beside the harness's that reproduces nothing.
void pin_rapidcheck_seed() {
    static const bool pinned = [] {
        if (!rc_params_set("seed")) {
            const std::string params = fmt::format("{}{}seed={}", user_rc_params(), user_rc_params().empty() ? "" : " ",
                                                   k_default_seed);
            ::setenv("RC_PARAMS", params.c_str(), 1);
        }
        return true;
    }();
    (void)pinned;
}

/// RICOCHET_SHRINK_TRIES, read once: after a property's first failure, how many shrink candidates it judges at
/// most (RapidCheck has no such bound: each candidate of a big-number case can take seconds, and a failure with
/// many candidates can shrink for minutes). Unset: no bound. Not a whole number: exit 2 with an error.
std::optional<long> shrink_tries_limit() {
    static const std::optional<long> limit = []() -> std::optional<long> {
        const char* env = std::getenv("RICOCHET_SHRINK_TRIES");
        if (env == nullptr) return std::nullopt;
        const std::string_view text(env);
        long n = 0;
        const bool digits = !text.empty() && text.size() <= 9 &&
                            std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
        if (!digits) {
            fmt::print(stderr, "RICOCHET_SHRINK_TRIES: error: '{}' is not a count of tries (a whole number, 0 to "
                               "999999999)\n", text);
            std::exit(2);
        }
        for (const char c : text) n = 10 * n + (c - '0');
        return n;
    }();
    return limit;
}

/// A RapidCheck listener that reports nothing: the harness reports every result itself.
class SilentListener final : public rc::detail::TestListener {
public:
    void onTestCaseFinished(const rc::detail::CaseDescription&) override {}
    void onShrinkTried(const rc::detail::CaseDescription&, bool) override {}
    void onTestFinished(const rc::detail::TestMetadata&, const rc::detail::TestResult&) override {}
};

/// The kernel as RICOCHET_KERNEL spells it: its name (a table linked in, too), or plugin:PATH for a loaded plug-in.
std::string kernel_spec(KernelId k) {
    if (const PluginInfo* info = plugin_info(k); info != nullptr && !info->path.empty())
        return fmt::format("plugin:{}", info->path.string());
    return std::string(kernel_name(k));
}

/// The one command that reproduces the current test's failure: the same kernel, folder, seed and case count,
/// this test alone.
std::string reproduce_command(KernelId k, const rc::detail::TestParams& params) {
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    std::error_code ec;
    const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
    const char* dir = std::getenv("RICOCHET_REPLAY_DIR");
    // The shrink bound too: a bounded run saves the case it stopped at, which an unbounded one shrinks further.
    const std::optional<long> tries = shrink_tries_limit();
    const char* domain = std::getenv("RICOCHET_DOMAIN");
    return fmt::format("RICOCHET_KERNEL={}{}{}{} RC_PARAMS=\"seed={} max_success={}{}\" {} --gtest_filter='{}.{}'",
                       kernel_spec(k),
                       dir != nullptr && *dir != '\0' ? fmt::format(" RICOCHET_REPLAY_DIR={}", dir) : std::string(),
                       domain != nullptr ? fmt::format(" RICOCHET_DOMAIN='{}'", domain) : std::string(),
                       tries ? fmt::format(" RICOCHET_SHRINK_TRIES={}", *tries) : std::string(),
                       params.seed, params.maxSuccess, params.disableShrinking ? " noshrink=1" : "",
                       ec ? std::string("ricochet_properties") : self.string(),
                       test != nullptr ? test->test_suite_name() : "*", test != nullptr ? test->name() : "*");
}

std::vector<std::string> words(std::string_view s) {
    std::vector<std::string> out;
    std::istringstream in{std::string(s)};
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

/// True if one of the scene's `from` lines reads `property NAME ...`.
bool names_property(const Scene& s, std::string_view name) {
    return std::any_of(s.provenance.begin(), s.provenance.end(), [&](const std::string& from) {
        const auto w = words(from);
        return w.size() >= 2 && w[0] == "property" && w[1] == name;
    });
}

/// Before case s of p runs under kernel k: a plug-in kernel's guard is told (plugin_guard.hpp), to keep the case
/// in save_dir(k) as NAME-ID.scene should the plug-in crash or hang on it.
void stage_case(const Property& p, KernelId k, const Scene& s, std::uint64_t seed) {
    if (plugin_info(k) == nullptr) return;
    const Scene log = plugin_case_log(s, k, fmt::format("property {} seed {}", p.name, seed));
    stage_plugin_input({fmt::format("running property {} (seed {})", p.name, seed), write_scene_log(log),
                        save_dir(k) / fmt::format("{}-{}.scene", p.name, scene_content_id(log))});
}

/// Runs the statement, turning an unexpected exception into a failure of the property's check.
std::optional<Failure> judge(const Property& p, KernelId k, const Scene& s) {
    try {
        return p.statement(k, s);
    } catch (const std::exception& e) {
        return Failure{p.check, fmt::format("the statement threw: {}", e.what())};
    }
}

/// Replays every saved log in replay_dir(), and in save_dir(k) when that is another folder, that names p, under
/// kernel k, in domain (a log of its own domain in that one). Returns how many it replayed.
int replay_saved(const Property& p, KernelId k, const Domain& domain) {
    std::vector<std::filesystem::path> logs;
    const std::filesystem::path dirs[] = {replay_dir(), save_dir(k)};
    for (const std::filesystem::path& dir : dirs) {
        std::error_code ec;
        if (!std::filesystem::is_directory(dir, ec)) continue;
        // The same folder twice (save_dir(k) is replay_dir() for a built-in kernel, and for every kernel of a
        // runner without a corpus of its own) is listed once.
        if (&dir == &dirs[1] && (dir == dirs[0] || std::filesystem::equivalent(dir, dirs[0], ec))) continue;
        std::vector<std::filesystem::path> found;
        for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
            if (entry.path().extension() == ".scene") found.push_back(entry.path());
        std::sort(found.begin(), found.end());  // a fixed order, whatever the file system's
        logs.insert(logs.end(), found.begin(), found.end());
    }
    int replayed = 0;
    for (const auto& path : logs) {
        auto parsed = read_scene_log(path);
        if (const auto* d = std::get_if<Diagnostic>(&parsed)) {
            // Not ours to judge: another harness may keep deliberately broken logs there.
            fmt::print("note: skipping {}: {}\n", path.string(), d->str());
            continue;
        }
        Scene s = std::get<Scene>(std::move(parsed));
        if (!names_property(s, p.name)) continue;
        // A log saved without a domain is judged in the domain under test, if it lies inside it: a case outside the
        // user's world is not one their kernel promises. A log with its own domain is judged in that.
        if (s.domain.full() && !domain.full()) {
            if (const auto why = outside_domain(s, domain)) {
                fmt::print("note: skipping {}: outside the domain under test ({}): {}\n", path.string(),
                           domain_spec(domain), *why);
                continue;
            }
            s.domain = domain;
        }
        ++replayed;
        // The log's case is replayed against the kernel under test: a case that once broke some kernel
        // stays a regression test for every kernel the property is claimed for.
        s.kernel = k;
        if (plugin_info(k) != nullptr) stage_plugin_input({fmt::format("replaying {} for property {}", path.string(), p.name), {}, {}});
        if (const auto f = judge(p, k, s))
            ADD_FAILURE() << fmt::format("saved log {} breaks {} under {} again: {}: {}", path.string(), p.name,
                                         kernel_name(k), check_name(f->check), f->message);
    }
    return replayed;
}

/// Tries the reducer may make on a shrunk counterexample before it is saved: a count, not a clock, so a run
/// saves the same log on every machine. RapidCheck shrinks the generated values; the reducer then removes
/// what the statement's check does not need (balls, walls, shapes, frames) and simplifies the numbers.
constexpr std::uint64_t k_reduce_tries = 2'000;

/// Saves the minimal failing case (the one shrinking stopped at, if not shrunk_fully), reduced (reduce.hpp), as a
/// failure log (make_failure_log) when the shared checker sees the failure (what it cannot see is not saved: replay
/// could not reproduce it); returns a report for the test's failure message.
std::string save_failure(const Property& p, KernelId k, std::uint64_t seed, const Scene& found, const Failure& f,
                         bool shrunk_fully) {
    Scene scene = found;
    scene.kernel = k;
    scene.checks = {f.check};
    scene.provenance = {fmt::format("property {} seed {}", p.name, seed)};
    scene.expect_hash.reset();
    scene.expect_states.clear();
    scene.expect_failure.reset();
    scene.found.reset();
    // A scene the kernel cannot step cannot be replayed: the case is shown, not saved.
    if (const auto why = refusal(scene, k))
        return fmt::format("NOT saved: replay cannot check this case ({}); the case:\n{}", *why, write_scene_log(scene));
    // A plug-in that crashes while the case is reduced keeps the case as it was shrunk.
    stage_case(p, k, scene, seed);
    ReduceOptions options;
    options.max_tries = k_reduce_tries;
    const auto result = reduce_log(scene, options);
    const auto* reduced = std::get_if<ReducedLog>(&result);
    if (reduced == nullptr || reduced->error)
        return fmt::format("NOT saved: the shared check {} holds on this case, so replay could not reproduce it",
                           check_name(f.check));
    const FailureLog& log = reduced->log;
    std::string error;
    const auto saved = save_scene_log_once(save_dir(k), p.name, std::string_view(log.text()), &error);
    if (!saved) return fmt::format("could not save the case: {}", error);
    g_saved_logs.push_back(saved->path.string());
    std::string report = fmt::format("{}, reduced from {} to {} entities and {} to {} frames in {} tries, {} {}",
                                     shrunk_fully ? "minimal case" : "the case shrinking stopped at",
                                     reduced->before.entities(), reduced->after.entities(), reduced->before.frames,
                                     reduced->after.frames, reduced->tries, saved->is_new ? "saved as" : "already saved as",
                                     saved->path.string());
    // Read the saved log back: it must still break the property, and replay must show the failure.
    auto parsed = read_scene_log(saved->path);
    if (const auto* d = std::get_if<Diagnostic>(&parsed)) return report + fmt::format(" (UNREADABLE: {})", d->str());
    const Scene back = std::get<Scene>(std::move(parsed));
    const auto again = judge(p, k, back);
    report += again ? "; re-running the saved log breaks the property again"
                    : "; WARNING: the saved log does NOT break the property when re-run";
    if (!log.reproduces()) report += "; WARNING: the saved log's run does not break the check at the same frame";
    const ReplayResult replay = replay_scene(back);
    report += fmt::format("; `ricochet replay` says: {} ({})", replay.passed ? "passed" : "FAILED", replay.message);
    return report;
}

}  // namespace

std::filesystem::path save_dir(KernelId k) {
    const char* env = std::getenv("RICOCHET_REPLAY_DIR");
    if (env != nullptr && *env != '\0') return env;
    if (std::find(k_all_kernels.begin(), k_all_kernels.end(), k) != k_all_kernels.end()) return replay_dir();
    // A peer's or a plug-in's log names a kernel the corpus's readers may not have: never into the corpus.
    std::error_code ec;
    const std::filesystem::path here = std::filesystem::current_path(ec);
    return (ec ? std::filesystem::path(".") : here) / "found";
}

void tag(std::string_view label) {
    if (g_case_tags != nullptr) g_case_tags->emplace(label);
}

std::string str(Vec2 p) { return fmt::format("({}, {})", p.x, p.y); }
std::string str(const Wall& w) { return fmt::format("wall {} -> {}", str(w.p0), str(w.p1)); }

long long total_cases() { return g_total_cases.load(); }

Statement checked(std::vector<Check> checks, std::function<void(const Scene&)> tags) {
    return [checks = std::move(checks), tags = std::move(tags)](KernelId k, const Scene& s) -> std::optional<Failure> {
        if (tags) tags(s);
        CheckOptions options;
        options.keep_events = false;
        // The world's default options, as `ricochet replay` steps the saved log: a bug in one path of the broad
        // phase only (every wall tried, or the grid's) must fail the log on the code that saved it, so the
        // statement judges the path replay takes. That the paths give the same bits is BroadPhaseSameBits' and
        // the broad-phase check's to say.
        long hits = 0;
        options.on_frame = [&](std::span<const Event> events) {
            for (const Event& e : events) hits += e.kind == Event::Kind::hit;
        };
        const CheckedRun run = run_checked(s, k, s.frames, checks, options);
        classify(run.error.has_value(), "a ball left the accepted range");
        classify(s.frames > 0 && hits == 0, "no hit");
        classify(hits > 0 && hits < 8, "1-7 hits");
        classify(hits >= 8, "8 or more hits");
        if (!run.failure) return std::nullopt;
        return Failure{run.failure->check, run.failure->str()};
    };
}

std::string kernel_param_name(const ::testing::TestParamInfo<KernelId>& info) {
    std::string n(kernel_name(info.param));
    std::replace(n.begin(), n.end(), '-', '_');
    return n;
}

void run_property(const Property& p, KernelId k) {
    // Saved logs are read below (replayed first, read back after saving): they may name a peer kernel.
    register_runner_kernels();
    const auto start = std::chrono::steady_clock::now();
    // The user's world (domain.hpp): saved logs are judged in it, and each drawn scene is brought into it, or
    // discarded where it cannot be.
    const Domain domain = domain_under_test(k);
    const int replayed = replay_saved(p, k, domain);

    pin_rapidcheck_seed();
    rc::detail::TestParams params = rc::detail::configuration().testParams;
    if (!rc_params_set("max_success")) params.maxSuccess = p.default_max_success;
    // No luck in tests: without a seed in RC_PARAMS every property runs its fixed seed (RapidCheck's own
    // default is a random one), so a CTest verdict is the same on every run; RC_PARAMS="seed=S" explores.
    if (!rc_params_set("seed")) params.seed = k_default_seed;
    rc::detail::TestMetadata metadata;
    metadata.id = fmt::format("{}/{}", p.name, kernel_name(k));
    metadata.description = metadata.id;

    struct Found {
        Scene scene;
        Failure failure;
    };
    std::optional<Found> last;  // the latest failing case: after shrinking, the minimal one
    std::optional<Scene> last_generated;  // last's scene as generated (the case RapidCheck holds)
    const std::optional<long> shrink_limit = shrink_tries_limit();
    long shrink_tries = 0;        // shrink candidates judged since the first failure
    bool shrink_stopped = false;  // a candidate was passed unjudged: the bound was reached
    std::map<std::string, long> tally;  // label -> cases carrying it
    long cases = 0;
    // The generated scene names the kernel it runs under, so that RapidCheck's counterexample is the log of the
    // case that failed.
    const rc::Gen<Scene> gen = rc::gen::map(p.gen, [k](Scene s) {
        s.kernel = k;
        return s;
    });
    const auto property = [&] {
        Scene s = *gen;
        if (!domain.full() && !fit_to_domain(s, domain)) RC_DISCARD("outside the domain");
        if (last && shrink_limit) {
            // Shrinking. Past the bound every candidate passes unjudged but the case RapidCheck holds (it runs
            // that one again at the end), so the shrinker stops at the smallest failure found so far.
            if (!(s == *last_generated)) {
                if (shrink_tries >= *shrink_limit) {
                    shrink_stopped = true;
                    return;
                }
                ++shrink_tries;
            }
        }
        std::optional<Scene> generated;  // kept only where shrinking is bounded
        if (shrink_limit) generated = s;
        stage_case(p, k, s, params.seed);
        std::set<std::string> labels;
        g_case_tags = &labels;
        auto f = judge(p, k, s);
        g_case_tags = nullptr;
        ++cases;
        for (const auto& l : labels) ++tally[l];
        if (f) {
            const std::string message = fmt::format("{}: {}", check_name(f->check), f->message);
            last = Found{std::move(s), std::move(*f)};
            last_generated = std::move(generated);
            RC_FAIL(message);
        }
    };
    // Our own listener, which says nothing: RapidCheck's would add, at exit, a `reproduce=` string of its own
    // beside the one command this harness prints (reproduce_command).
    SilentListener listener;
    const rc::detail::TestResult result =
        rc::detail::checkProperty(rc::detail::toProperty(property), metadata, params, listener);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    if (result.is<rc::detail::SuccessResult>()) {
        const auto* ok = &result.get<rc::detail::SuccessResult>();
        g_total_cases += ok->numSuccess;
        std::string table;
        for (const auto& [label, n] : tally)
            table += fmt::format("  {:6.2f}% {}\n", 100.0 * double(n) / double(std::max(cases, 1L)), label);
        fmt::print("{} [{}]: OK, {} cases, {} saved logs replayed, {:.2f} s, seed {}\n{}", p.name, kernel_name(k),
                   ok->numSuccess, replayed, seconds, params.seed, table);
        std::fflush(stdout);
        return;
    }
    std::ostringstream ss;
    rc::detail::printResultMessage(result, ss);
    if (result.is<rc::detail::FailureResult>()) {
        const auto* bad = &result.get<rc::detail::FailureResult>();
        g_total_cases += bad->numSuccess;
        std::string saved = last ? save_failure(p, k, params.seed, last->scene, last->failure, !shrink_stopped)
                                 : "no failing case was recorded";
        if (shrink_stopped)
            saved += fmt::format("; shrinking stopped after {} tries (RICOCHET_SHRINK_TRIES={}): the case is the "
                                 "smallest failure found by then",
                                 shrink_tries, *shrink_limit);
        ADD_FAILURE() << fmt::format("{} [{}] fails after {} cases ({:.2f} s, seed {}); {}\n{}\nreproduce: {}\n", p.name,
                                     kernel_name(k), bad->numSuccess, seconds, params.seed, saved, ss.str(),
                                     reproduce_command(k, params));
        return;
    }
    ADD_FAILURE() << fmt::format("{} [{}]: {}", p.name, kernel_name(k), ss.str());
}

}  // namespace ricochet::props
