// Kernel ids: the built-in kernels by number, and their names as scene logs and --kernel spell them.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace ricochet {

/// A kernel: the four built-in ones by name; a kernel registered later (kernel.hpp) gets the next
/// free number, KernelId{4}, KernelId{5}, …
enum class KernelId : std::uint8_t { lecture_float, lecture_double, robust, exact };
/// The built-in kernels, in id order (a registered kernel is listed by registered_kernels()).
inline constexpr std::array<KernelId, 4> k_all_kernels = {KernelId::lecture_float, KernelId::lecture_double,
                                                           KernelId::robust, KernelId::exact};
/// The kernel's name as scene logs and --kernel spell it ("lecture-float", …, "robust", "exact").
/// Read from the kernel registry; "?" for an id nobody registered.
std::string_view kernel_name(KernelId k);
/// The kernel called name, or nothing if there is none (looked up in the kernel registry).
std::optional<KernelId> parse_kernel(std::string_view name);
/// Every registered kernel's name, joined for error messages: "lecture-float, lecture-double, robust, exact".
std::string kernel_names();
/// For a name this build knows but lacks (note_absent_kernel, kernel.hpp): "kernel 'NAME' is not built into
/// this ricochet: WHY"; nothing for any other name.
std::optional<std::string> absent_kernel_message(std::string_view name);

}  // namespace ricochet
