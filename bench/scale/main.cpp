// ricochet_scale_bench [--quick | --smoke] [--meet] [--threads N] [--out DIR]: the scale benchmark on its own (--meet:
// its meet sweep alone).
#include <fmt/format.h>

#include <cstdlib>
#include <string>
#include <string_view>

#include "scale_bench.hpp"

int main(int argc, char** argv) {
    ricochet::ScaleSize size = ricochet::ScaleSize::full;
    unsigned threads = 0;
    std::string out = "bench-results";
    bool meet_only = false;
    for (int i = 1; i < argc; ++i) {
        const std::string_view a = argv[i];
        if (a == "--quick") {
            size = ricochet::ScaleSize::quick;
        } else if (a == "--smoke") {
            size = ricochet::ScaleSize::smoke;
        } else if (a == "--meet") {
            meet_only = true;
        } else if (a == "--threads" && i + 1 < argc) {
            threads = static_cast<unsigned>(std::strtoul(argv[++i], nullptr, 10));
        } else if (a == "--out" && i + 1 < argc) {
            out = argv[++i];
        } else {
            fmt::print(stderr, "usage: ricochet_scale_bench [--quick | --smoke] [--meet] [--threads N] [--out DIR]\n");
            return 2;
        }
    }
    return meet_only ? ricochet::run_meet_bench(size, out) : ricochet::run_scale_bench(size, threads, out);
}
