#!/bin/sh
# Plug-in kernels (ricochet/plugin.h) from the command line, one behaviour per call, with the test plug-ins of
# core/tests/plugins: a bad plug-in is refused with exit 2 naming it; a crash, a hang or a broken answer inside
# one ends with exit 3, a report naming the plug-in and the call, and the input kept; everything ends (each run
# is bounded by `timeout`, and a test killed by it fails: no verdict depends on timing beyond "it ends").
# Everything it writes goes into a mktemp folder, removed at the end.
#   plugin_test.sh RICOCHET PLUGIN_DIR PROPERTIES CASE    (PROPERTIES: the property binary, or "none")
#   plugin_test.sh --cases                                prints every case
set -u
if [ "$1" = --cases ]; then sed -n 's/^  \([a-z][a-z0-9-]*\)) .*/\1/p' "$0"; exit 0; fi
ricochet=$1 plugins=$(cd "$2" && pwd) props=$3 case=$4
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

fail() { echo "FAIL $case: $*"; for f in out err; do echo "--- std$f:"; cat "$dir/$f" 2>/dev/null; done; exit 1; }
# bounded RC CMD...: runs CMD (stdout in $dir/out, stderr in $dir/err) for at most 120 s; its status must be RC.
bounded() {
  want_rc=$1; shift
  timeout 120 "$@" >"$dir/out" 2>"$dir/err"
  rc=$?
  [ "$rc" != 124 ] || fail "$*: still running after 120 s"
  [ "$rc" = "$want_rc" ] || fail "$*: exit $rc, expected $want_rc"
}
# run RC ARGS...: ricochet ARGS, bounded.
run() { want=$1; shift; bounded "$want" "$ricochet" "$@"; }
# has FILE TEXT: FILE (out or err) holds the line TEXT exactly.
has() { grep -qxF -- "$2" "$dir/$1" || fail "std$1 lacks the line: $2"; }
# has_part FILE TEXT: some line of FILE holds TEXT.
has_part() { grep -qF -- "$2" "$dir/$1" || fail "std$1 lacks: $2"; }
first_line() { [ "$(head -n 1 "$dir/$1")" = "$2" ] || fail "std$1's first line is not: $2"; }
need_props() { [ -x "$props" ] || { echo "skip $case: no property binary"; exit 77; }; }
# need_fuzzer TARGET: skip unless the build has the libFuzzer binary fuzz_TARGET (clang, RICOCHET_FUZZ on).
need_fuzzer() {
  "$(dirname "$ricochet")/../fuzz/fuzz_$1" -help=1 2>&1 | grep -q '^Usage:' || { echo "skip $case: no libFuzzer fuzz_$1"; exit 77; }
}

# Every kernel's name as errors list them: the built-in four, then the peers this build has.
kernels='lecture-float, lecture-double, robust, exact'
for k in ${RICOCHET_PEER_KERNELS:-}; do kernels="$kernels, $k"; done

good=$plugins/test_plugin_good.so
crash=$plugins/test_plugin_crash.so
hang=$plugins/test_plugin_hang.so
# The report's first words for a plug-in P's kernel K.
named() { echo "ricochet: error: plug-in kernel '$1' ($plugins/test_plugin_$2.so)"; }
# A log whose only wall starts at x = X (test_plugin.c: the crash plug-in's signal is chosen by X), the ball
# moving right, so that no other crash rule applies.
wall_log() { printf 'ricochet 1\nframes 2\nwall %s -5 %s 5\nball 0 0 1 0\ncheck no-tunnel\n' "$1" "$1" >"$dir/$2"; }
# A log with a ball moving left (the hang and bad-miss plug-ins' trigger) across a wall at x = -5.
printf 'ricochet 1\nframes 2\nwall -5 -5 -5 5\nball 0 0 -1 0.5\ncheck no-tunnel\n' >"$dir/left.scene"
# A log with a wall at x = 7 crossed by the ball, and the same log naming the good plug-in's kernel.
printf 'ricochet 1\nframes 3\nwall 7 -5 7 5\nball 5 0 1.5 0.25\ncheck no-tunnel\ncheck oracle\n' >"$dir/seven.scene"
sed 's/^ricochet 1$/ricochet 1\nkernel test-good/' "$dir/seven.scene" >"$dir/good.scene"

case $case in
  missing)        run 2 run "$dir/left.scene" --kernel "plugin:$dir/none.so"
                  first_line err "ricochet: error: plug-in $dir/none.so: no such file" ;;
  empty-spec)     run 2 render "$dir/left.scene" -o "$dir/x.svg" --kernel plugin:
                  first_line err "ricochet: error: 'plugin:' names no file (plugin:PATH)"
                  [ ! -e "$dir/x.svg" ] || fail "render wrote the picture" ;;
  no-entry)       run 2 run "$dir/left.scene" --kernel "plugin:$plugins/test_plugin_no_entry.so"
                  first_line err "ricochet: error: plug-in $plugins/test_plugin_no_entry.so: no symbol ricochet_plugin_entry (a plug-in defines it: see ricochet/plugin.h)" ;;
  wrong-abi)      run 2 replay --plugin "$plugins/test_plugin_wrong_abi.so" "$dir/left.scene"
                  first_line err "ricochet: error: plug-in $plugins/test_plugin_wrong_abi.so: its table is for plugin.h ABI version 99, this ricochet speaks versions 1 and 2 (rebuild it against this ricochet's ricochet/plugin.h)" ;;
  not-a-library)  run 2 run "$dir/left.scene" --kernel "plugin:$dir/left.scene"
                  head -n 1 "$dir/err" | grep -q "^ricochet: error: plug-in $dir/left.scene: cannot load it: .\+" ||
                    fail "no dlerror message naming the file" ;;
  bad-timeout)    RICOCHET_PLUGIN_TIMEOUT=soon run 2 run "$dir/left.scene" --kernel "plugin:$good"
                  first_line err "ricochet: error: RICOCHET_PLUGIN_TIMEOUT: 'soon' is not a number of seconds from 0 (no limit) to 86400" ;;
  # A disc or a bumper under a kernel that cannot step it (a plug-in, a peer; every built-in kernel steps them):
  # refused before anything runs or is written, exit 2.
  unsupported-run) printf 'ricochet 1\nframes 2\nball 0 0 1 0 0.5\n' >"$dir/d.scene"
                  run 2 run "$dir/d.scene" --kernel "plugin:$good"
                  first_line err "$dir/d.scene: error: kernel 'test-good' steps point balls only: ball 0 has radius 0.5"
                  [ ! -s "$dir/out" ] || fail "run printed events before refusing" ;;
  unsupported-replay) printf 'ricochet 1\nkernel test-good\nframes 2\nball 0 0 1 0\nbumper 5 5 1\n' >"$dir/b.scene"
                  run 2 replay --plugin "$good" "$dir/b.scene" "$dir/good.scene"
                  first_line err "$dir/b.scene: error: kernel 'test-good' does not step bumpers: the scene has 1 (bumper 0 first)"
                  has out "FAIL $dir/b.scene: not run (unsupported)"
                  grep -q "^ok   $dir/good.scene: " "$dir/out" || fail "the next log was not replayed"
                  has out "1 passed, 1 failed" ;;
  unsupported-record) printf 'ricochet 1\nkernel test-good\nframes 2\nball 0 0 1 0 0.5\n' >"$dir/d.scene"; cp "$dir/d.scene" "$dir/keep"
                  run 2 record --plugin "$good" "$dir/d.scene"
                  first_line err "$dir/d.scene: error: kernel 'test-good' steps point balls only: ball 0 has radius 0.5"
                  cmp -s "$dir/keep" "$dir/d.scene" || fail "record changed the log" ;;
  unsupported-render) printf 'ricochet 1\nframes 2\nball 0 0 1 0 0.5\n' >"$dir/d.scene"
                  run 2 render "$dir/d.scene" -o "$dir/x.svg" --kernel "plugin:$good"
                  first_line err "$dir/d.scene: error: kernel 'test-good' steps point balls only: ball 0 has radius 0.5"
                  [ ! -e "$dir/x.svg" ] || fail "render wrote the picture" ;;
  unsupported-reduce) printf 'ricochet 1\nframes 2\nball 0 0 1 0 0.5\ncheck round-trip\n' >"$dir/d.scene"
                  run 2 reduce "$dir/d.scene" --kernel "plugin:$good"
                  first_line err "$dir/d.scene: error: kernel 'test-good' steps point balls only: ball 0 has radius 0.5" ;;
  run)            # The plug-in is what steps: blind to walls at x = 7 (test-no-reason), the ball goes through.
                  run 0 run "$dir/seven.scene" --kernel "plugin:$plugins/test_plugin_no_reason.so"
                  grep -q '^hit ' "$dir/out" && fail "the blind plug-in reports a hit"
                  has out "state 3 0 9.5 0.75 1.5 0.25"
                  # --kernel plugin:PATH comes before the log: a log naming the kernel reads.
                  run 0 run "$dir/good.scene" --kernel "plugin:$good"
                  has out "hit 2 0 0 7 0.3333333333333333" ;;
  log-names-plugin) # A log naming a plug-in's kernel reads only with the plug-in loaded.
                  run 2 replay "$dir/good.scene"
                  has err "$dir/good.scene:2:8: error: unknown kernel 'test-good' ($kernels)"
                  has err "ricochet: note: a plug-in's kernel is known once the plug-in is loaded: --plugin PATH"
                  run 0 replay --plugin "$good" "$dir/good.scene"
                  has out "1 passed, 0 failed" ;;
  log-never-loads) # A log cannot load code: plugin:PATH is no kernel name, and the crashing plug-in is never run.
                  wall_log -1001 c.scene
                  sed -i "s|^ricochet 1\$|ricochet 1\nkernel plugin:$crash|" "$dir/c.scene"
                  run 2 run "$dir/c.scene"
                  head -n 1 "$dir/err" | grep -q "^$dir/c.scene:2:8: error: unknown kernel 'plugin:/" || fail "not refused as an unknown kernel"
                  grep -q crashed "$dir/err" && fail "the plug-in was loaded and run" ;;
  record)         run 0 record --plugin "$good" "$dir/good.scene"
                  grep -q '^expect hash ' "$dir/good.scene" || fail "record wrote no expect hash"
                  run 0 replay --plugin "$good" "$dir/good.scene"
                  has out "1 passed, 0 failed" ;;
  render)         run 0 render "$dir/left.scene" -o "$dir/x.svg" --kernel "plugin:$good"
                  grep -q '<svg' "$dir/x.svg" || fail "no picture" ;;
  render-plugin)  # render takes --plugin as replay and reduce do: a log naming the plug-in's kernel reads and is drawn.
                  run 2 render "$dir/good.scene" -o "$dir/x.svg"
                  has err "$dir/good.scene:2:8: error: unknown kernel 'test-good' ($kernels)"
                  run 0 render --plugin "$good" "$dir/good.scene" -o "$dir/x.svg"
                  grep -q '>kernel test-good, frames 0\.\.3, ' "$dir/x.svg" || fail "the caption does not name the plug-in's kernel" ;;
  replay-kernel)  # replay --kernel plugin:PATH runs every log under the plug-in: the blind one lets the ball through x = 7.
                  run 1 replay --kernel "plugin:$plugins/test_plugin_no_reason.so" "$dir/seven.scene"
                  grep -q "^FAIL $dir/seven.scene: invariant no-tunnel broke at frame 2 ball 0: " "$dir/out" ||
                    fail "the log was not run under the plug-in"
                  run 0 replay --kernel "plugin:$good" "$dir/seven.scene" "$dir/good.scene"
                  has out "2 passed, 0 failed" ;;
  saved-failure-fails-until-fixed) # A plug-in's saved failure is a regression: replay fails it (exit 1, at its found
                  # check, frame and ball) while the bug is there, and passes it once the code is fixed.
                  need_props
                  blind=$plugins/test_plugin_no_reason.so
                  RICOCHET_KERNEL="plugin:$blind" RICOCHET_REPLAY_DIR="$dir/found" RC_PARAMS="seed=1 max_success=200" \
                    bounded 1 "$props" --gtest_filter='*NoTunnelSingleWall*'
                  set -- "$dir"/found/*.scene
                  [ "$#" = 1 ] && [ -f "$1" ] || fail "expected one saved log in $dir/found, found: $*"
                  log=$1
                  grep -qx 'kernel test-no-reason' "$log" || fail "the log does not name the plug-in's kernel"
                  ! grep -q '^expect failure' "$log" || fail "the saved log expects its failure: a bug would keep CI green"
                  set -- $(sed -n 's/^found \([a-z-]*\) \([0-9]*\) \([0-9]*\)$/\1 \2 \3/p' "$log")
                  [ "$#" = 3 ] || fail "the log has no found line"
                  run 1 replay --plugin "$blind" "$log"
                  has_part out "invariant $1 broke at frame $2 ball $3:"
                  has_part out "0 passed, 1 failed"
                  # The property suite, run again on the same folder, fails on the saved log before any new case.
                  RICOCHET_KERNEL="plugin:$blind" RICOCHET_REPLAY_DIR="$dir/found" RC_PARAMS="seed=2 max_success=1" \
                    bounded 1 "$props" --gtest_filter='*NoTunnelSingleWall*'
                  has_part out "$log"
                  # Fixed: the same log stepped by code without the bug (robust in the plug-in's place) passes.
                  run 0 replay --plugin "$blind" --kernel robust "$log"
                  has_part out "1 passed, 0 failed" ;;
  campaign-known-fails) # A campaign that meets a plug-in's saved failure again exits 1 (a regression still there),
                  # where a lecture kernel's known failure is its documented weakness seen again (exit 0: fuzz/ tests).
                  # The same seed and count twice: the second campaign finds the case the first saved.
                  need_fuzzer sweep
                  blind=$plugins/test_plugin_no_reason.so
                  for round in 1 2; do
                    run 1 fuzz --kernel "plugin:$blind" --target sweep --runs 500 --seed 1 --jobs 1 --no-merge \
                      --cache-dir "$dir/cache$round" --replay-dir "$dir/replays" --json -- -len_control=0 -max_len=64
                    cp "$dir/out" "$dir/round$round.json"
                  done
                  python3 -c 'import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:3])
sys.exit(0 if a["new_failures"] >= 1 and b["new_failures"] == 0 and b["known_failures"] >= 1 and b["exit"] == 1 else 1)' \
                    "$dir/round1.json" "$dir/round2.json" || fail "the second campaign did not fail on the known case"
                  has_part err "saved failures failing again (regressions until fixed) (exit 1)" ;;
  check-kernel)   # check --kernel plugin:PATH: the pinball example, the properties and the campaign under the plug-in
                  # alone, the corpus's logs under their own kernels. The blind plug-in's failure is saved into the
                  # corpus, and the next check fails on it there (a regression) until it is fixed.
                  need_props
                  blind=$plugins/test_plugin_no_reason.so
                  mkdir -p "$dir/proj"
                  cp "$(dirname "$0")/../../replays/pinball.scene" "$dir/proj/"
                  GTEST_FILTER='*NoTunnelSingleWall*' RC_PARAMS="seed=1 max_success=200" \
                    run 1 check --kernel "plugin:$blind" --replay-dir "$dir/proj" --fuzz-runs 0 --json
                  python3 -c 'import json, sys
d = json.load(open(sys.argv[1])); st = d["stages"]
ok = (d["kernel"] == "test-no-reason" and st["replay"]["status"] == "passed"
      and list(st["pinball"]["kernels"]) == ["test-no-reason"]
      and st["properties"]["status"] == "failed" and len(st["properties"]["saved_logs"]) == 1)
sys.exit(0 if ok else 1)' "$dir/out" || fail "the document does not show the stages under the plug-in"
                  set -- "$dir"/proj/NoTunnelSingleWall-*.scene
                  [ -f "$1" ] && grep -qx 'kernel test-no-reason' "$1" || fail "no saved log naming the plug-in in the corpus"
                  run 1 check --kernel "plugin:$blind" --replay-dir "$dir/proj" --fuzz-runs 0 --no-properties --json
                  python3 -c 'import json, sys
d = json.load(open(sys.argv[1])); r = d["stages"]["replay"]
sys.exit(0 if r["status"] == "failed" and r["failed"] == 1 and r["passed"] == 1 else 1)' "$dir/out" ||
                    fail "the second check does not fail on the saved failure" ;;
  reduce)         # reduce takes a plug-in as the other commands do: --kernel plugin:PATH, or --plugin for a log naming
                  # its kernel. The blind plug-in (test-no-reason) lets the ball through the wall at x = 7.
                  blind=$plugins/test_plugin_no_reason.so
                  run 0 reduce "$dir/seven.scene" --kernel "plugin:$blind" -o "$dir/small.scene"
                  grep -qx 'kernel test-no-reason' "$dir/small.scene" || fail "the reduced log does not name the plug-in's kernel"
                  # The user's own code: its failure is a regression, not a documented weakness.
                  ! grep -q '^expect failure ' "$dir/small.scene" || fail "the reduced log expects its failure"
                  run 1 replay --plugin "$blind" "$dir/small.scene"
                  has_part out "invariant no-tunnel broke at frame "
                  run 0 reduce --plugin "$blind" "$dir/small.scene" -o "$dir/again.scene"
                  run 1 replay --plugin "$blind" "$dir/again.scene"
                  wall_log -1001 c.scene; run 3 reduce "$dir/c.scene" --kernel "plugin:$crash"
                  first_line err "$(named test-crash crash) crashed: SIGSEGV in its sweep function, called with bs (0, 0), v (1, 0), wall (-1001, -5) -> (-1001, 5); while reducing $dir/c.scene" ;;
  check)          # check replays a corpus holding a plug-in's log once --plugin loads it.
                  mkdir -p "$dir/proj/replays"; cp "$dir/good.scene" "$dir/proj/replays/"
                  run 1 check --no-properties --fuzz-runs 0 --replay-dir "$dir/proj/replays"
                  has_part err "unknown kernel 'test-good'"
                  run 0 check --no-properties --fuzz-runs 0 --replay-dir "$dir/proj/replays" --plugin "$good"
                  has out "check passed" ;;
  crash-segv)     wall_log -1001 c.scene; run 3 run "$dir/c.scene" --kernel "plugin:$crash"
                  first_line err "$(named test-crash crash) crashed: SIGSEGV in its sweep function, called with bs (0, 0), v (1, 0), wall (-1001, -5) -> (-1001, 5); while running $dir/c.scene" ;;
  crash-abort)    wall_log -1002 c.scene; run 3 run "$dir/c.scene" --kernel "plugin:$crash"
                  first_line err "$(named test-crash crash) crashed: SIGABRT in its sweep function, called with bs (0, 0), v (1, 0), wall (-1002, -5) -> (-1002, 5); while running $dir/c.scene" ;;
  crash-fpe)      wall_log -1003 c.scene; run 3 run "$dir/c.scene" --kernel "plugin:$crash"
                  first_line err "$(named test-crash crash) crashed: SIGFPE in its sweep function, called with bs (0, 0), v (1, 0), wall (-1003, -5) -> (-1003, 5); while running $dir/c.scene" ;;
  crash-ill)      wall_log -1004 c.scene; run 3 run "$dir/c.scene" --kernel "plugin:$crash"
                  first_line err "$(named test-crash crash) crashed: SIGILL in its sweep function, called with bs (0, 0), v (1, 0), wall (-1004, -5) -> (-1004, 5); while running $dir/c.scene" ;;
  crash-bus)      wall_log -1005 c.scene; run 3 run "$dir/c.scene" --kernel "plugin:$crash"
                  first_line err "$(named test-crash crash) crashed: SIGBUS in its sweep function, called with bs (0, 0), v (1, 0), wall (-1005, -5) -> (-1005, 5); while running $dir/c.scene" ;;
  crash-stack)    # A stack overflow: the report runs on the guard's own signal stack.
                  wall_log -1006 c.scene; run 3 run "$dir/c.scene" --kernel "plugin:$crash"
                  first_line err "$(named test-crash crash) crashed: SIGSEGV in its sweep function, called with bs (0, 0), v (1, 0), wall (-1006, -5) -> (-1006, 5); while running $dir/c.scene" ;;
  hang)           RICOCHET_PLUGIN_TIMEOUT=0.5 run 3 run "$dir/left.scene" --kernel "plugin:$hang"
                  first_line err "$(named test-hang hang) hung: its sweep function did not return within 0.5 s (RICOCHET_PLUGIN_TIMEOUT), called with bs (0, 0), v (-1, 0x1p-1), wall (-5, -5) -> (-5, 5); while running $dir/left.scene" ;;
  bad-answer)     run 3 run "$dir/left.scene" --kernel "plugin:$plugins/test_plugin_bad_miss.so"
                  first_line err "$(named test-bad-miss bad_miss) broke ricochet/plugin.h: its sweep function answered miss code 42, which is none of RICOCHET_HIT, RICOCHET_MISS_* and RICOCHET_MISS, called with bs (0, 0), v (-1, 0x1p-1), wall (-5, -5) -> (-5, 5); while running $dir/left.scene" ;;
  replay-crash)   # The logs before the crash keep their verdicts; the report names the log it crashed on.
                  mkdir "$dir/logs"; printf 'ricochet 1\nkernel test-crash\nframes 1\nwall 5 -5 5 5\nball 0 0 1 0\n' >"$dir/logs/a.scene"
                  wall_log -1001 logs/b.scene; sed -i 's/^ricochet 1$/ricochet 1\nkernel test-crash/' "$dir/logs/b.scene"
                  run 3 replay --plugin "$crash" "$dir/logs"
                  has_part out "ok   $dir/logs/a.scene: "
                  has_part err "crashed: SIGSEGV in its sweep function"
                  has_part err "; while replaying $dir/logs/b.scene" ;;
  properties-crash) # A generated case the plug-in crashes on is kept, named by its content, and replays the crash.
                  need_props
                  RICOCHET_KERNEL="plugin:$crash" RICOCHET_REPLAY_DIR="$dir/kept" RC_PARAMS="seed=1" \
                    bounded 3 "$props" --gtest_filter='*NoTunnelSingleWall*'
                  has_part err "$(named test-crash crash) crashed: SIGSEGV in its sweep function, called with "
                  has_part err "; while running property NoTunnelSingleWall (seed 1)"
                  set -- "$dir"/kept/*
                  [ "$#" = 1 ] && [ -f "$1" ] || fail "expected one file in $dir/kept, found: $*"
                  kept=$1
                  case "$kept" in "$dir/kept/NoTunnelSingleWall-"????????????????.scene) ;; *) fail "kept as $kept" ;; esac
                  has err "ricochet: the scene is kept as $kept; replay it: ricochet replay --plugin $crash $kept"
                  grep -qx 'kernel test-crash' "$kept" && grep -qx 'from property NoTunnelSingleWall seed 1' "$kept" &&
                    grep -q "^# plug-in kernel 'test-crash' .* crashed: SIGSEGV in its sweep function" "$kept" ||
                    fail "the kept log does not say what it is: $(cat "$kept")"
                  run 3 replay --plugin "$crash" "$kept"
                  has_part err "crashed: SIGSEGV in its sweep function"
                  has_part err "; while replaying $kept" ;;
  properties-found) # A plug-in's failure without RICOCHET_REPLAY_DIR: saved in found/ of the folder it runs from, never
                  # in the corpus; the counterexample and the log name the plug-in's kernel, one seed, one command.
                  need_props
                  src=$(cd "$(dirname "$0")/../.." && pwd)
                  git -C "$src" rev-parse 2>/dev/null || { echo "skip $case: $src is not a git checkout"; exit 77; }
                  before=$(git -C "$src" status --porcelain -- replays)
                  mkdir "$dir/work"; cd "$dir/work"
                  wrong=$plugins/test_plugin_frame_wrong.so
                  unset RICOCHET_REPLAY_DIR RC_PARAMS
                  RICOCHET_KERNEL="plugin:$wrong" bounded 1 "$props" --gtest_filter='*NoTunnelSingleWall*'
                  after=$(git -C "$src" status --porcelain -- replays)
                  # (A log written into the corpus by mistake is removed, so that the failure is reported once.)
                  [ "$after" = "$before" ] || { git -C "$src" clean -fq -- replays; fail "the corpus changed: $after"; }
                  set -- "$dir"/work/found/NoTunnelSingleWall-*.scene
                  [ "$#" = 1 ] && [ -f "$1" ] || fail "expected one log in $dir/work/found, found: $*"
                  grep -qx 'kernel test-frame-wrong' "$1" || fail "the saved log does not name the plug-in's kernel"
                  has_part out "saved as $1"
                  ! grep -q '^kernel robust$' "$dir/out" || fail "the counterexample names kernel robust"
                  grep -q '^kernel test-frame-wrong$' "$dir/out" || fail "the counterexample does not name the kernel run"
                  seeds=$(cat "$dir/out" "$dir/err" | grep -o 'seed[ =][0-9]*' | sed 's/seed[ =]//' | sort -u | tr '\n' ' ')
                  [ "$seeds" = "1 " ] || fail "more than the one seed 1: $seeds"
                  repro=$(sed -n 's/^reproduce: //p' "$dir/out")
                  [ -n "$repro" ] || fail "no reproduce line"
                  [ "$(printf '%s\n' "$repro" | wc -l)" = 1 ] || fail "more than one reproduce line"
                  case "$repro" in "RICOCHET_KERNEL=plugin:$wrong RC_PARAMS=\"seed=1 max_success="*"\" $props --gtest_filter='Kernels/"*".NoTunnelSingleWall/"*"'") ;;
                    *) fail "the reproduce line is not the one command: $repro" ;; esac
                  # It reproduces: the saved log, replayed first, fails again from the same folder.
                  eval "$repro" >"$dir/again" 2>&1; [ "$?" = 1 ] || fail "the reproduce command did not fail"
                  grep -q "saved log $1 breaks NoTunnelSingleWall under test-frame-wrong again" "$dir/again" || fail "not reproduced by the saved log" ;;
  properties-hang) need_props
                  RICOCHET_PLUGIN_TIMEOUT=0.5 RICOCHET_KERNEL="plugin:$hang" RICOCHET_REPLAY_DIR="$dir/kept" RC_PARAMS="seed=1" \
                    bounded 3 "$props" --gtest_filter='*NoTunnelSingleWall*'
                  has_part err "$(named test-hang hang) hung: its sweep function did not return within 0.5 s (RICOCHET_PLUGIN_TIMEOUT), called with "
                  set -- "$dir"/kept/*.scene
                  [ "$#" = 1 ] && [ -f "$1" ] || fail "expected one log in $dir/kept, found: $*"
                  has_part err "ricochet: the scene is kept as $1;" ;;
  properties-bad-plugin) need_props
                  RICOCHET_KERNEL="plugin:$plugins/test_plugin_wrong_abi.so" bounded 2 "$props" --gtest_filter='*NoTunnelSingleWall*'
                  has_part err "RICOCHET_KERNEL: error: plug-in $plugins/test_plugin_wrong_abi.so: its table is for plugin.h ABI version 99" ;;
  fuzz-bad-plugin) run 2 fuzz --kernel "plugin:$plugins/test_plugin_no_entry.so" --target sweep --runs 10 --seed 1 \
                    --cache-dir "$dir/cache" --replay-dir "$dir/replays"
                  first_line err "ricochet fuzz: error: plug-in $plugins/test_plugin_no_entry.so: no symbol ricochet_plugin_entry (a plug-in defines it: see ricochet/plugin.h)" ;;
  fuzz-disc-point-kernel) # The disc target named with a kernel that steps point balls only: refused before anything starts.
                  need_fuzzer disc
                  run 2 fuzz --target disc --kernel "plugin:$good" --runs 20 --cache-dir "$dir/cache" --replay-dir "$dir/replays"
                  first_line err "ricochet fuzz: error: target disc needs a kernel that steps discs (lecture-float, lecture-double, robust, exact); kernel 'test-good' steps point balls only"
                  [ ! -d "$dir/cache/disc" ] || fail "the refused campaign made a corpus folder" ;;
  fuzz-disc-left-out) # Every target by default: disc is left out for such a kernel, saying so; the others run.
                  need_fuzzer disc
                  timeout 120 "$ricochet" fuzz --kernel "plugin:$good" --runs 1 --seed 1 --jobs 1 --cache-dir "$dir/cache" \
                    --replay-dir "$dir/replays" >"$dir/out" 2>"$dir/err"
                  rc=$?; [ "$rc" = 0 ] || [ "$rc" = 1 ] || fail "exit $rc, expected 0 or 1"
                  has err "ricochet fuzz: note: leaving out target disc: kernel 'test-good' steps point balls only"
                  grep -q '^scene ' "$dir/out" || fail "the scene target did not run"
                  ! grep -q '^disc ' "$dir/out" || fail "the disc target ran" ;;
  # ABI version 2: a plug-in that sweeps discs (test-disc) steps discs and bumpers under every command.
  disc-run)       # A disc off the wall at x = 5 (contact at x = 4, t = 1/3 of frame 2), then off the bumper at x = -5.
                  printf 'ricochet 1\nframes 4\nwall 5 -5 5 5\nbumper -5 0 1\nball 0 0 3 0 1\ncheck oracle\ncheck no-tunnel\n' >"$dir/d.scene"
                  run 0 run "$dir/d.scene" --kernel "plugin:$plugins/test_plugin_disc.so"
                  grep -q '^hit 2 0 0 4 0' "$dir/out" || fail "no hit at (4, 0) in frame 2"
                  grep -q '^bump 4 0 0 -3 0' "$dir/out" || fail "no bump at (-3, 0) in frame 4" ;;
  disc-reduce-replay) # Its discs' failures are found, reduced and replayed like its point balls': test-disc rounds B_i
                  # once, without robust's walk back, so `penetration` (δ = 0) catches a disc in a box at once.
                  disc=$plugins/test_plugin_disc.so
                  printf 'ricochet 1\nframes 20\nwall 0 0 0 16\nwall 0 16 16 16\nwall 16 16 16 0\nwall 16 0 0 0\nbumper 8 8 2\nball 4 4 3 1.25 1\nball 12 3 -2 3.5 0.5\ncheck penetration\n' >"$dir/box.scene"
                  run 0 reduce "$dir/box.scene" --kernel "plugin:$disc" -o "$dir/small.scene"
                  grep -qx 'kernel test-disc' "$dir/small.scene" || fail "the reduced log does not name the plug-in's kernel"
                  run 1 replay --plugin "$disc" "$dir/small.scene"
                  has_part out "invariant penetration broke at frame "
                  run 0 replay --plugin "$disc" --kernel robust "$dir/small.scene" ;;
  disc-bad-answer) # t = 2 from sweep_disc: a broken header, reported with the call.
                  printf 'ricochet 1\nframes 2\nwall -5 -5 -5 5\nball 0 0 -10 0 1\n' >"$dir/d.scene"
                  run 3 run "$dir/d.scene" --kernel "plugin:$plugins/test_plugin_disc_broken.so"
                  first_line err "$(named test-disc-broken disc_broken) broke ricochet/plugin.h: its sweep_disc function answered a hit at t = 2, which is not in [0, 1], called with bs (0, 0), v (-10, 0), radius 1, wall (-5, -5) -> (-5, 5); while running $dir/d.scene" ;;
  disc-fuzz)      # The disc target runs against it and finds a failure (test-disc rounds B_i once; found within 10
                  # inputs in the runs measured, so 300 leave room), kept as a log that replays it (exit 1), reduced.
                  need_fuzzer disc
                  disc=$plugins/test_plugin_disc.so
                  run 1 fuzz --kernel "plugin:$disc" --target disc --runs 300 --seed 1 --jobs 1 \
                    --cache-dir "$dir/cache" --replay-dir "$dir/replays"
                  has_part out "ricochet fuzz: kernel test-disc (plug-in $disc)"
                  set -- "$dir"/replays/fuzz-disc-*.scene
                  [ -f "$1" ] || fail "the campaign saved no log"
                  for log in "$@"; do
                    grep -qx 'kernel test-disc' "$log" || fail "$log does not name the plug-in's kernel"
                    grep -q '^from reduce ' "$log" || fail "$log was not reduced"
                    run 1 replay --plugin "$disc" "$log"
                  done ;;
  fuzz-crash)     # libFuzzer keeps the input; the campaign names the plug-in and turns the input into a scene log.
                  # Full-length inputs from the start: the crash rule needs a ball moving left, which libFuzzer's short
                  # first inputs never decode to; so set, four runs of fuzz_sweep crashed at input 35 each, and 2000
                  # leave room whatever order the fuzzer's coverage takes (its counts vary by an edge from run to run).
                  need_fuzzer sweep
                  run 1 fuzz --kernel "plugin:$crash" --target sweep --runs 2000 --seed 1 --cache-dir "$dir/cache" \
                    --replay-dir "$dir/replays" --json -- -len_control=0 -max_len=64
                  has_part err "sweep failure: $(named test-crash crash) crashed: SIGSEGV in its sweep function, called with "
                  has_part err "ricochet fuzz: kernel test-crash (plug-in $crash)"
                  set -- "$dir"/replays/fuzz-sweep-*.scene
                  [ "$#" = 1 ] && [ -f "$1" ] || fail "expected one scene log in $dir/replays, found: $*"
                  has_part err "scene log: $1  (ricochet replay --plugin $crash $1)"
                  # The document names the kernel by its own name and the plug-in by its file (docs/cli-json.md).
                  python3 -c 'import json, sys
d = json.load(open(sys.argv[1]))
sys.exit(0 if d["kernel"] == "test-crash" and d["plugin"] == sys.argv[2] and d["new_failures"] == 1 else 1)' \
                    "$dir/out" "$crash" || fail "the JSON document does not name the plug-in" 
                  grep -qx 'kernel test-crash' "$1" || fail "the log does not name the plug-in's kernel"
                  run 3 replay --plugin "$crash" "$1"
                  has_part err "crashed: SIGSEGV in its sweep function" ;;
  *)              echo "unknown case $case"; exit 2 ;;
esac
echo "ok $case"
