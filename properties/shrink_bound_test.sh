#!/bin/sh
# RICOCHET_SHRINK_TRIES bounds a property's shrinking by a count of tries. DiscEveryCheck fails under
# lecture-double (seed 1); with the bound at 0 no shrink candidate is judged: the run says where shrinking
# stopped, its reproduce command carries the bound, and the case it saves (the first failure, reduced) still
# reproduces at its found check, frame and ball. A bound that is not a count is an error (exit 2).
# Usage: shrink_bound_test.sh PROPERTIES_BINARY RICOCHET_BINARY
set -u
props=$1
ricochet=$2
dir=$(mktemp -d "${TMPDIR:-/tmp}/ricochet-shrink-bound.XXXXXX") || exit 1
trap 'rm -rf "$dir"' EXIT
die() { echo "shrink_bound: FAIL: $*"; exit 1; }
. "$(dirname "$0")/log_reproduces.sh"

RICOCHET_SHRINK_TRIES=x "$props" --gtest_filter='*Discs.DiscEveryCheck/*' >"$dir/bad.out" 2>&1
rc=$?
[ $rc = 2 ] || die "RICOCHET_SHRINK_TRIES=x: exit $rc, expected 2"
grep -q "^RICOCHET_SHRINK_TRIES: error: 'x' is not a count" "$dir/bad.out" || { cat "$dir/bad.out"; die "no error for x"; }

RICOCHET_KERNEL=lecture-double RICOCHET_REPLAY_DIR=$dir RICOCHET_SHRINK_TRIES=0 RC_PARAMS="seed=1 max_success=200" \
  "$props" --gtest_filter='*Discs.DiscEveryCheck/*' >"$dir/props.out" 2>&1 && die "DiscEveryCheck passed under lecture-double"
grep -q 'shrinking stopped after 0 tries (RICOCHET_SHRINK_TRIES=0)' "$dir/props.out" ||
  { tail -n 30 "$dir/props.out"; die "the run does not say where shrinking stopped"; }
grep -q '^reproduce: .*RICOCHET_SHRINK_TRIES=0 ' "$dir/props.out" || die "the reproduce command lacks the bound"
set -- "$dir"/*.scene
[ $# = 1 ] && [ -f "$1" ] || die "not one saved log: $*"
log_reproduces "$ricochet" "$1" "$dir" || die "the saved log does not reproduce"
echo "shrink_bound: OK: stopped at 0 tries, the saved log reproduces $found"
