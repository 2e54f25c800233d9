# Install rules and the package config. `cmake --install BUILD --prefix P` gives, by component:
#   core      P/include/ricochet/*.hpp, plugin.h   the core's public headers, and the plug-in interface (plain C)
#             P/lib/libricochet_core.a             the core (static unless BUILD_SHARED_LIBS)
#             P/lib/cmake/ricochet/                ricochetConfig.cmake, its version and ricochetTargets.cmake
#   harness   P/include/ricochet/*.hpp             the harness's public headers (checks, truth, replay, ...)
#             P/lib/libricochet_harness.a          the harness
#             P/lib/cmake/ricochet/ricochetHarnessTargets.cmake
#   properties P/include/ricochet/properties.hpp   the property suite in a user's own GoogleTest binary
#             P/lib/ricochet/properties/...        its objects (an object library: its tests register themselves)
#             P/lib/cmake/ricochet/ricochetPropertiesTargets.cmake
#             P/share/doc/ricochet/examples/gtest-kernel/   the example a user starts from
#   command   P/bin/ricochet                       the command
# (`--component core` installs the core alone). find_package(ricochet 0.2) gives ricochet::core with its include
# folder, C++20 and the floating-point flags; ricochet::plugin, the include folder alone, for a plug-in kernel
# (ricochet/plugin.h) in C or C++; and, where the harness was installed, ricochet::harness, which brings the core
# along. find_package(ricochet 0.2 COMPONENTS harness) fails where it was not; likewise COMPONENTS properties for
# ricochet::properties (the suite, with the harness, RapidCheck and GoogleTest), installed where the build has it.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)
set(_ricochet_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/ricochet)

install(TARGETS ricochet_core ricochet_plugin_interface EXPORT ricochetTargets COMPONENT core
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/core/include/ricochet DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT core
        FILES_MATCHING PATTERN "*.hpp" PATTERN "plugin.h")
install(TARGETS ricochet_harness EXPORT ricochetHarnessTargets COMPONENT harness
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/harness/include/ricochet DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        COMPONENT harness FILES_MATCHING PATTERN "*.hpp")
if(TARGET ricochet_properties_suite)
  install(TARGETS ricochet_properties_suite EXPORT ricochetPropertiesTargets COMPONENT properties
          OBJECTS DESTINATION ${CMAKE_INSTALL_LIBDIR}/ricochet/properties)
  install(FILES ${PROJECT_SOURCE_DIR}/properties/include/ricochet/properties.hpp
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/ricochet COMPONENT properties)
  install(EXPORT ricochetPropertiesTargets NAMESPACE ricochet:: DESTINATION ${_ricochet_cmake_dir}
          COMPONENT properties)
  # The example a user starts from (docs/testing-your-code.md), without ricochet's own test of it.
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/gtest-kernel DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples
          COMPONENT properties PATTERN "*_test.sh" EXCLUDE)
endif()
install(TARGETS ricochet RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT command)

# A static core's private xxhash is named in the export as $<LINK_ONLY:PkgConfig::XXHASH>: the config
# must find it then, and only then.
get_target_property(_ricochet_core_type ricochet_core TYPE)
if(_ricochet_core_type STREQUAL "STATIC_LIBRARY")
  set(RICOCHET_CONFIG_NEEDS_XXHASH TRUE)
else()
  set(RICOCHET_CONFIG_NEEDS_XXHASH FALSE)
endif()
# GMP is public on the GMP backend (core/CMakeLists.txt); the Boost backend's headers are not in the export.
if(RICOCHET_BIGNUM_BACKEND STREQUAL "gmp")
  set(RICOCHET_CONFIG_NEEDS_GMP TRUE)
else()
  set(RICOCHET_CONFIG_NEEDS_GMP FALSE)
endif()
install(EXPORT ricochetTargets NAMESPACE ricochet:: DESTINATION ${_ricochet_cmake_dir} COMPONENT core)
install(EXPORT ricochetHarnessTargets NAMESPACE ricochet:: DESTINATION ${_ricochet_cmake_dir} COMPONENT harness)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/ricochetConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/ricochetConfig.cmake
                              INSTALL_DESTINATION ${_ricochet_cmake_dir})
# SameMinorVersion: before 1.0 a minor release may change the API (0.3 is not a 0.2), a patch may not.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/ricochetConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/ricochetConfig.cmake ${PROJECT_BINARY_DIR}/ricochetConfigVersion.cmake
        DESTINATION ${_ricochet_cmake_dir} COMPONENT core)
