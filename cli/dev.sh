#!/usr/bin/env bash
# The two Quick start commands. Each installs what is missing (Debian 12, as root), configures and
# builds, then runs its job; a second run only rebuilds what changed.
#
#   cli/dev.sh check   build, then `ricochet check` (replays, properties, a short fuzz campaign)
#   cli/dev.sh test    build, then every test (ctest: unit, replay, property, fuzz)
#   cli/dev.sh deps    only install what is missing (CI's first step, before its other builds)
#   cli/dev.sh coverage  the `coverage` preset into build-coverage/: every test under clang's source-based
#                      coverage, then the llvm-cov report of core/ and harness/ (HTML in build-coverage/coverage-html)
#
# Environment: BUILD_DIR (default build), JOBS (default nproc), RICOCHET_NO_APT=1 to skip apt-get,
# RICOCHET_UNITY=OFF to configure a new build folder file by file (default ON, a unity build).
set -euo pipefail

cd "$(dirname "$0")/.."
job=${1:-}
case "$job" in
  check|test|coverage|deps) ;;
  *) echo "usage: cli/dev.sh check|test|coverage|deps" >&2; exit 2 ;;
esac
build=${BUILD_DIR:-build}
jobs=${JOBS:-$(nproc)}

# The coverage job: every CTest test (the fuzz targets on their standalone driver, since libFuzzer's and
# ASan's instrumentation do not mix with profile counters; the ClusterFuzzLite build, which compiles its
# own uninstrumented tree, left out), one raw profile per process and module (%p-%m), merged, then the
# report of core/ and harness/ per file. Everything it writes lands in build-coverage/.
coverage() {
  local dir=build-coverage status=0
  cmake --preset coverage >/dev/null
  # gtest_discover_tests runs each test binary at build time: its profiles go aside, not into the run's.
  LLVM_PROFILE_FILE="$PWD/$dir/profiles-build/%p-%m.profraw" cmake --build --preset coverage -j "$jobs"
  rm -rf "$dir/profiles" "$dir/tmp" && mkdir -p "$dir/profiles" "$dir/tmp"
  ctest --preset coverage -j "$jobs" || status=$?
  llvm-profdata-14 merge -sparse "$dir"/profiles/*.profraw -o "$dir/coverage.profdata"
  # Every instrumented executable of the build (the core is linked into each of them): llvm-cov takes the
  # first one as its argument, the others after -object.
  local objects=() f
  while IFS= read -r f; do
    llvm-readelf-14 -S "$f" 2>/dev/null | grep -q __llvm_covmap || continue
    if [ ${#objects[@]} = 0 ]; then objects=("$f"); else objects+=(-object "$f"); fi
  done < <(find "$dir" -type f -perm -u+x ! -name '*.so*' ! -path '*/CMakeFiles/*' | sort)
  local filter=(-ignore-filename-regex='/(core|harness)/tests/' "$PWD/core/" "$PWD/harness/")
  llvm-cov-14 show -instr-profile="$dir/coverage.profdata" "${objects[@]}" -format=html \
    -output-dir="$dir/coverage-html" "${filter[@]}" >/dev/null
  llvm-cov-14 report -instr-profile="$dir/coverage.profdata" "${objects[@]}" "${filter[@]}"
  # The two libraries' totals apart, then the command itself (cli/ and app/, the `ricochet` program's own files;
  # the aim is 90 % of its lines).
  local part
  for part in core harness; do
    echo "dev.sh coverage: $part/"
    llvm-cov-14 report -instr-profile="$dir/coverage.profdata" "${objects[@]}" -ignore-filename-regex="/$part/tests/" \
      "$PWD/$part/" | tail -n 1
  done
  echo "dev.sh coverage: cli/ and app/"
  llvm-cov-14 report -instr-profile="$dir/coverage.profdata" "${objects[@]}" "$PWD/cli/" "$PWD/app/" | tail -n 1
  echo "dev.sh coverage: HTML report in $dir/coverage-html/index.html; ctest exit status $status"
  exit "$status"
}

# Debian packages, never vendored or downloaded by the build.
packages=(cmake ninja-build g++ pkg-config clang-14 libclang-rt-14-dev llvm-14 zip
          libfmt-dev librapidcheck-dev libgtest-dev libgmock-dev libgmp-dev libboost-dev libcli11-dev libbenchmark-dev
          libxxhash-dev libssl-dev libbox2d-dev libchipmunk-dev libcgal-dev gnuplot-nox librsvg2-bin zsh
          nlohmann-json3-dev libpugixml-dev libxml2-utils python3-jsonschema)
if [ "${RICOCHET_NO_APT:-0}" != 1 ]; then
  missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    echo "dev.sh: installing ${missing[*]}"
    if [ "$(id -u)" != 0 ]; then echo "dev.sh: run as root to install packages" >&2; exit 2; fi
    export DEBIAN_FRONTEND=noninteractive
    # A mirror caught mid-sync fails `apt-get update` for a moment: tried again, then the install decides.
    bash cli/apt-update.sh || echo "dev.sh: installing from the package lists apt has" >&2
    apt-get install -y -qq --no-install-recommends "${missing[@]}"
  fi
fi

if [ "$job" = deps ]; then
  exit 0
fi
if [ "$job" = coverage ]; then
  coverage
fi

# clang builds everything, fuzzers included (libFuzzer needs clang); gcc is covered by CI's
# determinism build. A unity build (each target's files compiled in batches of 8): the whole tree in about
# two thirds of the time file by file (487 s against 747–791 s on 2 cores), at the price of a batch recompiled
# for one file changed. The presets (docs/development.md) compile file by file, for working on the code; so do
# CI's gcc -O0 reference builds.
if [ ! -f "$build/CMakeCache.txt" ]; then
  CC=clang-14 CXX=clang++-14 cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_UNITY_BUILD="${RICOCHET_UNITY:-ON}"
fi
build_t0=$SECONDS
cmake --build "$build" -j "$jobs"
echo "dev.sh: build took $((SECONDS - build_t0)) s" >&2

case "$job" in
  check) exec "$build/cli/ricochet" check ;;
  test) cd "$build" && exec ctest --output-on-failure -j "$jobs" ;;
esac
