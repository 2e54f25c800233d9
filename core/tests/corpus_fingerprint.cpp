// Prints, for every log given, under each of the four kernels, with the log's own checks and then with all
// fourteen: the run hash, the frames run and the first failure's or the step error's message (whose numbers
// come from the exact oracle, truth.cpp), one record per run. Built against the core on each big-number backend
// (bignum_corpus_test.sh compares the two outputs byte for byte):
//   corpus_fingerprint LOG...
#include <variant>

#include <fmt/format.h>

#include "ricochet/check.hpp"
#include "ricochet/checks.hpp"
#include "ricochet/format.hpp"
#include "ricochet/kernel.hpp"
#include "ricochet/scene_log.hpp"

int main(int argc, char** argv) {
    using namespace ricochet;
    int status = 0;
    for (int i = 1; i < argc; ++i) {
        const auto parsed = read_scene_log(argv[i]);
        if (const auto* d = std::get_if<Diagnostic>(&parsed)) {
            fmt::print(stderr, "{}\n", d->str());
            status = 2;
            continue;
        }
        const Scene& scene = std::get<Scene>(parsed);
        CheckOptions quiet;
        quiet.keep_events = false;
        for (const KernelId k : k_all_kernels) {
            for (const bool all : {false, true}) {
                const std::span<const Check> checks = all ? std::span<const Check>(k_all_checks) : scene.checks;
                const CheckedRun run = run_checked(scene, k, scene.frames, checks, quiet);
                fmt::print("{} {} {} hash {:016x} frames {}\n  {}\n", argv[i], k, all ? "all-checks" : "log-checks",
                           run.hash, run.frames_run,
                           run.failure ? run.failure->str() : run.error ? run.error->message() : "ok");
            }
        }
    }
    return status;
}
