#!/bin/sh
# One malformed-log kind per call: writes the log, runs `ricochet run` and `ricochet record` on it and
# checks the exact diagnostic on stderr, exit status 2, and that record left the file unchanged (for a
# stale expect line, expect-*, that record rewrites it into a log that replays).
#   malformed.sh RICOCHET KIND
#   malformed.sh --write KIND FILE   writes the kind's log to FILE and prints its diagnostic (LINE:COL: …)
#   malformed.sh --kinds             prints every kind (the case labels below)
set -u
case "$1" in
  --kinds) sed -n 's/^  \([a-z][a-z-]*\)) .*/\1/p' "$0"; exit 0 ;;
  --write) ricochet=""; kind=$2; f=$3 ;;
  *) ricochet=$1; kind=$2
     dir=$(mktemp -d)
     trap 'rm -rf "$dir"' EXIT
     f=$dir/bad.scene ;;
esac
h='ricochet 1'
# The kernel names a diagnostic lists: the built-in four, then the peers this build has (RICOCHET_PEER_KERNELS,
# set by CTest from the build: peers/).
kernels='lecture-float, lecture-double, robust, exact'
for k in ${RICOCHET_PEER_KERNELS:-}; do kernels="$kernels, $k"; done
case "$kind" in
  unknown-directive) printf '%s\nwal 0 0 1 1\n' "$h" >"$f"; want='2:1: error: unknown directive '\''wal'\''' ;;
  missing-token)     printf '%s\nwall 0 0 1\n' "$h" >"$f"; want='2:11: error: '\''wall'\'' needs X0 Y0 X1 Y1: missing Y1' ;;
  extra-token)       printf '%s\nball 0 0 1 1 7 8 9\n' "$h" >"$f"; want='2:18: error: unexpected '\''9'\'' after '\''ball'\'' (X Y VX VY [R [M]] expected)' ;;
  bad-number)        printf '%s\nball 0 0x 1 1\n' "$h" >"$f"; want='2:8: error: bad Y: '\''0x'\'' is not a number' ;;
  nan)               printf '%s\nball nan 0 1 1\n' "$h" >"$f"; want='2:6: error: X nan is outside the accepted range (finite, magnitude at most 2^256)' ;;
  inf)               printf '%s\ncircle 0 0 -inf\n' "$h" >"$f"; want='2:12: error: R -inf is outside the accepted range (finite, magnitude at most 2^256)' ;;
  out-of-range)      printf '%s\nwall 0 0 1e78 0\n' "$h" >"$f"; want='2:10: error: X1 1e78 is outside the accepted range (finite, magnitude at most 2^256)' ;;
  overflow)          printf '%s\nwall 0 0 1e400 0\n' "$h" >"$f"; want='2:10: error: bad X1: '\''1e400'\'' is out of the range of a double' ;;
  negative-radius)   printf '%s\ncircle 0 0 -1\n' "$h" >"$f"; want='2:12: error: negative radius -1' ;;
  ball-negative-radius) printf '%s\nball 0 0 1 1 -0.5\n' "$h" >"$f"; want='2:14: error: negative radius -0.5' ;;
  ball-radius-inf)   printf '%s\nball 0 0 1 1 inf\n' "$h" >"$f"; want='2:14: error: R inf is outside the accepted range (finite, magnitude at most 2^256)' ;;
  ball-radius-out-of-range) printf '%s\nball 0 0 1 1 1e78\n' "$h" >"$f"; want='2:14: error: R 1e78 is outside the accepted range (finite, magnitude at most 2^256)' ;;
  bumper-negative-radius) printf '%s\nbumper 0 0 -1\n' "$h" >"$f"; want='2:12: error: negative radius -1' ;;
  ball-mass-zero)    printf '%s\nball 0 0 1 1 0.5 0\n' "$h" >"$f"; want='2:18: error: mass 0 is outside [2^-256, 2^256]' ;;
  ball-mass-subnormal) printf '%s\nball 0 0 1 1 0 4e-324\n' "$h" >"$f"; want='2:16: error: mass 4e-324 is outside [2^-256, 2^256]' ;;
  ball-mass-inf)     printf '%s\nball 0 0 1 1 0.5 inf\n' "$h" >"$f"; want='2:18: error: M inf is outside the accepted range (finite, magnitude at most 2^256)' ;;
  balls-unknown)     printf '%s\nballs collides\n' "$h" >"$f"; want='2:7: error: unknown '\''collides'\'' after '\''balls'\'' (collide)' ;;
  balls-missing)     printf '%s\nballs\n' "$h" >"$f"; want='2:6: error: '\''balls'\'' needs collide: missing the word collide' ;;
  balls-extra-token) printf '%s\nballs collide x\n' "$h" >"$f"; want='2:15: error: unexpected '\''x'\'' after '\''balls'\'' (collide expected)' ;;
  balls-duplicate)   printf '%s\nballs collide\nball 0 0 1 0 1\nballs collide\n' "$h" >"$f"; want='4:1: error: duplicate '\''balls collide'\''' ;;
  bumper-missing-token) printf '%s\nbumper 0 0\n' "$h" >"$f"; want='2:11: error: '\''bumper'\'' needs X Y R: missing R' ;;
  left-gt-right)     printf '%s\nrect 2 0 1 1\n' "$h" >"$f"; want='2:6: error: left 2 is greater than right 1' ;;
  bottom-gt-top)     printf '%s\nrect 0 2 1 1\n' "$h" >"$f"; want='2:8: error: bottom 2 is greater than top 1' ;;
  negative-frames)   printf '%s\nframes -3\n' "$h" >"$f"; want='2:8: error: negative frame count -3' ;;
  absurd-frames)     printf '%s\nframes 99999999999\n' "$h" >"$f"; want='2:8: error: frame count 99999999999 is over the limit of 10000000' ;;
  unknown-kernel)    printf '%s\nkernel fast\n' "$h" >"$f"; want="2:8: error: unknown kernel 'fast' ($kernels)" ;;
  unknown-check)     printf '%s\ncheck speedy\n' "$h" >"$f"; want='2:7: error: unknown check '\''speedy'\'' (no-tunnel, symmetry, boundary, speed, deterministic, oracle, swap, translation, broad-phase, round-trip, no-escape, bounce-side, accuracy, event-order, penetration, ghost-bounce, plan, ball-overlap, pass-through, momentum, relabel, jump-through)' ;;
  future-version)    printf 'ricochet 2\n' >"$f"; want='1:10: error: format version 2 is newer than this reader (it reads version 1)' ;;
  missing-header)    printf 'wall 0 0 1 1\n' >"$f"; want='1:1: error: expected the header '\''ricochet 1'\'' before '\''wall'\''' ;;
  duplicate-header)  printf '%s\n%s\n' "$h" "$h" >"$f"; want='2:1: error: duplicate header '\''ricochet'\''' ;;
  empty)             : >"$f"; want='1:1: error: empty log: expected the header '\''ricochet 1'\''' ;;
  nul-byte)          printf '%s\nwall 0 0\0001 1\n' "$h" >"$f"; want='2:9: error: NUL byte in the log' ;;
  huge-line)         { echo "$h"; printf '# %05000d\n' 0; } >"$f"; want='2:4097: error: line is 5002 bytes long, over the limit of 4096' ;;
  huge-file)         { echo "$h"; i=0; while [ $i -lt 5000 ]; do printf '# %03990d\n' 0; i=$((i+1)); done; } >"$f"
                     want='1:1: error: the file is over the limit of 16777216 bytes' ;;
  bad-hash)          printf '%s\nexpect hash 12345g7890abcdef\n' "$h" >"$f"; want='2:13: error: bad hash '\''12345g7890abcdef'\'': expected exactly 16 lowercase hex digits' ;;
  expect-bad-ball)   printf '%s\nframes 1\nball 0 0 1 1\nexpect state 1 3 0 0 1 1\n' "$h" >"$f"; want='4:16: error: expect state for ball 3 but the log has 1 balls' ;;
  expect-past-frames) printf '%s\nframes 1\nball 0 0 1 1\nexpect state 2 0 0 0 1 1\n' "$h" >"$f"; want='4:14: error: expect state at frame 2 but the log runs 1 frames' ;;
  byte-order-mark)   printf '\357\273\277%s\n' "$h" >"$f"; want='1:1: error: a byte order mark (U+FEFF) is not allowed; save the file as UTF-8 without BOM' ;;
  escape-sequence)   printf '%s\nwal\033]0;pwned\007 0 0 1 1\n' "$h" >"$f"; want='2:1: error: unknown directive '\''wal\x1b]0;pwned\x07'\''' ;;
  crlf-missing-token) printf '%s\r\nwall 0 0 1\r\n' "$h" >"$f"; want='2:11: error: '\''wall'\'' needs X0 Y0 X1 Y1: missing Y1' ;;
  old-mac-comment)   printf 'ricochet 1\r# an old Mac file: CR-only line ends\rframes 10\rwall 0 -5 0 5\rball -1 0 0.5 0\rcheck no-tunnel\r' >"$f"
                     want='1:48: error: a carriage return (CR) inside a comment: lines end with LF or CRLF, and CR-only line ends (an old Mac file?) would let the comment hide the rest of the log' ;;
  cr-in-comment)     printf '%s\r\n# a comment\r with a CR inside\r\nwall 0 0 1 1\r\n' "$h" >"$f"
                     want='2:12: error: a carriage return (CR) inside a comment: lines end with LF or CRLF, and CR-only line ends (an old Mac file?) would let the comment hide the rest of the log' ;;
  duplicate-check)   printf '%s\ncheck speed\ncheck speed\n' "$h" >"$f"; want='3:7: error: duplicate check '\''speed'\''' ;;
  *) echo "unknown kind $kind" >&2; exit 1 ;;
esac
if [ -z "$ricochet" ]; then printf '%s\n' "$want"; exit 0; fi
before=$(cksum <"$f")
# A stale expect line is what record replaces (docs/scene-log.md, "Writing logs"): record rewrites it, and the
# log then replays; every other kind record refuses like run.
case "$kind" in
  expect-*) cmds=run; stale=yes ;;
  *)        cmds='run record'; stale=no ;;
esac
for cmd in $cmds; do
  err=$("$ricochet" "$cmd" "$f" 2>&1 >/dev/null)
  rc=$?
  if [ "$rc" != 2 ]; then echo "FAIL $kind ($cmd): exit $rc, expected 2; stderr: $err"; exit 1; fi
  if [ "$err" != "$f:$want" ]; then printf 'FAIL %s (%s): stderr\n  got:  %s\n  want: %s\n' "$kind" "$cmd" "$err" "$f:$want"; exit 1; fi
done
if [ "$stale" = yes ]; then
  err=$("$ricochet" record "$f" 2>&1 >/dev/null) || { echo "FAIL $kind (record): exit $?, expected 0; stderr: $err"; exit 1; }
  err=$("$ricochet" replay "$f" 2>&1 >/dev/null) || { echo "FAIL $kind: the recorded log does not replay: $err"; exit 1; }
  echo "ok $kind: $want; record rewrote it"
  exit 0
fi
if [ "$(cksum <"$f")" != "$before" ]; then echo "FAIL $kind: record changed the file"; exit 1; fi
echo "ok $kind: $want"
