// Kernel specs (kernel_spec.hpp): a registered name, or plugin:PATH.
#include "ricochet/kernel_spec.hpp"

#include <fmt/format.h>

#include "base/shown_text.hpp"
#include "ricochet/plugin_loader.hpp"

namespace ricochet {

std::optional<KernelId> resolve_kernel(std::string_view spec, std::string* error) {
    if (spec.starts_with(k_plugin_spec_prefix)) {
        const std::string_view path = spec.substr(k_plugin_spec_prefix.size());
        if (path.empty()) {
            if (error != nullptr) *error = fmt::format("'{}' names no file (plugin:PATH)", spec);
            return std::nullopt;
        }
        return load_plugin(std::filesystem::path(path), error);
    }
    if (const auto k = parse_kernel(spec)) return k;
    // A kernel this build knows but lacks (a peer not found at build time) is told apart from a typo.
    if (error != nullptr)
        *error = absent_kernel_message(spec).value_or(
            fmt::format("unknown kernel '{}' ({}, or plugin:PATH)", detail::shown(spec), kernel_names()));
    return std::nullopt;
}

}  // namespace ricochet
