#!/bin/bash
# Proof that the campaign bites, reproducibly: `ricochet fuzz --target scene --kernel lecture-double
# --runs N --seed S` (one worker, libFuzzer's -seed and -runs, no time limit) must exit 1 (a new failure),
# leave scene logs in a temporary replay folder, each naming its input by the SHA-1 libFuzzer would name it
# by, and `ricochet replay` must pass them (their `expect failure` reproduces) and fail them once
# `expect failure` is removed. Every target's oracle is replay's own checks (run_checked), so whatever it
# finds replay sees.
# Usage: lecture_proof_test.sh RICOCHET_EXE BIN_DIR
set -u
exe="$1"; bins="$2/"
# With seeds 1 to 12 the first failure came after 413 to 2 351 inputs (measured after the wall grid's cell
# budget, 2026-12-01; before it, flat boxes built grids of millions of cells and some seeds ran at 8
# inputs/s, past the CTest timeout). N leaves forty times that. The input sequence also depends on the
# binary (its code layout), so on another build the failure may differ, but one is found well within N.
seed=1
runs=100000
TMP="$(mktemp -d)"; trap 'rm -rf "$TMP"' EXIT
"$exe" fuzz --target scene --kernel lecture-double --runs "$runs" --seed "$seed" --bin-dir "$bins" \
  --cache-dir "$TMP/cache" --replay-dir "$TMP/replays" 2>&1 | tee "$TMP/out"
# The campaign's progress is printed as it runs, so a test killed by its timeout still shows how far it got.
rc=${PIPESTATUS[0]}
[ "$rc" = 1 ] || { echo "FAIL: expected exit 1 (new failure), got $rc"; exit 1; }
logs=$(find "$TMP/replays" -name '*.scene' | wc -l)
[ "$logs" -ge 1 ] || { echo "FAIL: no scene log written"; exit 1; }
if grep -q "replay's checks do not see" "$TMP/out"; then echo "FAIL: a failure replay cannot see"; exit 1; fi
# libFuzzer names each artifact by the SHA-1 of its bytes.
for a in "$TMP"/cache/scene/lecture-double/artifacts/crash-*; do
  [ "crash-$(sha1sum < "$a" | cut -c1-40)" = "$(basename "$a")" ] || { echo "FAIL: $a is not named by its SHA-1"; exit 1; }
done
"$exe" replay "$TMP/replays" || { echo "FAIL: the saved logs do not reproduce their expected failure"; exit 1; }
for f in "$TMP"/replays/*.scene; do
  sha=$(sed -n 's/^from fuzz scene \([0-9a-f]\{40\}\)$/\1/p' "$f")
  [ -n "$sha" ] || { echo "FAIL: $f has no 'from fuzz scene SHA1'"; exit 1; }
  # The SHA-1 names the minimized input the campaign printed, as sha1sum computes it.
  input=$(sed -n "s/^ *minimized: *\(.*\) (sha1 $sha)\$/\1/p" "$TMP/out")
  [ -n "$input" ] && [ "$(sha1sum < "$input" | cut -c1-40)" = "$sha" ] ||
    { echo "FAIL: $f names $sha, which is not the SHA-1 of the minimized input"; exit 1; }
  grep -v '^expect failure' "$f" > "$TMP/bare.scene"
  if "$exe" replay "$TMP/bare.scene" > /dev/null; then echo "FAIL: $f passes without expect failure"; exit 1; fi
done
echo "ok: $logs log(s) found by fuzzing lecture-double (seed $seed, $runs runs), each reproducing its failure"
