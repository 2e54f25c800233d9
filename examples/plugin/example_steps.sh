# The steps the plug-in examples' tests share (plugin_example_test.sh, ../plugin-disc/plugin_disc_example_test.sh),
# sourced after the settings file examples/CMakeLists.txt generates. Each writes only under $work.
#   install_ricochet               installs this build into $work/prefix; sets prefix and ricochet (its command)
#   build_example DIR NAME         builds the example project DIR against it with find_package(ricochet); sets lib to
#                                  its $work/NAME/NAME.so
#   caught_by PROPERTY FILTER CASES KERNEL
#                                  the property suite ($props) filtered to FILTER, under the plug-in with RapidCheck's
#                                  seed 1 and at most CASES cases, fails (exit 1) and saves one log, from PROPERTY, in
#                                  $work/replays, which replays_as_found
#   replays_as_found LOG KERNEL    LOG (naming KERNEL) is a regression, not a documented weakness (no `expect
#                                  failure`): `ricochet replay --plugin $lib` fails it (exit 1) at the check, frame and
#                                  ball of its `found` line while the bug is there, and passes it stepped by code
#                                  without the bug (robust in the plug-in's place)
fail() { echo "FAIL: $*"; exit 1; }

install_ricochet() {
  prefix=$work/prefix
  echo "== install into $prefix"
  "$cmake" --install "$build_dir" --prefix "$prefix" >"$work/install.log" || { cat "$work/install.log"; fail "cmake --install"; }
  [ -f "$prefix/include/ricochet/plugin.h" ] || fail "plugin.h is not installed"
  ricochet=$prefix/bin/ricochet
}

build_example() {
  echo "== examples/$1"
  "$cmake" -S "$source_dir/examples/$1" -B "$work/$2" -G "$generator" -DCMAKE_MAKE_PROGRAM="$make_program" \
    -DCMAKE_C_COMPILER="$cc" -DCMAKE_BUILD_TYPE="$build_type" -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF >"$work/configure.log" 2>&1 || { cat "$work/configure.log"; fail "configure"; }
  "$cmake" --build "$work/$2" >"$work/build.log" 2>&1 || { cat "$work/build.log"; fail "build"; }
  found=$(sed -n 's/^ricochet_DIR:PATH=//p' "$work/$2/CMakeCache.txt")
  [ "$found" = "$prefix/$libdir/cmake/ricochet" ] || fail "the example found ricochet in '$found', not in $prefix"
  lib=$work/$2/$2.so
  [ -f "$lib" ] || fail "no $lib"
}

replays_as_found() {
  grep -qx "kernel $2" "$1" || fail "$1 does not name the plug-in's kernel"
  set -- "$1" $(sed -n 's/^found \([a-z-]*\) \([0-9]*\) \([0-9]*\)$/\1 \2 \3/p' "$1")
  [ "$#" = 4 ] || fail "$1 has no found line"
  ! grep -q '^expect failure' "$1" || fail "$1 expects its failure: the bug would keep CI green"
  set +e
  "$ricochet" replay --plugin "$lib" "$1" >"$work/replay.out" 2>&1
  status=$?
  set -e
  [ "$status" = 1 ] || { cat "$work/replay.out"; fail "replay exits $status on $1, expected 1 (the bug is there)"; }
  grep -q "$2 broke at frame $3 ball $4:" "$work/replay.out" || { cat "$work/replay.out"; fail "replay does not fail $2 at frame $3 ball $4"; }
  "$ricochet" replay --plugin "$lib" --kernel robust "$1" >"$work/replay.out" 2>&1 ||
    { cat "$work/replay.out"; fail "$1 fails stepped by robust: it would not pass once the bug is fixed"; }
  echo "$(basename "$1"): $2 at frame $3 ball $4, reproduced; passes without the bug"
}

caught_by() {
  echo "== the property suite, RICOCHET_KERNEL=plugin:$lib, $1"
  set +e
  RICOCHET_KERNEL="plugin:$lib" RICOCHET_REPLAY_DIR="$work/replays" RC_PARAMS="seed=1 max_success=$3" \
    "$props" --gtest_filter="$2" >"$work/props.out" 2>&1
  status=$?
  set -e
  grep "$1 \[$4\]" "$work/props.out" || true
  [ "$status" = 1 ] || { tail -n 30 "$work/props.out"; fail "the property suite exits $status, expected 1 (a failure caught)"; }
  set -- "$work"/replays/*.scene "$1" "$4"
  [ "$#" = 3 ] && [ -f "$1" ] || fail "expected one saved log in $work/replays"
  grep -qx "from property $2 seed 1" "$1" || fail "$1 does not say where it came from"
  replays_as_found "$1" "$3"
}
