#!/usr/bin/env bash
# Determinism across architectures: cross-builds `ricochet` for each leg with Debian 12's cross gcc,
# runs it (i386 natively where the kernel can, else under qemu-i386; aarch64 and s390x under qemu-user),
# or for wasm32 with Debian 12's emscripten (run under node, with the host's files through NODERAWFS),
# and compares, byte for byte, with a native x86-64 gcc -O0 build:
#   - `ricochet replay --hashes LOG...` (one "HASH PATH" line per log), and
#   - per log, `ricochet run LOG` (its standard output and exit status),
#   - per log of replays/lecture/ (each fails under its lecture kernel), the failure log `ricochet reduce LOG`
#     writes (standard output and exit status): the harness's own saved logs,
#   - the harness itself (capture_harness): each fuzz target on each committed corpus input and the property
#     suite with a fixed seed, under both lecture kernels: which fail, where, and the logs they save,
# for every log in replays/ but those of replays/peers/: they run the peers' Debian libraries (Box2D,
# Chipmunk), whose bits are the library's, not this build's (Box2D's float code may be compiled with FMA
# contraction on other architectures), and the cross builds have no Box2D or Chipmunk at all.
# The wasm32 build has no GMP (Debian has none for emscripten): its exact numbers are Boost.Multiprecision's
# (-DRICOCHET_BIGNUM=boost), so that leg also compares the two big-number backends over the corpus.
# A difference fails the leg and names the log, the two builds and the first differing lines.
#
#   .ci/cross.sh [LEG...]       legs: i386 aarch64 s390x wasm32 (default: all four)
#   .ci/cross.sh --control      control: aarch64 built with -DRICOCHET_CONTROL_CONTRACT=ON (FMA
#                               contraction allowed); passes only if the corpus tells it apart
#
# Installs what a leg is missing (as root, apt-get, non-interactive; `dpkg --add-architecture` for the
# multiarch dev packages; libssl-dev, for the fuzz campaign's SHA-1, is unpacked aside and linked
# statically, see openssl_sysroot; emscripten, nodejs and the header-only libraries for wasm32); a leg
# whose packages cannot be installed fails with a message, never skips. Leg builds are -O2 (CROSS_OPT),
# where aarch64 and s390x gcc would contract into FMA, and unity builds (each target's files compiled in
# batches: under half the time of a build file by file; the reference compiles file by file). The wasm32
# leg builds `ricochet` without the fuzz campaign (no child processes under node) and without plug-in
# kernels (no dlopen): `ricochet run` and `replay --hashes`, the commands compared, are whole; its fuzz
# targets run with their standalone driver, and it has no property suite (no RapidCheck or GoogleTest for
# emscripten in Debian).
# Environment: JOBS (default 2), CROSS_PREFIX (leg build folders, default build-cross-),
# DET_PREFIX (the native reference is ${DET_PREFIX}gcc-O0, configured exactly as .ci/determinism.sh
# does, so that the two scripts share it; default build-det-), CROSS_OPT (leg flags, default -O2).
set -uo pipefail
cd "$(dirname "$0")/.."
jobs=${JOBS:-2}
prefix=${CROSS_PREFIX:-build-cross-}
ref_dir=${DET_PREFIX:-build-det-}gcc-O0
opt=${CROSS_OPT:--O2}
export DEBIAN_FRONTEND=noninteractive

control=0
legs=()
for a in "$@"; do
  case "$a" in
    --control) control=1 ;;
    i386|aarch64|s390x|wasm32) legs+=("$a") ;;
    -h|--help) sed -n '2,/^set /{/^set /!s/^# \{0,1\}//p}' "$0"; exit 0 ;;
    *) echo "cross.sh: unknown leg '$a' (legs: i386 aarch64 s390x wasm32, or --control)" >&2; exit 2 ;;
  esac
done
[ ${#legs[@]} -gt 0 ] || [ $control = 1 ] || legs=(i386 aarch64 s390x wasm32)

now() { date +%s; }
say() { echo "cross: $*" >&2; }

# --- packages -------------------------------------------------------------------------------------
updated=0
apt_update() {
  [ $updated = 1 ] && return 0
  # Tried again while a mirror is mid-sync; after that the install (or download) decides, with the lists apt has.
  # A mirror still mid-sync for the next leg's update is not waited for a second time.
  if ! APT_UPDATE_TRIES=${apt_tries:-3} bash cli/apt-update.sh; then
    say "apt-get update failed; installing from the package lists apt has"
    apt_tries=1
  fi
  updated=1
}
missing() {  # the packages among "$@" that are not installed
  local p
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || echo "$p"
  done
}
ensure() {  # ensure PKG...: install the missing ones, or say which could not be
  local need
  need=$(missing "$@")
  [ -z "$need" ] && return 0
  if [ "$(id -u)" != 0 ]; then
    say "missing packages and not root: $(echo $need)"; return 1
  fi
  apt_update || return 1
  # shellcheck disable=SC2086
  if ! apt-get install -y -q --no-install-recommends $need >/tmp/cross-apt.$$.log 2>&1; then
    tail -n 20 /tmp/cross-apt.$$.log >&2
    say "could not install: $(echo $need)"
    rm -f /tmp/cross-apt.$$.log
    return 1
  fi
  rm -f /tmp/cross-apt.$$.log
}
add_arch() {
  dpkg --print-foreign-architectures | grep -qx "$1" && return 0
  [ "$(id -u)" = 0 ] || { say "dpkg architecture $1 not enabled and not root"; return 1; }
  dpkg --add-architecture "$1" && updated=0
}

# leg -> Debian architecture, GNU triplet (compilers), multiarch triplet (libraries), runner
# (i386's is none, natively, unless the kernel refuses it: see leg).
# qemu without -L: the target's libc6:ARCH (installed with the dev packages) loads from /lib and
# /usr/lib/<multiarch> as on the target. `-L /usr/<triplet>` took the cross toolchain's older
# ld.so (libc6-s390x-cross 2.36-8) with the multiarch libc.so.6 (2.36-9+deb12u14) that the host's
# ld.so.cache names, and every s390x program, a C hello world too, died of "stack smashing detected".
leg_info() {
  case "$1" in
    i386)    deb=i386;  gnu=i686-linux-gnu;    multi=i386-linux-gnu;    runner=() ;;
    aarch64) deb=arm64; gnu=aarch64-linux-gnu; multi=aarch64-linux-gnu; runner=(qemu-aarch64) ;;
    s390x)   deb=s390x; gnu=s390x-linux-gnu;   multi=s390x-linux-gnu;   runner=(qemu-s390x) ;;
    wasm32)  deb=;      gnu=;                  multi=;                  runner=(node) ;;
  esac
}

# openssl_sysroot: libssl-dev:$deb unpacked into a folder of its own, linked statically. The fuzz
# campaign that `ricochet` links names inputs by SHA-1 through libcrypto, but libssl-dev and libssl3 are
# Multi-Arch: same, so :$deb must have exactly the host's version, and Debian's archives do not keep
# them in step (bookworm-security has no s390x; a host not upgraded has an older one). Unpacking the
# target's package aside needs no version match and changes nothing on the host.
openssl_sysroot() {
  case $prefix in
    /*) ssl_root=${prefix}openssl-$deb ;;
    *) ssl_root=$PWD/${prefix}openssl-$deb ;;
  esac
  [ -f "$ssl_root/usr/lib/$multi/libcrypto.a" ] && return 0
  apt_update || return 1
  rm -rf "$ssl_root"; mkdir -p "$ssl_root/deb"
  if ! (cd "$ssl_root/deb" && apt-get download -q "libssl-dev:$deb" >/dev/null 2>&1) ||
     ! dpkg -x "$ssl_root"/deb/libssl-dev_*.deb "$ssl_root"; then
    say "could not download and unpack libssl-dev:$deb"; return 1
  fi
}

# --- runs -----------------------------------------------------------------------------------------
# par CMD...: CMD in the background, with at most $jobs of them running at once. Every run below writes files
# of its own and nothing else, so the order they finish in changes no byte; `wait` collects them. (The runs are
# one process each, under qemu or node one core each: one at a time, a core stood idle through half a leg.)
par() {
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n; done
  "$@" &
}

# run_to FILE CMD...: CMD's standard output into FILE, then "# exit STATUS" after it.
run_to() {
  local file=$1; shift
  "$@" >"$file" 2>/dev/null </dev/null
  echo "# exit $?" >>"$file"
}

# capture DIR RUNNER...: the hashes and every log's `ricochet run` output into DIR.
capture() {
  local dir=$1; shift
  local log
  mkdir -p "$dir/run"
  # The peers' logs are left out (see the top of this file).
  local logs=()
  mapfile -t logs < <(find replays -name '*.scene' -not -path 'replays/peers/*' | LC_ALL=C sort)
  # Pass/fail of the replay is not the question here (the replay tests ask it); the bytes are.
  par run_to "$dir/hashes.txt" "$@" replay --hashes "${logs[@]}"
  for log in "${logs[@]}"; do
    par run_to "$dir/run/${log//\//__}" "$@" run "$log"
  done
  # The harness's own output: the failure log `ricochet reduce` saves for each of replays/lecture/'s logs
  # (each fails under its lecture kernel), on stdout, with its exit status; on the legs of reduce_legs.
  if [ "${capture_reduce:-1}" = 1 ]; then
    for log in replays/lecture/*.scene; do
      par run_to "$dir/run/reduce__${log//\//__}" "$@" reduce "$log"
    done
  fi
  wait
}

# fuzz_one DIR NAME INPUT KERNEL TARGET_PATH RUNNER...: one fuzz target on one input (see capture_harness).
fuzz_one() {
  local dir=$1 name=$2 input=$3 k=$4 target=$5; shift 5
  local saved=$dir/saved/$name.scene verdict=passed
  # In a subshell whose own stderr is dropped (the `exit` keeps bash from exec'ing the target in its place): a
  # failing input aborts the target, and bash would say so on the script's stderr.
  ( RICOCHET_KERNEL=$k RICOCHET_FUZZ_SCENE_OUT=$saved RICOCHET_FUZZ_SHA1=${input##*/} \
      "$@" "$target" "$input" >/dev/null 2>"$dir/saved/$name.err" </dev/null; exit $? ) 2>/dev/null ||
    verdict=failed
  { echo "# $verdict"; grep -a '^==ricochet-fuzz== FAILURE' "$dir/saved/$name.err"
    [ -f "$saved" ] && cat "$saved"; } >"$dir/run/$name"
}

# props_one DIR KERNEL PROPS RUNNER...: the property suite under KERNEL (see capture_harness).
props_one() {
  local dir=$1 k=$2 props=$3 saved; shift 3
  rm -rf "$dir/saved/props-$k"; mkdir -p "$dir/saved/props-$k"
  RICOCHET_KERNEL=$k RICOCHET_REPLAY_DIR=$dir/saved/props-$k RC_PARAMS="seed=1" \
    "$@" "$props" >"$dir/saved/props-$k.out" 2>&1 </dev/null
  echo "# exit $?" >"$dir/run/props__${k}__failed"
  sed -n 's/^\[  FAILED  \] \([A-Za-z0-9_./]*\).*/\1/p' "$dir/saved/props-$k.out" | LC_ALL=C sort -u >>"$dir/run/props__${k}__failed"
  for saved in "$dir/saved/props-$k"/*.scene; do
    [ -f "$saved" ] && cp "$saved" "$dir/run/props__${k}__${saved##*/}"
  done
}

# capture_harness DIR BUILDDIR RUNNER...: the logs the harness itself saves, for fixed inputs and a fixed seed.
#   - The fuzz targets (static, sweep, scene, disc, meet; standalone driver, fuzz/standalone_main.cpp) on every committed
#     input of fuzz/corpus/<target>/ under each lecture kernel, one run per input (a failure aborts the run):
#     whether it failed, its failure line (target, kernel, check, frame, kind) and the log it saved
#     ($RICOCHET_FUZZ_SCENE_OUT), into run/fuzz__TARGET__KERNEL__INPUT.
#   - The property suite (not on wasm32: Debian has no RapidCheck or GoogleTest for emscripten) under each
#     lecture kernel with RapidCheck's seed 1 and its failures saved into an empty folder: the failing
#     properties' names, then every saved log, into run/props__KERNEL__LOG. (Timings in its output are not
#     compared; the reducer's budget is a count of tries, so what it saves does not depend on the clock.)
capture_harness() {
  local dir=$1 build=$2; shift 2
  local t k input
  local ext=
  [ "$(basename "${1:-}")" = node ] && ext=.js
  mkdir -p "$dir/run" "$dir/saved"
  # The property suites first: the longest runs, started while the short ones fill the other core.
  if [ -z "$ext" ]; then
    for k in $harness_kernels; do
      par props_one "$dir" "$k" "$build/properties/ricochet_properties" "$@"
    done
  fi
  for t in static sweep scene disc meet; do
    for k in $harness_kernels; do
      for input in fuzz/corpus/$t/*; do
        par fuzz_one "$dir" "fuzz__${t}__${k}__${input##*/}" "$input" "$k" "$build/fuzz/fuzz_$t$ext" "$@"
      done
    done
  done
  wait
}
harness_kernels="lecture-float lecture-double"
harness_targets=(fuzz_static fuzz_sweep fuzz_scene fuzz_disc fuzz_meet)

# The legs whose reduced logs are compared: all. (The reduced float-long-wall-reflect-nan.scene's message prints
# a NaN velocity, whose sign is the processor's: negative on x86, positive on ARM and s390x. Messages print a NaN
# without its sign, core/include/ricochet/format.hpp.)
reduce_legs=" i386 aarch64 s390x wasm32 "

# what NAME: the command and log a captured output file stands for ("run replays/x.scene").
what() {
  local f=$1
  case "$f" in
    reduce__*) f=${f#reduce__}; echo "reduce ${f//__//}" ;;
    fuzz__*)  # fuzz__TARGET__KERNEL__INPUT
      local t k; f=${f#fuzz__}; t=${f%%__*}; f=${f#*__}; k=${f%%__*}
      echo "fuzz_$t on fuzz/corpus/$t/${f#*__} under $k (verdict, failure line, saved log)" ;;
    props__*) f=${f#props__}; echo "property suite, seed 1, under ${f%%__*}: ${f#*__}" ;;
    *) echo "run ${f//__//}" ;;
  esac
}

# compare REFDIR LEGDIR REFNAME LEGNAME: 0 if identical; otherwise name each differing output.
compare() {
  local a=$1 b=$2 an=$3 bn=$4 f status=0 nlogs
  if ! cmp -s "$a/hashes.txt" "$b/hashes.txt"; then
    status=1
    echo "DIFFERS replay --hashes: $an vs $bn; first differing lines:"
    diff "$a/hashes.txt" "$b/hashes.txt" | head -n 6
  fi
  local b_reduce
  b_reduce=$(find "$b/run" -name 'reduce__*' | wc -l)
  for f in "$a"/run/*; do
    f=${f##*/}
    # A leg outside reduce_legs captured no reduced logs; wasm32 runs no property suite.
    [ "$b_reduce" = 0 ] && [ "${f#reduce__}" != "$f" ] && continue
    [ "${compare_props:-1}" = 0 ] && [ "${f#props__}" != "$f" ] && continue
    if [ ! -f "$b/run/$f" ]; then
      status=1; echo "MISSING in $bn: $(what "$f")"; continue
    fi
    if ! cmp -s "$a/run/$f" "$b/run/$f"; then
      status=1
      echo "DIFFERS $(what "$f"): $an vs $bn; first differing lines:"
      diff "$a/run/$f" "$b/run/$f" | head -n 4
    fi
  done
  local nfuzz nprops
  nlogs=$(find "$b/run" -type f -not -name 'reduce__*' -not -name 'fuzz__*' -not -name 'props__*' | wc -l)
  nfuzz=$(grep -l '^ricochet 1$' "$b"/run/fuzz__* 2>/dev/null | wc -l)
  nprops=$(find "$b/run" -name 'props__*.scene' | wc -l)
  [ $status = 0 ] && say "$bn: replay --hashes, $nlogs run outputs, $b_reduce reduced logs, $(find "$b/run" -name 'fuzz__*' | wc -l) fuzz runs ($nfuzz saved logs) and $nprops property logs identical to $an"
  return $status
}

# --- the native reference -------------------------------------------------------------------------
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

build_reference() {
  ensure cmake ninja-build g++-12 pkg-config libfmt-dev libgmp-dev libxxhash-dev libssl-dev libcli11-dev \
    librapidcheck-dev libgtest-dev nlohmann-json3-dev libpugixml-dev || return 1
  if [ ! -f "$ref_dir/CMakeCache.txt" ]; then
    CC=gcc-12 CXX=g++-12 cmake -S . -B "$ref_dir" -G Ninja -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS="-O0" \
      -DRICOCHET_TESTS=OFF -DRICOCHET_BENCH=OFF -DRICOCHET_FUZZ=OFF >/dev/null || return 1
  fi
  # The property suite too (determinism.sh, which configures the same folder, needs only the command).
  if ! grep -q '^RICOCHET_PROPERTIES:BOOL=ON$' "$ref_dir/CMakeCache.txt"; then
    cmake -S . -B "$ref_dir" -DRICOCHET_PROPERTIES=ON >/dev/null || return 1
  fi
  cmake --build "$ref_dir" -j "$jobs" --target ricochet "${harness_targets[@]}" ricochet_properties >/dev/null || return 1
  capture "$out/native" "$ref_dir/cli/ricochet"
  capture_harness "$out/native" "$ref_dir"
}

# --- one leg --------------------------------------------------------------------------------------
# leg LEG [BUILDDIR EXTRA_CMAKE_ARGS...]
leg() {
  local name=$1 dir=${2:-$prefix$1}; shift; [ $# -gt 0 ] && shift
  local deb gnu multi runner ssl_root t0 t1 t2 t3
  leg_info "$name"
  t0=$(now)
  # nlohmann-json is header-only (Architecture: all): the host's package serves every leg.
  local pkgs=(cmake ninja-build pkg-config libcli11-dev nlohmann-json3-dev) target_args=() targets=()
  case "$name" in
    # qemu-user too: a kernel built without IA32 emulation (a Firecracker VM's, for one) refuses an i386
    # program with "Exec format error", and the leg then runs it under qemu-i386 (see the start check in leg).
    i386) pkgs+=(gcc-i686-linux-gnu g++-i686-linux-gnu qemu-user) ;;
    aarch64) pkgs+=(crossbuild-essential-arm64 qemu-user) ;;
    s390x) pkgs+=(crossbuild-essential-s390x qemu-user) ;;
    # Header-only on the host (cmake/emscripten.cmake): fmt, CLI11, xxhash and Boost.Multiprecision.
    wasm32) pkgs+=(emscripten nodejs libfmt-dev libxxhash-dev libboost-dev) ;;
  esac
  if [ "$name" = wasm32 ]; then
    if ! ensure "${pkgs[@]}"; then
      echo "FAIL $name: emscripten, nodejs or the header-only dev packages could not be installed (see above)"
      return 1
    fi
    target_args=(-DCMAKE_CXX_FLAGS="$opt" -DRICOCHET_BIGNUM=boost -DRICOCHET_FUZZ_CAMPAIGN=OFF -DRICOCHET_PEERS=OFF)
    targets=(ricochet "${harness_targets[@]}")
  else
    pkgs+=("libfmt-dev:$deb" "libgmp-dev:$deb" "libxxhash-dev:$deb" "librapidcheck-dev:$deb" "libgtest-dev:$deb"
           "libpugixml-dev:$deb")
    targets=(ricochet "${harness_targets[@]}" ricochet_properties)
    if ! add_arch "$deb" || ! ensure "${pkgs[@]}" || ! openssl_sysroot; then
      echo "FAIL $name: the cross toolchain or the :$deb dev packages could not be installed (see above)"
      return 1
    fi
    target_args=(-DCMAKE_CXX_FLAGS="$opt -isystem $ssl_root/usr/include/$multi"
                 -DOPENSSL_INCLUDE_DIR="$ssl_root/usr/include" -DOPENSSL_CRYPTO_LIBRARY="$ssl_root/usr/lib/$multi/libcrypto.a"
                 -DRICOCHET_PROPERTIES=ON)
  fi
  t1=$(now)
  if [ ! -f "$dir/CMakeCache.txt" ]; then
    if ! cmake -S . -B "$dir" -G Ninja -DCMAKE_TOOLCHAIN_FILE="$PWD/cmake/toolchains/$name.cmake" \
         -DCMAKE_BUILD_TYPE=None -DCMAKE_UNITY_BUILD=ON "${target_args[@]}" \
         -DRICOCHET_TESTS=OFF -DRICOCHET_BENCH=OFF -DRICOCHET_FUZZ=OFF "$@" >"$out/$name.configure.log" 2>&1; then
      cat "$out/$name.configure.log"; rm -rf "$dir"
      echo "FAIL $name: configure failed"; return 1
    fi
  fi
  if ! cmake --build "$dir" -j "$jobs" --target "${targets[@]}" >"$out/$name.build.log" 2>&1; then
    tail -n 40 "$out/$name.build.log"
    echo "FAIL $name: build failed"; return 1
  fi
  t2=$(now)
  # emscripten writes the program as ricochet.js (node's part) beside ricochet.wasm.
  local exe=$dir/cli/ricochet
  [ "$name" = wasm32 ] && exe=$dir/cli/ricochet.js
  if [ "$name" = i386 ] && ! "$exe" --version >/dev/null 2>&1 && qemu-i386 "$exe" --version >/dev/null 2>&1; then
    say "i386: this kernel does not run 32-bit x86 programs; the leg runs them under qemu-i386"
    runner=(qemu-i386)
  fi
  local bin=("${runner[@]}" "$exe")
  if ! "${bin[@]}" --version >/dev/null 2>&1; then
    "${bin[@]}" --version
    echo "FAIL $name: the $name binary does not start (${runner[*]:-natively})"; return 1
  fi
  capture_reduce=0
  [ "${reduce_legs/ $name /}" != "$reduce_legs" ] && capture_reduce=1
  capture "$out/$name" "${bin[@]}"
  capture_reduce=1
  capture_harness "$out/$name" "$dir" "${runner[@]}"
  t3=$(now)
  say "$name: packages $((t1 - t0)) s, configure+build $((t2 - t1)) s, runs $((t3 - t2)) s, total $((t3 - t0)) s"
  leg_seconds=$((t3 - t0))
}

status=0
t_ref=$(now)
say "building the native reference (gcc-12 -O0, $ref_dir)"
if ! build_reference; then echo "FAIL native reference: build or run failed"; exit 1; fi
say "native reference: $(( $(now) - t_ref )) s"

summary=()
for l in "${legs[@]}"; do
  say "leg $l"
  leg_seconds=0
  build_name="$l-gcc$opt"
  [ "$l" = wasm32 ] && build_name="wasm32-emscripten$opt-boost"
  compare_props=1
  [ "$l" = wasm32 ] && compare_props=0
  if leg "$l" && compare "$out/native" "$out/$l" "native-gcc-O0" "$build_name"; then
    summary+=("$l: identical (${leg_seconds} s)")
  else
    summary+=("$l: FAILED"); status=1
  fi
done

if [ $control = 1 ]; then
  # The control: a build that may contract a*b+c into FMA (aarch64 has it, gcc -O2 uses it) must
  # give other bits somewhere in the corpus, or the corpus could not see the flag go missing.
  say "control: aarch64 with -DRICOCHET_CONTROL_CONTRACT=ON"
  leg_seconds=0
  if leg aarch64 "${prefix}aarch64-control" -DRICOCHET_CONTROL_CONTRACT=ON; then
    if compare "$out/native" "$out/aarch64" "native-gcc-O0" "aarch64-contract" >"$out/control.txt"; then
      summary+=("control: FAILED, the corpus does not detect FMA contraction")
      status=1
    else
      n=$(grep -c '^DIFFERS' "$out/control.txt")
      head -n 3 "$out/control.txt"
      summary+=("control: contraction detected, $n outputs differ (${leg_seconds} s)")
    fi
  else
    summary+=("control: FAILED to build or run"); status=1
  fi
fi

for s in "${summary[@]}"; do echo "cross: $s"; done
exit $status
