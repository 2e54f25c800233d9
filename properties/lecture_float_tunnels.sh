#!/bin/sh
# The harness bites: pointed at lecture-float, NoTunnelSingleWall must fail within 10 s and leave exactly
# one log, written into a fresh temporary folder (not replays/), that names the property, its seed and the
# no-tunnel check, and that `ricochet replay` shows failing.
# Usage: lecture_float_tunnels.sh PROPERTIES_BINARY RICOCHET_BINARY
set -u
props=$1
ricochet=$2
dir=$(mktemp -d "${TMPDIR:-/tmp}/ricochet-props.XXXXXX") || exit 1
trap 'rm -rf "$dir"' EXIT
die() { echo "lecture_float_tunnels: FAIL: $*"; exit 1; }

start=$(date +%s.%N)
RICOCHET_KERNEL=lecture-float RICOCHET_REPLAY_DIR=$dir \
  "$props" --gtest_filter='*NoTunnelSingleWall*' >"$dir/props.out" 2>&1
status=$?
end=$(date +%s.%N)
elapsed=$(echo "$end - $start" | bc)
tail -n 40 "$dir/props.out"
[ "$status" -ne 0 ] || die "the no-tunnelling property passed under lecture-float"
[ "$(echo "$elapsed < 10" | bc)" -eq 1 ] || die "it took ${elapsed} s to fail (limit 10 s)"

set -- "$dir"/*.scene
[ "$#" -eq 1 ] && [ -f "$1" ] || die "expected exactly one saved log in $dir, found $#"
log=$1
cat "$log"
grep -q '^from property NoTunnelSingleWall seed [0-9][0-9]*$' "$log" || die "the log lacks 'from property NoTunnelSingleWall seed S'"
grep -q '^check no-tunnel$' "$log" || die "the log lacks 'check no-tunnel'"
grep -q '^kernel lecture-float$' "$log" || die "the log does not name kernel lecture-float"
grep -q '^expect failure' "$log" && die "the log expects its failure, so replay would pass"

"$ricochet" replay "$log" >"$dir/replay.out" 2>&1
rstatus=$?
cat "$dir/replay.out"
[ "$rstatus" -ne 0 ] || die "ricochet replay passes the saved log"
grep -q 'no-tunnel' "$dir/replay.out" || die "ricochet replay does not name the no-tunnel check"

echo "lecture_float_tunnels: OK: failed in ${elapsed} s, log $(basename "$log"), replay exit $rstatus"
