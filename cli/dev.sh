#!/usr/bin/env bash
# The two Quick start commands. Each installs what is missing (Debian 12, as root), configures and
# builds, then runs its job; a second run only rebuilds what changed.
#
#   cli/dev.sh check   build, then `ricochet check` (replays, properties, a short fuzz campaign)
#   cli/dev.sh test    build, then every test (ctest: unit, replay, property, fuzz)
#
# Environment: BUILD_DIR (default build), JOBS (default nproc), RICOCHET_NO_APT=1 to skip apt-get.
set -euo pipefail

cd "$(dirname "$0")/.."
job=${1:-}
case "$job" in
  check|test) ;;
  *) echo "usage: cli/dev.sh check|test" >&2; exit 2 ;;
esac
build=${BUILD_DIR:-build}
jobs=${JOBS:-$(nproc)}

# Debian packages, never vendored or downloaded by the build.
packages=(cmake ninja-build g++ pkg-config clang-14 libclang-rt-14-dev llvm-14 zip
          libfmt-dev librapidcheck-dev libgtest-dev libgmock-dev libgmp-dev libcli11-dev libbenchmark-dev
          libxxhash-dev libssl-dev libbox2d-dev libchipmunk-dev libcgal-dev gnuplot-nox librsvg2-bin)
if [ "${RICOCHET_NO_APT:-0}" != 1 ]; then
  missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  if [ ${#missing[@]} -gt 0 ]; then
    echo "dev.sh: installing ${missing[*]}"
    if [ "$(id -u)" != 0 ]; then echo "dev.sh: run as root to install packages" >&2; exit 2; fi
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq --no-install-recommends "${missing[@]}"
  fi
fi

# clang builds everything, fuzzers included (libFuzzer needs clang); gcc is covered by CI's
# determinism build.
if [ ! -f "$build/CMakeCache.txt" ]; then
  CC=clang-14 CXX=clang++-14 cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
fi
cmake --build "$build" -j "$jobs"

case "$job" in
  check) exec "$build/cli/ricochet" check ;;
  test) cd "$build" && exec ctest --output-on-failure -j "$jobs" ;;
esac
