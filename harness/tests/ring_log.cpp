// Prints the ring scene of ring_scene.hpp as a log, for measuring `ricochet reduce` on a large failing log:
//   ring_log N KERNEL FRAMES > ring.scene
#include <cstdio>
#include <cstdlib>
#include <string>

#include <fmt/format.h>

#include "ricochet/scene_log.hpp"
#include "ring_scene.hpp"

int main(int argc, char** argv) {
    if (argc != 4) {
        fmt::print(stderr, "usage: ring_log WALLS KERNEL FRAMES\n");
        return 2;
    }
    const auto kernel = ricochet::parse_kernel(argv[2]);
    if (!kernel) {
        fmt::print(stderr, "ring_log: unknown kernel '{}'\n", argv[2]);
        return 2;
    }
    fmt::print("{}", ricochet::write_scene_log(ricochet::test::ring_scene(std::strtoull(argv[1], nullptr, 10), *kernel,
                                                                         std::strtoll(argv[3], nullptr, 10))));
    return 0;
}
