#!/bin/bash
# The contract for the disc target: a failure it saves is one `ricochet replay` reproduces at the same check,
# frame and ball. Run reproducibly (`ricochet fuzz --target disc --kernel K --runs N --seed S`, one worker, no
# time limit) against each lecture kernel, into temporary folders; every saved log must carry `found C F B` and
# `expect failure C F`, replay must pass it, and without `expect failure` fail it with check C at frame F for
# ball B. Fails unless each campaign saved at least one log and every one reproduces.
# Usage: disc_failures_reproduce_test.sh RICOCHET_EXE FUZZ_BIN_DIR
set -u
exe=$(realpath -s "$1"); bins=$(realpath -s "$2")
seed=1
runs=20000
TMP="$(mktemp -d "${TMPDIR:-/tmp}/ricochet-disc-reproduce.XXXXXX")" || exit 1
trap 'rm -rf "$TMP"' EXIT
cd "$TMP" || exit 1
for k in lecture-float lecture-double; do
  "$exe" fuzz --target disc --kernel "$k" --runs "$runs" --seed "$seed" --jobs 1 --bin-dir "$bins" \
    --cache-dir "$TMP/cache" --replay-dir "$TMP/replays-$k" > "$TMP/$k.out" 2>&1
  rc=$?
  tail -n 5 "$TMP/$k.out"
  [ "$rc" = 1 ] || { echo "FAIL: the campaign against $k exited $rc, expected 1 (a failure found)"; exit 1; }
  n=$(find "$TMP/replays-$k" -name '*.scene' | wc -l)
  [ "$n" -ge 1 ] || { echo "FAIL: the campaign against $k saved no log"; exit 1; }
done
total=0; ok=0
for f in $(find "$TMP" -path "$TMP/cache" -prune -o -name '*.scene' -print | sort); do
  total=$((total + 1))
  why=""
  read -r c fr b < <(sed -n 's/^found \([^ ]*\) \([0-9]*\) \([0-9]*\)$/\1 \2 \3/p' "$f")
  if [ -z "${c:-}" ]; then why="no 'found' line"
  elif ! grep -q "^from fuzz disc [0-9a-f]\{40\}\$" "$f"; then why="no 'from fuzz disc SHA1'"
  elif ! grep -q "^expect failure $c $fr\$" "$f"; then why="no 'expect failure $c $fr'"
  elif ! "$exe" replay "$f" > "$TMP/r1" 2>&1; then why="replay fails it: $(cat "$TMP/r1")"
  else
    grep -v '^expect failure' "$f" > "$TMP/bare.scene"
    if "$exe" replay "$TMP/bare.scene" > "$TMP/r2" 2>&1; then why="without expect failure it passes"
    elif ! grep -q "invariant $c broke at frame $fr ball $b:" "$TMP/r2"; then why="fails otherwise than found $c $fr $b: $(cat "$TMP/r2")"
    fi
  fi
  if [ -z "$why" ]; then ok=$((ok + 1)); else echo "NOT REPRODUCED: $f: $why" | cut -c1-400; fi
  c=""
done
echo "reproduced $ok/$total (kernels: lecture-float, lecture-double)"
[ "$ok" -eq "$total" ] || { echo "FAIL: $((total - ok)) log(s) did not reproduce"; exit 1; }
echo "ok"
