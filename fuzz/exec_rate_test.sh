#!/bin/sh
# fuzz/exec_rate.sh on a tiny budget: the table's shape (a row per target with its numbers, a row per --jobs
# value), its refusals, and that it writes nothing where it runs nor in the source tree. Never its verdicts or
# its rates: those are the machine's, not the code's.
#   exec_rate_test.sh SOURCE_DIR BUILD_DIR TARGET...
set -u
src=$1 build=$2; shift 2
script=$src/fuzz/exec_rate.sh
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
mkdir "$dir/here"
cd "$dir/here" || exit 1
fail() { echo "FAIL: $*"; [ -f "$dir/out" ] && { echo "--- its output:"; cat "$dir/out"; }; exit 1; }
src_status() { git -C "$src" status --porcelain --untracked-files=all -- fuzz 2>/dev/null; }
before=$(src_status)

# run RC ARGS...: the script, its output in $dir/out, its exit status RC.
run() {
  want=$1; shift
  sh "$script" "$@" >"$dir/out" 2>&1
  rc=$?
  [ "$rc" = "$want" ] || fail "exec_rate.sh $*: exit $rc, expected $want"
}
has() { grep -qE -- "$1" "$dir/out" || fail "no line matching: $1"; }

run 0 --help
has '^usage: fuzz/exec_rate.sh BUILD'
run 2 "$dir/here"
has "exec_rate.sh: error: .*: no CMakeCache.txt, not a CMake build folder"
run 2 "$build" --seconds 0
has "exec_rate.sh: error: --seconds 0: a whole number of seconds above 0"
run 2 "$build" --target nope
has "exec_rate.sh: error: --target nope: not one of"

# Every target: a row per target, with its runs, seconds, exec/s and aim, and no verdict. One run asked: libFuzzer
# runs every committed input whatever -runs says and no mutated one, so whether a target finds a failure is no
# campaign's luck (the committed inputs pass under robust: fuzz_*_regression).
run 0 "$build" --runs 1
has "^exec_rate.sh: .*\(.*libFuzzer with (ASan\+UBSan|no sanitizers \(campaign mode\))\), kernel robust, seed 1, 1 runs per target alone$"
has '^target +runs +seconds +exec/s +aim +verdict$'
for t in "$@"; do
  has "^$t +[0-9]+ +[0-9]+\.[0-9] +[0-9]+ +([0-9]+|-)  \(by runs: no verdict\)$"
done
[ "$(grep -cE '^(parser|static|sweep|scene|disc|meet) ' "$dir/out")" = $# ] || fail "expected $# rows, one per target"

# --jobs-scaling: a row per number of jobs, the workers as many.
run 0 "$build" --runs 20 --target static --jobs-scaling 1,2
has '^exec_rate.sh: .*, kernel robust, seed 1, 20 runs per campaign$'
has '^target +jobs +workers +runs +exec/s in all +per worker +speed-up$'
has '^static +1 +1 +[0-9]+ +[0-9]+ +[0-9]+  ×1\.00$'
has '^static +2 +2 +[0-9]+ +[0-9]+ +[0-9]+  ×[0-9]+\.[0-9][0-9]$'

[ -z "$(ls -A "$dir/here")" ] || fail "it wrote in the folder it ran from: $(ls -A "$dir/here")"
[ "$(src_status)" = "$before" ] || fail "the source tree changed: $(src_status)"
echo "exec_rate.sh: help, refusals, a row per target ($*), --jobs-scaling 1,2"
