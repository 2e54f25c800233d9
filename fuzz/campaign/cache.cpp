// The cache folder of a campaign (cache.hpp).
#include "cache.hpp"

#include <cstdlib>
#include <system_error>

#include <fmt/format.h>

#include "process.hpp"

namespace ricochet::fuzz {

namespace fs = std::filesystem;

fs::path default_cache_dir() {
    if (const char* d = std::getenv("RICOCHET_FUZZ_CACHE"); d != nullptr && *d != '\0') return d;
    if (const char* x = std::getenv("XDG_CACHE_HOME"); x != nullptr && *x != '\0') return fs::path(x) / "ricochet" / "fuzz";
    if (const char* h = std::getenv("HOME"); h != nullptr && *h != '\0') return fs::path(h) / ".cache" / "ricochet" / "fuzz";
    return fs::path(RICOCHET_BINARY_DIR) / ".cache" / "ricochet-fuzz";
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

void merge_corpus(TargetRun& run, const std::string& kernel) {
    std::error_code ec;
    const fs::path merged = run.dir / "corpus.merged";
    fs::remove_all(merged, ec);
    fs::create_directories(merged, ec);
    const fs::path log = run.dir / "merge.log";
    const auto [rc, out] = run_capture({run.bin.string(), "-merge=1", "-timeout=10", merged.string(), run.corpus.string()},
                                       {"RICOCHET_KERNEL=" + kernel}, log);
    if (rc != 0) {
        fmt::print("  {}: merge failed (exit {}), corpus kept as it was; see {}\n", run.target, rc, log.string());
        return;
    }
    fs::remove_all(run.corpus, ec);
    fs::rename(merged, run.corpus, ec);
    run.corpus_size = count_files(run.corpus);
}

}  // namespace ricochet::fuzz
