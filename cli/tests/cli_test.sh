#!/bin/sh
# The command line's edges, one behaviour per call: the exit status and the message on stderr (and stdout
# where it matters). Everything it writes goes into a mktemp folder, removed at the end.
#   cli_test.sh RICOCHET VERSION CASE
#   cli_test.sh --cases     prints every case (the case labels below)
set -u
if [ "$1" = --cases ]; then sed -n 's/^  \([a-z][a-z0-9-]*\)) .*/\1/p' "$0"; exit 0; fi
ricochet=$1 version=$2 case=$3
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

fail() { echo "FAIL $case: $*"; for f in out err; do echo "--- std$f:"; cat "$dir/$f"; done; exit 1; }
# run RC ARGS...: runs ricochet with stdout in $dir/out and stderr in $dir/err; its exit status must be RC.
run() {
  want_rc=$1; shift
  "$ricochet" "$@" >"$dir/out" 2>"$dir/err"
  rc=$?
  [ "$rc" = "$want_rc" ] || fail "ricochet $*: exit $rc, expected $want_rc"
}
# A run to /dev/full: stdout cannot be written.
run_full() {
  want_rc=$1; shift
  [ -w /dev/full ] || { echo "skip $case: no /dev/full"; exit 77; }
  "$ricochet" "$@" >/dev/full 2>"$dir/err"
  rc=$?
  : >"$dir/out"
  [ "$rc" = "$want_rc" ] || fail "ricochet $* >/dev/full: exit $rc, expected $want_rc"
}
# has FILE TEXT: FILE (out or err) holds the line TEXT exactly.
has() { grep -qxF -- "$2" "$dir/$1" || fail "std$1 lacks the line: $2"; }
# first_line FILE TEXT: FILE's first line is TEXT.
first_line() { [ "$(head -n 1 "$dir/$1")" = "$2" ] || fail "std$1's first line is not: $2"; }

# A small valid log: 10 frames × 2 balls × (1 wall + 0 shapes + 1) = 40 units of work.
log=$dir/tiny.scene
printf 'ricochet 1\nframes 10\nwall 0 -5 0 5\nball -1 0 0.5 0\nball -3 1 0.25 0\ncheck no-tunnel\n' >"$log"
# A small valid log that would run for hours: 10^7 frames × 200 balls × (4 walls + 1) = 10^10.
big=$dir/big.scene
{ printf 'ricochet 1\nkernel exact\nframes 10000000\nwall 0 0 0 100\nwall 0 100 100 100\nwall 100 100 100 0\nwall 100 0 0 0\n'
  i=0; while [ $i -lt 200 ]; do printf 'ball %d.5 50 0.25 0.125\n' $((i % 90 + 5)); i=$((i + 1)); done; } >"$big"
enospc="ricochet: error: writing standard output: No space left on device"

case "$case" in
  full-run)          run_full 1 run "$log"; first_line err "$enospc" ;;
  full-replay)       run_full 1 replay "$log"; first_line err "$enospc" ;;
  full-replay-hashes) run_full 1 replay --hashes "$log"; first_line err "$enospc" ;;
  full-record)       cp "$log" "$dir/r.scene"; run_full 1 record "$dir/r.scene"; first_line err "$enospc" ;;
  full-help)         run_full 1 help; first_line err "$enospc" ;;
  replay-empty-folder) mkdir "$dir/empty"; run 2 replay "$dir/empty"
                     has err "ricochet: error: no scene logs (*.scene) under $dir/empty"; has out "0 passed, 0 failed" ;;
  replay-empty-hashes) mkdir "$dir/empty"; run 2 replay --hashes "$dir/empty"
                     has err "ricochet: error: no scene logs (*.scene) under $dir/empty" ;;
  replay-missing-path) run 2 replay "$dir/replys"; has err "$dir/replys:1:1: error: no such file or folder"
                     has out "0 passed, 1 failed" ;;
  replay-missing-among) run 2 replay "$log" "$dir/nope.scene"; has err "$dir/nope.scene:1:1: error: no such file or folder"
                     has out "1 passed, 1 failed" ;;
  unknown-command)   run 2 replya replays; first_line err "ricochet: error: unknown command 'replya'; did you mean 'replay'?" ;;
  unknown-far)       run 2 xyzzy
                     first_line err "ricochet: error: unknown command 'xyzzy' (commands: run, record, replay, render, check, bench, fuzz, help)" ;;
  version)           run 0 --version; [ "$(cat "$dir/out")" = "ricochet $version" ] || fail "stdout is not 'ricochet $version'" ;;
  help)              run 0 help; first_line out "ricochet: the 2D collision core's scene logs, replay and checks"
                     has out "Subcommands:"; grep -q '^  replay ' "$dir/out" || fail "help lists no replay" ;;
  help-command)      run 0 help replay; has out "Usage: ricochet replay [OPTIONS] [PATH...]"
                     grep -q -- '--max-work N' "$dir/out" || fail "replay's help has no --max-work" ;;
  help-unknown)      run 2 help rnu; first_line err "ricochet: error: unknown command 'rnu'; did you mean 'run'?" ;;
  no-arguments)      run 2; has err "Usage: ricochet [OPTIONS] SUBCOMMAND"; [ ! -s "$dir/out" ] || fail "stdout not empty" ;;
  run-frames-abc)    run 2 run "$log" --frames abc
                     first_line err "ricochet: error: --frames: 'abc' is not a frame count (expected 0 to 10000000)" ;;
  run-frames-over)   run 2 run "$log" --frames 10000001
                     first_line err "ricochet: error: --frames: '10000001' is out of range (expected a frame count from 0 to 10000000)" ;;
  render-frames-abc) run 2 render "$log" -o "$dir/x.svg" --frames abc
                     first_line err "ricochet: error: --frames: 'abc' is not a frame range (expected A:B, integers with 0 <= A <= B)"
                     [ ! -e "$dir/x.svg" ] || fail "render wrote the picture" ;;
  check-fuzz-runs)   run 2 check --fuzz-runs many
                     first_line err "ricochet: error: --fuzz-runs: 'many' is not a count of inputs (expected 0 to 9223372036854775807)" ;;
  fuzz-time-0)       run 2 fuzz --time 0
                     first_line err "ricochet: error: --time: '0' is out of range (expected a number of seconds from 1 to 604800)" ;;
  fuzz-time-absurd)  run 2 fuzz --time 1e300
                     first_line err "ricochet: error: --time: '1e300' is out of range (expected a number of seconds from 1 to 604800)" ;;
  work-run)          run 2 run "$log" --max-work 39
                     first_line err "ricochet: error: $log: too much work: 10 frames × 2 balls × (1 walls + 0 circles + 0 rects + 1) = 40 is over the bound of 39; raise it with --max-work N (0: no bound)"
                     [ ! -s "$dir/out" ] || fail "run printed events before refusing"
                     run 0 run "$log" --max-work 40; has out "state 10 1 -0.5 1 0.25 0" ;;
  work-replay)       run 2 replay "$log" --max-work 39; has out "FAIL $log: not run (over --max-work)"
                     first_line err "ricochet: error: $log: too much work: 10 frames × 2 balls × (1 walls + 0 circles + 0 rects + 1) = 40 is over the bound of 39; raise it with --max-work N (0: no bound)"
                     run 0 replay "$log" --max-work 40 ;;
  work-record)       cp "$log" "$dir/r.scene"; run 2 record "$dir/r.scene" --max-work 39
                     cmp -s "$log" "$dir/r.scene" || fail "record changed the log"
                     grep -q "too much work" "$dir/err" || fail "no work error" ;;
  record-lowered-frames) cp "$log" "$dir/r.scene"; run 0 record "$dir/r.scene"
                     grep -q '^expect state 10 ' "$dir/r.scene" || fail "no expect state at frame 10"
                     sed 's/^frames 10$/frames 3/' "$dir/r.scene" >"$dir/low.scene"
                     run 0 record "$dir/low.scene"
                     ! grep -q '^expect state \([4-9]\|10\) ' "$dir/low.scene" || fail "stale expect lines kept"
                     grep -q '^expect state 3 ' "$dir/low.scene" || fail "no expect state at frame 3"
                     [ "$(grep -c '^expect hash ' "$dir/low.scene")" = 1 ] || fail "not one expect hash"
                     run 0 replay "$dir/low.scene" ;;
  record-symlink)    mkdir "$dir/real"; cp "$log" "$dir/real/r.scene"; ln -s real/r.scene "$dir/link.scene"
                     run 0 record "$dir/link.scene"
                     [ -L "$dir/link.scene" ] || fail "record replaced the link with a file"
                     grep -q '^expect hash ' "$dir/real/r.scene" || fail "the link's target was not recorded"
                     [ -z "$(ls -A "$dir/real" | grep -v '^r.scene$')" ] || fail "a temporary file is left next to the target"
                     [ -z "$(ls -A "$dir" | grep '\.tmp\.')" ] || fail "a temporary file is left next to the link" ;;
  record-stale-temp) cp "$log" "$dir/r.scene"
                     # A killed record's temporary (PID 2147483647 is past every pid_max), a live one's ($$),
                     # another log's.
                     for t in .r.scene.tmp.2147483647.AbC123 .r.scene.tmp.$$.AbC123 .q.scene.tmp.2147483647.AbC123; do
                       echo partial >"$dir/$t"; touch -d '2000-01-01' "$dir/$t"; done
                     run 0 record "$dir/r.scene"
                     [ ! -e "$dir/.r.scene.tmp.2147483647.AbC123" ] || fail "the stale temporary file is left"
                     [ -e "$dir/.r.scene.tmp.$$.AbC123" ] || fail "a live writer's temporary file was removed"
                     [ -e "$dir/.q.scene.tmp.2147483647.AbC123" ] || fail "another log's temporary file was removed" ;;
  work-render)       run 2 render "$log" -o "$dir/x.svg" --max-work 39; grep -q "too much work" "$dir/err" || fail "no work error"
                     [ ! -e "$dir/x.svg" ] || fail "render wrote the picture" ;;
  work-default)      run 2 replay "$big"
                     first_line err "ricochet: error: $big: too much work: 10000000 frames × 200 balls × (4 walls + 0 circles + 0 rects + 1) = 10000000000 is over the bound of 100000000; raise it with --max-work N (0: no bound)" ;;
  work-frames-flag)  run 2 run "$log" --frames 5 --max-work 19; grep -q "= 20 is over the bound of 19" "$dir/err" || fail "work not from --frames" ;;
  # render: its view, its bounds on what is drawn, and the pinball table's tunnel marked where it crossed.
  render-view-bad)   run 2 render "$log" -o "$dir/x.svg" --view some
                     first_line err "ricochet: error: --view: 'some' is not a view (expected failure or all)"
                     [ ! -e "$dir/x.svg" ] || fail "render wrote the picture" ;;
  render-max-balls-0) run 2 render "$log" -o "$dir/x.svg" --max-balls 0
                     first_line err "ricochet: error: --max-balls: '0' is out of range (expected a ball count from 1 to 100000)"
                     [ ! -e "$dir/x.svg" ] || fail "render wrote the picture" ;;
  render-max-points-abc) run 2 render "$log" -o "$dir/x.svg" --max-points abc
                     first_line err "ricochet: error: --max-points: 'abc' is not a point count (expected 1 to 10000000)" ;;
  render-width-tiny) run 2 render "$log" -o "$dir/x.svg" --width 5
                     first_line err "ricochet: error: --width: '5' is out of range (expected a width in pixels from 100 to 20000)" ;;
  render-max-balls)  run 0 render "$log" -o "$dir/x.svg" --max-balls 1
                     grep -q 'paths of 1 of 2 balls drawn (balls 0..0), 1 left out' "$dir/x.svg" || fail "no left-out caption"
                     ! grep -q '>b1</text>' "$dir/x.svg" || fail "ball 1 drawn" ;;
  render-tunnel-view) printf 'ricochet 1\nkernel lecture-double\nframes 10\nwall 0 10 0 0\nwall 0 0 10 0\nwall 10 0 10 10\nwall 10 10 0 10\nwall 0 2 3 0.5\nwall 7 0.5 10 2\nball 8 5 4 1\ncheck no-tunnel\n' >"$dir/t.scene"
                     run 0 render "$dir/t.scene" -o "$dir/x.svg"
                     grep -q '^wrote .* (marked: no-tunnel broke at frame 4 ball 0: ' "$dir/out" || fail "no mark reported"
                     grep -q 'data-x="0" data-y="8"' "$dir/x.svg" || fail "the mark is not the crossing (0, 8)"
                     grep -q 'view: the failing frame 4 of ball 0' "$dir/x.svg" || fail "not framed on the failure"
                     run 0 render "$dir/t.scene" -o "$dir/all.svg" --view all
                     ! grep -q 'view: the failing frame' "$dir/all.svg" || fail "--view all framed the failure"
                     grep -q 'data-x="0" data-y="8"' "$dir/all.svg" || fail "--view all lost the mark" ;;
  *) echo "unknown case $case" >&2; exit 1 ;;
esac
echo "ok $case"
