#!/bin/sh
# `bench`'s flags and edges (bench/src/bench.cpp, ricochet_bench/result_file.hpp, scale/), one case per call:
# progress while it runs, result files whole or absent after Ctrl-C, a clear error when one cannot be written,
# what --seed, --quick, --smoke and the frames and scale subcommands print and write.
#   bench_cli_test.sh BENCH CASE      BENCH: a program with the `bench` command (ricochet-bench or ricochet)
#   bench_cli_test.sh --cases         prints every case (the case labels below)
set -u
if [ "$1" = --cases ]; then sed -n 's/^  \([a-z][a-z0-9-]*\)) .*/\1/p' "$0"; exit 0; fi
bench=$1 case=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL $case: $*"; for f in out err; do [ -f "$dir/$f" ] && { echo "--- std$f:"; cat "$dir/$f"; }; done; exit 1; }

case "$case" in
  progress)        "$bench" bench --smoke --no-chart --out "$dir/res" >"$dir/out" 2>"$dir/err" || fail "exit $?"
                   # One line per workload as it starts, counted to the last.
                   first=$(grep -m1 '^bench: \[' "$dir/err") || fail "no progress line on stderr"
                   total=$(echo "$first" | sed -n 's|^bench: \[1/\([0-9]*\)\] .*|\1|p')
                   [ -n "$total" ] || fail "the first progress line is not [1/N]: $first"
                   [ "$(grep -c '^bench: \[' "$dir/err")" = "$total" ] || fail "not $total progress lines"
                   grep -q "^bench: \[$total/$total\] " "$dir/err" || fail "no last progress line [$total/$total]"
                   [ -s "$dir/res/bench.csv" ] || fail "no bench.csv" ;;
  stop-stability)  # stability makes its CSV row by row as it goes: stopped once it has started (its table's header
                   # is out; a full run takes seconds), it must leave no CSV, torn or whole, and no temporary.
                   # SIGTERM: sh starts a background job with SIGINT ignored, and bench keeps the default actions.
                   mkdir "$dir/res"
                   "$bench" bench stability --no-chart --out "$dir/res" >"$dir/out" 2>"$dir/err" & pid=$!
                   while ! grep -q '^axis' "$dir/out" 2>/dev/null; do
                     kill -0 "$pid" 2>/dev/null || fail "stability ended before its header"; sleep 0.02; done
                   kill -TERM "$pid"; wait "$pid"; rc=$?
                   [ "$rc" = 143 ] || fail "exit $rc after SIGTERM, expected 143"
                   [ -z "$(ls -A "$dir/res")" ] || fail "left in --out: $(ls -A "$dir/res")" ;;
  write-error)     mkdir -p "$dir/res/bench.csv"  # a folder where the CSV goes: it cannot be written
                   "$bench" bench --smoke --no-chart --out "$dir/res" >"$dir/out" 2>"$dir/err"; rc=$?
                   [ "$rc" = 2 ] || fail "exit $rc, expected 2"
                   grep -q "bench.csv" "$dir/err" || fail "the error does not name bench.csv" ;;
  seed)            # --seed picks the workloads: the same seed gives the same errors (every column but the two
                   # timings, in bench.csv and disc.csv), another seed other ones; the header says which.
                   n=0
                   for s in 7 7 8; do
                     n=$((n + 1))
                     "$bench" bench --smoke --no-chart --seed $s --out "$dir/$n" >"$dir/out" 2>"$dir/err" || fail "--seed $s: exit $?"
                     head -n 1 "$dir/out" | grep -q "; seed $s\$" || fail "the header does not say seed $s"
                     cut -d, -f1-4,7- "$dir/$n/bench.csv" >"$dir/errors-$n"
                     cut -d, -f1-4,7- "$dir/$n/disc.csv" >>"$dir/errors-$n"
                   done
                   cmp -s "$dir/errors-1" "$dir/errors-2" || fail "seed 7 twice gives different errors"
                   ! cmp -s "$dir/errors-1" "$dir/errors-3" || fail "seeds 7 and 8 give the same errors" ;;
  quick-smoke)     # --quick and --smoke are one or the other, for bench, stability and scale.
                   for sub in "" stability scale; do
                     "$bench" bench $sub --quick --smoke --out "$dir/res" >"$dir/out" 2>"$dir/err"; rc=$?
                     [ "$rc" = 2 ] || fail "bench $sub --quick --smoke: exit $rc, expected 2"
                     grep -q -- "--quick excludes --smoke\|--smoke excludes --quick" "$dir/err" || fail "bench $sub: no excludes error"
                   done
                   [ ! -e "$dir/res" ] || fail "a usage error left --out behind" ;;
  stability-quick) # The smaller sets of --quick from seed 3 (0.8 s without the chart on the 2-core dev box): its header,
                   # and a row per magnitude and angle for robust with no wrong decision and no tunnel.
                   "$bench" bench stability --quick --seed 3 --no-chart --out "$dir/res" >"$dir/out" 2>"$dir/err" || fail "exit $?"
                   first_line="ricochet bench stability --quick: 4000 queries per magnitude and angle; seed 3"
                   grep -qxF "$first_line" "$dir/out" || fail "no line: $first_line"
                   rows=$(grep -c ',robust,' "$dir/res/stability.csv")
                   [ "$rows" -ge 10 ] || fail "$rows robust rows in stability.csv"
                   bad=$(grep ',robust,' "$dir/res/stability.csv" | awk -F, '$4 != 0 || ($7 != "" && $7 != 0)' | head -n 1)
                   [ -z "$bad" ] || fail "robust is wrong or tunnels: $bad" ;;
  frames)          # bench frames --smoke: one run of each ball for --frames frames, ending in the robust box.
                   "$bench" bench frames --smoke --frames 1000 >"$dir/out" 2>"$dir/err" || fail "exit $?"
                   [ "$(grep -c ': 1000 frames x 1 runs, ' "$dir/out")" = 2 ] || fail "not two runs of 1000 frames"
                   grep -q '^target >= 1e7 ball-frames/s on one core (slow ball): ' "$dir/out" || fail "no target line" ;;
  scale)           # bench scale --smoke --threads 2: every column of the walls and balls sweeps, the thread sweep on 1
                   # and 2 threads, no robust tunnel; scale.csv in --out.
                   "$bench" bench scale --smoke --threads 2 --out "$dir/res" >"$dir/out" 2>"$dir/err" || fail "exit $?"
                   head -n 1 "$dir/out" | grep -q '^ricochet bench scale --smoke: ' || fail "no --smoke header"
                   csv=$dir/res/scale.csv
                   [ "$(grep -c '^walls,robust+grid,[0-9]*,100,1,' "$csv")" = 2 ] || fail "not two rows in the walls sweep"
                   grep -q '^balls,robust+grid,[0-9]*,100,1,' "$csv" || fail "no balls row for 100 balls"
                   grep -q '^threads,robust+grid,[0-9]*,1000,1,' "$csv" || fail "no 1-thread row"
                   grep -q '^threads,robust+grid,[0-9]*,1000,2,' "$csv" || fail "no 2-thread row"
                   bad=$(grep '^[a-z]*,robust+grid,' "$csv" | awk -F, '$10 > 0' | head -n 1)
                   [ -z "$bad" ] || fail "robust tunnelled: $bad"
                   grep -q '^walls,robust+grid,[0-9]*,100,1,[^,]*,[^,]*,[^,]*,[^,]*,0,500,-1$' "$csv" ||
                     fail "the walls sweep checked not 100 balls x 5 frames with 0 tunnels"
                   grep -q '^walls,robust-disc+grid,[0-9]*,100,1,[^,]*,[^,]*,[^,]*,[^,]*,0,500,0$' "$csv" ||
                     fail "the robust discs checked not 100 balls x 5 frames with 0 tunnels and 0 penetrations"
                   # The meet sweep: 100 discs in a box, without and with balls collide, each checked over 100 balls x
                   # 5 frames with 0 tunnels and 0 penetrations; its targets need 10^3 and 10^4 discs: not measured.
                   for m in robust-disc+grid robust-meet+grid; do
                     grep -q "^meet,$m,4,100,1,[^,]*,[^,]*,[^,]*,[^,]*,0,500,0\$" "$csv" ||
                       fail "the meet sweep's $m row did not check 100 discs x 5 frames with 0 tunnels and 0 penetrations"
                   done
                   if grep -q '^walls,box2d-2.4.1,' "$csv"; then
                     grep -q '^walls,box2d-disc-2.4.1,[0-9]*,100,1,[^,]*,[^,]*,[^,]*,[^,]*,[0-9]*,500,[0-9]*$' "$csv" ||
                       fail "Box2D's discs not checked over 100 balls x 5 frames"
                   fi
                   # The scale targets: no maze of 10^4 walls or more in --smoke, so those are not measured; the
                   # thread sweep ran on 2 threads, so its row has a verdict (which one is the machine's business).
                   md=$dir/res/scale_targets.md
                   [ -s "$md" ] || fail "no scale_targets.md"
                   [ "$(grep -c '^| maze, 10^[456] walls | .* | not measured | ' "$md")" = 3 ] || fail "maze rows not 'not measured'"
                   [ "$(grep -c '^| discs that meet in a box, 10^[34].* | not measured | ' "$md")" = 4 ] ||
                     fail "the four meet rows not 'not measured'"
                   grep -q '^| 2 threads against 1 | speed-up [0-9.]*× .* | ≥ 1.96× (kept) | \(met\|\*\*missed\*\*\) | ' "$md" ||
                     fail "no verdict on the 2-thread row" ;;
  scale-meet)      # bench scale --meet --smoke: the meet sweep alone, meet.csv (scale.csv's columns) and meet_targets.md.
                   "$bench" bench scale --meet --smoke --out "$dir/res" >"$dir/out" 2>"$dir/err" || fail "exit $?"
                   head -n 1 "$dir/out" | grep -q '^ricochet bench scale --meet --smoke: ' || fail "no --meet --smoke header"
                   [ "$(grep -c '^meet,' "$dir/res/meet.csv")" = 2 ] || fail "not two rows in meet.csv"
                   ! grep -q '^walls,' "$dir/res/meet.csv" || fail "the walls sweep ran"
                   [ "$(grep -c '^| discs that meet in a box, 10^[34].* | not measured | ' "$dir/res/meet_targets.md")" = 4 ] ||
                     fail "meet_targets.md has not the four meet rows, not measured" ;;
  targets)         # bench --smoke: the speed targets, a verdict each, printed and written to targets.md.
                   "$bench" bench --smoke --no-chart --out "$dir/res" >"$dir/out" 2>"$dir/err" || fail "exit $?"
                   md=$dir/res/targets.md
                   [ -s "$md" ] || fail "no targets.md"
                   [ "$(grep -c '^| [a-z]' "$md")" = 15 ] || fail "not a header and 14 targets in targets.md"
                   [ "$(grep -c ' | \(met\|\*\*missed\*\*\) | ' "$md")" = 14 ] || fail "not 14 verdicts in targets.md"
                   grep -q '^| discs, uniform | [0-9.]* ns | [0-9.]*× | ≤ 2× | ' "$md" || fail "no disc row with robust's ratio"
                   grep -q '^| closed box, turned | [0-9.]* ns per ball-frame, 0 tunnels | [0-9.]*× | ≤ 1.5× | ' "$md" ||
                     fail "no closed-box row with robust's time, 0 tunnels and its ratio"
                   grep -qF "$(sed -n 4p "$md")" "$dir/out" || fail "the table is not printed too" ;;
  *) echo "unknown case $case" >&2; exit 1 ;;
esac
echo "ok $case"
