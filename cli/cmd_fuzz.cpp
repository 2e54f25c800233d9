// `ricochet fuzz`: a libFuzzer campaign over the fuzz targets of this build. Targets run in parallel
// (each with --jobs workers shared out), progress is printed while they run, the working corpus lives
// in a cache folder outside the source tree and is merged (minimized) after each campaign, and each
// new failure is minimized, turned into a scene log (`from fuzz TARGET SHA1`, the failed `check`,
// `expect failure` for a lecture kernel) and saved into the replay folder unless an equal log exists.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "ricochet/scene_log.hpp"

extern char** environ;

namespace ricochet::cli {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

/// Every target the fuzz/ folder defines, in the order the summary lists them.
constexpr std::array<const char*, 4> k_targets = {"parser", "static", "sweep", "scene"};
/// Most failures of one target minimized and converted per campaign (the rest keep their artifacts).
constexpr int k_max_failures_converted = 5;
/// Runs cap for -minimize_crash (keeps minimization to seconds).
constexpr int k_minimize_runs = 20000;

// ---- SHA1 (FIPS 180-4), for `from fuzz TARGET SHA1`: libFuzzer names its artifacts the same way.
std::string sha1_hex(const std::string& data) {
    std::uint32_t h[5] = {0x67452301u, 0xEFCDAB89u, 0x98BADCFEu, 0x10325476u, 0xC3D2E1F0u};
    std::string m = data;
    const std::uint64_t bits = static_cast<std::uint64_t>(data.size()) * 8u;
    m += static_cast<char>(0x80);
    while (m.size() % 64 != 56) m += '\0';
    for (int i = 7; i >= 0; --i) m += static_cast<char>((bits >> (8 * i)) & 0xffu);
    const auto rol = [](std::uint32_t x, int n) { return (x << n) | (x >> (32 - n)); };
    for (std::size_t off = 0; off < m.size(); off += 64) {
        std::uint32_t w[80];
        for (int i = 0; i < 16; ++i)
            w[i] = (std::uint32_t(std::uint8_t(m[off + 4 * i])) << 24) | (std::uint32_t(std::uint8_t(m[off + 4 * i + 1])) << 16) |
                   (std::uint32_t(std::uint8_t(m[off + 4 * i + 2])) << 8) | std::uint32_t(std::uint8_t(m[off + 4 * i + 3]));
        for (int i = 16; i < 80; ++i) w[i] = rol(w[i - 3] ^ w[i - 8] ^ w[i - 14] ^ w[i - 16], 1);
        std::uint32_t a = h[0], b = h[1], c = h[2], d = h[3], e = h[4];
        for (int i = 0; i < 80; ++i) {
            std::uint32_t f, k;
            if (i < 20) f = (b & c) | (~b & d), k = 0x5A827999u;
            else if (i < 40) f = b ^ c ^ d, k = 0x6ED9EBA1u;
            else if (i < 60) f = (b & c) | (b & d) | (c & d), k = 0x8F1BBCDCu;
            else f = b ^ c ^ d, k = 0xCA62C1D6u;
            const std::uint32_t t = rol(a, 5) + f + e + k + w[i];
            e = d, d = c, c = rol(b, 30), b = a, a = t;
        }
        h[0] += a, h[1] += b, h[2] += c, h[3] += d, h[4] += e;
    }
    return fmt::format("{:08x}{:08x}{:08x}{:08x}{:08x}", h[0], h[1], h[2], h[3], h[4]);
}

std::string read_all(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

/// Starts argv with extra environment entries, stdout and stderr appended to log. Returns the pid.
pid_t spawn(const std::vector<std::string>& argv, const std::vector<std::string>& env_extra, const fs::path& log) {
    std::vector<std::string> env;
    for (char** e = environ; *e != nullptr; ++e) {
        const std::string s = *e;
        const bool overridden = std::any_of(env_extra.begin(), env_extra.end(), [&](const std::string& x) {
            return s.compare(0, x.find('=') + 1, x, 0, x.find('=') + 1) == 0;
        });
        if (!overridden) env.push_back(s);
    }
    env.insert(env.end(), env_extra.begin(), env_extra.end());
    std::vector<char*> cargv, cenv;
    for (const auto& a : argv) cargv.push_back(const_cast<char*>(a.c_str()));
    cargv.push_back(nullptr);
    for (const auto& e : env) cenv.push_back(const_cast<char*>(e.c_str()));
    cenv.push_back(nullptr);
    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 1, log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    posix_spawn_file_actions_adddup2(&fa, 1, 2);
    posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
    pid_t pid = -1;
    if (posix_spawn(&pid, cargv[0], &fa, nullptr, cargv.data(), cenv.data()) != 0) pid = -1;
    posix_spawn_file_actions_destroy(&fa);
    return pid;
}

/// Runs argv to completion; returns its exit status (128+signal if killed) and its output.
std::pair<int, std::string> run_capture(const std::vector<std::string>& argv, const std::vector<std::string>& env_extra,
                                        const fs::path& scratch) {
    fs::remove(scratch);
    const pid_t pid = spawn(argv, env_extra, scratch);
    if (pid < 0) return {127, "cannot start " + argv[0]};
    int status = 0;
    waitpid(pid, &status, 0);
    const int rc = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return {rc, read_all(scratch)};
}

/// The number after key in line (e.g. "cov: "), if there is one.
std::optional<std::uint64_t> number_after(const std::string& line, std::string_view key) {
    const auto at = line.find(key);
    if (at == std::string::npos) return std::nullopt;
    std::size_t i = at + key.size();
    while (i < line.size() && line[i] == ' ') ++i;
    std::uint64_t v = 0;
    bool any = false;
    while (i < line.size() && line[i] >= '0' && line[i] <= '9') v = v * 10 + static_cast<std::uint64_t>(line[i++] - '0'), any = true;
    return any ? std::optional(v) : std::nullopt;
}

/// One target's campaign: its workers, what their output says, what it found.
struct Campaign {
    std::string target;
    fs::path bin, dir, corpus, artifacts, log, dict;
    std::vector<fs::path> seeds;
    int workers = 1;
    std::vector<pid_t> pids;
    std::vector<Clock::time_point> started;  // per worker, when its current process started
    std::uint64_t runs_done = 0;           // runs of worker processes that have exited
    std::uint64_t cov = 0, corpus_size = 0, exec_s = 0;
    std::size_t log_read = 0;
    int restarts = 0, quick_crashes = 0;
    std::set<std::string> artifacts_before;
    double seconds = 0.0;
    int new_failures = 0, known_failures = 0;
    std::vector<std::string> notes;
};

std::set<std::string> list_artifacts(const fs::path& dir) {
    std::set<std::string> out;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec)) {
        const std::string n = e.path().filename().string();
        if (n.starts_with("crash-") || n.starts_with("timeout-") || n.starts_with("oom-") || n.starts_with("leak-") ||
            n.starts_with("slow-unit-"))
            out.insert(n);
    }
    return out;
}

std::size_t count_files(const fs::path& dir) {
    std::size_t n = 0;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec))
        if (e.is_regular_file()) ++n;
    return n;
}

/// Reads what the workers wrote since last time: runs, coverage, corpus size, exec/s.
void poll_log(Campaign& c) {
    std::ifstream in(c.log, std::ios::binary);
    in.seekg(static_cast<std::streamoff>(c.log_read));
    std::string line;
    std::streamoff consumed = 0;
    while (std::getline(in, line)) {
        if (in.eof()) break;  // a partial last line: read it next time
        consumed += static_cast<std::streamoff>(line.size() + 1);
        if (line.empty() || line[0] != '#') continue;
        // "#RUNS\tNEW|pulse|REDUCE cov: N ft: N corp: N/Nb ... exec/s: N rss: NMb" (tagged by worker "[w]")
        if (auto cov = number_after(line, "cov: ")) c.cov = std::max(c.cov, *cov);
        if (auto corp = number_after(line, "corp: ")) c.corpus_size = *corp;
        if (auto e = number_after(line, "exec/s: ")) c.exec_s = *e;
    }
    c.log_read += static_cast<std::size_t>(consumed);
}

std::string human(double x) {
    if (x >= 1e9) return fmt::format("{:.1f}G", x / 1e9);
    if (x >= 1e6) return fmt::format("{:.1f}M", x / 1e6);
    if (x >= 1e3) return fmt::format("{:.1f}k", x / 1e3);
    return fmt::format("{:.0f}", x);
}

/// The folder that holds this build's fuzz binaries, or why there is none.
fs::path default_bin_dir() {
    if (const char* d = std::getenv("RICOCHET_FUZZ_BIN_DIR"); d != nullptr && *d != '\0') return d;
    const fs::path baked = fs::path(RICOCHET_BINARY_DIR) / "fuzz";
    if (fs::exists(baked)) return baked;
    // Next to the executable: BUILD/cli/ricochet → BUILD/fuzz.
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    return ec ? baked : self.parent_path().parent_path() / "fuzz";
}

fs::path default_cache_dir() {
    if (const char* d = std::getenv("RICOCHET_FUZZ_CACHE"); d != nullptr && *d != '\0') return d;
    if (const char* x = std::getenv("XDG_CACHE_HOME"); x != nullptr && *x != '\0') return fs::path(x) / "ricochet" / "fuzz";
    if (const char* h = std::getenv("HOME"); h != nullptr && *h != '\0') return fs::path(h) / ".cache" / "ricochet" / "fuzz";
    return fs::path(RICOCHET_BINARY_DIR) / ".cache" / "ricochet-fuzz";
}

fs::path default_replay_dir() {
    if (const char* d = std::getenv("RICOCHET_REPLAY_DIR"); d != nullptr && *d != '\0') return d;
    return source_replays_dir();
}

/// A log under dir (recursively) holding the same case (scene_content_id), if any.
std::optional<fs::path> find_equal_log(const fs::path& dir, const std::string& id) {
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        if (!it->is_regular_file() || it->path().extension() != ".scene") continue;
        const SceneOrDiagnostic s = read_scene_log(it->path());
        if (const Scene* scene = std::get_if<Scene>(&s); scene != nullptr && scene_content_id(*scene) == id) return it->path();
    }
    return std::nullopt;
}

struct Options {
    std::vector<std::string> targets;
    std::string kernel = "robust";
    double time = 60;
    int jobs = 0;
    std::string bin_dir, cache_dir, replay_dir;
    bool no_merge = false;
};

/// Minimizes one failure, converts it to a scene log, saves it unless an equal one exists.
void handle_failure(Campaign& c, const Options& opt, const fs::path& replay_dir, const std::string& artifact,
                    std::set<std::string>& signatures) {
    const fs::path raw = c.artifacts / artifact;
    const std::vector<std::string> env = {"RICOCHET_KERNEL=" + opt.kernel};
    const fs::path minimized = c.artifacts / ("minimized-" + artifact);
    const fs::path scratch = c.dir / "scratch.log";
    // Minimize: libFuzzer keeps the input failing while it shrinks it; capped in runs and time.
    run_capture({c.bin.string(), "-minimize_crash=1", fmt::format("-runs={}", k_minimize_runs), "-max_total_time=20",
                 "-exact_artifact_path=" + minimized.string(), raw.string()},
                env, scratch);
    const fs::path input = fs::exists(minimized) && fs::file_size(minimized) > 0 ? minimized : raw;
    const std::string sha = sha1_hex(read_all(input));
    const fs::path scene_out = c.dir / "failure.scene";
    fs::remove(scene_out);
    const auto [rc, out] = run_capture({c.bin.string(), input.string()},
                                       {"RICOCHET_KERNEL=" + opt.kernel, "RICOCHET_FUZZ_SCENE_OUT=" + scene_out.string(),
                                        "RICOCHET_FUZZ_SHA1=" + sha},
                                       scratch);
    // The signature: the target's failure line, or the sanitizer's summary.
    std::string signature, first_line;
    std::istringstream lines(out);
    for (std::string line; std::getline(lines, line);) {
        if (line.starts_with("==ricochet-fuzz== FAILURE")) {
            const auto k = line.find(" check=");
            const auto f = line.find(" frame=");
            const auto kind = line.find(" kind=");
            signature = line.substr(k, f - k) + line.substr(kind);
            first_line = line;
            break;
        }
        if (line.starts_with("SUMMARY:")) signature = first_line = line;
    }
    if (rc == 0) {
        c.notes.push_back(fmt::format("{}: does not fail when run again (flaky?); kept at {}", artifact, raw.string()));
        ++c.new_failures;
        return;
    }
    if (signature.empty()) signature = fmt::format("exit {}", rc);
    if (!signatures.insert(signature).second) {
        c.notes.push_back(fmt::format("{}: same failure as one above ({})", artifact, signature));
        return;
    }
    fmt::print("  {} failure: {}\n    raw artifact: {}\n    minimized:    {} (sha1 {})\n", c.target, first_line, raw.string(),
               input.string(), sha);
    if (!fs::exists(scene_out)) {
        // The parser's inputs, and sanitizer crashes, have no scene: the input is the reproducer.
        fmt::print("    no scene log (run `{} {}` to reproduce; add it to fuzz/corpus/{}/ once fixed)\n", c.bin.string(),
                   input.string(), c.target);
        ++c.new_failures;
        return;
    }
    const SceneOrDiagnostic parsed = read_scene_log(scene_out);
    const Scene* scene = std::get_if<Scene>(&parsed);
    if (scene == nullptr) {
        fmt::print("    the target wrote an unreadable log: {}\n", std::get<Diagnostic>(parsed).str());
        ++c.new_failures;
        return;
    }
    const std::string id = scene_content_id(*scene);
    if (auto existing = find_equal_log(replay_dir, id)) {
        fmt::print("    known: an equal log is already there: {}\n", existing->string());
        ++c.known_failures;
        return;
    }
    std::error_code ec;
    fs::create_directories(replay_dir, ec);
    const fs::path dest = replay_dir / fmt::format("fuzz-{}-{}.scene", c.target, id);
    std::string error;
    if (!write_file_atomically(dest, read_all(scene_out), &error)) {
        fmt::print("    cannot save the log: {}\n", error);
    } else {
        fmt::print("    scene log: {}  (ricochet replay {})\n", dest.string(), dest.string());
    }
    ++c.new_failures;
}

int run_fuzz(const Options& opt) {
    if (!parse_kernel(opt.kernel)) {
        fmt::print(stderr, "ricochet fuzz: error: unknown kernel '{}' (lecture-float, lecture-double, robust, exact)\n", opt.kernel);
        return 2;
    }
    const fs::path bin_dir = opt.bin_dir.empty() ? default_bin_dir() : fs::path(opt.bin_dir);
    const fs::path cache = opt.cache_dir.empty() ? default_cache_dir() : fs::path(opt.cache_dir);
    const fs::path replay_dir = opt.replay_dir.empty() ? default_replay_dir() : fs::path(opt.replay_dir);
    const fs::path src = RICOCHET_SOURCE_DIR;
    std::vector<std::string> targets = opt.targets;
    if (targets.empty())
        for (const char* t : k_targets)
            if (fs::exists(bin_dir / fmt::format("fuzz_{}", t))) targets.emplace_back(t);
    const std::string how = fmt::format(
        "build them with clang and libFuzzer:\n  CC=clang-14 CXX=clang++-14 cmake -S {} -B build-fuzz-clang -G Ninja && "
        "cmake --build build-fuzz-clang --target fuzz_parser fuzz_static fuzz_sweep fuzz_scene ricochet\n"
        "then run build-fuzz-clang/cli/ricochet fuzz (or pass --bin-dir)",
        src.string());
    if (targets.empty()) {
        fmt::print(stderr, "ricochet fuzz: error: no fuzz targets in {}; {}\n", bin_dir.string(), how);
        return 2;
    }
    std::error_code ec;
    fs::create_directories(cache, ec);
    std::vector<Campaign> cs;
    for (const std::string& t : targets) {
        if (std::find(k_targets.begin(), k_targets.end(), t) == k_targets.end()) {
            fmt::print(stderr, "ricochet fuzz: error: unknown target '{}' (parser, static, sweep, scene)\n", t);
            return 2;
        }
        Campaign c;
        c.target = t;
        c.bin = bin_dir / fmt::format("fuzz_{}", t);
        if (!fs::exists(c.bin)) {
            fmt::print(stderr, "ricochet fuzz: error: {} is missing; {}\n", c.bin.string(), how);
            return 2;
        }
        // A libFuzzer binary answers -help=1 with its usage; the gcc build's standalone driver says what it is.
        const auto [rc, out] = run_capture({c.bin.string(), "-help=1"}, {}, cache / fmt::format("probe-{}.log", t));
        if (out.find("standalone fuzz driver") != std::string::npos || out.find("Usage:") == std::string::npos) {
            fmt::print(stderr, "ricochet fuzz: error: {} is not a libFuzzer binary (a gcc build runs regression inputs only); {}\n",
                       c.bin.string(), how);
            return 2;
        }
        // The corpus is per kernel: an input that is fine under robust may fail under a lecture kernel and
        // would stop every run at start-up.
        c.dir = cache / t / opt.kernel;
        c.corpus = c.dir / "corpus";
        c.artifacts = c.dir / "artifacts";
        c.log = c.dir / "campaign.log";
        fs::create_directories(c.corpus, ec);
        fs::create_directories(c.artifacts, ec);
        fs::remove(c.log, ec);
        c.dict = src / "fuzz" / fmt::format("{}.dict", t);
        // Seeds: the committed regression inputs (and the replays for the parser). A lecture kernel starts
        // from its own corpus only: committed inputs may be known failures of it.
        const bool lecture = opt.kernel.starts_with("lecture");
        if (!lecture) {
            if (fs::exists(src / "fuzz" / "corpus" / t)) c.seeds.push_back(src / "fuzz" / "corpus" / t);
            if (t == "parser" && fs::exists(src / "replays")) c.seeds.push_back(src / "replays");
        }
        c.artifacts_before = list_artifacts(c.artifacts);
        cs.push_back(std::move(c));
    }
    const int jobs = opt.jobs > 0 ? opt.jobs : static_cast<int>(cs.size());
    for (std::size_t i = 0; i < cs.size(); ++i)
        cs[i].workers = std::max(1, jobs / static_cast<int>(cs.size()) + (static_cast<int>(i) < jobs % static_cast<int>(cs.size()) ? 1 : 0));

    fmt::print("ricochet fuzz: kernel {}, {} s, {} target(s), {} worker(s)\n  binaries {}\n  corpus   {}\n  logs to  {}\n",
               opt.kernel, opt.time, cs.size(), jobs, bin_dir.string(), cache.string(), replay_dir.string());
    const auto t0 = Clock::now();
    const auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - t0).count(); };
    const auto start_worker = [&](Campaign& c, std::size_t w) {
        const double left = opt.time - elapsed();
        std::vector<std::string> argv = {c.bin.string(),
                                         fmt::format("-max_total_time={}", std::max(1, static_cast<int>(left))),
                                         "-timeout=10",
                                         "-rss_limit_mb=2048",
                                         "-print_final_stats=1",
                                         "-artifact_prefix=" + c.artifacts.string() + "/"};
        if (fs::exists(c.dict)) argv.push_back("-dict=" + c.dict.string());
        argv.push_back(c.corpus.string());
        for (const auto& s : c.seeds) argv.push_back(s.string());
        c.pids[w] = spawn(argv, {"RICOCHET_KERNEL=" + opt.kernel}, c.log);
        c.started[w] = Clock::now();
    };
    for (Campaign& c : cs) {
        c.pids.assign(static_cast<std::size_t>(c.workers), -1);
        c.started.assign(static_cast<std::size_t>(c.workers), Clock::now());
        for (std::size_t w = 0; w < c.pids.size(); ++w) start_worker(c, w);
    }
    double last_print = 0;
    for (;;) {
        bool any = false;
        for (Campaign& c : cs) {
            for (std::size_t w = 0; w < c.pids.size(); ++w) {
                if (c.pids[w] < 0) continue;
                int status = 0;
                const pid_t r = waitpid(c.pids[w], &status, WNOHANG);
                if (r == 0) {
                    any = true;
                    if (elapsed() > opt.time + 60) kill(c.pids[w], SIGTERM);  // a worker that ignores its time limit
                    continue;
                }
                c.pids[w] = -1;
                poll_log(c);
                const bool clean = WIFEXITED(status) && WEXITSTATUS(status) == 0;
                if (!clean && std::chrono::duration<double>(Clock::now() - c.started[w]).count() < 1) ++c.quick_crashes;
                // A worker stops at its first failure; restart it while time is left, unless it keeps failing
                // at start-up (a corpus input that fails).
                if (!clean && elapsed() < opt.time - 1 && c.restarts < 50 && c.quick_crashes < 5) {
                    ++c.restarts;
                    start_worker(c, w);
                    any = true;
                }
            }
            poll_log(c);
        }
        if (!any) break;
        if (elapsed() - last_print >= 5) {
            last_print = elapsed();
            for (Campaign& c : cs) {
                const std::size_t failures = list_artifacts(c.artifacts).size() - c.artifacts_before.size();
                fmt::print("[{:4.0f}s] {:<7} exec/s {:>7}  cov {:>5}  corpus {:>5}  failures {}\n", elapsed(), c.target,
                           human(static_cast<double>(c.exec_s)), c.cov, c.corpus_size, failures);
            }
            std::fflush(stdout);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
    }
    const double wall = elapsed();
    // Runs: the sum over every worker process of its last "#N" (read from the whole log).
    for (Campaign& c : cs) {
        const std::string all = read_all(c.log);
        std::uint64_t runs = 0, last = 0;
        std::istringstream in(all);
        for (std::string line; std::getline(in, line);) {
            if (line.size() > 1 && line[0] == '#' && line[1] >= '0' && line[1] <= '9') {
                const std::uint64_t n = number_after(line, "#").value_or(0);
                // A new process starts counting again from 1.
                if (n < last) runs += last;
                last = n;
            }
            if (auto n = number_after(line, "stat::number_of_executed_units: ")) runs += *n, last = 0;
        }
        c.runs_done = runs + last;
        c.seconds = wall;
        c.corpus_size = count_files(c.corpus);
    }
    // Failures: minimize, convert, save.
    bool any_new = false;
    for (Campaign& c : cs) {
        std::set<std::string> fresh;
        for (const std::string& a : list_artifacts(c.artifacts))
            if (!c.artifacts_before.contains(a) && !a.starts_with("slow-unit-"))
                fresh.insert(a);
        std::set<std::string> signatures;
        int converted = 0;
        for (const std::string& a : fresh) {
            if (converted++ == k_max_failures_converted) {
                c.notes.push_back(fmt::format("{} more failure artifact(s) left unconverted in {}", fresh.size() - k_max_failures_converted,
                                              c.artifacts.string()));
                break;
            }
            handle_failure(c, opt, replay_dir, a, signatures);
        }
        for (const auto& n : c.notes) fmt::print("  {}: {}\n", c.target, n);
        any_new = any_new || c.new_failures > 0;
    }
    // Merge: keep only the inputs that add coverage, for the next campaign.
    if (!opt.no_merge) {
        for (Campaign& c : cs) {
            const fs::path merged = c.dir / "corpus.merged";
            fs::remove_all(merged, ec);
            fs::create_directories(merged, ec);
            const auto [rc, out] = run_capture({c.bin.string(), "-merge=1", "-timeout=10", merged.string(), c.corpus.string()},
                                               {"RICOCHET_KERNEL=" + opt.kernel}, c.dir / "merge.log");
            if (rc == 0) {
                fs::remove_all(c.corpus, ec);
                fs::rename(merged, c.corpus, ec);
                c.corpus_size = count_files(c.corpus);
            } else {
                fmt::print("  {}: merge failed (exit {}), corpus kept as it was; see {}\n", c.target, rc, (c.dir / "merge.log").string());
            }
        }
    }
    fmt::print("\n{:<8} {:>10} {:>9} {:>6} {:>7} {:>13} {:>6}\n", "target", "runs", "exec/s", "cov", "corpus", "new failures",
               "known");
    for (const Campaign& c : cs)
        fmt::print("{:<8} {:>10} {:>9} {:>6} {:>7} {:>13} {:>6}\n", c.target, c.runs_done,
                   human(static_cast<double>(c.runs_done) / std::max(c.seconds, 1e-9) / c.workers), c.cov, c.corpus_size,
                   c.new_failures, c.known_failures);
    fmt::print("kernel {}, {:.0f} s, exec/s per worker; {}\n", opt.kernel, wall,
               any_new ? "NEW FAILURES (exit 1)" : "no new failures");
    return any_new ? 1 : 0;
}

}  // namespace

void register_fuzz(CLI::App& app) {
    auto opt = std::make_shared<Options>();
    CLI::App* sub = app.add_subcommand("fuzz", "run a libFuzzer campaign; failures become scene logs");
    sub->add_option("--target", opt->targets, "target(s): parser, static, sweep, scene (default: all built)");
    sub->add_option("--kernel", opt->kernel, "kernel under test (default robust)");
    sub->add_option("--time", opt->time, "seconds to fuzz (default 60)")->check(CLI::PositiveNumber);
    sub->add_option("--jobs", opt->jobs, "worker processes in all, shared out among the targets (default: one per target)")
        ->check(CLI::PositiveNumber);
    sub->add_option("--bin-dir", opt->bin_dir, "folder of the fuzz_* binaries (default: this build's fuzz/, or $RICOCHET_FUZZ_BIN_DIR)");
    sub->add_option("--cache-dir", opt->cache_dir,
                    "working corpus and artifacts (default $RICOCHET_FUZZ_CACHE, $XDG_CACHE_HOME/ricochet/fuzz or ~/.cache/ricochet/fuzz)");
    sub->add_option("--replay-dir", opt->replay_dir, "where failure logs go (default $RICOCHET_REPLAY_DIR or the source tree's replays/)");
    sub->add_flag("--no-merge", opt->no_merge, "skip the corpus merge at the end");
    sub->callback([opt] { throw Exit{run_fuzz(*opt)}; });
}

}  // namespace ricochet::cli
