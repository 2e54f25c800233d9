#!/bin/sh
# The contract for discs, on the properties: every disc property that fails under a lecture kernel saves a log,
# and every log it saves reproduces. The Discs suite runs under lecture-float, then lecture-double (a fresh
# folder each, a fixed RapidCheck seed and case count: the same verdict on every run); each failed property must
# have saved a log naming it, and each saved log must pass `ricochet replay` (its expected failure reproduced)
# and, with `expect failure` removed, fail at the check, frame and ball of its `found` line. DiscEveryCheck, which
# asks the checks read for discs (oracle, boundary, bounce-side, symmetry, swap, translation), must be among the
# failures: the lecture kernels fail them.
# Usage: disc_failures_reproduce.sh PROPERTIES_BINARY RICOCHET_BINARY
set -u
props=$1
ricochet=$2
root=$(mktemp -d "${TMPDIR:-/tmp}/ricochet-disc-reproduce.XXXXXX") || exit 1
trap 'rm -rf "$root"' EXIT
die() { echo "disc_failures_reproduce: FAIL: $*"; exit 1; }
. "$(dirname "$0")/log_reproduces.sh"
total_logs=0
for kernel in lecture-float lecture-double; do
  dir=$root/$kernel
  mkdir -p "$dir"
  RICOCHET_KERNEL=$kernel RICOCHET_REPLAY_DIR=$dir RICOCHET_PROPERTIES_REPORT=$dir/report \
    RC_PARAMS="seed=1 max_success=200" "$props" --gtest_filter='*Discs.*' >"$dir/props.out" 2>&1
  [ -f "$dir/report" ] || { tail -n 30 "$dir/props.out"; die "$kernel: the run wrote no report"; }
  ! grep -q 'NOT saved' "$dir/props.out" || { grep 'NOT saved' "$dir/props.out"; die "$kernel: a failure was not saved"; }
  failed=$(sed -n 's/^failed Kernels\/Discs\.\([A-Za-z]*\)\/.*/\1/p' "$dir/report")
  echo "$failed" | grep -qx DiscEveryCheck || die "$kernel: DiscEveryCheck did not fail"
  for p in $failed; do
    grep -lq "^from property $p seed 1\$" "$dir"/*.scene 2>/dev/null || die "$kernel: $p failed and saved no log"
  done
  for log in "$dir"/*.scene; do
    log_reproduces "$ricochet" "$log" "$dir" || die "$kernel: a saved log does not reproduce"
    total_logs=$((total_logs + 1))
  done
  echo "ok   $kernel: $(echo $failed | wc -w) properties failed, each saved a log; every log reproduces:" $failed
done
echo "disc_failures_reproduce: OK: $total_logs logs, all reproduce"
