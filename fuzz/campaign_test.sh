#!/bin/sh
# `ricochet fuzz` and `ricochet fuzz convert`, one behaviour per call: the time budget, failures a stopped or
# timed campaign leaves for the next, the binaries' own words when they refuse to start, reproducible
# campaigns, the --json document's failures, bad folders, a build without tests. Fixed seeds and run counts
# decide every verdict; the one case by time (time-budget) checks what holds whatever the machine's load.
# Everything goes into a mktemp folder.
#   campaign_test.sh RICOCHET CASE [CXX]
#   campaign_test.sh --cases     prints every case
set -u
if [ "$1" = --cases ]; then sed -n 's/^  \([a-z][a-z0-9-]*\)) .*/\1/p' "$0"; exit 0; fi
ricochet=$1 case=$2 cxx=${3:-c++}
src=$(cd "$(dirname "$0")/.." && pwd)
bins=$(cd "$(dirname "$ricochet")/../fuzz" && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
unset RICOCHET_REPLAY_DIR RICOCHET_FUZZ_CACHE RICOCHET_FUZZ_BIN_DIR RICOCHET_KERNEL

fail() { echo "FAIL $case: $*"; for f in out err; do [ -f "$dir/$f" ] && { echo "--- std$f:"; cat "$dir/$f"; }; done; exit 1; }
# run RC ARGS...: ricochet with stdout in $dir/out and stderr in $dir/err; its exit status must be RC.
run() {
  want_rc=$1; shift
  "$ricochet" "$@" >"$dir/out" 2>"$dir/err"
  rc=$?
  [ "$rc" = "$want_rc" ] || fail "ricochet $*: exit $rc, expected $want_rc"
}
has() { grep -qF -- "$2" "$dir/$1" || fail "std$1 lacks: $2"; }
lacks() { ! grep -qF -- "$2" "$dir/$1" || fail "std$1 has: $2"; }
# need_fuzzer TARGET: skip unless this build has the libFuzzer binary fuzz_TARGET (clang, RICOCHET_FUZZ on).
need_fuzzer() { "$bins/fuzz_$1" -help=1 2>&1 | grep -q '^Usage:' || { echo "skip $case: no libFuzzer fuzz_$1"; exit 77; }; }
# json_is FILE EXPRESSION: FILE is one JSON document and the Python expression over it as d holds.
json_is() {
  python3 -c 'import json, os, sys
d = json.load(open(sys.argv[1]))
sys.exit(0 if eval(sys.argv[2]) else 1)' "$dir/$1" "$2" 2>"$dir/py" || fail "std$1 is not JSON where $2: $(cat "$dir/py")"
}
# A project folder with an empty replays/.
proj=$dir/proj
mkdir -p "$proj/replays"
# A fake fuzz binary: FAKE NAME SCRIPT-BODY writes $dir/bin/fuzz_NAME.
fake() { mkdir -p "$dir/bin"; printf '#!/bin/sh\n%s\n' "$2" >"$dir/bin/fuzz_$1"; chmod +x "$dir/bin/fuzz_$1"; }
# found LOG: the check, frame and ball of LOG's `found` line.
found() { sed -n 's/^found \([^ ]*\) \([0-9]*\) \([0-9]*\)$/\1 \2 \3/p' "$1"; }

case "$case" in
  replay-dir-file)   # A replay "folder" that is a file: refused before anything is made.
                     : >"$dir/file"
                     cd "$proj"; run 2 fuzz --runs 1 --replay-dir "$dir/file" --cache-dir "$dir/cache"
                     has err "ricochet fuzz: error: --replay-dir $dir/file: not a folder"
                     [ ! -e "$dir/cache" ] || fail "the cache folder was made"
                     [ ! -s "$dir/file" ] || fail "the file was written"
                     RICOCHET_REPLAY_DIR=$dir/file run 2 fuzz convert --replay-dir "$dir/file" --target scene "$dir/file"
                     has err "ricochet fuzz convert: error: --replay-dir $dir/file: not a folder"
                     RICOCHET_REPLAY_DIR=$dir/file run 2 fuzz --runs 1 --cache-dir "$dir/cache"
                     has err "ricochet fuzz: error: \$RICOCHET_REPLAY_DIR $dir/file: not a folder" ;;
  runs-with-time)    # A campaign is by count or by clock: both is a usage error, nothing run.
                     cd "$proj"; run 2 fuzz --runs 5 --time 5 --cache-dir "$dir/cache"
                     has err "ricochet fuzz: error: --runs and --time exclude each other"
                     [ ! -e "$dir/cache" ] || fail "the cache folder was made" ;;
  probe-refused)     # A binary that refuses to start says why; the campaign repeats its words, not "build with clang".
                     fake scene 'echo "fuzz_scene: error: kernel '"'mine'"' steps point balls only" >&2; exit 2'
                     cd "$proj"; run 2 fuzz --target scene --runs 1 --cache-dir "$dir/cache" --bin-dir "$dir/bin"
                     has err "fuzz_scene -help=1 (RICOCHET_KERNEL=robust) ended with exit 2 instead of printing libFuzzer's usage"
                     has err "fuzz_scene: error: kernel 'mine' steps point balls only"
                     lacks err "not a libFuzzer binary"
                     lacks err "build them with clang" ;;
  probe-own-kernel)  # The binaries are asked under the campaign's kernel, not the caller's RICOCHET_KERNEL: fuzz_disc asks
                     # its kernel first thing, and would refuse one it does not know.
                     need_fuzzer disc
                     cd "$proj"; RICOCHET_KERNEL=no-such-kernel run 0 fuzz --target disc --runs 1 --seed 1 --cache-dir "$dir/cache"
                     lacks err "not a libFuzzer binary"
                     has out "ricochet fuzz: kernel robust, 1 runs per worker" ;;
  cache-unwritable)  # A cache where nothing can be written (no byte may be written: ulimit -f 0, SIGXFSZ ignored, as on a
                     # full disk, without root and without a mount): the campaign says so, not "not a libFuzzer binary".
                     fake scene 'echo "Usage: fake"'
                     cd "$proj"
                     { ( ulimit -f 0; trap '' XFSZ; "$ricochet" fuzz --target scene --runs 1 --cache-dir "$dir/cache" --bin-dir "$dir/bin"
                         echo "exit $?" ) 2>&1; } | cat >"$dir/err"
                     has err "exit 2"
                     has err "ricochet fuzz: error: cannot write in the cache folder $dir/cache: File too large"
                     lacks err "not a libFuzzer binary"
                     [ -z "$(ls -A "$dir/cache/runs")" ] || fail "its own folder is left: $(ls -A "$dir/cache/runs")" ;;
  rates-own-time)    # The closing table's exec/s is each worker's runs over its own running time, not the campaign's. Two
                     # fake targets print 1000 runs each; sweep (started first) ends only after static's process is gone
                     # (reaped: a zombie still answers kill -0), so sweep ran strictly longer, whatever the load. Over the
                     # campaign's time both showed the same rate.
                     stats='printf "#1000\tDONE   cov: 1 ft: 1 corp: 1/1b exec/s: 0 rss: 1Mb\nstat::number_of_executed_units: 1000\n"'
                     fake static 'case "$1" in -help=1) echo "Usage: fake"; exit 0 ;; esac
echo $$ >"'"$dir"'/static.pid"; '"$stats"
                     fake sweep 'case "$1" in -help=1) echo "Usage: fake"; exit 0 ;; esac
until [ -s "'"$dir"'/static.pid" ]; do sleep 0.05; done
while kill -0 "$(cat "'"$dir"'/static.pid")" 2>/dev/null; do sleep 0.05; done; '"$stats"
                     cd "$proj"; run 0 fuzz --json --target sweep static --runs 1000 --seed 1 --no-merge --cache-dir "$dir/cache" --bin-dir "$dir/bin"
                     json_is out '[(t["target"], t["workers"], t["runs"]) for t in d["targets"]] == [("sweep", 1, 1000), ("static", 1, 1000)]'
                     json_is out 'd["targets"][1]["exec_per_s_per_worker"] > d["targets"][0]["exec_per_s_per_worker"] > 0'
                     # One worker each: its rate in all is its rate; the campaign's is theirs summed; each worker ran
                     # within the campaign's fuzzing time.
                     json_is out 'all(t["exec_per_s"] == t["exec_per_s_per_worker"] and t["runs"] / t["exec_per_s"] <= d["seconds"] for t in d["targets"])'
                     json_is out 'abs(d["exec_per_s"] - sum(t["exec_per_s"] for t in d["targets"])) <= 1e-9 * d["exec_per_s"]' ;;
  merge-writes-in-cache) # What libFuzzer's merge writes (an input that ran out of memory in the one merge process) goes
                     # into the campaign's own folder (removed with it), never into the folder the campaign was started
                     # from. The fake writes such a file where -artifact_prefix says, as libFuzzer does (by default ./).
                     stats='printf "#1000\tDONE   cov: 1 ft: 1 corp: 1/1b exec/s: 0 rss: 1Mb\nstat::number_of_executed_units: 1000\n"'
                     fake static 'case "$1" in -help=1) echo "Usage: fake"; exit 0 ;; esac
p=./; m=; for a in "$@"; do case "$a" in -artifact_prefix=*) p=${a#-artifact_prefix=} ;; -merge=1) m=1 ;; esac; done
if [ -n "$m" ]; then printf big >"${p}oom-0123456789abcdef0123456789abcdef01234567"; exit 0; fi
'"$stats"
                     cd "$proj"; run 0 fuzz --target static --runs 1000 --seed 1 --cache-dir "$dir/cache" --bin-dir "$dir/bin"
                     [ "$(ls -A "$proj")" = replays ] || fail "the campaign wrote in the folder it was started from: $(ls -A "$proj")" ;;
  slow-unit-progress) # A slow unit a worker saves is kept as an input, not a failure: the progress lines count the failures
                     # the closing table counts. The fake worker saves one, then waits for the first progress line.
                     stats='printf "#1000\tDONE   cov: 1 ft: 1 corp: 1/1b exec/s: 0 rss: 1Mb\nstat::number_of_executed_units: 1000\n"'
                     fake static 'case "$1" in -help=1) echo "Usage: fake"; exit 0 ;; esac
for a in "$@"; do case "$a" in -artifact_prefix=*) p=${a#-artifact_prefix=} ;; esac; done
printf slow >"${p}slow-unit-0123456789abcdef0123456789abcdef01234567"
n=0; until grep -q "failures" "'"$dir"'/out" || [ $n -ge 1200 ]; do sleep 0.05; n=$((n + 1)); done; '"$stats"
                     cd "$proj"; run 0 fuzz --target static --runs 1000 --seed 1 --no-merge --cache-dir "$dir/cache" --bin-dir "$dir/bin"
                     has out "static  exec/s"
                     has out "failures 0"
                     lacks out "failures 1" ;;
  stop-keeps-failures) # Stopped after a worker saved a failure artifact, before the tail: the table and the JSON say the
                     # failure, it waits in pending/, and the next campaign on the cache converts it.
                     need_fuzzer disc
                     cd "$proj"
                     "$ricochet" fuzz --json --target disc --kernel lecture-float --time 604800 --seed 1 --jobs 1 \
                       --cache-dir "$dir/cache" >"$dir/out" 2>"$dir/err" &
                     pid=$!
                     # lecture-float's speed check fails on the first input: wait for the worker's artifact.
                     while ! ls "$dir"/cache/runs/*/disc/artifacts/crash-* >/dev/null 2>&1; do
                       kill -0 $pid 2>/dev/null || fail "the campaign ended before it found a failure"; sleep 0.05
                     done
                     kill -INT $pid; wait $pid; rc=$?
                     [ "$rc" = 130 ] || fail "exit $rc after SIGINT, expected 130"
                     grep -qE '^disc +[0-9]+ +[^ ]+ +[0-9]+ +[0-9]+ +0 +0 +[1-9][0-9]*$' "$dir/err" || fail "the table does not count the pending failure"
                     has err "NEW FAILURES (some not converted yet); stopped by SIGINT (exit 130)"
                     has err "left for the next campaign on this cache: "
                     lacks err "no new failures"
                     json_is out 'd["stopped"] and d["exit"] == 130 and d["pending_failures"] >= 1 and d["targets"][0]["pending_failures"] == d["pending_failures"]'
                     json_is out 'all(f["status"] == "pending" and f["new"] and os.path.isfile(f["artifact"]) and "/disc/lecture-float/pending/" in f["artifact"] for f in d["failures"]) and len(d["failures"]) == d["pending_failures"]'
                     first=$(ls "$dir/cache/disc/lecture-float/pending" | head -n 1)
                     # The next campaign converts what waits, first thing in its tail.
                     run 1 fuzz --json --target disc --kernel lecture-float --runs 1 --seed 1 --jobs 1 --cache-dir "$dir/cache"
                     has err "left by earlier campaigns"
                     [ ! -e "$dir/cache/disc/lecture-float/pending/$first" ] || fail "$first still waits"
                     [ -f "$dir/cache/disc/lecture-float/artifacts/$first" ] || fail "$first is not kept with the converted artifacts"
                     json_is out 'any(f["artifact"].endswith("/'"$first"'") and f["status"] in ("saved", "known", "duplicate") for f in d["failures"])'
                     ls "$proj"/replays/fuzz-disc-*.scene >/dev/null 2>&1 || fail "no log saved" ;;
  convert)           # An artifact turned into a scene log on demand: in a cache's pending/ folder its place names the
                     # target and kernel; elsewhere --target and --kernel do.
                     need_fuzzer disc
                     mkdir -p "$dir/art" "$dir/cache/disc/lecture-float/pending" "$dir/cache/disc/lecture-float/artifacts"
                     RICOCHET_KERNEL=lecture-float "$bins/fuzz_disc" -runs=10 -seed=1 -artifact_prefix="$dir/art/" >"$dir/raw" 2>&1
                     a=$(ls "$dir"/art/crash-* 2>/dev/null | head -n 1)
                     [ -n "$a" ] || fail "fuzz_disc under lecture-float left no artifact: $(tail -n 5 "$dir/raw")"
                     cd "$proj"
                     run 2 fuzz convert "$a" --cache-dir "$dir/cache"
                     has err "which target is it for?"
                     run 0 fuzz convert "$a" --target disc --kernel lecture-float --cache-dir "$dir/cache" --replay-dir "$dir/logs" --bin-dir "$bins"
                     log=$(ls "$dir"/logs/fuzz-disc-*.scene | head -n 1)
                     [ -n "$log" ] && grep -q '^expect failure ' "$log" || fail "no failure log saved"
                     has out "$a: saved $log"
                     [ -f "$a" ] || fail "the artifact given was moved"
                     "$ricochet" replay "$log" >"$dir/r" 2>&1 || fail "the log does not reproduce: $(cat "$dir/r")"
                     # The same artifact from pending/: target and kernel from its place; the case is known now; it
                     # leaves pending/ for artifacts/.
                     cp "$a" "$dir/cache/disc/lecture-float/pending/"
                     p=$dir/cache/disc/lecture-float/pending/$(basename "$a")
                     run 0 fuzz convert "$p" --cache-dir "$dir/cache" --replay-dir "$dir/logs"
                     has out "$p: known $log"
                     [ ! -e "$p" ] && [ -f "$dir/cache/disc/lecture-float/artifacts/$(basename "$a")" ] || fail "it did not leave pending/"
                     run 2 fuzz convert "$dir/art" --target disc
                     has err "$dir/art: not a file" ;;
  json-failures)     # Each failure in the --json document with its fields: target, kernel, check, frame, ball, the log.
                     need_fuzzer disc
                     cd "$proj"; run 1 fuzz --json --target disc --kernel lecture-float --runs 1 --seed 1 --jobs 1 --cache-dir "$dir/cache"
                     json_is out 'len(d["failures"]) == 1 and d["new_failures"] == 1 and d["pending_failures"] == 0'
                     json_is out '[(f["target"], f["kernel"], f["status"], f["new"]) for f in d["failures"]] == [("disc", "lecture-float", "saved", True)]'
                     log=$(ls "$proj"/replays/fuzz-disc-*.scene)
                     set -- $(found "$log")
                     [ $# = 3 ] || fail "$log has no found line"
                     json_is out 'd["failures"][0]["check"] == "'"$1"'" and d["failures"][0]["frame"] == '"$2"' and d["failures"][0]["ball"] == '"$3"
                     json_is out 'os.path.samefile(d["failures"][0]["log"], "'"$log"'") and d["failures"][0]["message"].startswith("==ricochet-fuzz== FAILURE target=disc")'
                     json_is out 'os.path.isfile(d["failures"][0]["artifact"]) and "/disc/lecture-float/artifacts/" in d["failures"][0]["artifact"]' ;;
  time-budget)       # --time bounds the whole command: the tail's steps are said as they go, the table's time is the
                     # command's own, and whatever the tail could not do is said and kept. What gets done in 8 s depends on
                     # the machine's load; what is checked here holds whatever it is.
                     need_fuzzer disc
                     cd "$proj"
                     t0=$(date +%s.%N)
                     "$ricochet" fuzz --json --target disc --kernel lecture-float --time 8 --seed 1 --jobs 1 --cache-dir "$dir/cache" \
                       >"$dir/out" 2>"$dir/err"
                     rc=$?
                     t1=$(date +%s.%N)
                     [ "$rc" = 1 ] || fail "exit $rc, expected 1 (lecture-float fails on the first input)"
                     has err "s in all (fuzzing until 6 s, then converting failures and merging corpora)"
                     has err "fuzzing done; converting failures, then merging the corpora"
                     # The table's time is the command's: no more than measured from outside, and short of it by no more
                     # than its start and exit (3 s, generous).
                     json_is out 'd["time_s"] == 8 and d["seconds"] <= d["wall_seconds"] <= '"$t1"' - '"$t0"' and d["wall_seconds"] >= '"$t1"' - '"$t0"' - 3'
                     s=$(python3 -c 'import json,sys; print(round(json.load(open(sys.argv[1]))["wall_seconds"]))' "$dir/out")
                     grep -q "^kernel lecture-float, $s s (" "$dir/err" || fail "the table's time is not $s s"
                     # Within a generous margin of the budget: the deadline kills what runs past it.
                     json_is out 'd["wall_seconds"] <= d["time_s"] + 20'
                     # Every failure is accounted for: converted (its steps said) or waiting in pending/ (and said so).
                     json_is out 'd["pending_failures"] == len([f for f in d["failures"] if f["status"] == "pending"]) == len(os.listdir("'"$dir"'/cache/disc/lecture-float/pending"))'
                     python3 -c 'import json, os, sys
d = json.load(open(sys.argv[1])); err = open(sys.argv[2]).read()
for f in d["failures"]:
    name = os.path.basename(f["artifact"])
    if f["status"] != "pending" and name + ": running it again" not in err: sys.exit("no progress line for " + name)
for t in d["targets"]:
    if t["merge"] == "done" and "merging the corpus" not in err: sys.exit("no progress line for the merge")
if bool(d["pending_failures"] or d["unmerged"]) != ("left for the next campaign on this cache:" in err): sys.exit("leftovers not said")
' "$dir/out" "$dir/err" 2>"$dir/py" || fail "$(cat "$dir/py")" ;;
  reproducible-coverage) # The same inputs cover the same edges on every run (ASLR moved UBSan's vptr cache: 2813 to 2823).
                     need_fuzzer scene
                     for i in 1 2 3; do
                       RICOCHET_KERNEL=robust "$bins/fuzz_scene" -seed=1 -runs=0 "$src/fuzz/corpus/scene" 2>&1 | grep INITED | cut -d' ' -f1-7 >>"$dir/inited"
                     done
                     [ "$(sort -u "$dir/inited" | wc -l)" = 1 ] || fail "three runs over the same inputs: $(cat "$dir/inited")" ;;
  reproducible-campaign) # --runs and --seed: on fresh caches, the same runs, coverage, corpus and saved log, twice. The
                     # parser's 10 000 inputs are where comparison tracing of addresses made runs part (after 2 596 and
                     # 5 499 inputs); the lecture-float campaign fails after 444 inputs (this build), and minimizing
                     # takes most of its time.
                     need_fuzzer scene && need_fuzzer parser
                     cd "$proj"
                     for i in 1 2; do
                       mkdir "$dir/logs$i"
                       run 0 fuzz --json --target scene --runs 300 --seed 1 --jobs 1 --cache-dir "$dir/cache$i" --replay-dir "$dir/logs$i"
                       mv "$dir/out" "$dir/robust$i"
                       run 0 fuzz --json --target parser --runs 10000 --seed 1 --jobs 1 --cache-dir "$dir/cache$i" --replay-dir "$dir/logs$i"
                       mv "$dir/out" "$dir/parser$i"
                       run 1 fuzz --json --target scene --kernel lecture-float --runs 1000 --seed 1 --jobs 1 --cache-dir "$dir/cache$i" \
                         --replay-dir "$dir/logs$i"
                       python3 -c 'import json, sys
for f in sys.argv[1:]:
    print([(t["target"], t["runs"], t["cov"], t["corpus"], t["new_failures"]) for t in json.load(open(f))["targets"]])' \
                         "$dir/robust$i" "$dir/parser$i" "$dir/out" >"$dir/table$i"
                       (cd "$dir/cache$i" && ls scene/robust/corpus parser/robust/corpus scene/lecture-float/corpus) >"$dir/corpus$i"
                     done
                     cmp -s "$dir/table1" "$dir/table2" || fail "different tables: $(cat "$dir/table1" "$dir/table2")"
                     cmp -s "$dir/corpus1" "$dir/corpus2" || fail "different corpora: $(diff "$dir/corpus1" "$dir/corpus2" | head)"
                     [ -n "$(ls "$dir/logs1")" ] || fail "no log saved"
                     diff -r "$dir/logs1" "$dir/logs2" >"$dir/d" || fail "different logs: $(head -n 20 "$dir/d")" ;;
  minimal-build)     # A build without tests and without libFuzzer builds neither the standalone fuzz targets nor what only
                     # they use, but still the campaign (part of the command); the targets stay buildable by name.
                     CXX=$cxx cmake -S "$src" -B "$dir/b" -G Ninja -DRICOCHET_TESTS=OFF -DRICOCHET_FUZZ=OFF -DRICOCHET_BENCH=OFF \
                       >"$dir/out" 2>"$dir/err" || fail "configure failed"
                     ninja -C "$dir/b" -t commands all >"$dir/all" 2>&1 || fail "ninja -t commands all failed"
                     for t in fuzz_parser fuzz_static fuzz_sweep fuzz_scene fuzz_disc grammar_agreement ricochet_fuzz_common ricochet_grammar; do
                       ! grep -qE -- "-o fuzz/(CMakeFiles/)?(lib)?$t[ ./]" "$dir/all" || fail "$t is built by default"
                     done
                     grep -qF -- "-o fuzz/CMakeFiles/ricochet_fuzz_campaign.dir/campaign/campaign.cpp.o" "$dir/all" || fail "the campaign is not built"
                     ninja -C "$dir/b" -t targets all 2>/dev/null | grep -q '^fuzz_scene: phony' || fail "fuzz_scene is not a target"
                     ! ctest --test-dir "$dir/b" -N | grep -q 'fuzz_.*_regression' || fail "regression tests without their binaries" ;;
  *) echo "unknown case $case" >&2; exit 1 ;;
esac
echo "ok $case"
