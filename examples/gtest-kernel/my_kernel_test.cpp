// The example user's test binary: tests of their own, and every property of ricochet run against their kernel,
// one GoogleTest test per property (Kernels/SUITE.PROPERTY/my_kernel).
#include <gtest/gtest.h>
#include <ricochet/properties.hpp>

#include "my_kernel.hpp"

RICOCHET_TEST_KERNEL(my::kernel_table());

// A test of the user's own, beside ricochet's: a head-on bounce off a unit wall keeps the speed either way.
TEST(MyKernel, BouncesHeadOnOffAUnitWall) {
    const ricochet_wall wall = {{0, 0}, {0, 1}};
    const ricochet_vec2 v = my::kernel_table().reflect(nullptr, {-3, 0}, &wall);
    EXPECT_EQ(v.x, 3);
    EXPECT_EQ(v.y, 0);
}
