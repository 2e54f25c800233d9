#!/bin/bash
# Two `ricochet fuzz` campaigns at once on one cache folder and one replay folder (scene target against
# lecture-double, fixed seeds and run counts, no time limit), after a first campaign that fills the cache's
# corpus. Checks:
#   - each exits 0 or 1 (1: it saved a new failure), at least one exits 1, and neither prints an error
#     (no "not a libFuzzer binary", no "cannot", no failed merge);
#   - the cache's corpus is still there (the bug deleted it). Its size is not compared: a merge may
#     rightly replace several inputs by fewer that cover the same, and which merge runs first is timing;
#   - every log a campaign reports (new or known) exists, passes `ricochet replay` (its expect failure) and
#     fails it once `expect failure` is removed;
#   - no two logs in the replay folder are the same case, no temporary file is left, and both campaigns'
#     own folders (CACHE/runs/) are gone.
# Writes only into a mktemp folder. Usage: concurrent_campaigns_test.sh RICOCHET_EXE BIN_DIR
set -u
exe=$(realpath -s "$1"); bins=$(realpath -s "$2")
TMP="$(mktemp -d "${TMPDIR:-/tmp}/ricochet-concurrent.XXXXXX")" || exit 1
trap 'rm -rf "$TMP"' EXIT
trap 'exit 143' INT TERM
cd "$TMP" || exit 1
cache="$TMP/cache"; replays="$TMP/replays"; corpus="$cache/scene/lecture-double/corpus"
# Seeds 1-12 fail first after 413-2 351 inputs (lecture_proof_test.sh): N leaves forty times that.
runs=100000
campaign() {  # campaign SEED OUT
  "$exe" fuzz --target scene --kernel lecture-double --runs "$runs" --seed "$1" --bin-dir "$bins" \
    --cache-dir "$cache" --replay-dir "$replays" > "$2" 2>&1
}
campaign 1 "$TMP/first.out"
rc=$?
[ "$rc" = 1 ] || { echo "FAIL: the first campaign exited $rc, expected 1"; cat "$TMP/first.out"; exit 1; }
before=$(find "$corpus" -type f | wc -l)
[ "$before" -ge 1 ] || { echo "FAIL: the first campaign left an empty corpus"; exit 1; }

campaign 2 "$TMP/a.out" & pa=$!
campaign 3 "$TMP/b.out" & pb=$!
wait "$pa"; ra=$?
wait "$pb"; rb=$?
for x in a b; do echo "--- campaign $x"; cat "$TMP/$x.out"; done
for r in "$ra" "$rb"; do
  [ "$r" = 0 ] || [ "$r" = 1 ] || { echo "FAIL: a campaign exited $r, expected 0 or 1"; exit 1; }
done
[ "$ra" = 1 ] || [ "$rb" = 1 ] || { echo "FAIL: neither campaign found a new failure"; exit 1; }
if grep -Ei "not a libFuzzer binary|ricochet fuzz: error|cannot |merge failed|unlocked" "$TMP/a.out" "$TMP/b.out"; then
  echo "FAIL: a campaign printed an error"; exit 1
fi
after=$(find "$corpus" -type f | wc -l)
[ "$after" -ge 1 ] || { echo "FAIL: the corpus is gone: $before inputs before, none after"; exit 1; }

# Every log reported, new ("scene log: P") or known ("already there: P").
reported=$(sed -n 's/^ *scene log: \([^ ]*\) .*$/\1/p; s/^ *known: the same case is already there: \(.*\)$/\1/p' \
  "$TMP/a.out" "$TMP/b.out" | sort -u)
[ -n "$reported" ] || { echo "FAIL: no log reported"; exit 1; }
for f in $reported; do
  [ -f "$f" ] || { echo "FAIL: $f was reported but is not there"; exit 1; }
  "$exe" replay "$f" > /dev/null || { echo "FAIL: $f does not reproduce its expected failure"; exit 1; }
  grep -v '^expect failure' "$f" > "$TMP/bare.scene"
  "$exe" replay "$TMP/bare.scene" > /dev/null
  [ $? = 1 ] || { echo "FAIL: $f without expect failure does not fail replay (exit 1)"; exit 1; }
done
# Logs are named PREFIX-ID.scene by content id, so a duplicate case would be a second name of one ID.
dups=$(find "$replays" -name '*.scene' | sed 's/.*-\([^-]*\)\.scene$/\1/' | sort | uniq -d)
[ -z "$dups" ] || { echo "FAIL: the same case saved twice: $dups"; exit 1; }
left=$(find "$replays" "$cache" -name '.*.tmp.*' | wc -l)
[ "$left" = 0 ] || { echo "FAIL: $left temporary file(s) left"; exit 1; }
runs_left=$(find "$cache/runs" -mindepth 1 -maxdepth 1 | wc -l)
[ "$runs_left" = 0 ] || { echo "FAIL: $runs_left campaign folder(s) left in $cache/runs"; exit 1; }
echo "ok: two campaigns on one cache (exits $ra, $rb), corpus $before -> $after, $(echo "$reported" | wc -l) log(s) reported, each reproducing"
