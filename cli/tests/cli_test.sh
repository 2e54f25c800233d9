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

# Every kernel's name as errors list them: the built-in four, then the peers this build has.
kernels='lecture-float, lecture-double, robust, exact'
for k in ${RICOCHET_PEER_KERNELS:-}; do kernels="$kernels, $k"; done

# A small valid log: 10 frames × 2 balls × (1 wall + 0 shapes + 1) + 64 × 1 wall (its index) = 104 units of work.
log=$dir/tiny.scene
printf 'ricochet 1\nframes 10\nwall 0 -5 0 5\nball -1 0 0.5 0\nball -3 1 0.25 0\ncheck no-tunnel\n' >"$log"
# A small valid log that would run for hours: 10^7 frames × 200 balls × (4 walls + 1) + 64 × 4 ≈ 10^10.
big=$dir/big.scene
{ printf 'ricochet 1\nkernel exact\nframes 10000000\nwall 0 0 0 100\nwall 0 100 100 100\nwall 100 100 100 0\nwall 100 0 0 0\n'
  i=0; while [ $i -lt 200 ]; do printf 'ball %d.5 50 0.25 0.125\n' $((i % 90 + 5)); i=$((i + 1)); done; } >"$big"
enospc="ricochet: error: writing standard output: No space left on device"

# The project folder (cli/include/ricochet_app/project.hpp): a clone-like folder with replays/ and a log in
# it, a subfolder two levels down, and a folder no project holds (mktemp's folder is under /tmp).
proj=$dir/proj
mkproj() {
  unset RICOCHET_REPLAY_DIR
  mkdir -p "$proj/replays" "$proj/a/b" "$dir/none"
  cp "$log" "$proj/replays/t.scene"
}
# need_fuzzer TARGET: skip unless the build has the libFuzzer binary fuzz_TARGET (clang, RICOCHET_FUZZ on).
need_fuzzer() {
  "$(dirname "$ricochet")/../fuzz/fuzz_$1" -help=1 2>&1 | grep -q '^Usage:' || { echo "skip $case: no libFuzzer fuzz_$1"; exit 77; }
}
# no_project_here: skip if some folder above $dir/none holds replays/ (then it is in a project after all).
no_project_here() {
  d=$dir
  while [ "$d" != / ]; do [ -d "$d/replays" ] && { echo "skip $case: $d holds replays/"; exit 77; }; d=$(dirname "$d"); done
  [ -d /replays ] && { echo "skip $case: /replays exists"; exit 77; }
  return 0
}
# The tree this script is in (the source tree ricochet was built from, in a CTest run), and its git status
# leaving out this script's own folder (TMPDIR may put it inside the tree).
src=$(cd "$(dirname "$0")/../.." && pwd)
src_status() {
  case "$dir" in
    "$src"/*) git -C "$src" status --porcelain -- . ":(exclude)${dir#"$src"/}" ;;
    *) git -C "$src" status --porcelain ;;
  esac
}
# json_is FILE PYTHON-EXPRESSION [ARG...]: FILE (out or err) is one JSON document and the expression, over it
# as d (and the ARGs as a), holds; python3's json module parses it, so any syntax error fails.
json_is() {
  f=$1 e=$2; shift 2
  python3 -c 'import json, sys
d = json.load(open(sys.argv[1]))
a = sys.argv[3:]
sys.exit(0 if eval(sys.argv[2]) else 1)' "$dir/$f" "$e" "$@" 2>"$dir/py" || fail "std$f is not JSON where $e: $(cat "$dir/py")"
}
# junit_valid FILE: FILE validates against the JUnit schema docs/schemas/ holds (xmllint); sarif_valid FILE against
# the SARIF 2.1.0 schema (python3-jsonschema). Each is first shown a broken copy, which it must reject: a check
# that cannot fail checks nothing.
junit_valid() {
  command -v xmllint >/dev/null || fail "no xmllint (Debian package libxml2-utils)"
  sed 's/<testsuite name="\([^"]*\)" tests="[0-9]*"/<testsuite name="\1"/' "$1" >"$dir/broken.xml"
  cmp -s "$1" "$dir/broken.xml" && fail "$1 has no <testsuite> to break"
  ! xmllint --noout --schema "$src/docs/schemas/junit-10.xsd" "$dir/broken.xml" 2>/dev/null || fail "the JUnit schema takes a <testsuite> without tests"
  xmllint --noout --schema "$src/docs/schemas/junit-10.xsd" "$1" 2>"$dir/py" || fail "$1 is not valid JUnit: $(cat "$dir/py")"
}
sarif_valid() {
  python3 -c 'import json, sys, jsonschema
schema = json.load(open(sys.argv[1]))
doc = json.load(open(sys.argv[2]))
broken = json.loads(json.dumps(doc)); broken["runs"][0]["results"].append({"ruleId": "x", "level": "fatal", "message": {"text": "x"}})
try:
    jsonschema.validate(broken, schema)
    sys.exit("the SARIF schema takes a result of level fatal")
except jsonschema.ValidationError:
    pass
jsonschema.validate(doc, schema)' "$src/docs/schemas/sarif-schema-2.1.0.json" "$1" 2>"$dir/py" || fail "$1 is not valid SARIF: $(tail -n 3 "$dir/py")"
}
# junit_properties FILE: GoogleTest's XML (--gtest_output=xml:FILE) is well-formed, holds a case per test with name,
# classname and time, and is valid JUnit but for the attributes GoogleTest adds that junit-10.xsd does not know
# (docs/cli-reports.md): a copy without them validates against the schema as it is.
junit_properties() {
  xmllint --noout "$1" 2>"$dir/py" || fail "$1 is not XML: $(cat "$dir/py")"
  xml_is "$1" 'd.tag == "testsuites" and len(list(d.iter("testcase"))) >= 1 and all(c.get("name") and c.get("classname") and c.get("time") for c in d.iter("testcase"))'
  ! xmllint --noout --schema "$src/docs/schemas/junit-10.xsd" "$1" 2>/dev/null || return 0
  sed -E 's/ (disabled|timestamp|status|result|file|line|value_param|type_param)="[^"]*"//g' "$1" >"$dir/gtest-plain.xml"
  junit_valid "$dir/gtest-plain.xml"
}
# xml_is FILE PYTHON-EXPRESSION [ARG...]: as json_is, over FILE's XML root element as d (xml.etree).
xml_is() {
  f=$1 e=$2; shift 2
  python3 -c 'import sys, xml.etree.ElementTree as ET
d = ET.parse(sys.argv[1]).getroot()
a = sys.argv[3:]
sys.exit(0 if eval(sys.argv[2]) else 1)' "$f" "$e" "$@" 2>"$dir/py" || fail "$f is not XML where $e: $(cat "$dir/py")"
}
# stop_after_first_line SIGNAL ARGS...: starts ricochet ARGS in the background (stdout in $dir/out, stderr in
# $dir/err), waits until it has printed its first line (synchronised on its output, not on a delay), sends
# SIGNAL, and leaves its exit status in rc. The commands given run for hours unless stopped, so the verdict
# does not depend on timing.
stop_after_first_line() { stop_once '[ -s "$dir/out" ]' "$@"; }
# stop_once CONDITION SIGNAL ARGS...: runs ricochet ARGS in the background and sends SIGNAL once the shell test
# CONDITION holds; rc is its exit status.
stop_once() {
  cond=$1; sig=$2; shift 2
  "$ricochet" "$@" >"$dir/out" 2>"$dir/err" &
  pid=$!
  while ! eval "$cond"; do
    kill -0 "$pid" 2>/dev/null || { wait "$pid"; fail "ricochet $* ended (exit $?) before it was under way"; }
    sleep 0.02
  done
  kill "-$sig" "$pid"
  wait "$pid"
  rc=$?
}
# stop_when_running SIGNAL ARGS...: as stop_after_first_line, for a command that prints nothing before its end
# (record, render): SIGNAL goes once its run is under way, a tenth of a second of its own CPU time in
# /proc/PID/stat (reading a 200-line log takes microseconds). Skips the case where there is no /proc.
stop_when_running() {
  [ -r /proc/$$/stat ] || { echo "skip $case: no /proc"; exit 77; }
  stop_once '[ "$(awk '"'"'{print $14}'"'"' "/proc/$pid/stat" 2>/dev/null || echo 0)" -ge 10 ]' "$@"
}
# reduced_reproduces LOG [CHECK]: LOG is a failure log (of CHECK): replay passes it (its expected failure
# reproduces), and without `expect failure` fails it at its found check, frame and ball.
reduced_reproduces() {
  found=$(sed -n 's/^found \([^ ]*\) \([0-9]*\) \([0-9]*\)$/\1 \2 \3/p' "$1")
  [ -n "$found" ] || fail "$1 has no found line"
  set -- "$1" "${2:-}" $found
  [ -z "$2" ] || [ "$3" = "$2" ] || fail "$1 found $3, expected $2"
  grep -qx "expect failure $3 $4" "$1" || fail "$1 does not expect its failure"
  "$ricochet" replay "$1" >"$dir/r1" 2>&1 || fail "replay fails $1: $(cat "$dir/r1")"
  grep -v '^expect failure' "$1" >"$dir/bare.scene"
  ! "$ricochet" replay "$dir/bare.scene" >"$dir/r2" 2>&1 || fail "without expect failure $1 passes"
  grep -q "invariant $3 broke at frame $4 ball $5:" "$dir/r2" || fail "not found $3 $4 $5: $(cat "$dir/r2")"
  ! grep -q "when saved" "$dir/r2" || fail "replay says the run differs from found"
}
# A log that runs for hours (10^7 frames, 200 balls): a whole frame prints 200 state lines.
long=$dir/long.scene
{ printf 'ricochet 1\nframes 10000000\nwall 0 0 0 100\nwall 0 100 100 100\nwall 100 100 100 0\nwall 100 0 0 0\n'
  i=0; while [ $i -lt 200 ]; do printf 'ball %d.5 50 0.25 0.125\n' $((i % 90 + 5)); i=$((i + 1)); done; } >"$long"
# A valid log whose expect hash is wrong: replay fails it (exit 1).
badlog=$dir/bad.scene
printf 'ricochet 1\nframes 10\nwall 0 -5 0 5\nball -1 0 0.5 0\nexpect hash 0123456789abcdef\n' >"$badlog"

case "$case" in
  full-run)          run_full 1 run "$log"; first_line err "$enospc" ;;
  full-replay)       run_full 1 replay "$log"; first_line err "$enospc" ;;
  full-replay-hashes) run_full 1 replay --hashes "$log"; first_line err "$enospc" ;;
  full-record)       cp "$log" "$dir/r.scene"; run_full 1 record "$dir/r.scene"; first_line err "$enospc" ;;
  full-help)         run_full 1 help; first_line err "$enospc" ;;
  full-reduce)       run_full 1 reduce "$src/replays/lecture/double-pinball-tunnel.scene"; first_line err "$enospc" ;;
  check-new-corpus)  # A replay folder --replay-dir names is made if it is not there; with no log yet the replay stage is
                     # skipped, not failed (failures will be saved there); a folder whose parent is missing is refused.
                     run 0 check --replay-dir "$dir/new" --no-properties --fuzz-runs 0
                     [ -d "$dir/new" ] || fail "the replay folder was not made"
                     has err "ricochet check: note: made the replay folder $dir/new"
                     has out "replay      skipped (no scene logs in $dir/new yet)"
                     run 2 check --replay-dir "$dir/none/new" --no-properties --fuzz-runs 0
                     first_line err "ricochet check: error: cannot make the replay folder $dir/none/new: No such file or directory" ;;
  check-bad-domain)  # A domain that does not read is refused before anything runs.
                     mkproj; cd "$proj"; run 2 check --domain waive=corners --no-properties --fuzz-runs 0
                     first_line err "ricochet check: error: --domain: unknown domain item 'waive=corners' (coordinates=C, speed=V, wall-length=L, no-subnormals, waive=touching)" ;;
  fuzz-bad-domain)   # A domain that does not read is refused before any worker starts, saying which item.
                     run 2 fuzz --domain coordinates=1e6,speed=0 --runs 1 --cache-dir "$dir/cache"
                     first_line err "ricochet fuzz: error: --domain: 'speed' needs a number above 0 and at most 2^256: speed=0"
                     [ ! -e "$dir/cache" ] || fail "the cache was made" ;;
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
                     first_line err "ricochet: error: unknown command 'xyzzy' (commands: run, record, replay, render, reduce, check, bench, fuzz, help, completion)" ;;
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
  run-unknown-kernel) run 2 run "$log" --kernel nope
                     first_line err "ricochet: error: unknown kernel 'nope' ($kernels, or plugin:PATH)" ;;
  # The peers as kernels, where built: run and render take them, and a log naming one replays.
  peer-kernels)      [ -n "${RICOCHET_PEER_KERNELS:-}" ] || { echo "skip $case: no peer kernel in this build"; exit 77; }
                     for k in $RICOCHET_PEER_KERNELS; do
                       run 0 run "$log" --kernel "$k"
                       [ "$(grep -c '^state 10 ' "$dir/out")" = 2 ] || fail "run --kernel $k did not run both balls 10 frames"
                       run 0 render "$log" -o "$dir/$k.svg" --kernel "$k"
                       grep -q ">kernel $k, frames 0\.\.10, " "$dir/$k.svg" || fail "the caption does not say kernel $k"
                       # Without its check (the peers tunnel through this wall: replays/peers/ shows how).
                       sed "s/^ricochet 1$/ricochet 1\nkernel $k/; /^check /d" "$log" >"$dir/$k.scene"
                       run 0 replay "$dir/$k.scene"
                       has out "1 passed, 0 failed"
                     done ;;
  replay-unreadable) mkdir "$dir/logs"; cp "$log" "$dir/logs/a.scene"; printf 'ricochet 1\nbogus 1\n' >"$dir/logs/b.scene"
                     run 2 replay "$dir/logs"
                     has out "FAIL $dir/logs/b.scene: unreadable log"; has out "1 passed, 1 failed"
                     grep -q "^$dir/logs/b.scene:2:1: error: " "$dir/err" || fail "no diagnostic naming b.scene:2:1" ;;
  # A log for a kernel this build knows but lacks (a peer left out: RICOCHET_PEERS=OFF, or its library not found)
  # is skipped and said so, never a failure of replay or check.
  absent-kernel)     absent=; for k in box2d chipmunk; do case " ${RICOCHET_PEER_KERNELS:-} " in *" $k "*) ;; *) absent=$k; break ;; esac; done
                     [ -n "$absent" ] || { echo "skip $case: this build has every peer kernel"; exit 77; }
                     mkproj; peer=$(ls "$src/replays/peers/$absent/"*.scene | head -n 1); cp "$peer" "$proj/replays/p.scene"
                     run 0 replay "$proj/replays"
                     grep -q "^skip $proj/replays/p.scene: kernel '$absent' is not built into this ricochet: " "$dir/out" || fail "no skip line"
                     has out "1 passed, 0 failed, 1 skipped"
                     run 0 replay --json "$proj/replays"
                     json_is out 'd["exit"] == 0 and d["skipped"] == 1 and d["failed"] == 0 and d["bad_input"] is False and [l["status"] for l in d["logs"]] == ["skipped", "passed"] and list(d["skip_reasons"].values()) == [1] and list(d["skip_reasons"])[0].startswith("kernel \x27" + a[0] + "\x27 is not built into this ricochet: ")' "$absent"
                     cd "$proj"; run 0 check --no-properties --fuzz-runs 0
                     grep -q '^replay      1 passed, 0 failed, 1 skipped ([0-9.]* s)$' "$dir/out" || fail "no replay summary with 1 skipped"
                     grep -q "^            1 skipped: kernel '$absent' is not built into this ricochet: " "$dir/out" || fail "check does not say why"
                     has out "check passed"
                     run 0 check --json --no-properties --fuzz-runs 0
                     json_is out 'd["passed"] is True and d["stages"]["replay"]["status"] == "passed" and d["stages"]["replay"]["skipped"] == 1' ;;
  check-fuzz-seconds-env) mkproj; cd "$proj"; RICOCHET_CHECK_FUZZ_SECONDS=soon run 2 check --no-properties
                     first_line err "ricochet check: error: RICOCHET_CHECK_FUZZ_SECONDS='soon' is not a number of seconds (0 to 86400)" ;;
  check-properties)  # The property suite as check runs it, with a fixed RapidCheck seed (no luck in the verdict).
                     mkproj; cd "$proj"; RC_PARAMS="seed=1" run 0 check --fuzz-runs 0
                     grep -q '^properties  not built' "$dir/out" && { echo "skip $case: no property suite in this build"; exit 77; }
                     grep -q '^properties  passed ([0-9.]* s)$' "$dir/out" || fail "no passed properties line"
                     has out "check passed" ;;
  check-fuzz-seed)   # The campaign check ends with: its count and seed, in a cache of its own.
                     mkproj; need_fuzzer scene
                     cd "$proj"; XDG_CACHE_HOME=$dir/cache run 0 check --no-properties --fuzz-runs 20 --fuzz-seed 3 --junit "$dir/c.xml" --sarif "$dir/c.sarif"
                     has out "== fuzz: 20 inputs per target, seed 3"
                     # The campaign's own report, taken into check's: a case per target.
                     junit_valid "$dir/c.xml"; sarif_valid "$dir/c.sarif"
                     xml_is "$dir/c.xml" 'd[-1].get("name") == "fuzz" and "scene" in [c.get("name") for c in d[-1]] and {c.get("classname") for c in d[-1]} == {"fuzz.robust"}' 
                     grep -q '^fuzz        passed (' "$dir/out" || fail "no fuzz passed line"
                     [ -d "$dir/cache/ricochet/fuzz/scene" ] || fail "the campaign did not use \$XDG_CACHE_HOME" ;;
  check-fuzz-time)   run 2 check --fuzz-time soon
                     first_line err "ricochet: error: --fuzz-time: 'soon' is not a number of seconds (expected 0 to 86400)" ;;
  check-max-work)    # The bound on work reaches every stage: the corpus log is refused, pinball is not run.
                     mkproj; cp "$src/replays/pinball.scene" "$proj/replays/"; cd "$proj"
                     run 1 check --no-properties --fuzz-runs 0 --max-work 1000
                     grep -q '^FAIL replays/pinball.scene: not run (over --max-work)$' "$dir/out" || fail "pinball.scene was run"
                     has out "pinball     not run (over --max-work)"
                     has out "check FAILED" ;;
  check-fuzz-runs)   run 2 check --fuzz-runs many
                     first_line err "ricochet: error: --fuzz-runs: 'many' is not a count of inputs (expected 0 to 9223372036854775807)" ;;
  fuzz-time-0)       run 2 fuzz --time 0
                     first_line err "ricochet: error: --time: '0' is out of range (expected a number of seconds from 1 to 604800)" ;;
  fuzz-time-absurd)  run 2 fuzz --time 1e300
                     first_line err "ricochet: error: --time: '1e300' is out of range (expected a number of seconds from 1 to 604800)" ;;
  work-run)          run 2 run "$log" --max-work 103
                     first_line err "ricochet: error: $log: too much work: 10 frames × 2 balls × (1 walls + 0 circles + 0 rects + 0 bumpers + 1) + 64 × 1 walls (the wall index) = 104 is over the bound of 103; raise it with --max-work N (0: no bound)"
                     [ ! -s "$dir/out" ] || fail "run printed events before refusing"
                     run 0 run "$log" --max-work 104; has out "state 10 1 -0.5 1 0.25 0" ;;
  work-replay)       run 2 replay "$log" --max-work 103; has out "FAIL $log: not run (over --max-work)"
                     first_line err "ricochet: error: $log: too much work: 10 frames × 2 balls × (1 walls + 0 circles + 0 rects + 0 bumpers + 1) + 64 × 1 walls (the wall index) = 104 is over the bound of 103; raise it with --max-work N (0: no bound)"
                     run 0 replay "$log" --max-work 104 ;;
  work-record)       cp "$log" "$dir/r.scene"; run 2 record "$dir/r.scene" --max-work 103
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
  work-render)       run 2 render "$log" -o "$dir/x.svg" --max-work 103; grep -q "too much work" "$dir/err" || fail "no work error"
                     [ ! -e "$dir/x.svg" ] || fail "render wrote the picture" ;;
  work-default)      run 2 replay "$big"
                     first_line err "ricochet: error: $big: too much work: 10000000 frames × 200 balls × (4 walls + 0 circles + 0 rects + 0 bumpers + 1) + 64 × 4 walls (the wall index) = 10000000256 is over the bound of 100000000; raise it with --max-work N (0: no bound)" ;;
  # The wall index is built before frame 1: 100 copies of one wall and `frames 0` are 64 × 100 = 6400 units.
  work-index)        { printf 'ricochet 1\nframes 0\nball 0 0 1 0\n'; i=0; while [ $i -lt 100 ]; do
                         printf 'wall 0 0 1 1\n'; i=$((i + 1)); done; } >"$dir/walls.scene"
                     run 2 run "$dir/walls.scene" --max-work 6399
                     first_line err "ricochet: error: $dir/walls.scene: too much work: 0 frames × 1 balls × (100 walls + 0 circles + 0 rects + 0 bumpers + 1) + 64 × 100 walls (the wall index) = 6400 is over the bound of 6399; raise it with --max-work N (0: no bound)"
                     run 0 run "$dir/walls.scene" --max-work 6400 ;;
  work-frames-flag)  run 2 run "$log" --frames 5 --max-work 83; grep -q "= 84 is over the bound of 83" "$dir/err" || fail "work not from --frames" ;;
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
                     grep -q 'data-x="0" data-y="8"' "$dir/all.svg" || fail "--view all lost the mark"
                     # --kernel robust: the same table holds, nothing is marked, the caption names the kernel.
                     run 0 render "$dir/t.scene" -o "$dir/robust.svg" --kernel robust
                     grep -q '^wrote [^(]*$' "$dir/out" || fail "render --kernel robust marked a failure"
                     grep -q '>kernel robust, frames 0\.\.10, ' "$dir/robust.svg" || fail "the caption does not say kernel robust" ;;
  # -o and LOG: `-` is stdout or stdin; a device, a FIFO or a link to one is written in place, never replaced.
  out-stdout)        run 0 render "$log" -o -
                     head -n 1 "$dir/out" | grep -q "^<svg xmlns=" || fail "stdout does not start with the picture"
                     [ "$(tail -n 1 "$dir/out")" = "</svg>" ] || fail "stdout is not the whole picture"
                     has err "ricochet render: wrote the picture to standard output"
                     run 0 reduce "$src/replays/lecture/double-wedge-tunnel.scene" -o -
                     first_line out "ricochet 1"; grep -q '^found no-tunnel ' "$dir/out" || fail "stdout is not the reduced log"
                     [ ! -e ./- ] && [ ! -e "$dir/-" ] || fail "a file named - was written" ;;
  in-stdin)          run 0 run - <"$log"; "$ricochet" run "$log" >"$dir/want" || fail "run LOG failed"
                     cmp -s "$dir/out" "$dir/want" || fail "run - <LOG differs from run LOG"
                     run 0 replay - <"$log"; has out "ok   -: 10 frames, hash $("$ricochet" replay --hashes "$log" | cut -c1-16)"
                     run 0 render - -o "$dir/x.svg" <"$log"; grep -q '^<svg ' "$dir/x.svg" || fail "render - drew nothing"
                     printf 'ricochet 1\nbogus 1\n' >"$dir/b.scene"
                     run 2 run - <"$dir/b.scene"; first_line err "<stdin>:2:1: error: unknown directive 'bogus'"
                     run 2 record - <"$log"; first_line err "ricochet: error: record writes its log back: it needs a file, not standard input (-)" ;;
  out-fifo)          # A reader on a FIFO made here gets the picture and the reduced log; the FIFO stays a FIFO.
                     mkfifo "$dir/pipe" || { echo "skip $case: no mkfifo"; exit 77; }
                     ln -s pipe "$dir/link"
                     for target in pipe link; do
                       # (A reader that never sees a writer, as when the FIFO was replaced, gives up after 10 s.)
                       timeout 10 cat "$dir/pipe" >"$dir/got" & reader=$!
                       run 0 render "$log" -o "$dir/$target"; wait "$reader" || fail "the FIFO's reader got nothing ($target)"
                       [ -p "$dir/pipe" ] || fail "render -o $target replaced the FIFO"
                       [ "$(tail -n 1 "$dir/got")" = "</svg>" ] || fail "the FIFO's reader did not get the picture ($target)"
                       has out "wrote $dir/$target"
                     done
                     [ -L "$dir/link" ] || fail "the link to the FIFO was replaced"
                     timeout 10 cat "$dir/pipe" >"$dir/got" & reader=$!
                     run 0 reduce "$src/replays/lecture/double-wedge-tunnel.scene" -o "$dir/link"; wait "$reader" || fail "reduce's reader got nothing"
                     [ -p "$dir/pipe" ] && [ -L "$dir/link" ] || fail "reduce -o replaced the FIFO or its link"
                     grep -q '^found no-tunnel ' "$dir/got" || fail "the FIFO's reader did not get the reduced log"
                     [ -z "$(ls -A "$dir" | grep '\.tmp\.')" ] || fail "a temporary file is left" ;;
  out-device)        # A character device made here (the null device's numbers, 1 3), never the system's /dev/null.
                     [ "$(id -u)" = 0 ] || { echo "skip $case: mknod needs root"; exit 77; }
                     mknod "$dir/null" c 1 3 2>/dev/null || { echo "skip $case: mknod is not allowed here"; exit 77; }
                     ln -s null "$dir/link"
                     run 0 render "$log" -o "$dir/null"; has out "wrote $dir/null"
                     run 0 render "$log" -o "$dir/link"
                     run 0 reduce "$src/replays/lecture/double-wedge-tunnel.scene" -o "$dir/null"
                     [ -c "$dir/null" ] || fail "the device was replaced by a regular file"
                     [ -L "$dir/link" ] || fail "the link to the device was replaced"
                     [ -z "$(ls -A "$dir" | grep '\.tmp\.')" ] || fail "a temporary file is left" ;;
  replay-kernel)     # --kernel runs each log under another kernel, its checks and expect lines as they are: the
                     # lecture's tunnel, expected under lecture-double, does not happen under robust.
                     t=$src/replays/lecture/double-pinball-tunnel.scene
                     run 0 replay "$t"
                     run 1 replay --kernel robust "$t"
                     grep -q "^FAIL $t: .*expected no-tunnel to break first at frame [0-9]*, but every check held" "$dir/out" ||
                       fail "not run under robust"
                     run 2 replay --kernel nope "$t"
                     first_line err "ricochet: error: unknown kernel 'nope' ($kernels, or plugin:PATH)" ;;
  # reduce: a failing log made small; the input never changes, the output is a failure log replay reproduces.
  reduce-corpus)     cp "$src/replays/lecture/double-pinball-tunnel.scene" "$dir/in.scene"
                     run 0 reduce "$dir/in.scene" -o "$dir/out.scene"
                     cmp -s "$src/replays/lecture/double-pinball-tunnel.scene" "$dir/in.scene" || fail "reduce changed its input"
                     grep -q '^ricochet reduce: 6 walls, 1 balls, 2 circles, 1 rects, 500 frames → 1 walls, 1 balls, 0 circles, 0 rects, [0-9]* frames; [0-9]* tries, [0-9.]* s, nothing smaller found; wrote ' "$dir/err" ||
                       fail "no summary line"
                     [ ! -s "$dir/out" ] || fail "stdout not empty with -o"
                     [ -z "$(ls -A "$dir" | grep '\.tmp\.')" ] || fail "a temporary file is left"
                     reduced_reproduces "$dir/out.scene" no-tunnel ;;
  reduce-stdout)     # Without -o the reduced log goes to stdout, the same bytes.
                     run 0 reduce "$src/replays/lecture/double-wedge-tunnel.scene" -o "$dir/a.scene"
                     run 0 reduce "$src/replays/lecture/double-wedge-tunnel.scene"
                     cmp -s "$dir/out" "$dir/a.scene" || fail "stdout differs from -o's file"
                     grep -q '^ricochet reduce: .*nothing smaller found$' "$dir/err" || fail "no summary line" ;;
  reduce-kernel)     # pinball.scene holds under robust; --kernel lecture-double breaks it, and the reduced log says so.
                     run 2 reduce "$src/replays/pinball.scene" -o "$dir/out.scene"
                     first_line err "$src/replays/pinball.scene: error: every check holds under robust through frame 500: nothing to reduce"
                     [ ! -e "$dir/out.scene" ] || fail "a log was written"
                     run 0 reduce "$src/replays/pinball.scene" --kernel lecture-double -o "$dir/out.scene"
                     grep -qx 'kernel lecture-double' "$dir/out.scene" || fail "the reduced log does not name the kernel"
                     reduced_reproduces "$dir/out.scene" ;;
  reduce-malformed)  printf 'ricochet 1\nwall 0 0 1\n' >"$dir/bad.scene"
                     run 2 reduce "$dir/bad.scene" -o "$dir/out.scene"
                     first_line err "$dir/bad.scene:2:11: error: 'wall' needs X0 Y0 X1 Y1: missing Y1"
                     [ ! -e "$dir/out.scene" ] || fail "a log was written" ;;
  reduce-passing)    run 2 reduce "$log"
                     first_line err "$log: error: every check holds under robust through frame 10: nothing to reduce"
                     [ ! -s "$dir/out" ] || fail "stdout not empty" ;;
  reduce-same-file)  # -o naming the input, as another path, through a symbolic link or a hard link: refused.
                     cp "$src/replays/lecture/double-wedge-tunnel.scene" "$dir/in.scene"
                     ln -s in.scene "$dir/link.scene"; ln "$dir/in.scene" "$dir/hard.scene"
                     for o in "$dir/in.scene" "$dir/./in.scene" "$dir/link.scene" "$dir/hard.scene"; do
                       run 2 reduce "$dir/in.scene" -o "$o"
                       first_line err "ricochet: error: -o $o is the log being reduced; reduce never changes its input"
                     done
                     cmp -s "$src/replays/lecture/double-wedge-tunnel.scene" "$dir/in.scene" || fail "reduce changed its input"
                     [ -L "$dir/link.scene" ] || fail "the link is gone" ;;
  reduce-max-tries)  run 0 reduce "$src/replays/lecture/double-pinball-tunnel.scene" --max-tries 3 -o "$dir/out.scene"
                     grep -q '; 3 tries, [0-9.]* s, stopped at --max-tries 3; wrote ' "$dir/err" || fail "not stopped at 3 tries"
                     reduced_reproduces "$dir/out.scene" no-tunnel
                     run 2 reduce "$log" --max-tries 0
                     first_line err "ricochet: error: --max-tries: '0' is out of range (expected a number of tries from 1 to 4294967295)" ;;
  reduce-max-work)   run 2 reduce "$src/replays/lecture/double-pinball-tunnel.scene" --max-work 5383
                     grep -q "= 5384 is over the bound of 5383" "$dir/err" || fail "no work error"
                     [ ! -s "$dir/out" ] || fail "stdout not empty" ;;
  # --- The project folder: defaults from the nearest folder holding replays/, never the source tree.
  project-here)      mkproj; cd "$proj"; run 0 replay
                     grep -q '^ok   replays/t\.scene: ' "$dir/out" || fail "replay did not read the project's replays/"
                     has out "1 passed, 0 failed" ;;
  project-subfolder) mkproj; cd "$proj/a/b"; run 0 replay
                     grep -q '^ok   \.\./\.\./replays/t\.scene: ' "$dir/out" || fail "replay did not find the project above"
                     has out "1 passed, 0 failed" ;;
  project-build-folder) mkproj; mkdir -p "$proj/build/replays"; : >"$proj/build/CMakeCache.txt"; cd "$proj/build"
                     run 0 replay; grep -q '^ok   \.\./replays/t\.scene: ' "$dir/out" || fail "a build folder was taken for the project" ;;
  project-none)      mkproj; no_project_here; cd "$dir/none"
                     run 2 replay
                     first_line err "ricochet replay: error: no project folder: neither $dir/none nor any folder above it holds replays/; name the logs or folders to replay (ricochet replay PATH...), or set RICOCHET_REPLAY_DIR"
                     [ ! -s "$dir/out" ] || fail "replay printed on stdout"
                     run 2 check --no-properties --fuzz-runs 0
                     first_line err "ricochet check: error: no project folder: neither $dir/none nor any folder above it holds replays/; run it in a project folder or pass --replay-dir DIR, or set RICOCHET_REPLAY_DIR"
                     run 2 fuzz --runs 1 --cache-dir "$dir/cache"
                     first_line err "ricochet fuzz: error: no project folder: neither $dir/none nor any folder above it holds replays/; run it in a project folder or pass --replay-dir DIR, or set RICOCHET_REPLAY_DIR"
                     [ -z "$(ls -A "$dir/none")" ] || fail "something was written in the folder" ;;
  project-env)       mkproj; no_project_here; cd "$dir/none"
                     export RICOCHET_REPLAY_DIR="$proj/replays"; run 0 replay; unset RICOCHET_REPLAY_DIR
                     grep -q "^ok   $proj/replays/t\.scene: " "$dir/out" || fail "RICOCHET_REPLAY_DIR was not read"
                     run 0 check --no-properties --fuzz-runs 0 --replay-dir "$proj/replays"
                     has out "check passed"; grep -q "^pinball     skipped (no $proj/replays/pinball.scene)" "$dir/out" || fail "no pinball line" ;;
  project-check)     mkproj; cd "$proj/a"; run 0 check --no-properties --fuzz-runs 0
                     has out "== replay ../replays"
                     grep -q '^replay      1 passed, 0 failed' "$dir/out" || fail "check did not replay the project's corpus" ;;
  project-fuzz)      mkproj; need_fuzzer scene
                     git -C "$src" rev-parse 2>/dev/null || { echo "skip $case: $src is not a git checkout"; exit 77; }
                     before=$(src_status)
                     cd "$proj/a/b"
                     # Fixed seed and count, no clock: seeds 1-12 fail lecture-double after 413 to 2 351 inputs
                     # (fuzz/lecture_proof_test.sh); the minimization gets as many runs.
                     run 1 fuzz --target scene --kernel lecture-double --runs 5000 --seed 1 --cache-dir "$dir/cache"
                     ls "$proj"/replays/fuzz-scene-*.scene >/dev/null 2>&1 || fail "no failure log saved in the project's replays/"
                     [ "$(src_status)" = "$before" ] || fail "the source tree changed: $(src_status)"
                     [ -z "$(ls -A "$proj/a/b")" ] || fail "something was written in the current folder"
                     run 0 replay "$proj/replays" ;;
  # --- --json: one document on stdout (docs/cli-json.md), the human lines on stderr, the same exit status.
  json-replay-pass)  run 0 replay --json "$log"
                     json_is out 'd["schema"] == "ricochet-replay/1" and d["exit"] == 0 and d["passed"] == 1 and d["failed"] == 0'
                     json_is out 'd["bad_input"] is False and d["errors"] == [] and len(d["logs"]) == 1'
                     json_is out 'd["logs"][0] == {"path": a[0], "status": "passed", "message": a[1], "hash": a[2], "check": None, "frame": None, "ball": None, "line": None, "column": None}' "$log" \
                       "10 frames, hash $("$ricochet" replay --hashes "$log" | cut -c1-16)" "$("$ricochet" replay --hashes "$log" | cut -c1-16)"
                     has err "1 passed, 0 failed" ;;
  json-replay-fail)  run 1 replay --json "$log" "$badlog"
                     json_is out 'd["exit"] == 1 and d["passed"] == 1 and d["failed"] == 1 and [l["status"] for l in d["logs"]] == ["passed", "failed"]'
                     json_is out 'd["logs"][1]["path"] == a[0] and d["logs"][1]["message"].startswith("hash expected 0123456789abcdef, got ")' "$badlog"
                     grep -q "^FAIL $badlog: hash expected 0123456789abcdef, got " "$dir/err" || fail "the FAIL line is not on stderr" ;;
  json-replay-missing) run 2 replay --json "$dir/nope.scene"
                     json_is out 'd["exit"] == 2 and d["bad_input"] and d["logs"][0]["status"] == "missing" and d["logs"][0]["hash"] is None' ;;
  json-replay-escape) q=$dir/$(printf 'q"a\\b\tc\377d'); mkdir "$q"; cp "$log" "$q/t.scene"; run 0 replay --json "$q"
                     # A quote, a backslash, a tab and a byte that is not UTF-8 (written as U+FFFD).
                     json_is out 'd["logs"][0]["path"].endswith("q\"a\\b\tc\ufffdd/t.scene")'
                     grep -q 'q\\"a\\\\b\\tc\\ufffdd/t.scene' "$dir/out" || fail "not escaped as expected" ;;
  json-check)        mkproj; cp "$badlog" "$proj/replays/"; cd "$proj"; run 1 check --json --no-properties --fuzz-runs 0
                     json_is out 'd["schema"] == "ricochet-check/1" and d["passed"] is False and d["exit"] == 1 and d["replay_dir"] == "replays"'
                     json_is out 'd["stages"]["replay"]["status"] == "failed" and d["stages"]["replay"]["passed"] == 1 and d["stages"]["replay"]["failed"] == 1'
                     json_is out 'd["stages"]["pinball"]["status"] == "skipped" and d["stages"]["properties"]["status"] == "skipped" and d["stages"]["fuzz"]["status"] == "skipped"'
                     grep -q '^== replay replays$' "$dir/err" || fail "the stage lines are not on stderr"
                     rm "$proj/replays/bad.scene"; cp "$src/replays/pinball.scene" "$proj/replays/"
                     run 0 check --json --no-properties --fuzz-runs 0
                     json_is out 'd["passed"] is True and d["exit"] == 0 and d["stages"]["pinball"]["status"] == "passed" and d["stages"]["pinball"]["kernels"]["robust"] == "ok"' ;;
  json-fields)       # What a CI step reads without parsing a message: a failure's check, frame and ball, a parse error's place.
                     printf 'ricochet 1\nkernel lecture-double\nframes 10\nwall 0 10 0 0\nwall 0 0 10 0\nwall 10 0 10 10\nwall 10 10 0 10\nwall 0 2 3 0.5\nwall 7 0.5 10 2\nball 8 5 4 1\ncheck no-tunnel\n' >"$dir/t.scene"
                     printf 'ricochet 1\nbogus 1\n' >"$dir/b.scene"
                     run 2 replay --json "$dir/t.scene" "$dir/b.scene" "$src/replays/lecture/double-pinball-tunnel.scene"
                     json_is out '[(l["status"], l["check"], l["frame"], l["ball"], l["line"], l["column"]) for l in d["logs"]][:2] == [("failed", "no-tunnel", 4, 0, None, None), ("unreadable", None, None, None, 2, 1)]'
                     # A log whose expected failure reproduced passes, and says where that failure is.
                     json_is out 'd["logs"][2]["status"] == "passed" and d["logs"][2]["check"] == "no-tunnel" and d["logs"][2]["frame"] == int(a[0])' \
                       "$(sed -n 's/^expect failure no-tunnel \([0-9]*\)$/\1/p' "$src/replays/lecture/double-pinball-tunnel.scene")" ;;
  json-check-properties) # check's properties stage names the failed tests and the logs they saved (a fixed seed and filter).
                     props=$(dirname "$ricochet")/../properties/ricochet_properties
                     [ -x "$props" ] || { echo "skip $case: no property suite in this build"; exit 77; }
                     mkproj; cd "$proj"
                     GTEST_FILTER='*NoTunnelSingleWall*' RICOCHET_KERNEL=lecture-float RC_PARAMS="seed=1 max_success=4000" \
                       run 1 check --json --fuzz-runs 0 --junit "$dir/c.xml" --sarif "$dir/c.sarif"
                     json_is out 'd["stages"]["properties"]["status"] == "failed" and d["stages"]["properties"]["exit"] == 1 and len(d["stages"]["properties"]["failed_properties"]) == 1 and d["stages"]["properties"]["failed_properties"][0].startswith("Kernels/") and d["stages"]["properties"]["failed_properties"][0].endswith(".NoTunnelSingleWall/lecture_float")'
                     set -- "$proj"/replays/NoTunnelSingleWall-*.scene
                     [ "$#" = 1 ] && [ -f "$1" ] || fail "expected one saved log in $proj/replays, found: $*"
                     json_is out 'd["stages"]["properties"]["saved_logs"] == [a[0]]' "$(cd "$proj/replays" && pwd -P)/$(basename "$1")"
                     # The reports: the failed property's case names its saved log, and SARIF points at its found line.
                     junit_valid "$dir/c.xml"; sarif_valid "$dir/c.sarif"
                     xml_is "$dir/c.xml" 'any(c.get("name").startswith("NoTunnelSingleWall/") and c.find("failure") is not None and a[0] in c.find("failure").get("message") for c in d.iter("testcase"))' "$(basename "$1")"
                     json_is c.sarif '[(r["locations"][0]["physicalLocation"]["artifactLocation"]["uri"], r["locations"][0]["physicalLocation"]["region"]["startLine"]) for r in d["runs"][0]["results"]] == [("replays/" + a[0], int(a[1]))]' \
                       "$(basename "$1")" "$(grep -n '^found ' "$1" | cut -d: -f1)" ;;
  json-fuzz)         mkproj; need_fuzzer scene
                     cd "$proj"; run 0 fuzz --json --target scene --runs 20 --seed 1 --cache-dir "$dir/cache"
                     json_is out 'd["schema"] == "ricochet-fuzz/1" and d["exit"] == 0 and d["kernel"] == "robust" and d["runs_per_worker"] == 20 and d["time_s"] is None and d["seed"] == 1'
                     json_is out 'd["replay_dir"] == "replays" and d["new_failures"] == 0 and [t["target"] for t in d["targets"]] == ["scene"] and d["targets"][0]["runs"] >= 20'
                     grep -q '^target ' "$dir/err" || fail "the human summary is not on stderr" ;;
  fuzz-disc)         # The disc target: a campaign against robust, the one kernel here that steps discs.
                     mkproj; need_fuzzer disc
                     cd "$proj"; run 0 fuzz --target disc --runs 20 --seed 1 --jobs 1 --cache-dir "$dir/cache"
                     first_line out "ricochet fuzz: kernel robust, 20 runs per worker, 1 target(s), 1 worker(s)"
                     grep -q '^disc ' "$dir/out" || fail "the summary has no disc row" ;;
  fuzz-jobs)         # --jobs: the workers in all, here two for one target.
                     mkproj; need_fuzzer scene
                     cd "$proj"; run 0 fuzz --target scene --runs 20 --seed 1 --jobs 2 --cache-dir "$dir/cache"
                     first_line out "ricochet fuzz: kernel robust, 20 runs per worker, 1 target(s), 2 worker(s)" ;;
  fuzz-no-merge)     # Two names for the same bytes in the working corpus: the merge keeps one input under its SHA-1
                     # name, --no-merge leaves both as they were.
                     mkproj; need_fuzzer parser
                     cd "$proj"
                     for m in no-merge merge; do
                       c=$dir/cache-$m/parser/robust/corpus; mkdir -p "$c"
                       printf 'ricochet 1\nframes 1\n' >"$c/dup-a"; cp "$c/dup-a" "$c/dup-b"
                     done
                     run 0 fuzz --target parser --runs 1 --seed 1 --jobs 1 --cache-dir "$dir/cache-no-merge" --no-merge
                     run 0 fuzz --target parser --runs 1 --seed 1 --jobs 1 --cache-dir "$dir/cache-merge"
                     [ -f "$dir/cache-no-merge/parser/robust/corpus/dup-a" ] && [ -f "$dir/cache-no-merge/parser/robust/corpus/dup-b" ] ||
                       fail "--no-merge changed the corpus"
                     [ ! -e "$dir/cache-merge/parser/robust/corpus/dup-a" ] && [ ! -e "$dir/cache-merge/parser/robust/corpus/dup-b" ] ||
                       fail "the merge kept the duplicate names"
                     sha=$(printf 'ricochet 1\nframes 1\n' | sha1sum | cut -d' ' -f1)
                     [ -f "$dir/cache-merge/parser/robust/corpus/$sha" ] || fail "the merge did not keep the input as $sha" ;;
  # --- --junit and --sarif: reports CI reads (docs/cli-reports.md), valid against their schemas (docs/schemas/).
  junit-replay)      # A lecture log without its expect failure line fails at its found check; an unreadable log errors.
                     grep -v '^expect failure' "$src/replays/lecture/double-pinball-tunnel.scene" >"$dir/t.scene"
                     printf 'ricochet 1\nbogus 1\n' >"$dir/b.scene"
                     run 2 replay --junit "$dir/r.xml" "$log" "$dir/t.scene" "$dir/b.scene"
                     junit_valid "$dir/r.xml"
                     xml_is "$dir/r.xml" 'd.tag == "testsuites" and [(c.get("name"), c.get("classname")) for c in d.iter("testcase")] == [(p, a[3]) for p in a[:3]]' "$log" "$dir/t.scene" "$dir/b.scene" "$dir"
                     xml_is "$dir/r.xml" 'd.find("testsuite").get("failures") == "1" and d.find("testsuite").get("errors") == "1"'
                     xml_is "$dir/r.xml" 'd.find(".//failure").get("type") == "no-tunnel" and d.find(".//failure").get("message").startswith("no-tunnel broke at frame 4 ball 0: ") and d.find(".//failure").get("message").endswith(" (log " + a[0] + ")")' "$dir/t.scene"
                     xml_is "$dir/r.xml" 'd.find(".//error").get("message").startswith(a[0] + ":2:1: error: ")' "$dir/b.scene"
                     # --json and --junit together: the document on stdout, the report in its file.
                     run 1 replay --json --junit "$dir/r2.xml" "$log" "$dir/t.scene"
                     json_is out 'd["exit"] == 1 and d["failed"] == 1'; junit_valid "$dir/r2.xml" ;;
  junit-sarif-check) # check's reports: a case per log, per pinball kernel, per stage skipped; a SARIF result at the log's line.
                     mkproj; grep -v '^expect failure' "$src/replays/lecture/double-pinball-tunnel.scene" >"$proj/replays/t.scene"
                     cp "$src/replays/pinball.scene" "$proj/replays/"; cd "$proj"
                     run 1 check --no-properties --fuzz-runs 0 --junit "$dir/c.xml" --sarif "$dir/c.sarif"
                     junit_valid "$dir/c.xml"; sarif_valid "$dir/c.sarif"
                     xml_is "$dir/c.xml" '[s.get("name") for s in d] == ["replay", "pinball", "properties", "fuzz"] and [c.get("name") for c in d[1]][:4] == ["lecture-float", "lecture-double", "robust", "exact"]'
                     xml_is "$dir/c.xml" 'd[2].find("testcase/skipped") is not None and d[0].find("testcase/failure") is not None'
                     json_is c.sarif '[(r["ruleId"], r["locations"][0]["physicalLocation"]["artifactLocation"], r["locations"][0]["physicalLocation"]["region"]["startLine"]) for r in d["runs"][0]["results"]] == [("no-tunnel", {"uri": "replays/t.scene", "uriBaseId": "PROJECTROOT"}, int(a[0]))]' \
                       "$(grep -n '^check no-tunnel$' "$proj/replays/t.scene" | cut -d: -f1)"
                     json_is c.sarif 'd["runs"][0]["originalUriBaseIds"]["PROJECTROOT"]["uri"] == "file://" + a[0] + "/" and [r["id"] for r in d["runs"][0]["tool"]["driver"]["rules"]] == ["no-tunnel"]' "$(pwd -P)" ;;
  junit-sarif-fuzz)  # A campaign that saves a failure: its target's case fails naming check, frame, ball and log; SARIF points at the log's found line.
                     mkproj; need_fuzzer disc; cd "$proj"
                     run 1 fuzz --json --target disc --kernel lecture-float --runs 1 --seed 1 --jobs 1 --cache-dir "$dir/cache" --junit "$dir/f.xml" --sarif "$dir/f.sarif"
                     junit_valid "$dir/f.xml"; sarif_valid "$dir/f.sarif"
                     json_is out 'd["exit"] == 1 and d["new_failures"] >= 1'
                     saved=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["failures"][0]["log"])' "$dir/out")
                     [ -f "$saved" ] || fail "no saved log $saved"
                     found=$(sed -n 's/^found \([^ ]*\) \([0-9]*\) \([0-9]*\)$/\1 broke at frame \2 ball \3/p' "$saved")
                     xml_is "$dir/f.xml" '[(c.get("classname"), c.get("name")) for c in d.iter("testcase")] == [("fuzz.lecture-float", "disc")] and d.find(".//failure").get("message").startswith(a[0] + ": ") and ("(log " + a[1] + ")") in d.find(".//failure").get("message")' "$found" "$saved"
                     json_is f.sarif 'd["runs"][0]["results"][0]["locations"][0]["physicalLocation"]["artifactLocation"]["uri"] == a[0] and d["runs"][0]["results"][0]["locations"][0]["physicalLocation"]["region"]["startLine"] == int(a[1])' \
                       "$saved" "$(grep -n '^found ' "$saved" | cut -d: -f1)" ;;
  report-bad-path)   # A report that cannot be written is refused before any work, naming the file; nothing is left.
                     mkproj; cd "$proj"
                     run 2 replay --junit "$dir/no/r.xml" "$log"; first_line err "ricochet: error: cannot write $dir/no/r.xml: no such folder: $dir/no"
                     [ ! -s "$dir/out" ] || fail "replay ran"
                     run 2 check --no-properties --fuzz-runs 0 --sarif "$dir"; first_line err "ricochet: error: cannot write $dir: it is a folder"
                     run 2 fuzz --runs 1 --cache-dir "$dir/cache" --junit "$dir/no/f.xml"; first_line err "ricochet: error: cannot write $dir/no/f.xml: no such folder: $dir/no"
                     [ ! -e "$dir/cache" ] || fail "fuzz made its cache"
                     run 2 replay --junit; first_line err "ricochet: error: --junit: 1 required FILE missing"
                     # A write that fails at the end (a full device) says so, and the exit status is 2.
                     if [ -w /dev/full ]; then run 2 replay --junit /dev/full "$log"
                       grep -q '^ricochet: error: cannot write /dev/full: .*No space left on device' "$dir/err" || fail "no write error"; fi ;;
  junit-properties)  # The property suite's own JUnit (GoogleTest's --gtest_output=xml), a tiny filtered run.
                     props=$(dirname "$ricochet")/../properties/ricochet_properties
                     [ -x "$props" ] || { echo "skip $case: no property suite in this build"; exit 77; }
                     mkproj; cd "$proj"
                     RC_PARAMS="seed=1 max_success=20" RICOCHET_REPLAY_DIR="$proj/replays" "$props" --gtest_filter='*NoTunnelSingleWall*robust*' \
                       --gtest_output="xml:$dir/p.xml" >"$dir/out" 2>"$dir/err" || fail "the filtered property run failed"
                     junit_properties "$dir/p.xml" ;;
  # --- SIGINT and SIGTERM: stop at the next frame or log boundary, say what was done, exit 128 + signal.
  stop-run)          stop_after_first_line INT run "$long" --max-work 0
                     [ "$rc" = 130 ] || fail "exit $rc after SIGINT, expected 130"
                     frame=$(sed -n 's/^ricochet run: stopped by SIGINT after frame \([0-9]*\) of 10000000$/\1/p' "$dir/err")
                     [ -n "$frame" ] || fail "no 'stopped by SIGINT after frame F' line"
                     # Whole frames: frame 0 and 1..F, 200 state lines each (and hit lines), nothing after.
                     [ "$(grep -c '^state ' "$dir/out")" = $(( (frame + 1) * 200 )) ] || fail "not $((frame + 1)) whole frames of output"
                     [ "$(tail -n 1 "$dir/out" | cut -d' ' -f1-3)" = "state $frame 199" ] || fail "the last line is not frame $frame's last ball"
                     [ "$(ls -A "$dir" | sort | tr '\n' ' ')" = "bad.scene big.scene err long.scene out tiny.scene " ] ||
                       fail "files left: $(ls -A "$dir")" ;;
  stop-run-term)     stop_after_first_line TERM run "$long" --max-work 0
                     [ "$rc" = 143 ] || fail "exit $rc after SIGTERM, expected 143"
                     grep -q '^ricochet run: stopped by SIGTERM after frame [0-9]* of 10000000$' "$dir/err" || fail "no stopped line" ;;
  stop-replay)       mkdir "$dir/many"
                     # 301 logs of 2 000 frames × 200 balls: minutes of work.
                     sed 's/^frames 10000000$/frames 2000/' "$long" >"$dir/many/a.scene"
                     i=0; while [ $i -lt 300 ]; do ln "$dir/many/a.scene" "$dir/many/l$i.scene"; i=$((i + 1)); done
                     stop_after_first_line INT replay "$dir/many"
                     [ "$rc" = 130 ] || fail "exit $rc after SIGINT, expected 130"
                     n=$(sed -n 's/^ricochet replay: stopped by SIGINT after \([0-9]*\) of 301 logs$/\1/p' "$dir/err")
                     [ -n "$n" ] || fail "no 'stopped by SIGINT after N of 301 logs' line"
                     [ "$(grep -c '^ok   ' "$dir/out")" = "$n" ] || fail "not $n verdict lines"
                     [ "$(tail -n 1 "$dir/out")" = "$n passed, 0 failed" ] || fail "the summary is not '$n passed, 0 failed'" ;;
  stop-replay-json)  mkdir "$dir/many"; sed 's/^frames 10000000$/frames 2000/' "$long" >"$dir/many/a.scene"
                     i=0; while [ $i -lt 300 ]; do ln "$dir/many/a.scene" "$dir/many/l$i.scene"; i=$((i + 1)); done
                     # Under --json the verdict lines go to stderr: wait on a copy of replay's stdout there.
                     "$ricochet" replay --json --junit "$dir/many.xml" "$dir/many" >"$dir/json" 2>"$dir/out" & pid=$!
                     while ! grep -q '^ok ' "$dir/out"; do kill -0 "$pid" 2>/dev/null || fail "replay ended early"; sleep 0.02; done
                     kill -INT "$pid"; wait "$pid"; rc=$?; mv "$dir/json" "$dir/out"
                     [ "$rc" = 130 ] || fail "exit $rc after SIGINT, expected 130"
                     json_is out 'd["exit"] == 130 and d["stopped"] is True and d["total"] == 301 and 1 <= d["passed"] == len(d["logs"]) < 301'
                     # The report of a stopped replay is whole: the logs it ran, valid JUnit, and no temporary file left.
                     junit_valid "$dir/many.xml"
                     xml_is "$dir/many.xml" 'd.get("tests") == a[0]' "$(python3 -c 'import json, sys; print(len(json.load(open(sys.argv[1]))["logs"]))' "$dir/out")"
                     [ -z "$(ls -A "$dir" | grep '\.tmp\.')" ] || fail "a temporary file is left" ;;
  stop-check)        mkproj; sed 's/^frames 10000000$/frames 2000/' "$long" >"$proj/replays/a.scene"
                     i=0; while [ $i -lt 300 ]; do ln "$proj/replays/a.scene" "$proj/replays/l$i.scene"; i=$((i + 1)); done
                     cd "$proj"; stop_after_first_line INT check --no-properties --fuzz-runs 0
                     [ "$rc" = 130 ] || fail "exit $rc after SIGINT, expected 130"
                     has out "check stopped by SIGINT"; has out "== summary"
                     ! grep -q '^== lecture pinball' "$dir/out" || fail "check went on to the next stage"
                     grep -q '^ricochet replay: stopped by SIGINT after [0-9]* of 302 logs$' "$dir/err" || fail "no stopped line" ;;
  stop-replay-frame) # One log of hours: stopped between two of its frames, not at its end.
                     stop_when_running INT replay "$long" --max-work 0
                     [ "$rc" = 130 ] || fail "exit $rc after SIGINT, expected 130"
                     grep -q "^ricochet replay: stopped by SIGINT in $long after frame [0-9]* of 10000000\$" "$dir/err" ||
                       fail "no 'stopped by SIGINT in LOG after frame F' line"
                     has err "ricochet replay: stopped by SIGINT after 0 of 1 logs"
                     has out "0 passed, 0 failed" ;;
  stop-replay-frame-json) stop_when_running TERM replay --json "$long" --max-work 0
                     [ "$rc" = 143 ] || fail "exit $rc after SIGTERM, expected 143"
                     json_is out 'd["exit"] == 143 and d["stopped"] is True and d["logs"] == [] and d["stopped_at"]["path"] == a[0] and d["stopped_at"]["frames"] == 10000000 and 0 <= d["stopped_at"]["frame"] < 10000000' "$long" ;;
  stop-render)       # render draws nothing before its run ends: no picture and no temporary may be left.
                     stop_when_running INT render "$long" -o "$dir/x.svg" --max-work 0
                     [ "$rc" = 130 ] || fail "exit $rc after SIGINT, expected 130"
                     has err "ricochet render: nothing written; stopped by SIGINT"
                     [ -z "$(ls -A "$dir" | grep -v -e '^out$' -e '^err$' -e '\.scene$')" ] ||
                       fail "render left: $(ls -A "$dir")" ;;
  stop-record)       cp "$long" "$dir/r.scene"
                     # record prints nothing before its write: stopped during its run, the log must be unchanged.
                     stop_when_running INT record "$dir/r.scene" --max-work 0
                     [ "$rc" = 130 ] || fail "exit $rc after SIGINT, expected 130"
                     has err "ricochet record: the log is unchanged; stopped by SIGINT"
                     cmp -s "$long" "$dir/r.scene" || fail "record changed the log"
                     [ -z "$(ls -A "$dir" | grep '\.tmp\.')" ] || fail "a temporary file is left" ;;
  stop-reduce)       # A closed chain of 10^4 walls (harness/tests/ring_log) under no-escape: every wall is needed, so the
                     # reduction would run its 20 000 tries (tens of seconds); stopped, it writes what it has.
                     ring=$(dirname "$ricochet")/../harness/tests/ring_log
                     [ -x "$ring" ] || { echo "skip $case: no $ring"; exit 77; }
                     "$ring" 10000 lecture-float 3000 | sed 's/^check no-tunnel$/check no-escape/' >"$dir/ring.scene"
                     cp "$dir/ring.scene" "$dir/in.scene"
                     stop_when_running INT reduce "$dir/in.scene" -o "$dir/small.scene"
                     [ "$rc" = 130 ] || fail "exit $rc after SIGINT, expected 130"
                     grep -q '^ricochet reduce: 10000 walls, .*, stopped by SIGINT; wrote ' "$dir/err" || fail "no stopped summary"
                     cmp -s "$dir/ring.scene" "$dir/in.scene" || fail "reduce changed its input"
                     [ -z "$(ls -A "$dir" | grep '\.tmp\.')" ] || fail "a temporary file is left"
                     reduced_reproduces "$dir/small.scene" no-escape ;;
  stop-fuzz-stuck)   mkproj; mkdir "$dir/bin"
                     # A worker that never ends on SIGINT or SIGTERM (as a libFuzzer deadlocked in its
                     # interrupt handler would): the campaign kills it k_stop_grace_s (10 s) after passing the
                     # signal on, and still ends as a stopped campaign.
                     # It says when it runs: a signal before the campaign has started it would find no worker to kill.
                     printf '#!/bin/sh\ncase "$1" in -help=1) echo "Usage: fake"; exit 0;; esac\ntrap "" INT TERM\n: > "%s/started"\nwhile :; do sleep 1; done\n' "$dir" >"$dir/bin/fuzz_scene"
                     chmod +x "$dir/bin/fuzz_scene"; cd "$proj"
                     stop_once '[ -e "$dir/started" ]' INT fuzz --target scene --time 604800 --seed 1 --cache-dir "$dir/cache" --bin-dir "$dir/bin"
                     [ "$rc" = 130 ] || fail "exit $rc after SIGINT, expected 130"
                     grep -q 'scene worker 0 did not stop within 10 s of SIGINT: killed' "$dir/out" || fail "the stuck worker was not killed"
                     grep -q 'stopped by SIGINT (exit 130)$' "$dir/out" || fail "the summary does not say it was stopped" ;;
  stop-fuzz)         mkproj; need_fuzzer scene
                     cd "$proj"
                     # A campaign of a week, stopped once it has started: the header is its first line.
                     stop_after_first_line INT fuzz --target scene --time 604800 --seed 1 --cache-dir "$dir/cache"
                     [ "$rc" = 130 ] || fail "exit $rc after SIGINT, expected 130"
                     grep -q 'stopped by SIGINT (exit 130)$' "$dir/out" || fail "the summary does not say it was stopped"
                     [ -d "$dir/cache/scene/robust/corpus" ] || fail "the corpus folder is gone"
                     [ -z "$(ls -A "$dir/cache/runs")" ] || fail "the campaign's own folder is left: $(ls -A "$dir/cache/runs")"
                     ! grep -q 'stopped early' "$dir/out" || fail "stopped workers reported as stopped early" ;;
  *) echo "unknown case $case" >&2; exit 1 ;;
esac
echo "ok $case"
