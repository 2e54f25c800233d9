#!/bin/bash
# The contract under bugs that are not the lecture's: a failure the harness reports is one `ricochet replay`
# reproduces from the saved log on the code that saved it, and the log passes once the bug is gone.
# fuzz_failures_reproduce proves it on the lecture kernels, whose logs expect their documented failures; here the
# code under test is a modified core held to the guarantees (fuzz/contract/bug_plugin.c, one bug per plug-in: a
# whole-frame step that drifts, static and sweep tests that miss touching), whose saved logs are regressions. Every fuzz target but the parser
# (libFuzzer with a fixed -seed and -runs, one process, as fuzz_failures_reproduce runs them; each failure written
# as a log and reduced with `ricochet reduce`, as the campaign does) and a set of properties (a fixed RapidCheck seed
# and case count) run against each plug-in, saving into temporary folders. Then for every saved log:
#   - it names the plug-in's kernel, has `found C F B` and no `expect failure`;
#   - `ricochet replay --plugin P LOG` fails it (exit 1) with check C at frame F for ball B, without saying that the
#     run differs from `found` (it reproduces on the modified core);
#   - `ricochet replay --plugin P --kernel robust LOG` passes it (the same log on a core without the bug).
# Prints "reproduced N/N"; fails unless every log does both, and the static, sweep and scene targets and the
# properties each found at least one failure.
# Usage: modified_cores_test.sh RICOCHET_EXE FUZZ_BIN_DIR SOURCE_DIR PROPERTIES_EXE [disc:]PLUGIN.so...
#   (disc: a plug-in that steps discs, plugin.h version 2: the disc target and the disc properties run too)
set -u
exe=$(realpath -s "$1"); bins=$(realpath -s "$2"); src=$(realpath -s "$3"); props=$(realpath -s "$4")
shift 4
plugins=()
for p in "$@"; do
  case $p in disc:*) plugins+=("disc:$(realpath -s "${p#disc:}")") ;; *) plugins+=("$(realpath -s "$p")") ;; esac
done
TMP="$(mktemp -d "${TMPDIR:-/tmp}/ricochet-modified.XXXXXX")" || exit 1
trap 'rm -rf "$TMP"' EXIT
trap 'exit 143' INT TERM
cd "$TMP" || exit 1  # libFuzzer writes nothing into the source tree, whatever it is asked
# Inputs per libFuzzer process; a process stops at its first failure. With these seeds and counts (measured
# 2026-12-05, ASan+UBSan build): static 2, sweep 4, scene 4 and properties 8 logs, in about 20 s.
runs=3000
fuzz_seeds="1 2"
properties='*NoTunnelWalls*:*FrameOracle*:*NoEscapeClosedPolygon*:*StaticBoundary*:*SweepBoundary*:*HitAccuracy*'
disc_properties='*DiscNoTunnelChains*:*BumperNoTunnel*:*DiscAccuracy*'
declare -A found_by
logs=()
for spec in "${plugins[@]}"; do
  p=${spec#disc:} targets="static sweep scene" filter=$properties
  [ "$spec" = "$p" ] || { targets="$targets disc"; filter="$filter:$disc_properties"; }
  name=$(basename "$p" .so)
  for t in $targets; do
    [ -x "$bins/fuzz_$t" ] || { echo "FAIL: $bins/fuzz_$t is missing"; exit 1; }
    for s in $fuzz_seeds; do
      art="$TMP/art/$name-$t-$s/"; mkdir -p "$art" "$TMP/junk" "$TMP/logs/$name"
      RICOCHET_KERNEL="plugin:$p" "$bins/fuzz_$t" -seed="$s" -runs="$runs" -reload=0 -use_cmp=0 -use_memmem=0 \
        -dict="$src/fuzz/$t.dict" -artifact_prefix="$art" -print_final_stats=0 > "$art/out" 2>&1
      crash=$(find "$art" -name 'crash-*' | sort | head -n 1)
      [ -n "$crash" ] || continue
      log="$TMP/logs/$name/$t-$s.scene"
      sha=$(sha1sum < "$crash" | cut -c1-40)
      RICOCHET_KERNEL="plugin:$p" RICOCHET_FUZZ_SCENE_OUT="$log" RICOCHET_FUZZ_SHA1="$sha" \
        "$bins/fuzz_$t" -artifact_prefix="$TMP/junk/" "$crash" > "$art/again" 2>&1
      [ -f "$log" ] || { echo "FAIL: fuzz_$t ($name, seed $s) failed but wrote no log:"; tail -n 5 "$art/again"; exit 1; }
      "$exe" reduce --plugin "$p" "$log" -o "$art/reduced.scene" 2>"$art/reduce" ||
        { echo "FAIL: ricochet reduce --plugin $p $log:"; cat "$art/reduce"; exit 1; }
      mv "$art/reduced.scene" "$log"
      logs+=("$p|$log")
      found_by[$t]=$(( ${found_by[$t]:-0} + 1 ))
    done
    echo "$name $t: ${found_by[$t]:-0} so far, at ${SECONDS} s"
  done
  d="$TMP/logs/$name/properties"; mkdir -p "$d"
  RICOCHET_KERNEL="plugin:$p" RICOCHET_REPLAY_DIR="$d" RC_PARAMS="seed=1 max_success=300" GTEST_FILTER="$filter" \
    "$props" > "$TMP/$name-props.out" 2>&1
  n=0
  for log in "$d"/*.scene; do
    [ -f "$log" ] || continue
    logs+=("$p|$log"); n=$((n + 1))
  done
  found_by[properties]=$(( ${found_by[properties]:-0} + n ))
  echo "$name properties: $n logs, at ${SECONDS} s"
done

reproduced=0 total=0
for entry in "${logs[@]}"; do
  p=${entry%%|*} log=${entry#*|}
  total=$((total + 1))
  kernel=$(sed -n 's/^kernel //p' "$log")
  set -- $(sed -n 's/^found \([a-z-]*\) \([0-9]*\) \([0-9]*\)$/\1 \2 \3/p' "$log")
  if [ "$#" != 3 ]; then echo "FAIL: $log has no found line"; continue; fi
  if grep -q '^expect failure' "$log"; then echo "FAIL: $log expects its failure (a bug of code held to the guarantees)"; continue; fi
  "$exe" replay --plugin "$p" "$log" > "$TMP/replay.out" 2>&1
  rc=$?
  if [ "$rc" != 1 ] || ! grep -q "invariant $1 broke at frame $2 ball $3:" "$TMP/replay.out" || grep -q "when saved" "$TMP/replay.out"; then
    echo "FAIL: $log (kernel $kernel, found $1 $2 $3) does not reproduce on the modified core (exit $rc):"
    cat "$TMP/replay.out"; continue
  fi
  if ! "$exe" replay --plugin "$p" --kernel robust "$log" > "$TMP/fixed.out" 2>&1; then
    echo "FAIL: $log (kernel $kernel) fails without the bug (robust in its place):"; cat "$TMP/fixed.out"; continue
  fi
  reproduced=$((reproduced + 1))
done
echo "found: static ${found_by[static]:-0}, sweep ${found_by[sweep]:-0}, scene ${found_by[scene]:-0}, disc ${found_by[disc]:-0}, properties ${found_by[properties]:-0}"
echo "reproduced $reproduced/$total, and each passes without its bug"
[ "$total" -gt 0 ] && [ "$reproduced" = "$total" ] || exit 1
wanted="static sweep scene properties"
case " ${plugins[*]}" in *" disc:"*) wanted="$wanted disc" ;; esac
for what in $wanted; do
  [ "${found_by[$what]:-0}" -ge 1 ] || { echo "FAIL: $what found no failure in any modified core"; exit 1; }
done
echo PASS
