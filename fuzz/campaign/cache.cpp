// The cache folder of a campaign (cache.hpp).
#include "cache.hpp"

#include <cstdlib>
#include <system_error>

#include <fmt/format.h>

#include "cache_lock.hpp"
#include "process.hpp"
#include "ricochet_app/stop_signal.hpp"

namespace ricochet::fuzz {

namespace fs = std::filesystem;

fs::path default_cache_dir() {
    if (const char* d = std::getenv("RICOCHET_FUZZ_CACHE"); d != nullptr && *d != '\0') return d;
    if (const char* x = std::getenv("XDG_CACHE_HOME"); x != nullptr && *x != '\0') return fs::path(x) / "ricochet" / "fuzz";
    if (const char* h = std::getenv("HOME"); h != nullptr && *h != '\0') return fs::path(h) / ".cache" / "ricochet" / "fuzz";
    // Degenerate: no home to keep a cache in; the caller asks for --cache-dir.
    return {};
}

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

void merge_corpus(TargetRun& run, const Plan& plan) {
    const Budget& budget = plan.budget;
    // One merge of a target's corpus at a time; another campaign's workers may still add inputs meanwhile.
    const CacheLock lock(plan.cache, fmt::format("merging the {} corpus", run.target), budget.deadline());
    if (lock.timed_out()) {
        run.merge = "out of time";
        budget.say(run.target, "merge not done: another campaign held the cache's lock until the time was up");
        return;
    }
    std::error_code ec;
    // The inputs this merge judges: those there now. One a worker adds later is not judged, so it stays.
    std::set<std::string> judged;
    for (const auto& e : fs::directory_iterator(run.corpus, ec))
        if (e.is_regular_file()) judged.insert(e.path().filename().string());
    const fs::path merged = run.work / "corpus.merged";
    fs::create_directories(merged, ec);
    const fs::path log = run.work / "merge.log";
    budget.say(run.target, fmt::format("merging the corpus ({} inputs)", judged.size()));
    const Clock::time_point began = Clock::now();
    int ticks = 0;
    // libFuzzer writes what crashes, runs out of memory or time in the merge (one process runs every input) where
    // -artifact_prefix says, by default the folder the campaign was started from: the campaign's own folder instead.
    const RunResult merge = run_bounded({run.bin.string(), "-merge=1", "-timeout=10",
                                         "-artifact_prefix=" + (run.work / "merge-").string(), merged.string(),
                                         run.corpus.string()},
                                        {"RICOCHET_KERNEL=" + plan.kernel_env}, log, budget.deadline(), [&] {
                                            if (++ticks % k_progress_every_s == 0)
                                                budget.say(run.target, fmt::format("merging, {:.0f} s so far",
                                                                                   std::chrono::duration<double>(Clock::now() - began).count()));
                                        });
    if (merge.cut) {
        run.merge = "out of time";
        budget.say(run.target, "merge cut at the time limit: the corpus stays unmerged, for the next campaign's merge");
        fs::remove_all(merged, ec);
        return;
    }
    if (app::stop_requested()) {
        run.merge = "stopped";
        fs::remove_all(merged, ec);
        return;
    }
    if (merge.rc != 0) {
        run.merge = "failed";
        fmt::print("  {}: merge failed (exit {}), corpus kept as it was; its output:\n{}\n", run.target, merge.rc, merge.out);
        fs::remove_all(merged, ec);
        return;
    }
    // The kept inputs go in first (named by their SHA-1, as libFuzzer names corpus files: the same name is
    // the same bytes), then the judged ones left out are removed: the corpus is never without an input it keeps.
    std::set<std::string> kept;
    for (const auto& e : fs::directory_iterator(merged, ec)) {
        const std::string name = e.path().filename().string();
        kept.insert(name);
        if (!judged.contains(name)) fs::rename(e.path(), run.corpus / name, ec);
    }
    for (const std::string& name : judged)
        if (!kept.contains(name)) fs::remove(run.corpus / name, ec);
    fs::remove_all(merged, ec);
    run.corpus_size = count_files(run.corpus);
    run.merge = "done";
}

}  // namespace ricochet::fuzz
