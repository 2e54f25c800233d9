#!/bin/sh
# The plug-in example end to end: installs this build into BUILD/plugin-test/prefix, builds examples/plugin (a
# float ray/segment test in C, naive_float.so) against it with find_package(ricochet), and runs the harness on it:
#   - the installed `ricochet run --kernel plugin:…` steps a log with it;
#   - the property suite (RICOCHET_KERNEL=plugin:…, a fixed RapidCheck seed) catches it tunnelling and saves one
#     log, a regression (no `expect failure`), which the installed `ricochet replay --plugin …` fails at the check,
#     frame and ball of its `found` line, and passes stepped by code without the bug (`--kernel robust`);
#   - where the fuzz targets are libFuzzer ones, `ricochet fuzz --kernel plugin:… --target sweep` (fixed seed and
#     run count) finds a failure (exit 1), and every log it saves replays the same way.
# Writes only under BUILD/plugin-test.
#   plugin_example_test.sh SETTINGS PROPERTIES FUZZ_BIN_DIR    (SETTINGS: the shell file examples/CMakeLists.txt
#                                                               generates; PROPERTIES: the property binary)
set -eu
. "$1"
props=$2 fuzz_bins=$3
work=$build_dir/plugin-test
. "$source_dir/examples/plugin/example_steps.sh"
rm -rf "$work"
mkdir -p "$work"

install_ricochet
build_example plugin naive_float

echo "== ricochet run --kernel plugin:$lib"
"$ricochet" run "$source_dir/replays/pinball.scene" --kernel "plugin:$lib" >"$work/run.out" || fail "run exits $?"
grep -q '^hit ' "$work/run.out" || fail "no hit in the pinball table's run"

# With seed 1 it tunnels after 9 passing cases (measured); the verdict is the same on every run.
caught_by NoTunnelSingleWall '*NoTunnelSingleWall*' 1000 naive-float

if "$fuzz_bins/fuzz_sweep" -help=1 2>&1 | grep -q '^Usage:'; then
  echo "== ricochet fuzz --kernel plugin:$lib --target sweep"
  # Full-length inputs from the start (-len_control=0 -max_len=64): three runs of fuzz_sweep on this plug-in
  # found a failure at input 89; 3000 inputs leave room whatever order the fuzzer's coverage takes.
  set +e
  "$ricochet" fuzz --kernel "plugin:$lib" --target sweep --runs 3000 --seed 1 --bin-dir "$fuzz_bins" \
    --cache-dir "$work/cache" --replay-dir "$work/fuzz-replays" -- -len_control=0 -max_len=64 >"$work/fuzz.out" 2>&1
  status=$?
  set -e
  [ "$status" = 1 ] || { cat "$work/fuzz.out"; fail "the campaign exits $status, expected 1 (a new failure)"; }
  grep -q "^ricochet fuzz: kernel naive-float (plug-in $lib)" "$work/fuzz.out" || fail "the campaign does not name the plug-in"
  for log in "$work"/fuzz-replays/*.scene; do
    [ -f "$log" ] || fail "the campaign saved no log"
    grep -q "scene log: $log  (ricochet replay --plugin $lib $log)" "$work/fuzz.out" || fail "no replay hint for $log"
    # Reduced as every saved failure is, in a process of its own (`ricochet reduce --plugin`).
    grep -q '^from reduce ' "$log" || { cat "$work/fuzz.out"; fail "$log was not reduced"; }
    replays_as_found "$log" naive-float
  done
else
  echo "== no libFuzzer fuzz_sweep in $fuzz_bins: the campaign is not run"
fi
echo "PASS"
