#!/bin/sh
# `bench`'s edges (bench/src/bench.cpp, ricochet_bench/result_file.hpp), one case per call: progress while
# it runs, result files whole or absent after Ctrl-C, a clear error when one cannot be written.
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
  *) echo "unknown case $case" >&2; exit 1 ;;
esac
echo "ok $case"
