#!/bin/bash
# The harnesses bite the peers, reproducibly: pointed at a peer kernel with a fixed seed and count (never a
# clock), a harness must find a failure and save logs into a temporary folder that carry `expect failure` (a
# peer's failures are documented), pass `ricochet replay`, and, with `expect failure` removed, fail replay at
# the check, frame and ball of their `found` line.
#   peer_harness_test.sh property RICOCHET PROPERTIES KERNEL PROPERTY SEED CASES
#   peer_harness_test.sh fuzz RICOCHET FUZZ_BIN_DIR KERNEL TARGET RUNS SEED
set -u
mode=$1 ricochet=$2 tool=$3 kernel=$4
TMP=$(mktemp -d "${TMPDIR:-/tmp}/ricochet-peers.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT
die() { echo "peer_harness_test: FAIL: $*"; exit 1; }
mkdir -p "$TMP/replays"

case "$mode" in
  property)
    property=$5 seed=$6 cases=$7
    RICOCHET_KERNEL=$kernel RICOCHET_REPLAY_DIR=$TMP/replays RC_PARAMS="seed=$seed max_success=$cases" \
      "$tool" --gtest_filter="*.$property/*" >"$TMP/out" 2>&1
    status=$?
    tail -n 20 "$TMP/out"
    [ "$status" -ne 0 ] || die "$property passed under $kernel (seed $seed, $cases cases)"
    set -- "$TMP"/replays/*.scene
    [ "$#" -eq 1 ] && [ -f "$1" ] || die "expected exactly one saved log, found $#"
    grep -qx "from property $property seed $seed" "$1" || die "the log lacks 'from property $property seed $seed'" ;;
  fuzz)
    target=$5 runs=$6 seed=$7
    "$ricochet" fuzz --target "$target" --kernel "$kernel" --runs "$runs" --seed "$seed" --jobs 1 --bin-dir "$tool" \
      --cache-dir "$TMP/cache" --replay-dir "$TMP/replays" >"$TMP/out" 2>&1
    status=$?
    cat "$TMP/out"
    [ "$status" = 1 ] || die "expected exit 1 (new failure) from fuzz $target under $kernel, got $status"
    set -- "$TMP"/replays/*.scene
    [ -f "$1" ] || die "no log saved"
    ! grep -q "replay's checks do not see" "$TMP/out" || die "a failure replay cannot see" ;;
  *) die "unknown mode $mode" ;;
esac

for log in "$@"; do
  cat "$log"
  grep -qx "kernel $kernel" "$log" || die "$log does not name kernel $kernel"
  check=$(sed -n 's/^found \([a-z-]*\) [0-9]* [0-9]*$/\1/p' "$log")
  frame=$(sed -n 's/^found [a-z-]* \([0-9]*\) [0-9]*$/\1/p' "$log")
  ball=$(sed -n 's/^found [a-z-]* [0-9]* \([0-9]*\)$/\1/p' "$log")
  [ -n "$check" ] || die "$log lacks 'found CHECK F BALL'"
  # A peer's failure is documented: the log expects it, so replay passes while it reproduces.
  grep -qx "expect failure $check $frame" "$log" || die "$log does not expect its $check failure at frame $frame"
  "$ricochet" replay "$log" >"$TMP/replay.out" 2>&1 || { cat "$TMP/replay.out"; die "ricochet replay fails $log"; }
  grep -v '^expect failure' "$log" >"$TMP/bare.scene"
  "$ricochet" replay "$TMP/bare.scene" >"$TMP/replay.out" 2>&1 && die "$log passes replay without expect failure"
  grep -q "$check broke at frame $frame ball $ball:" "$TMP/replay.out" ||
    { cat "$TMP/replay.out"; die "replay does not fail $log's bare run at $check, frame $frame, ball $ball"; }
done
echo "peer_harness_test: OK: $mode under $kernel: $# log(s), each replaying its failure"
