#!/bin/sh
# The disc properties bite where a kernel steps discs badly: pointed at lecture-float, DiscNoEscapeClosedPolygon
# (no-escape, no-tunnel, penetration and speed on discs in closed polygons) must fail and leave exactly one log,
# in a fresh temporary folder, that names the property, its seed and the check that broke, expects that failure
# (a documented weakness) and records it in `found`; `ricochet replay` passes it, and with `expect failure`
# removed fails it at that check, frame and ball. A fixed RapidCheck seed and case count: the same verdict on
# every run. A skipped property (a kernel that refuses discs) fails this test: lecture-float steps discs.
# Usage: disc_lecture_float.sh PROPERTIES_BINARY RICOCHET_BINARY
set -u
props=$1
ricochet=$2
seed=1
cases=500
property=DiscNoEscapeClosedPolygon
dir=$(mktemp -d "${TMPDIR:-/tmp}/ricochet-disc-props.XXXXXX") || exit 1
trap 'rm -rf "$dir"' EXIT
die() { echo "disc_lecture_float: FAIL: $*"; exit 1; }

RICOCHET_KERNEL=lecture-float RICOCHET_REPLAY_DIR=$dir RC_PARAMS="seed=$seed max_success=$cases" \
  "$props" --gtest_filter="*Discs.$property/*" >"$dir/props.out" 2>&1
status=$?
tail -n 40 "$dir/props.out"
! grep -q '^\[  SKIPPED \] ' "$dir/props.out" || die "the property was skipped under lecture-float"
[ "$status" -ne 0 ] || die "$property passed under lecture-float (seed $seed, $cases cases)"

set -- "$dir"/*.scene
[ "$#" -eq 1 ] && [ -f "$1" ] || die "expected exactly one saved log in $dir, found $#"
log=$1
cat "$log"
grep -q "^from property $property seed $seed\$" "$log" || die "the log lacks 'from property $property seed $seed'"
grep -q '^kernel lecture-float$' "$log" || die "the log does not name kernel lecture-float"
check=$(sed -n 's/^expect failure \([a-z-]*\) [0-9]*$/\1/p' "$log")
[ -n "$check" ] || die "the log does not expect its failure"
found=$(sed -n "s/^found $check \\([0-9]*\\) \\([0-9]*\\)\$/\\1 \\2/p" "$log")
[ -n "$found" ] || die "the log lacks 'found $check F BALL'"
"$ricochet" replay "$log" >"$dir/replay.out" 2>&1 || { cat "$dir/replay.out"; die "ricochet replay fails the saved log"; }
grep -v '^expect failure' "$log" >"$dir/bare.scene"
"$ricochet" replay "$dir/bare.scene" >"$dir/replay.out" 2>&1
rstatus=$?
cat "$dir/replay.out"
[ "$rstatus" -ne 0 ] || die "ricochet replay passes the saved log without expect failure"
set -- $found
grep -q "$check broke at frame $1 ball $2:" "$dir/replay.out" || die "ricochet replay does not fail $check at frame $1 ball $2"

echo "disc_lecture_float: OK: seed $seed, log $(basename "$log"), $check at frame $1 ball $2, replay exit $rstatus"
