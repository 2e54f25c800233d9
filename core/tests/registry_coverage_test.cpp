// The kernel registry filling up: in a process of its own (it registers kernels for good), the
// registry takes k_max_kernels kernels in all and refuses the next one, whatever its name.
#include <gtest/gtest.h>

#include <array>
#include <string>

#include "ricochet/kernel.hpp"

namespace ricochet {
namespace {

TEST(RegistryFull, TakesSixteenKernelsThenRefusesEvenANewName) {
    // The names must outlive the registry: literals.
    static constexpr std::array<const char*, 13> k_names = {"p0", "p1", "p2", "p3", "p4",  "p5", "p6",
                                                            "p7", "p8", "p9", "p10", "p11", "p12"};
    // The robust kernel's operations under other names.
    KernelOps ops = kernel_ops(KernelId::robust);
    ASSERT_EQ(registered_kernels().size(), k_all_kernels.size());
    std::size_t taken = 0;
    for (const char* name : k_names) {
        ops.name = name;
        const auto id = register_kernel(ops);
        if (!id) break;
        EXPECT_EQ(static_cast<std::size_t>(*id), k_all_kernels.size() + taken);
        EXPECT_EQ(parse_kernel(name), id);
        ++taken;
    }
    // 16 in all: the four built in and twelve more; "p12" finds the registry full.
    EXPECT_EQ(taken, k_max_kernels - k_all_kernels.size());
    EXPECT_EQ(registered_kernels().size(), k_max_kernels);
    EXPECT_FALSE(parse_kernel("p12"));
    EXPECT_EQ(kernel_name(static_cast<KernelId>(k_max_kernels - 1)), "p11");
    EXPECT_TRUE(kernel_names().ends_with(", robust, exact, p0, p1, p2, p3, p4, p5, p6, p7, p8, p9, p10, p11")) << kernel_names();
    // A plug-in dispatches like the kernel whose operations it took.
    EXPECT_EQ(classify(static_cast<KernelId>(k_max_kernels - 1), {5, -1}, Wall{{0, 0}, {10, 0}}), Side::outside);
}

}  // namespace
}  // namespace ricochet
