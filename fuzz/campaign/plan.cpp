// The campaign's plan (plan.hpp): default folders, the targets this build has, one run per target.
#include "plan.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>

#include <fmt/format.h>

#include "cache.hpp"
#include "process.hpp"
#include "ricochet/kernel.hpp"
#include "ricochet/kernel_spec.hpp"
#include "ricochet/plugin_loader.hpp"
#include "ricochet/scene_log.hpp"
#include "ricochet_app/project.hpp"
#include "ricochet_peers/peers.hpp"
#include "run_dir.hpp"

namespace ricochet::fuzz {

std::string_view status_name(FailureStatus status) {
    switch (status) {
        case FailureStatus::saved: return "saved";
        case FailureStatus::known: return "known";
        case FailureStatus::no_log: return "no-log";
        case FailureStatus::unsaved: return "unsaved";
        case FailureStatus::flaky: return "flaky";
        case FailureStatus::duplicate: return "duplicate";
        case FailureStatus::slow: return "slow";
        case FailureStatus::pending: return "pending";
    }
    return "pending";
}

bool FailureRecord::counts_as_new() const {
    return status == FailureStatus::saved || status == FailureStatus::no_log || status == FailureStatus::unsaved ||
           status == FailureStatus::flaky || status == FailureStatus::pending;
}

namespace {

namespace fs = std::filesystem;

/// The folder that holds this build's fuzz binaries.
fs::path default_bin_dir() {
    if (const char* d = std::getenv("RICOCHET_FUZZ_BIN_DIR"); d != nullptr && *d != '\0') return d;
    const fs::path baked = fs::path(RICOCHET_BINARY_DIR) / "fuzz";
    if (fs::exists(baked)) return baked;
    // Next to the executable: BUILD/cli/ricochet → BUILD/fuzz.
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    return ec ? baked : self.parent_path().parent_path() / "fuzz";
}

bool known_target(const std::string& t) {
    return std::find(k_campaign_targets.begin(), k_campaign_targets.end(), t) != k_campaign_targets.end();
}

/// How to get libFuzzer binaries, for the messages that find none.
std::string how_to_build(const Plan& plan) {
    return fmt::format(
        "build them with clang and libFuzzer:\n  CC=clang-14 CXX=clang++-14 cmake -S {} -B build-fuzz-clang -G Ninja && "
        "cmake --build build-fuzz-clang --target fuzz_parser fuzz_static fuzz_sweep fuzz_scene fuzz_disc fuzz_meet "
        "ricochet\n"
        "then run build-fuzz-clang/cli/ricochet fuzz (or pass --bin-dir)",
        plan.source.string());
}

/// The last lines of out that are not empty, at most n, each indented.
std::string last_lines(const std::string& out, std::size_t n) {
    std::vector<std::string> lines;
    std::istringstream in(out);
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) lines.push_back(line);
    std::string text;
    for (std::size_t i = lines.size() > n ? lines.size() - n : 0; i < lines.size(); ++i) text += "\n  " + lines[i];
    return text;
}

/// Writes a few bytes into dir and removes them: a cache on a full disk (or one this user cannot write in)
/// would lose every worker's output, and the binaries' answers with it. The error, or empty.
std::string cannot_write_in(const fs::path& dir) {
    const fs::path probe = dir / "write-probe";
    std::string error;
    {
        std::ofstream out(probe, std::ios::binary);
        // A libFuzzer worker's usage text is about this long.
        const std::string bytes(4096, '\n');
        errno = 0;
        if (out) out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        if (out) out.flush();
        if (!out) error = errno != 0 ? std::strerror(errno) : "the write failed";
    }
    std::error_code ec;
    fs::remove(probe, ec);
    return error;
}

/// Why r.bin cannot be a worker, from what `r.bin -help=1` printed under the campaign's own RICOCHET_KERNEL (the
/// disc target asks its kernel before anything else, and the caller's environment must not decide); empty if it
/// is a libFuzzer binary.
std::string probe_binary(const TargetRun& r, const Plan& plan) {
    const auto [rc, out] = run_capture({r.bin.string(), "-help=1"}, {"RICOCHET_KERNEL=" + plan.kernel_env},
                                       plan.run_dir / fmt::format("probe-{}.log", r.target));
    // A libFuzzer binary answers -help=1 with its usage.
    if (rc == 0 && out.find("Usage:") != std::string::npos) return {};
    // The gcc build's standalone driver says what it is.
    if (out.find("standalone fuzz driver") != std::string::npos)
        return fmt::format("{} is not a libFuzzer binary (a gcc build runs regression inputs only); {}", r.bin.string(),
                           how_to_build(plan));
    // It could not be started at all.
    if (rc == 127 && out.starts_with("cannot start ")) return out;
    // It refused to start, and said why (a kernel it cannot fuzz, a plug-in it cannot load, a full disk): its words.
    if (rc != 0 && out.find_first_not_of(" \n") != std::string::npos)
        return fmt::format("{} -help=1 (RICOCHET_KERNEL={}) ended with exit {} instead of printing libFuzzer's usage; its last "
                           "words:{}",
                           r.bin.string(), plan.kernel_env, rc, last_lines(out, 4));
    if (rc != 0) return fmt::format("{} -help=1 (RICOCHET_KERNEL={}) ended with exit {} and printed nothing", r.bin.string(),
                                    plan.kernel_env, rc);
    return fmt::format("{} is not a libFuzzer binary (-help=1 printed no libFuzzer usage{}); {}", r.bin.string(),
                       out.empty() ? ", nor anything else" : "", how_to_build(plan));
}

/// The kernel, the folders and the run folder every plan needs; nothing after printing why not (exit 2).
std::optional<Plan> base_plan(const std::string& kernel_spec, const std::string& bin_dir, const std::string& cache_dir,
                              const std::string& replay_dir, std::string_view word, KernelId* kernel_out) {
    const std::string command = fmt::format("ricochet {}", word);
    peers::register_peer_kernels();
    // A plug-in is loaded here too: a bad one is refused before any worker starts, and its name is known.
    std::string kernel_error;
    const auto kernel = resolve_kernel(kernel_spec, &kernel_error);
    if (!kernel) {
        fmt::print(stderr, "{}: error: {}\n", command, kernel_error);
        return std::nullopt;
    }
    *kernel_out = *kernel;
    Plan plan;
    plan.kernel_name = kernel_name(*kernel);
    plan.kernel_env = kernel_spec;
    if (const PluginInfo* plugin = plugin_info(*kernel)) {
        // The workers start elsewhere (another folder): they get the file by its absolute path.
        plan.plugin = plugin->path;
        plan.kernel_env = std::string(k_plugin_spec_prefix) + plugin->path.string();
    }
    plan.bin_dir = bin_dir.empty() ? default_bin_dir() : fs::path(bin_dir);
    plan.cache = cache_dir.empty() ? default_cache_dir() : fs::path(cache_dir);
    if (plan.cache.empty()) {
        fmt::print(stderr, "{}: error: no cache folder (HOME, XDG_CACHE_HOME and RICOCHET_FUZZ_CACHE are unset); "
                           "pass --cache-dir DIR\n", command);
        return std::nullopt;
    }
    // Failures are saved into the project's corpus (--replay-dir, $RICOCHET_REPLAY_DIR, or the project
    // folder's replays/), never into the tree this binary was built from.
    const auto project = app::find_project(replay_dir);
    if (!project) {
        fmt::print(stderr, "{}\n", app::no_project_message(word, "run it in a project folder or pass --replay-dir DIR"));
        return std::nullopt;
    }
    std::error_code ec;
    // Degenerate: a replay "folder" that is a file (or anything else but a folder) would take no log.
    if (fs::exists(project->replay_dir, ec) && !fs::is_directory(project->replay_dir, ec)) {
        const std::string named_by = !replay_dir.empty() ? "--replay-dir" : fmt::format("${}", app::k_replay_dir_env);
        fmt::print(stderr, "{}: error: {} {}: not a folder (failure logs are saved in a folder)\n", command, named_by,
                   project->replay_dir.string());
        return std::nullopt;
    }
    plan.replay_dir = project->replay_dir;
    plan.project = project->root;
    plan.source = RICOCHET_SOURCE_DIR;
    return plan;
}

/// Makes plan's run folder in its cache and checks that the cache can be written; false after printing why not.
bool make_run_folder(Plan& plan, const char* command) {
    std::error_code ec;
    fs::create_directories(plan.cache, ec);
    // This campaign's own folder: another campaign on the same cache never touches it.
    std::string error;
    const auto run_dir = make_run_dir(plan.cache, &error);
    if (!run_dir) {
        fmt::print(stderr, "{}: error: {}\n", command, error);
        return false;
    }
    plan.run_dir = *run_dir;
    if (const std::string why = cannot_write_in(plan.run_dir); !why.empty()) {
        fmt::print(stderr, "{}: error: cannot write in the cache folder {}: {} (a full disk? pass --cache-dir DIR elsewhere)\n",
                   command, plan.cache.string(), why);
        fs::remove_all(plan.run_dir, ec);
        return false;
    }
    return true;
}

/// The run of target t in plan (its binary checked, its folders made), or nothing after printing why not.
std::optional<TargetRun> target_run(const Plan& plan, const std::string& t, const char* command) {
    TargetRun r;
    r.target = t;
    r.bin = plan.bin_dir / fmt::format("fuzz_{}", t);
    if (!fs::exists(r.bin)) {
        fmt::print(stderr, "{}: error: {} is missing; {}\n", command, r.bin.string(), how_to_build(plan));
        return std::nullopt;
    }
    if (const std::string why = probe_binary(r, plan); !why.empty()) {
        fmt::print(stderr, "{}: error: {}\n", command, why);
        return std::nullopt;
    }
    // The corpus is per kernel: an input that is fine under robust may fail under a lecture kernel and
    // would stop every run at start-up.
    r.dir = plan.cache / t / plan.kernel_name;
    r.corpus = r.dir / "corpus";
    r.kept = r.dir / "artifacts";
    r.pending = r.dir / "pending";
    r.work = plan.run_dir / t;
    r.artifacts = r.work / "artifacts";
    r.dict = plan.source / "fuzz" / fmt::format("{}.dict", t);
    std::error_code ec;
    for (const fs::path& d : {r.corpus, r.kept, r.pending, r.artifacts}) {
        fs::create_directories(d, ec);
        if (ec) {
            fmt::print(stderr, "{}: error: {}: cannot create the folder: {}\n", command, d.string(), ec.message());
            return std::nullopt;
        }
    }
    // Where this run's failure artifacts go if it ends without converting them, even by SIGKILL: the next
    // campaign that removes its folder moves them there (run_dir.hpp).
    if (std::string error; !write_file_atomically(r.work / k_pending_to, fs::absolute(r.pending).string(), &error)) {
        fmt::print(stderr, "{}: error: {}\n", command, error);
        return std::nullopt;
    }
    return r;
}

}  // namespace

std::optional<Plan> make_plan(const CampaignOptions& opt, const Budget& budget) {
    constexpr const char* command = "ricochet fuzz";
    KernelId kernel{};
    std::optional<Plan> made = base_plan(opt.kernel, opt.bin_dir, opt.cache_dir, opt.replay_dir, "fuzz", &kernel);
    if (!made) return std::nullopt;
    Plan& plan = *made;
    plan.budget = budget;
    plan.known_fails = !kernel_ops(kernel).failures_documented;
    std::vector<std::string> targets = opt.targets;
    // The disc target needs a kernel that steps discs, the meet target one that steps balls that meet: each left out
    // of the default set for a kernel that does not (saying so), refused when named.
    const bool steps_discs = kernel_ops(kernel).step_disc != nullptr;
    const bool steps_meets = steps_discs && kernel_ops(kernel).meet_rule != MeetRule::none;
    const auto named = [&](std::string_view t) {
        return std::find(targets.begin(), targets.end(), t) != targets.end();
    };
    if (targets.empty()) {
        for (std::string_view t : k_campaign_targets)
            if (fs::exists(plan.bin_dir / fmt::format("fuzz_{}", t))) {
                if (t == "disc" && !steps_discs) {
                    fmt::print(stderr, "ricochet fuzz: note: leaving out target disc: kernel '{}' steps point balls only\n",
                               plan.kernel_name);
                    continue;
                }
                if (t == "meet" && !steps_meets) {
                    fmt::print(stderr,
                               "ricochet fuzz: note: leaving out target meet: kernel '{}' does not step balls that meet\n",
                               plan.kernel_name);
                    continue;
                }
                targets.emplace_back(t);
            }
    } else if (!steps_discs && named("disc")) {
        fmt::print(stderr, "ricochet fuzz: error: target disc needs a kernel that steps discs (lecture-float, lecture-double, "
                           "robust, exact); kernel '{}' steps point balls only\n", plan.kernel_name);
        return std::nullopt;
    } else if (!steps_meets && named("meet")) {
        fmt::print(stderr, "ricochet fuzz: error: target meet needs a kernel that steps balls that meet (lecture-float, "
                           "lecture-double, robust, exact); kernel '{}' does not\n", plan.kernel_name);
        return std::nullopt;
    }
    // Degenerate: nothing to fuzz.
    if (targets.empty()) {
        fmt::print(stderr, "ricochet fuzz: error: no fuzz targets in {}; {}\n", plan.bin_dir.string(), how_to_build(plan));
        return std::nullopt;
    }
    for (const std::string& t : targets)
        if (!known_target(t)) {
            fmt::print(stderr, "ricochet fuzz: error: unknown target '{}' (parser, static, sweep, scene, disc, meet)\n", t);
            return std::nullopt;
        }
    if (!make_run_folder(plan, command)) return std::nullopt;
    std::error_code ec;
    for (const std::string& t : targets) {
        std::optional<TargetRun> r = target_run(plan, t, command);
        if (!r) {
            fs::remove_all(plan.run_dir, ec);
            return std::nullopt;
        }
        // Seeds, read only: the project's committed regression inputs (PROJECT/fuzz/corpus/TARGET, else the
        // target's own, committed with the tool), and the project's replays for the parser. A kernel whose
        // failures are documented (a lecture baseline, a peer, a plug-in) starts from its own corpus only: committed
        // inputs may be known failures of it.
        if (!kernel_ops(kernel).failures_documented) {
            const fs::path mine = plan.project.empty() ? fs::path() : plan.project / "fuzz" / "corpus" / t;
            const fs::path tools = plan.source / "fuzz" / "corpus" / t;
            if (!mine.empty() && fs::is_directory(mine, ec))
                r->seeds.push_back(mine);
            else if (fs::is_directory(tools, ec))
                r->seeds.push_back(tools);
            if (t == "parser" && fs::is_directory(plan.replay_dir, ec)) r->seeds.push_back(plan.replay_dir);
        }
        plan.runs.push_back(std::move(*r));
    }
    // --jobs workers shared out: each target gets jobs / targets, the first jobs % targets one more.
    const int n = static_cast<int>(plan.runs.size());
    plan.jobs = opt.jobs > 0 ? opt.jobs : n;
    for (int i = 0; i < n; ++i) plan.runs[std::size_t(i)].workers = std::max(1, plan.jobs / n + (i < plan.jobs % n ? 1 : 0));
    return plan;
}

std::optional<Plan> make_convert_plan(const ConvertOptions& opt, const std::string& target, const std::string& kernel_spec) {
    constexpr const char* command = "ricochet fuzz convert";
    if (!known_target(target)) {
        fmt::print(stderr, "{}: error: unknown target '{}' (parser, static, sweep, scene, disc, meet)\n", command, target);
        return std::nullopt;
    }
    KernelId kernel{};
    std::optional<Plan> made = base_plan(kernel_spec, opt.bin_dir, opt.cache_dir, opt.replay_dir, "fuzz convert", &kernel);
    if (!made) return std::nullopt;
    Plan& plan = *made;
    if (!make_run_folder(plan, command)) return std::nullopt;
    std::optional<TargetRun> r = target_run(plan, target, command);
    if (!r) {
        std::error_code ec;
        fs::remove_all(plan.run_dir, ec);
        return std::nullopt;
    }
    plan.runs.push_back(std::move(*r));
    plan.jobs = 0;
    return plan;
}

}  // namespace ricochet::fuzz
