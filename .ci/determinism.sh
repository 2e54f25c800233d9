#!/usr/bin/env bash
# Determinism across builds: builds `ricochet` in several configurations and compares the run hash
# of every replay log (`ricochet replay --hashes` prints "HASH PATH" per log). Exits non-zero, naming
# each log whose hash differs, if any two builds disagree. replays/peers/ is left out: those logs run the
# peers' Debian libraries (Box2D, Chipmunk), whose bits are the library's, not this build's, so they are no
# part of the determinism contract (.ci/cross.sh leaves them out for the same reason).
#
#   .ci/determinism.sh [CONFIG...]     configs: gcc-O0 gcc-O3-native clang-O3-native clang-O0 (default: gcc-O0 clang-O3-native)
# Environment: JOBS (default 2), DET_PREFIX (build folders, default build-det-).
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=${JOBS:-2}
prefix=${DET_PREFIX:-build-det-}
configs=("$@")
[ ${#configs[@]} -gt 0 ] || configs=(gcc-O0 clang-O3-native)

build() {
  local name=$1 cc cxx flags unity=OFF
  # The -O3 builds are unity builds (CMake compiles each target's files in batches, one translation unit
  # each): twice as fast to build, and the comparison also covers a different grouping of the sources, where
  # inlining across files differs. The -O0 builds, the references, compile file by file.
  case "$name" in
    gcc-O0)          cc=gcc-12;   cxx=g++-12;     flags="-O0" ;;
    gcc-O3-native)   cc=gcc-12;   cxx=g++-12;     flags="-O3 -march=native"; unity=ON ;;
    clang-O0)        cc=clang-14; cxx=clang++-14; flags="-O0" ;;
    clang-O3-native) cc=clang-14; cxx=clang++-14; flags="-O3 -march=native"; unity=ON ;;
    *) echo "determinism.sh: unknown config $name" >&2; exit 2 ;;
  esac
  local dir=$prefix$name
  if [ ! -f "$dir/CMakeCache.txt" ]; then
    CC=$cc CXX=$cxx cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS="$flags" \
      -DCMAKE_UNITY_BUILD=$unity -DRICOCHET_TESTS=OFF -DRICOCHET_BENCH=OFF -DRICOCHET_FUZZ=OFF >/dev/null
  fi
  cmake --build "$dir" -j "$jobs" --target ricochet >/dev/null
}

out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
mapfile -t logs < <(find replays -name '*.scene' -not -path 'replays/peers/*' | LC_ALL=C sort)
for c in "${configs[@]}"; do
  echo "determinism: building $c" >&2
  build "$c"
  # Replay pass/fail is not the question here (the replay tests ask it); the hashes are.
  "$prefix$c/cli/ricochet" replay --hashes "${logs[@]}" >"$out/$c.txt" || true
  echo "determinism: $c: $(wc -l <"$out/$c.txt") logs" >&2
done

status=0
ref=${configs[0]}
for c in "${configs[@]:1}"; do
  # Join on the path, print every log whose hash differs.
  diffs=$(join -1 2 -2 2 <(sort -k2 "$out/$ref.txt") <(sort -k2 "$out/$c.txt") | awk '$2 != $3 {print}')
  missing=$(join -v1 -v2 -1 2 -2 2 <(sort -k2 "$out/$ref.txt") <(sort -k2 "$out/$c.txt") || true)
  if [ -n "$diffs" ] || [ -n "$missing" ]; then
    status=1
    echo "$diffs" | while read -r path a b; do [ -n "$path" ] && echo "DIFFERS $path: $ref $a, $c $b"; done
    [ -z "$missing" ] || echo "MISSING in one build: $missing"
  fi
done
if [ $status = 0 ]; then
  echo "determinism: $(wc -l <"$out/$ref.txt") logs, identical hashes across ${configs[*]}"
fi
exit $status
