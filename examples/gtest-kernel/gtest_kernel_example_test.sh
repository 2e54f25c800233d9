#!/bin/sh
# The GoogleTest example end to end: installs this build into BUILD/gtest-kernel-test/prefix, builds
# examples/gtest-kernel against it (find_package(ricochet COMPONENTS properties)), and shows the contract from
# the user's side:
#   - the user's test binary runs BounceSpeed (a fixed seed and case count) against its kernel linked in, fails
#     (exit 1) and saves one log in found/ of the folder it ran in, naming the kernel, without `expect failure`;
#   - the reproduce command the failure message prints, run as printed, fails again on the saved log;
#   - the same kernel built as a plug-in: the installed `ricochet replay --plugin` fails the log at the check,
#     frame and ball of its `found` line, and passes it stepped by robust;
#   - the kernel built without its bug (-DMY_KERNEL_FIXED=ON): `ricochet replay --plugin` passes the log, and the
#     test binary replays it (RC_PARAMS=max_success=0: the saved logs only) and passes, then passes BounceSpeed.
# Writes only under BUILD/gtest-kernel-test.
#   gtest_kernel_example_test.sh SETTINGS    (SETTINGS: the shell file examples/CMakeLists.txt generates)
set -eu
. "$1"
work=$build_dir/gtest-kernel-test
. "$source_dir/examples/plugin/example_steps.sh"
rm -rf "$work"
mkdir -p "$work"

install_ricochet
[ -f "$prefix/include/ricochet/properties.hpp" ] || fail "ricochet/properties.hpp is not installed"

# build NAME [CMAKE ARGS]: the example into $work/NAME.
build() {
  name=$1
  shift
  echo "== examples/gtest-kernel into $name $*"
  "$cmake" -S "$source_dir/examples/gtest-kernel" -B "$work/$name" -G "$generator" -DCMAKE_MAKE_PROGRAM="$make_program" \
    -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE="$build_type" -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF "$@" >"$work/$name-configure.log" 2>&1 ||
    { cat "$work/$name-configure.log"; fail "configure $name"; }
  "$cmake" --build "$work/$name" >"$work/$name-build.log" 2>&1 || { cat "$work/$name-build.log"; fail "build $name"; }
  found=$(sed -n 's/^ricochet_DIR:PATH=//p' "$work/$name/CMakeCache.txt")
  [ "$found" = "$prefix/$libdir/cmake/ricochet" ] || fail "$name found ricochet in '$found', not in $prefix"
}
build buggy
build fixed -DMY_KERNEL_FIXED=ON
lib=$work/buggy/my_kernel.so

# The user's binary, run from a folder of theirs: ricochet's property and the user's own test.
run=$work/project
mkdir -p "$run"
filter='Kernels/Sweep.BounceSpeed/*:MyKernel.*'
echo "== my_kernel_tests --gtest_filter='$filter'"
set +e
(cd "$run" && RC_PARAMS="seed=1 max_success=300" "$work/buggy/my_kernel_tests" --gtest_filter="$filter") >"$work/first.out" 2>&1
status=$?
set -e
[ "$status" = 1 ] || { tail -n 30 "$work/first.out"; fail "the buggy binary exits $status, expected 1 (a failure caught)"; }
grep -q '^\[       OK \] MyKernel.BouncesHeadOnOffAUnitWall' "$work/first.out" || fail "the user's own test did not pass"
grep -q '^\[  FAILED  \] Kernels/Sweep.BounceSpeed/my_kernel' "$work/first.out" || fail "BounceSpeed did not fail"
grep 'BounceSpeed \[my-kernel\]' "$work/first.out" | cut -c1-200
set -- "$run"/found/*.scene
[ "$#" = 1 ] && [ -f "$1" ] || fail "expected one saved log in $run/found"
log=$1
grep -qx "from property BounceSpeed seed 1" "$log" || fail "$log does not say where it came from"

echo "== the reproduce command, as printed"
command=$(sed -n 's/^reproduce: //p' "$work/first.out")
[ -n "$command" ] || fail "no reproduce command printed"
echo "$command"
set +e
(cd "$run" && eval "$command") >"$work/again.out" 2>&1
status=$?
set -e
[ "$status" = 1 ] || { tail -n 30 "$work/again.out"; fail "the reproduce command exits $status, expected 1"; }
grep -q "saved log $log breaks BounceSpeed under my-kernel again" "$work/again.out" ||
  { tail -n 30 "$work/again.out"; fail "the reproduce command did not fail on the saved log"; }

echo "== ricochet replay --plugin"
replays_as_found "$log" my-kernel

echo "== without the bug"
"$ricochet" replay --plugin "$work/fixed/my_kernel.so" "$log" >"$work/replay-fixed.out" 2>&1 ||
  { cat "$work/replay-fixed.out"; fail "the log fails on the fixed kernel"; }
(cd "$run" && RC_PARAMS="seed=1 max_success=0" "$work/fixed/my_kernel_tests" --gtest_filter="$filter") >"$work/fixed.out" 2>&1 ||
  { tail -n 30 "$work/fixed.out"; fail "the fixed binary fails its saved log"; }
grep -q 'BounceSpeed \[my-kernel\]: OK, 0 cases, 1 saved logs replayed' "$work/fixed.out" ||
  { tail -n 30 "$work/fixed.out"; fail "the fixed binary did not replay the saved log"; }
(cd "$run" && RC_PARAMS="seed=1 max_success=300" "$work/fixed/my_kernel_tests" --gtest_filter="$filter") >"$work/fixed.out" 2>&1 ||
  { tail -n 30 "$work/fixed.out"; fail "the fixed kernel fails BounceSpeed"; }
grep 'BounceSpeed \[my-kernel\]' "$work/fixed.out"
echo "PASS"
