# wasm32 with Debian 12's emscripten (3.1.6, on clang-14), the program run under node.
# Used by .ci/cross.sh: cmake -DCMAKE_TOOLCHAIN_FILE=cmake/toolchains/wasm32.cmake
# Emscripten's own toolchain file says "x86" for the processor (for projects that only know CPUs); ricochet
# chooses its floating-point flags by processor, and -msse2 -mfpmath=sse mean nothing to wasm32: say wasm32.
set(EMSCRIPTEN_SYSTEM_PROCESSOR wasm32)
include(/usr/share/emscripten/cmake/Modules/Platform/Emscripten.cmake)
