// The speed targets a benchmark run is judged against, and the verdicts it prints and writes: `ricochet bench`
// writes targets.md, `ricochet bench scale` scale_targets.md (bench/README.md, "Speed targets"); the README's table
// "Where each speed target stands" is those two files from one run. A verdict is computed from the run's own
// figures, never written by hand: met, **missed**, or "not measured" when the run has no such row (--smoke, a
// peer or a size left out).
#pragma once

#include <cmath>
#include <span>
#include <string>

#include <fmt/format.h>

#include "ricochet_bench/result_file.hpp"

namespace ricochet::bench {

/// One target and where this run stands on it.
struct Verdict {
    std::string workload{};  ///< what is measured: "sweep, uniform"
    std::string robust{};    ///< robust's figure as measured, for people: "21.8 ns"
    std::string ratio{};     ///< robust ÷ lecture-double in the same run, for people ("–" where none)
    double value = NAN;      ///< the number the target bounds; NaN: not measured in this run
    double limit = 0.0;      ///< the bound
    bool at_least = false;   ///< the target is value ≥ limit (a speed-up); else value ≤ limit (a time or a ratio)
    std::string target{};    ///< the bound, for people: "≤ 1.2×"
    std::string peers{};     ///< the peers' figures in the same run ("–" where none)
};

/// True if v's value is measured and within its bound (the bound itself counts as met).
inline bool met(const Verdict& v) {
    if (std::isnan(v.value)) return false;
    return v.at_least ? v.value >= v.limit : v.value <= v.limit;
}

/// "met", "**missed**" or "not measured": the verdict column.
inline std::string verdict_word(const Verdict& v) {
    if (std::isnan(v.value)) return "not measured";
    return met(v) ? "met" : "**missed**";
}

/// The verdicts as a Markdown table (the README's columns), one line a target.
inline std::string targets_markdown(std::span<const Verdict> verdicts) {
    std::string out = "| workload | robust | ÷ lecture-double | target | verdict | peers in the same run |\n"
                      "| --- | ---: | ---: | --- | --- | --- |\n";
    for (const Verdict& v : verdicts)
        out += fmt::format("| {} | {} | {} | {} | {} | {} |\n", v.workload, v.robust.empty() ? "–" : v.robust,
                           v.ratio.empty() ? "–" : v.ratio, v.target, verdict_word(v), v.peers.empty() ? "–" : v.peers);
    return out;
}

/// Prints the verdicts under title and writes them to path as Markdown (whole or not at all, ResultFile).
inline void report_targets(std::span<const Verdict> verdicts, const std::string& title, const std::string& path) {
    fmt::print("\n{}\n{}", title, targets_markdown(verdicts));
    ResultFile f(path);
    f.print("<!-- {} -->\n{}", title, targets_markdown(verdicts));
    f.close();
    fmt::print("wrote {}\n", path);
}

}  // namespace ricochet::bench
