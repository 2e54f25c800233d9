#!/bin/sh
# The harness bites: pointed at lecture-float, NoTunnelSingleWall must fail and leave exactly one log,
# written into a fresh temporary folder (not replays/), that names the property, its seed and the
# no-tunnel check, and that `ricochet replay` shows failing. RapidCheck runs with a fixed seed and case
# count, so the verdict (and the log) is the same on every run, whatever the machine's load.
# Usage: lecture_float_tunnels.sh PROPERTIES_BINARY RICOCHET_BINARY
set -u
props=$1
ricochet=$2
# The seed and case count: with seed 1 the property fails after 9 passing cases, the same case in every
# run; the count, the property's default, leaves room.
seed=1
cases=4000
dir=$(mktemp -d "${TMPDIR:-/tmp}/ricochet-props.XXXXXX") || exit 1
trap 'rm -rf "$dir"' EXIT
die() { echo "lecture_float_tunnels: FAIL: $*"; exit 1; }

RICOCHET_KERNEL=lecture-float RICOCHET_REPLAY_DIR=$dir RC_PARAMS="seed=$seed max_success=$cases" \
  "$props" --gtest_filter='*NoTunnelSingleWall*' >"$dir/props.out" 2>&1
status=$?
tail -n 40 "$dir/props.out"
[ "$status" -ne 0 ] || die "the no-tunnelling property passed under lecture-float (seed $seed, $cases cases)"

set -- "$dir"/*.scene
[ "$#" -eq 1 ] && [ -f "$1" ] || die "expected exactly one saved log in $dir, found $#"
log=$1
cat "$log"
grep -q "^from property NoTunnelSingleWall seed $seed\$" "$log" || die "the log lacks 'from property NoTunnelSingleWall seed $seed'"
grep -q '^check no-tunnel$' "$log" || die "the log lacks 'check no-tunnel'"
grep -q '^kernel lecture-float$' "$log" || die "the log does not name kernel lecture-float"
grep -q '^expect failure' "$log" && die "the log expects its failure, so replay would pass"

"$ricochet" replay "$log" >"$dir/replay.out" 2>&1
rstatus=$?
cat "$dir/replay.out"
[ "$rstatus" -ne 0 ] || die "ricochet replay passes the saved log"
grep -q 'no-tunnel' "$dir/replay.out" || die "ricochet replay does not name the no-tunnel check"

echo "lecture_float_tunnels: OK: seed $seed, log $(basename "$log"), replay exit $rstatus"
