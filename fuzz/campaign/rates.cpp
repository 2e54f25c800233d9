// A campaign's rates (rates.hpp): the runs a worker's log reports, and runs over each worker's own time.
#include "rates.hpp"

namespace ricochet::fuzz {

std::optional<std::uint64_t> number_after(std::string_view line, std::string_view key) {
    const auto at = line.find(key);
    if (at == std::string_view::npos) return std::nullopt;
    std::size_t i = at + key.size();
    while (i < line.size() && line[i] == ' ') ++i;
    std::uint64_t v = 0;
    bool any = false;
    while (i < line.size() && line[i] >= '0' && line[i] <= '9') v = v * 10 + static_cast<std::uint64_t>(line[i++] - '0'), any = true;
    return any ? std::optional(v) : std::nullopt;
}

std::uint64_t runs_in_log(std::string_view log) {
    std::uint64_t runs = 0, last = 0;
    while (!log.empty()) {
        const auto end = log.find('\n');
        const std::string_view line = log.substr(0, end);
        log = end == std::string_view::npos ? std::string_view() : log.substr(end + 1);
        // "#RUNS\tINITED|NEW|pulse|REDUCE|DONE cov: ..."; a new process starts counting again from 1.
        if (line.size() > 1 && line[0] == '#' && line[1] >= '0' && line[1] <= '9') {
            const std::uint64_t n = number_after(line, "#").value_or(0);
            if (n < last) runs += last;
            last = n;
        }
        // The process's own total, printed last (-print_final_stats=1): it replaces its "#N" lines.
        if (auto n = number_after(line, "stat::number_of_executed_units: ")) runs += *n, last = 0;
    }
    return runs + last;
}

double exec_per_s(const WorkerTally& worker) {
    // Degenerate: a worker that never ran.
    if (worker.seconds <= 0) return 0;
    return static_cast<double>(worker.runs) / worker.seconds;
}

double exec_per_s_per_worker(std::span<const WorkerTally> workers) {
    WorkerTally sum;
    for (const WorkerTally& w : workers) sum.runs += w.runs, sum.seconds += w.seconds;
    return exec_per_s(sum);
}

double exec_per_s_in_all(std::span<const WorkerTally> workers) {
    double sum = 0;
    for (const WorkerTally& w : workers) sum += exec_per_s(w);
    return sum;
}

}  // namespace ricochet::fuzz
