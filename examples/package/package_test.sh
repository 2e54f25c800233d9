#!/bin/sh
# The package end to end: installs this build into BUILD/package-test/prefix, builds examples/consumer
# and the contraction probe (package/contraction) against it with -march=native, and checks
#   - what is installed: headers, the core archive, the command, the config and its version file;
#   - the version file takes 0.2 and 0.2.x and refuses 0.1, 0.3 and 1.0 (SameMinorVersion);
#   - the consumer found this prefix, and its hash of replays/pinball.scene is the installed
#     `ricochet replay --hashes`'s and the log's own `expect hash`;
#   - the consumer's compile line carries the floating-point flags and C++20 from ricochet::core;
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
         "$libdir/libricochet_core.a" bin/ricochet \
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

# configure_and_build NAME SOURCE: the project at SOURCE into $work/NAME, against $prefix, -march=native.
configure_and_build() {
  "$cmake" -S "$2" -B "$work/$1" -G "$generator" -DCMAKE_MAKE_PROGRAM="$make_program" \
    -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE="$build_type" \
    -DCMAKE_CXX_FLAGS="$cxx_flags -march=native" -DCMAKE_EXE_LINKER_FLAGS="$linker_flags" \
    -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF -DCMAKE_EXPORT_COMPILE_COMMANDS=ON \
    >"$work/$1-configure.log" 2>&1 || { cat "$work/$1-configure.log"; fail "configure $1"; }
  "$cmake" --build "$work/$1" >"$work/$1-build.log" 2>&1 || { cat "$work/$1-build.log"; fail "build $1"; }
  found=$(sed -n 's/^ricochet_DIR:PATH=//p' "$work/$1/CMakeCache.txt")
  [ "$found" = "$prefix/$libdir/cmake/ricochet" ] || fail "$1 found ricochet in '$found', not in $prefix"
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

echo "== contraction probe"
configure_and_build contraction "$source_dir/examples/package/contraction"
"$work/contraction/contraction" || fail "cross() in the user's code was contracted into an FMA"
if "$work/contraction/contraction_fused"; then
  echo "control: this compiler and CPU do not fuse here; the compile-line check above is the proof"
else
  echo "control: with -ffp-contract=fast the same code fuses here, so the probe bites"
fi
echo "PASS"
