# Sourced by the property tests' scripts (sh): log_reproduces RICOCHET LOG TMPDIR checks that LOG, a failure log
# saved under a lecture kernel (`expect failure` and a `found C F B` line), passes `ricochet replay` (its expected
# failure reproduced) and, with `expect failure` removed, fails with check C at frame F for ball B. Leaves the
# found line's words in $found; prints what is wrong and returns 1 otherwise. Writes only into TMPDIR.
log_reproduces() {
  lr_ricochet=$1 lr_log=$2 lr_tmp=$3
  found=$(sed -n 's/^found \([a-z-]*\) \([0-9]*\) \([0-9]*\)$/\1 \2 \3/p' "$lr_log")
  [ -n "$found" ] || { echo "$lr_log has no found line"; return 1; }
  grep -q '^expect failure ' "$lr_log" || { echo "$lr_log does not expect its failure"; return 1; }
  "$lr_ricochet" replay "$lr_log" >"$lr_tmp/replay.out" 2>&1 ||
    { cat "$lr_log" "$lr_tmp/replay.out"; echo "replay fails $lr_log"; return 1; }
  grep -v '^expect failure' "$lr_log" >"$lr_tmp/bare.scene"
  "$lr_ricochet" replay "$lr_tmp/bare.scene" >"$lr_tmp/replay.out" 2>&1 &&
    { cat "$lr_log"; echo "replay passes $lr_log without expect failure"; return 1; }
  set -- $found
  grep -q "$1 broke at frame $2 ball $3:" "$lr_tmp/replay.out" ||
    { cat "$lr_log" "$lr_tmp/replay.out"; echo "replay does not fail $lr_log at $1, frame $2, ball $3"; return 1; }
}
