# ricochet on wasm32 (emscripten, cmake/toolchains/wasm32.cmake), included by the top CMakeLists.txt.
#
# Debian packages no library built for emscripten, but what the `ricochet` command needs is header-only or can be:
# fmt (FMT_HEADER_ONLY), CLI11, xxhash (XXH_INLINE_ALL), nlohmann-json and Boost.Multiprecision, the big numbers
# there (no GMP); pugixml is not (`--junit` is left out). They are taken from the host's Debian packages through a
# folder of links to those headers alone, never /usr/include itself, whose glibc headers would shadow emscripten's
# libc; the targets are named as find_package and pkg-config name them elsewhere, so the rest of the build does not
# change.
#
# Left out, because wasm32 under node has no child processes and no dlopen: libFuzzer and the fuzz campaign
# (`ricochet fuzz` says it is not in this build; the fuzz targets build with their standalone driver, which runs
# given inputs once), the benchmarks (`ricochet bench` likewise), the
# peers (their Debian libraries are x86-64 code), the tests and the property suite (Debian has no RapidCheck or
# GoogleTest for emscripten). Plug-in kernels are refused at load time, with
# the reason (plugin_loader.cpp).

foreach(_option RICOCHET_TESTS RICOCHET_PROPERTIES RICOCHET_BENCH RICOCHET_FUZZ RICOCHET_FUZZ_CAMPAIGN RICOCHET_PEERS)
  if(${_option})
    message(FATAL_ERROR "ricochet on wasm32: ${_option} needs child processes, dlopen or libraries Debian does "
      "not build for emscripten; configure with -D${_option}=OFF")
  endif()
  set(${_option} OFF CACHE BOOL "OFF on wasm32 (cmake/emscripten.cmake)")
endforeach()
if(RICOCHET_BIGNUM STREQUAL "gmp")
  message(FATAL_ERROR "ricochet on wasm32: Debian has no GMP for emscripten; use -DRICOCHET_BIGNUM=boost (the default there)")
endif()

# The host's headers, one link each, under the build folder.
set(RICOCHET_HOST_INCLUDE_DIR /usr/include CACHE PATH "Where the host's Debian packages put fmt, CLI11, xxhash and Boost headers")
set(_headers ${PROJECT_BINARY_DIR}/host-headers)
file(MAKE_DIRECTORY ${_headers})
foreach(_entry fmt/format.h CLI/CLI.hpp xxhash.h boost/multiprecision/cpp_int.hpp nlohmann/json.hpp)
  if(NOT EXISTS ${RICOCHET_HOST_INCLUDE_DIR}/${_entry})
    message(FATAL_ERROR "ricochet on wasm32: ${RICOCHET_HOST_INCLUDE_DIR}/${_entry} not found (Debian packages "
      "libfmt-dev, libcli11-dev, libxxhash-dev, libboost-dev, nlohmann-json3-dev)")
  endif()
  string(REGEX REPLACE "/.*" "" _top ${_entry})
  file(CREATE_LINK ${RICOCHET_HOST_INCLUDE_DIR}/${_top} ${_headers}/${_top} SYMBOLIC)
endforeach()

add_library(fmt::fmt INTERFACE IMPORTED GLOBAL)
target_include_directories(fmt::fmt SYSTEM INTERFACE ${_headers})
target_compile_definitions(fmt::fmt INTERFACE FMT_HEADER_ONLY)
add_library(CLI11::CLI11 INTERFACE IMPORTED GLOBAL)
target_include_directories(CLI11::CLI11 SYSTEM INTERFACE ${_headers})
add_library(PkgConfig::XXHASH INTERFACE IMPORTED GLOBAL)
target_include_directories(PkgConfig::XXHASH SYSTEM INTERFACE ${_headers})
target_compile_definitions(PkgConfig::XXHASH INTERFACE XXH_INLINE_ALL)
add_library(Boost::headers INTERFACE IMPORTED GLOBAL)
target_include_directories(Boost::headers SYSTEM INTERFACE ${_headers})
add_library(nlohmann_json::nlohmann_json INTERFACE IMPORTED GLOBAL)
target_include_directories(nlohmann_json::nlohmann_json SYSTEM INTERFACE ${_headers})

# C++ exceptions (CLI11's usage errors, the commands' exits) need emscripten's catching, at compile and link
# time. The program runs under node with the host's files (NODERAWFS: paths as on the host, so logs are read and
# results written where the user runs it), ends with its exit status (EXIT_RUNTIME, which also flushes stdout),
# grows its memory as a large scene needs, and compiles its wasm synchronously (node 18 and later have fetch(),
# which emscripten 3.1.6's asynchronous start then tries on a file path, and fails).
add_compile_options(-fexceptions)
add_link_options(-fexceptions -sNODERAWFS=1 -sEXIT_RUNTIME=1 -sALLOW_MEMORY_GROWTH=1 -sWASM_ASYNC_COMPILATION=0)
# getenv answers from node's environment (cmake/node_env.js), as on every other platform.
add_link_options(--pre-js ${CMAKE_CURRENT_LIST_DIR}/node_env.js)
# Debian's emscripten tidies the JavaScript it links with node and Debian's node-acorn, installed in /usr/share/nodejs,
# a folder Debian's own nodejs searches and other builds of node (NodeSource's) do not: the link names it.
set(CMAKE_CXX_LINKER_LAUNCHER ${CMAKE_COMMAND} -E env NODE_PATH=/usr/share/nodejs)
