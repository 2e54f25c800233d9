#!/bin/bash
# `ricochet fuzz --target sweep --kernel lecture-double --time 30` must exit 1 (a new failure), leave
# exactly the scene logs it announces in a temporary replay folder, and `ricochet replay` must pass them
# (their `expect failure` reproduces) and fail them once `expect failure` is removed.
# Usage: lecture_proof_test.sh RICOCHET_EXE BIN_DIR
set -u
exe="$1"; bins="$2/"
TMP="$(mktemp -d)"; trap 'rm -rf "$TMP"' EXIT
"$exe" fuzz --target sweep --kernel lecture-double --time 30 --bin-dir "$bins" --cache-dir "$TMP/cache" \
  --replay-dir "$TMP/replays" > "$TMP/out" 2>&1
rc=$?
cat "$TMP/out"
[ "$rc" = 1 ] || { echo "FAIL: expected exit 1 (new failure), got $rc"; exit 1; }
logs=$(find "$TMP/replays" -name '*.scene' | wc -l)
[ "$logs" -ge 1 ] || { echo "FAIL: no scene log written"; exit 1; }
"$exe" replay "$TMP/replays" || { echo "FAIL: the saved logs do not reproduce their expected failure"; exit 1; }
for f in "$TMP"/replays/*.scene; do
  grep -q '^from fuzz sweep [0-9a-f]\{40\}$' "$f" || { echo "FAIL: $f has no 'from fuzz sweep SHA1'"; exit 1; }
  grep -v '^expect failure' "$f" > "$TMP/bare.scene"
  if "$exe" replay "$TMP/bare.scene" > /dev/null; then echo "FAIL: $f passes without expect failure"; exit 1; fi
done
echo "ok: $logs log(s) found by fuzzing lecture-double, each reproducing its failure"
