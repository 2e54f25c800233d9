// The same kernel as a plug-in (ricochet/plugin.h), so that the installed command runs it too:
//     ricochet replay --plugin ./my_kernel.so found/
//     ricochet fuzz --kernel plugin:./my_kernel.so
#include "my_kernel.hpp"

extern "C" RICOCHET_PLUGIN_EXPORT const ricochet_plugin* ricochet_plugin_entry(uint32_t) { return &my::kernel_table(); }
