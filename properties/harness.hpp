// The property harness: which kernels are under test, how a property is run (saved logs first, then
// RapidCheck), and how its shrunk counterexample becomes a scene log (reduced first, reduce.hpp).
#pragma once

#include <gtest/gtest.h>  // before rapidcheck/gtest.h, which uses it
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <filesystem>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "ricochet/kernel.hpp"
#include "ricochet/scene.hpp"

namespace ricochet {
/// Shows a Scene in RapidCheck's counterexample as the scene log it would be saved as.
void showValue(const Scene& scene, std::ostream& os);
/// Shows a kernel in GoogleTest's messages by its name ("GetParam() = my-kernel", not its byte).
void PrintTo(KernelId k, std::ostream* os);
}  // namespace ricochet

namespace ricochet::props {

/// The kernels RICOCHET_KERNEL names (one name, or several separated by commas); if unset, the kernels put under
/// test with RICOCHET_TEST_KERNEL (ricochet/properties.hpp), or robust and exact where there are none (kernels.cpp).
std::vector<KernelId> kernels_under_test();

/// The domain kernel k's properties draw from and judge in: RICOCHET_DOMAIN if set (for every kernel), else the
/// one its RICOCHET_TEST_KERNEL_IN line gives, else the full domain. A RICOCHET_DOMAIN that does not read ends the
/// program with status 2.
Domain domain_under_test(KernelId k);

/// What the program running the properties adds (set before main, read after): ricochet's own runner
/// (runner/in_tree.cpp) replays and saves into the source tree's corpus and registers the peers; a user's test
/// binary has neither.
struct RunnerDefaults {
    std::filesystem::path replay_dir;      ///< replay_dir() without RICOCHET_REPLAY_DIR; empty: found/ here
    void (*register_kernels)() = nullptr;  ///< registers kernels saved logs may name (the peers)
};
void set_runner_defaults(RunnerDefaults defaults);
/// Runs the runner's register_kernels, if any (idempotent, as register_peer_kernels is).
void register_runner_kernels();

/// The folder saved logs are replayed from: RICOCHET_REPLAY_DIR, else the runner's (ricochet's runner: the source
/// tree's replays/, the corpus), else found/ in the current folder.
std::filesystem::path replay_dir();

/// The folder kernel k's failures (and a plug-in's kept cases) are saved into: RICOCHET_REPLAY_DIR; else, for a
/// built-in kernel, the corpus (replay_dir()); else (a peer, a plug-in) found/ in the current folder, so that a
/// kernel of the user's never writes into ricochet's own corpus. Its saved logs are replayed too.
std::filesystem::path save_dir(KernelId k);

/// Why a case broke a property: the scene-log check it breaks and what was expected against what happened.
struct Failure {
    Check check = Check::no_tunnel;
    std::string message;
};

/// A property's statement: nothing if the scene satisfies it under the kernel, else the failure. Must be a
/// pure function of (kernel, scene): it is also run on saved logs, so it may not rely on how the generator
/// built the scene. A scene the statement does not apply to (a precondition fails) passes.
using Statement = std::function<std::optional<Failure>(KernelId, const Scene&)>;

/// A property: its name (as logs spell it in `from property NAME`), its main check, its generator and
/// statement, and how many cases a default run generates per kernel.
struct Property {
    std::string name;
    Check check = Check::no_tunnel;  ///< the check a log of this property names if the statement throws
    rc::Gen<Scene> gen;
    Statement statement;
    int default_max_success = 1000;
};

/// Runs p against kernel k as the current GoogleTest test: first every saved log in replay_dir() that
/// names p, then RapidCheck's search. A failure is reported through GoogleTest and its minimal case, reduced
/// (reduce_log, a fixed budget of tries), saved.
void run_property(const Property& p, KernelId k);

/// Cases generated (RapidCheck successes) so far in this process, over every property and kernel.
long long total_cases();

/// GoogleTest's parameter name for a kernel ("lecture_float", "robust", ...).
std::string kernel_param_name(const ::testing::TestParamInfo<KernelId>& info);

/// Marks the current case with label (each label counted once per case). The harness prints, per
/// property and kernel, the share of generated cases carrying each label. RapidCheck's own RC_TAG /
/// RC_CLASSIFY table counts every combination of labels, which with a dozen labels per case is
/// unreadable; these are its marginals. No effect outside a generated case (e.g. replaying a log).
void tag(std::string_view label);
/// tag(label) if cond.
inline void classify(bool cond, std::string_view label) {
    if (cond) tag(label);
}

/// "(x, y)" with both numbers in shortest round-trip form.
std::string str(Vec2 p);
/// "wall (x0, y0) -> (x1, y1)".
std::string str(const Wall& w);
/// A failure of check c with a message.
inline std::optional<Failure> fail(Check c, std::string message) { return Failure{c, std::move(message)}; }

/// A property's statement made of checks: tags the scene (if tags is given), runs it under the kernel with
/// exactly these checks (run_checked, checks.hpp) and reports the first failure the checker gives. A ball
/// leaving the accepted range ends the run: a documented outcome, tagged, not a failure.
Statement checked(std::vector<Check> checks, std::function<void(const Scene&)> tags = {});

}  // namespace ricochet::props

/// Declares the per-kernel GoogleTest suite SUITE: TEST_P(SUITE, Name) { run_property(make(), GetParam()); }.
#define RICOCHET_PROPERTY_SUITE(SUITE)                                                                         \
    class SUITE : public ::testing::TestWithParam<::ricochet::KernelId> {};                                    \
    INSTANTIATE_TEST_SUITE_P(Kernels, SUITE, ::testing::ValuesIn(::ricochet::props::kernels_under_test()),     \
                             ::ricochet::props::kernel_param_name)
