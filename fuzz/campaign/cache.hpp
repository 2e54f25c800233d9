// The cache folder of a campaign: where it is, the artifacts libFuzzer leaves in it, and the working
// corpus merged down to the inputs that add coverage.
#pragma once

#include <cstddef>
#include <filesystem>
#include <set>
#include <string>

#include "plan.hpp"

namespace ricochet::fuzz {

/// $RICOCHET_FUZZ_CACHE, else $XDG_CACHE_HOME/ricochet/fuzz, else ~/.cache/ricochet/fuzz; empty if none
/// of them is set (never a folder in the source or build tree).
std::filesystem::path default_cache_dir();

/// The names of libFuzzer's artifacts in dir (crash-, timeout-, oom-, leak-, slow-unit- files).
std::set<std::string> list_artifacts(const std::filesystem::path& dir);

/// Regular files directly in dir.
std::size_t count_files(const std::filesystem::path& dir);

/// Shrinks run's corpus to its -merge=1 minimization (the inputs that add coverage), holding the cache's
/// lock (cache_lock.hpp); inputs added by another campaign during the merge stay. Keeps the corpus as it
/// was if the merge fails (then it prints the merge's output), is stopped, or does not end by plan's deadline (it
/// is killed then). Prints a progress line as it starts and every few seconds; sets run.merge (plan.hpp) and
/// updates run.corpus_size.
void merge_corpus(TargetRun& run, const Plan& plan);

}  // namespace ricochet::fuzz
