// "Did you mean" (suggest.hpp).
#include "suggest.hpp"

#include <algorithm>

namespace ricochet::cli {

std::size_t edit_distance(std::string_view a, std::string_view b) {
    // d[i][j]: distance between a's first i and b's first j characters, three rows kept.
    std::vector<std::size_t> prev2(b.size() + 1), prev(b.size() + 1), cur(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        cur[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + cost});
            // A swap of two adjacent characters counts once.
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) cur[j] = std::min(cur[j], prev2[j - 2] + 1);
        }
        std::swap(prev2, prev);
        std::swap(prev, cur);
    }
    return prev[b.size()];
}

std::optional<std::string> nearest_name(std::string_view word, const std::vector<std::string>& names) {
    std::optional<std::string> best;
    std::size_t best_d = 3;  // a typo is at most 2 edits away
    for (const std::string& n : names) {
        const std::size_t d = edit_distance(word, n);
        if (d < best_d && d < word.size()) {
            best = n;
            best_d = d;
        }
    }
    return best;
}

}  // namespace ricochet::cli
