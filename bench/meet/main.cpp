// ricochet_meet_bench [--quick | --smoke] [--seed S] [--frames F]: `ricochet bench meet` on its own.
#include <fmt/format.h>

#include <cstdlib>
#include <string_view>

#include "meet_bench.hpp"

int main(int argc, char** argv) {
    using ricochet::meet_bench::MeetSize;
    MeetSize size = MeetSize::full;
    std::uint64_t seed = 20261123;  // as `ricochet bench`
    std::int64_t frames = 0;
    for (int i = 1; i < argc; ++i) {
        const std::string_view a = argv[i];
        if (a == "--quick" && size == MeetSize::full) {
            size = MeetSize::quick;
        } else if (a == "--smoke" && size == MeetSize::full) {
            size = MeetSize::smoke;
        } else if (a == "--seed" && i + 1 < argc) {
            seed = std::strtoull(argv[++i], nullptr, 10);
        } else if (a == "--frames" && i + 1 < argc) {
            frames = std::strtoll(argv[++i], nullptr, 10);
        } else {
            fmt::print(stderr, "usage: ricochet_meet_bench [--quick | --smoke] [--seed S] [--frames F]\n");
            return 2;
        }
    }
    return ricochet::meet_bench::run_meet_bench(size, seed, frames);
}
