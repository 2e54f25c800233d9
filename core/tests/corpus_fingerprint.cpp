// Prints, for every log given, under each of the four kernels, with the log's own checks and then with all the
// checks (all seventeen, each defined for every scene): the run
// hash, the frames run and the first failure's or the step error's message (whose numbers come from the exact
// oracle, truth.cpp), or the kernel's refusal of the scene, one record per run. Built against the core on each big-number backend
// (bignum_corpus_test.sh compares the two outputs byte for byte):
//   corpus_fingerprint LOG...
#include <variant>
#include <vector>

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
        const std::vector<Check> defined(k_all_checks.begin(), k_all_checks.end());
        for (const KernelId k : k_all_kernels) {
            for (const bool all : {false, true}) {
                const std::span<const Check> checks = all ? std::span<const Check>(defined) : scene.checks;
                const char* which = all ? "all-checks" : "log-checks";
                try {
                    const CheckedRun run = run_checked(scene, k, scene.frames, checks, quiet);
                    fmt::print("{} {} {} hash {:016x} frames {}\n  {}\n", argv[i], k, which, run.hash, run.frames_run,
                               run.failure ? run.failure->str() : run.error ? run.error->message() : "ok");
                } catch (const UnsupportedScene& e) {
                    // A kernel that steps point balls only refuses a disc or a bumper.
                    fmt::print("{} {} {} refused\n  {}\n", argv[i], k, which, e.what());
                }
            }
        }
    }
    return status;
}
