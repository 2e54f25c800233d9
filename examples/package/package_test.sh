#!/bin/sh
# The package end to end: installs this build into BUILD/package-test/prefix, builds examples/consumer,
# examples/harness and the contraction probe (package/contraction) against it with -march=native, and checks
#   - what is installed: headers, the core and harness archives, the command, the config and its version file;
#   - the version file takes 0.2 and 0.2.x and refuses 0.1, 0.3 and 1.0 (SameMinorVersion);
#   - the consumer found this prefix, and its hash of replays/pinball.scene is the installed
#     `ricochet replay --hashes`'s and the log's own `expect hash`;
#   - the consumer's compile line carries the floating-point flags and C++20 from ricochet::core;
#   - the harness consumer's replay verdicts are the installed `ricochet replay`'s, on a log that passes and on
#     a lecture log that reproduces its expected failure, and it finds that failure with every check;
#   - the core alone (`--component core`, into BUILD/package-test/core-only) has no harness file, the consumer
#     builds and runs against it with nothing of the harness on its link line, and find_package(... COMPONENTS
#     harness) there fails, saying how to install it;
#   - the probe's inline cross() is not contracted (its control says whether this CPU would fuse).
# Writes only under BUILD/package-test.
#   package_test.sh SETTINGS    (SETTINGS: the shell file examples/CMakeLists.txt generates)
set -eu
. "$1"
work=$build_dir/package-test
prefix=$work/prefix
log=$source_dir/replays/pinball.scene
fail() { echo "FAIL: $*"; exit 1; }
rm -rf "$work"
mkdir -p "$work"

echo "== install into $prefix"
"$cmake" --install "$build_dir" --prefix "$prefix" >"$work/install.log" || { cat "$work/install.log"; fail "cmake --install"; }
for f in include/ricochet/vec2.hpp include/ricochet/fp_guard.hpp include/ricochet/world.hpp \
         include/ricochet/checks.hpp include/ricochet/replay.hpp "$libdir/libricochet_harness.a" \
         "$libdir/cmake/ricochet/ricochetHarnessTargets.cmake" "$libdir/libricochet_core.a" bin/ricochet \
         "$libdir/cmake/ricochet/ricochetConfig.cmake" "$libdir/cmake/ricochet/ricochetConfigVersion.cmake" \
         "$libdir/cmake/ricochet/ricochetTargets.cmake"; do
  [ -e "$prefix/$f" ] || fail "not installed: $f"
done

echo "== version file"
cat >"$work/version.cmake" <<CMAKE
foreach(want 0.2 0.2.0 0.2.7 0.1 0.3 1.0)
  string(REPLACE "." ";" parts \${want})
  list(GET parts 0 PACKAGE_FIND_VERSION_MAJOR)
  list(GET parts 1 PACKAGE_FIND_VERSION_MINOR)
  set(PACKAGE_FIND_VERSION \${want})
  unset(PACKAGE_VERSION_COMPATIBLE)
  include("$prefix/$libdir/cmake/ricochet/ricochetConfigVersion.cmake")
  message("\${want} \${PACKAGE_VERSION_COMPATIBLE}")
endforeach()
CMAKE
versions=$("$cmake" -P "$work/version.cmake" 2>&1 | tr '\n' ' ')
[ "$versions" = "0.2 TRUE 0.2.0 TRUE 0.2.7 FALSE 0.1 FALSE 0.3 FALSE 1.0 FALSE " ] || fail "version answers: $versions"
echo "$versions"

# configure NAME SOURCE [PREFIX]: the project at SOURCE into $work/NAME, against PREFIX ($prefix by default),
# -march=native.
configure() {
  "$cmake" -S "$2" -B "$work/$1" -G "$generator" -DCMAKE_MAKE_PROGRAM="$make_program" \
    -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE="$build_type" \
    -DCMAKE_CXX_FLAGS="$cxx_flags -march=native" -DCMAKE_EXE_LINKER_FLAGS="$linker_flags" \
    -DCMAKE_PREFIX_PATH="${3:-$prefix}" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF -DCMAKE_EXPORT_COMPILE_COMMANDS=ON \
    >"$work/$1-configure.log" 2>&1
}
# configure_and_build NAME SOURCE [PREFIX]: configure, then build (its commands kept in $work/NAME-build.log), and
# check that it found PREFIX.
configure_and_build() {
  configure "$@" || { cat "$work/$1-configure.log"; fail "configure $1"; }
  "$cmake" --build "$work/$1" --verbose >"$work/$1-build.log" 2>&1 || { cat "$work/$1-build.log"; fail "build $1"; }
  found=$(sed -n 's/^ricochet_DIR:PATH=//p' "$work/$1/CMakeCache.txt")
  [ "$found" = "${3:-$prefix}/$libdir/cmake/ricochet" ] || fail "$1 found ricochet in '$found', not in ${3:-$prefix}"
}

echo "== examples/consumer"
configure_and_build consumer "$source_dir/examples/consumer"
got=$("$work/consumer/consumer" "$log") || fail "consumer $log failed"
replayed=$("$prefix/bin/ricochet" replay --hashes "$log" | cut -d' ' -f1)
expected=$(sed -n 's/^expect hash //p' "$log")
echo "consumer $got, installed ricochet replay --hashes $replayed, expect hash $expected"
[ "$got" = "$replayed" ] && [ "$got" = "$expected" ] || fail "hashes differ"

line=$(grep '"command"' "$work/consumer/compile_commands.json" | grep 'main\.cpp') || fail "no compile line for main.cpp"
for flag in $fp_flags -march=native; do
  case " $line " in *" $flag "*) ;; *) fail "main.cpp compiled without $flag: $line" ;; esac
done
echo "$line" | grep -Eq -- '-std=(c|gnu)\+\+(20|2a)' || fail "main.cpp compiled without C++20: $line"
echo "main.cpp compiled with $fp_flags and C++20"

echo "== examples/harness"
configure_and_build harness "$source_dir/examples/harness"
lecture_log=$source_dir/replays/lecture/double-pinball-tunnel.scene
for l in "$log" "$lecture_log"; do
  "$work/harness/harness_consumer" "$l" >"$work/harness-out.txt" || fail "harness_consumer $l: exit $?"
  cat "$work/harness-out.txt"
  "$prefix/bin/ricochet" replay "$l" >"$work/replay-out.txt" || fail "ricochet replay $l: exit $?"
  # The installed command prints "ok   PATH: MESSAGE"; the consumer "replay: passed: MESSAGE".
  want=$(head -n 1 "$work/replay-out.txt" | sed 's/^ok *[^:]*: //')
  got=$(sed -n 's/^replay: passed: //p' "$work/harness-out.txt")
  [ -n "$want" ] && [ "$got" = "$want" ] || fail "harness_consumer $l says '$got', ricochet replay '$want'"
done
# The lecture log expects a tunnel; with every check the consumer finds a broken invariant in it too.
grep -q '^all checks: .* broke at frame' "$work/harness-out.txt" || fail "harness_consumer found no failure in $lecture_log"

echo "== the core alone (--component core)"
core_prefix=$work/core-only
"$cmake" --install "$build_dir" --prefix "$core_prefix" --component core >"$work/install-core.log" ||
  { cat "$work/install-core.log"; fail "cmake --install --component core"; }
for f in include/ricochet/checks.hpp include/ricochet/truth.hpp include/ricochet/replay.hpp \
         "$libdir/libricochet_harness.a" "$libdir/cmake/ricochet/ricochetHarnessTargets.cmake" bin/ricochet; do
  [ ! -e "$core_prefix/$f" ] || fail "--component core installed $f"
done
configure_and_build consumer-core "$source_dir/examples/consumer" "$core_prefix"
grep -q 'libricochet_core\.a' "$work/consumer-core-build.log" || fail "the consumer's link line names no libricochet_core.a"
! grep -q 'ricochet_harness' "$work/consumer-core-build.log" ||
  fail "the core consumer's build names the harness: $(grep ricochet_harness "$work/consumer-core-build.log" | head -n 1)"
got=$("$work/consumer-core/consumer" "$log") || fail "the core-only consumer failed on $log"
[ "$got" = "$expected" ] || fail "the core-only consumer's hash $got, not $expected"
echo "core-only consumer $got, its build names nothing of the harness"
if configure harness-core "$source_dir/examples/harness" "$core_prefix"; then
  fail "examples/harness configured against the core alone"
fi
grep -q 'component harness' "$work/harness-core-configure.log" ||
  { cat "$work/harness-core-configure.log"; fail "find_package(ricochet COMPONENTS harness) did not say how to install it"; }
echo "find_package(ricochet COMPONENTS harness) against the core alone: refused, naming --component harness"

echo "== contraction probe"
configure_and_build contraction "$source_dir/examples/package/contraction"
"$work/contraction/contraction" || fail "cross() in the user's code was contracted into an FMA"
if "$work/contraction/contraction_fused"; then
  echo "control: this compiler and CPU do not fuse here; the compile-line check above is the proof"
else
  echo "control: with -ffp-contract=fast the same code fuses here, so the probe bites"
fi
echo "PASS"
