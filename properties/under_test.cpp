// What the properties run against and where their logs live, as the program running them sets it
// (harness.hpp): the kernels under test (RICOCHET_KERNEL, else the tables of RICOCHET_TEST_KERNEL, else robust
// and exact), their domains (RICOCHET_DOMAIN, else RICOCHET_TEST_KERNEL_IN's) and the runner's defaults
// (ricochet's own runner: the corpus and the peers).
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <utility>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "harness.hpp"
#include "ricochet/kernel_spec.hpp"
#include "ricochet/plugin_loader.hpp"
#include "ricochet/properties.hpp"

namespace ricochet::props {
namespace {

// Function-local statics: RICOCHET_TEST_KERNEL and the runner write them from static initializers of other
// files, whose order against this file's is unspecified.
RunnerDefaults& runner_defaults() {
    static RunnerDefaults defaults;
    return defaults;
}

/// A table put under test and the domain its line gives.
struct Pending {
    const ricochet_plugin* table;
    std::string domain;
};
std::vector<Pending>& pending_tables() {
    static std::vector<Pending> tables;
    return tables;
}

/// spec read as a domain, or the program ends with status 2 naming where it came from.
Domain read_domain(std::string_view spec, std::string_view from) {
    std::string error;
    const auto d = parse_domain_spec(spec, &error);
    if (!d) {
        fmt::print(stderr, "{}: error: {}\n", from, error);
        std::exit(2);
    }
    return *d;
}

/// The domains of the tables under test, by kernel (filled with test_kernels()).
std::vector<std::pair<KernelId, Domain>>& test_domains() {
    static std::vector<std::pair<KernelId, Domain>> domains;
    return domains;
}

/// The kernels of the tables put under test, registered on the first call (after main has begun: the
/// registry's own statics are initialized by then). A refused table ends the program.
const std::vector<KernelId>& test_kernels() {
    static const std::vector<KernelId> kernels = [] {
        std::vector<KernelId> out;
        for (const Pending& p : pending_tables()) {
            std::string error;
            const auto k = register_plugin(*p.table, &error);
            if (!k) {
                fmt::print(stderr, "RICOCHET_TEST_KERNEL: error: {}\n", error);
                std::exit(2);
            }
            out.push_back(*k);
            test_domains().emplace_back(*k, read_domain(p.domain, fmt::format("RICOCHET_TEST_KERNEL_IN({})", kernel_name(*k))));
        }
        return out;
    }();
    return kernels;
}

}  // namespace

bool test_kernel(const ricochet_plugin& table, const char* domain) {
    pending_tables().push_back({&table, domain != nullptr ? domain : ""});
    return true;
}

Domain domain_under_test(KernelId k) {
    static const std::optional<Domain> from_env = []() -> std::optional<Domain> {
        const char* env = std::getenv("RICOCHET_DOMAIN");
        if (env == nullptr) return std::nullopt;
        return read_domain(env, "RICOCHET_DOMAIN");
    }();
    if (from_env) return *from_env;
    (void)test_kernels();
    for (const auto& [kernel, domain] : test_domains())
        if (kernel == k) return domain;
    return {};
}

void set_runner_defaults(RunnerDefaults defaults) { runner_defaults() = std::move(defaults); }

void register_runner_kernels() {
    if (runner_defaults().register_kernels != nullptr) runner_defaults().register_kernels();
}

std::vector<KernelId> kernels_under_test() {
    // The runner's kernels and the tables under test join the registry before RICOCHET_KERNEL is read (the suites
    // are instantiated from here, when GoogleTest sets up its parameterized tests).
    register_runner_kernels();
    const std::vector<KernelId>& mine = test_kernels();
    const char* env = std::getenv("RICOCHET_KERNEL");
    if (env == nullptr || *env == '\0') {
        if (!mine.empty()) return mine;
        return {KernelId::robust, KernelId::exact};
    }
    std::vector<KernelId> out;
    std::string_view rest = env;
    while (!rest.empty()) {
        const auto comma = rest.find(',');
        const std::string_view name = rest.substr(0, comma);
        if (name == "all") {
            out.assign(k_all_kernels.begin(), k_all_kernels.end());
        } else if (std::string error; const auto k = resolve_kernel(name, &error)) {
            out.push_back(*k);
        } else {
            // A name or plugin:PATH (kernel_spec.hpp), or all.
            fmt::print(stderr, "RICOCHET_KERNEL: error: {}; all names the built-in kernels\n", error);
            std::exit(2);
        }
        rest = comma == std::string_view::npos ? std::string_view{} : rest.substr(comma + 1);
    }
    return out;
}

std::filesystem::path replay_dir() {
    const char* env = std::getenv("RICOCHET_REPLAY_DIR");
    if (env != nullptr && *env != '\0') return env;
    if (!runner_defaults().replay_dir.empty()) return runner_defaults().replay_dir;
    std::error_code ec;
    const std::filesystem::path here = std::filesystem::current_path(ec);
    return (ec ? std::filesystem::path(".") : here) / "found";
}

}  // namespace ricochet::props
