#!/usr/bin/env bash
# Mutation score of the harness: for each NN-name.patch here, a mutant of core/ is built in a scratch copy
# of the tree and attacked by the property suite, then (if it survives) by a fuzz campaign. A mutant is
# caught only if the harness leaves a saved scene log that fails `ricochet replay` on the mutant and passes
# on the unmutated build: the contract is that a failure the harness reports is one replay reproduces.
# The parser target saves no scene log (its input is the reproducer): a parser finding counts when its
# minimized input makes the parser target (gcc, standalone driver) fail on the mutant and pass unmutated.
#
#   properties/mutants/run.sh [--only NN[,NN...]] [--out DIR] [--fuzz-runs N] [--no-fuzz] [--no-unit]
#                             [--seeds S[,S...]]
#
# DIR (default build-mutants/ in the checkout, ignored by git) keeps everything between runs, so a run can
# be restarted with --only: tree/ (the scratch copy; the checkout is never modified), gcc/ (RelWithDebInfo:
# ricochet, ricochet_properties, fuzz_parser), clang/ (clang-14 + libFuzzer: ricochet, fuzz_*; built only
# when a mutant survives the properties), ref/ (the unmutated ricochet and fuzz_parser), NN/ (each
# mutant's logs and outputs) and results.tsv (one line per mutant; the table is printed from it). Unless
# --no-unit, each mutant also runs core/tests/promise_test (reported in its own column, not scored: a unit
# test is not the harness).
#
# Settings, fixed so that a run measures the same thing each time:
#   RICOCHET_KERNEL=robust, RC_PARAMS="seed=$MUT_SEED max_success=$MUT_CASES" (defaults 1 and 150: about
#   10 s for the robust suite on a quiet core), fuzz: `ricochet fuzz --kernel robust --runs $MUT_FUZZ_RUNS
#   --seed $MUT_SEED` (default 30 000 inputs per target: about the 60 s campaign the issue names, all four
#   targets on 2 cores at the ~1 000 inputs/s measured under ASan; a fixed count, not a clock, so a verdict
#   never depends on the machine's load) with a fresh cache per mutant (seeded from fuzz/corpus/), every fuzz
#   target the clang build defines (its RICOCHET_FUZZ_TARGETS); RICOCHET_SHRINK_TRIES=$MUT_SHRINK_TRIES (default
#   200) bounds each failing property's shrinking by a count (a timeout of 1800 s guards against a hang only).
#   libFuzzer's -timeout is $MUT_FUZZ_TIMEOUT s (default 120, not its 10): a campaign by runs does not restart a
#   worker, and under six workers on two cores a slow meet input took over 10 s and ended the meet worker early;
#   a timeout saves no log, so it is never a catch either way.
# Seconds to bug: from the start of the property suite to the moment the reproducing log was written (for a
# fuzz catch: the suite's time plus the campaign's until then, the clang build left out).
# --seeds S1,S2,… (MUT_SEEDS; default MUT_SEED alone) runs the property suite once per seed on each mutant's one
# build, each into its own folder (props/ for S1, props-S/ for the others): a mutant is caught by the properties
# where some seed left a reproducing log (the first such seed names it); the row lists each seed's seconds to bug
# and, in brackets, the cases its property ran until it failed ("-": no log), and the seconds' median (over every
# seed, a seed without a log counting as longer than any: "-" where half or more have none). The fuzz campaign, for
# a mutant no seed caught, uses S1.
# Exit status: 0 after a complete run (the score is a measurement), 2 on a broken setup (a patch that does
# not apply, a build that fails, a reference build that fails its own logs).
set -uo pipefail

here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/../.." && pwd)
out="$src/build-mutants"
only=""
fuzz_runs=${MUT_FUZZ_RUNS:-30000}
fuzz_timeout=${MUT_FUZZ_TIMEOUT:-120}
do_fuzz=1
do_unit=1
seed=${MUT_SEED:-1}
seeds=${MUT_SEEDS:-}
cases=${MUT_CASES:-150}
shrink_tries=${MUT_SHRINK_TRIES:-200}
jobs=${MUT_JOBS:-2}
while [ $# -gt 0 ]; do
  case "$1" in
    --only) only=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --fuzz-runs) fuzz_runs=$2; shift 2 ;;
    --no-fuzz) do_fuzz=0; shift ;;
    --no-unit) do_unit=0; shift ;;
    --seeds) seeds=$2; shift 2 ;;
    -h|--help) sed -n '2,/^set /{/^set /!s/^# \{0,1\}//p}' "$0"; exit 0 ;;
    *) echo "run.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
[ -n "$seeds" ] || seeds=$seed
[[ "$seeds" =~ ^[0-9]+(,[0-9]+)*$ ]] || { echo "run.sh: --seeds wants numbers separated by commas, not '$seeds'" >&2; exit 2; }
seed=${seeds%%,*}
mkdir -p "$out"
out=$(cd "$out" && pwd)
case "$out/" in "$src"/tree/*|"$src"/core/*) echo "run.sh: --out must not be inside the sources" >&2; exit 2 ;; esac
tree="$out/tree"
results="$out/results.tsv"
touch "$results"

die() { echo "run.sh: $*" >&2; exit 2; }
now() { date +%s; }

# The scratch tree: every tracked file of the checkout, copied where its content differs (a fresh mtime,
# so ninja rebuilds exactly what a patch or its reversal touched).
sync_tree() {
  mkdir -p "$tree"
  (cd "$src" && git ls-files -z) | while IFS= read -r -d '' f; do
    if [ ! -f "$tree/$f" ] || ! cmp -s "$src/$f" "$tree/$f"; then
      mkdir -p "$tree/$(dirname "$f")"
      cp "$src/$f" "$tree/$f"
    fi
  done
}

build_gcc() {
  if [ ! -f "$out/gcc/CMakeCache.txt" ]; then
    cmake -S "$tree" -B "$out/gcc" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DRICOCHET_FUZZ=OFF \
      -DRICOCHET_BENCH=OFF > "$out/gcc-configure.log" 2>&1 || return 1
  fi
  ninja -C "$out/gcc" -j"$jobs" ricochet ricochet_properties fuzz_parser > "$1" 2>&1
}

build_clang() {
  if [ ! -f "$out/clang/CMakeCache.txt" ]; then
    CC=clang-14 CXX=clang++-14 cmake -S "$tree" -B "$out/clang" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DRICOCHET_FUZZ=ON -DRICOCHET_BENCH=OFF -DRICOCHET_TESTS=OFF > "$out/clang-configure.log" 2>&1 || return 1
  fi
  # Every fuzz target the build defines (its cache's RICOCHET_FUZZ_TARGETS), so the campaign runs them all:
  # a target left unbuilt would be skipped by the campaign without a word.
  local targets
  targets=$(sed -n 's/^RICOCHET_FUZZ_TARGETS:INTERNAL=//p' "$out/clang/CMakeCache.txt" | tr ';' ' ')
  [ -n "$targets" ] || { echo "run.sh: the clang build names no fuzz targets" > "$1"; return 1; }
  fuzz_targets=$targets
  # shellcheck disable=SC2046
  ninja -C "$out/clang" -j"$jobs" ricochet $(for t in $targets; do printf 'fuzz_%s ' "$t"; done) > "$1" 2>&1
}

# The first saved log under $1 that fails replay on the mutant and passes on the unmutated build; prints
# "LOG" or nothing. Every log's verdicts go to $2.
reproduced_log() {
  local dir=$1 verdicts=$2 log
  : > "$verdicts"
  [ -d "$dir" ] || return 0
  while IFS= read -r log; do
    "$out/gcc/cli/ricochet" replay "$log" > "$log.mutant.txt" 2>&1
    local m=$?
    "$out/ref/ricochet" replay "$log" > "$log.ref.txt" 2>&1
    local r=$?
    echo "$(basename "$log") mutant=$m ref=$r" >> "$verdicts"
    if [ "$m" = 1 ] && [ "$r" = 0 ]; then
      echo "$log"
      return 0
    fi
  done < <(find "$dir" -name '*.scene' | sort)
}

# The first parser finding under $1 (a campaign cache: parser/*/artifacts/) whose input (the minimized one
# where there is one) makes fuzz_parser fail on the mutant (a failure report, non-zero exit) and pass on
# the unmutated build; prints "INPUT" or nothing. Every input's verdicts go to $2.
reproduced_parser_input() {
  local cache=$1 verdicts=$2 raw input
  : > "$verdicts"
  [ -d "$cache/parser" ] || return 0
  while IFS= read -r raw; do
    input=$(dirname "$raw")/minimized-$(basename "$raw")
    [ -s "$input" ] || input=$raw
    "$out/gcc/fuzz/fuzz_parser" "$input" > "$input.mutant.txt" 2>&1
    local m=$?
    "$out/ref/fuzz_parser" "$input" > "$input.ref.txt" 2>&1
    local r=$?
    local tag=0
    grep -q '^==ricochet-fuzz== FAILURE' "$input.mutant.txt" && tag=1
    echo "$(basename "$input") mutant=$m ref=$r report=$tag" >> "$verdicts"
    if [ "$m" != 0 ] && [ "$tag" = 1 ] && [ "$r" = 0 ]; then
      echo "$input"
      return 0
    fi
  done < <(find "$cache/parser" -path '*/artifacts/*' -type f ! -name 'minimized-*' ! -name 'slow-unit-*' \
             ! -name '*.txt' | sort)
}

# --- the unmutated build -----------------------------------------------------------------------------
echo "== reference: syncing $tree and building (gcc RelWithDebInfo) =="
t0=$(now)
sync_tree
build_gcc "$out/gcc-ref-build.log" || die "the unmutated gcc build fails ($out/gcc-ref-build.log)"
mkdir -p "$out/ref"
cp "$out/gcc/cli/ricochet" "$out/ref/ricochet"
cp "$out/gcc/fuzz/fuzz_parser" "$out/ref/fuzz_parser"
"$out/ref/ricochet" replay "$tree/replays" > "$out/ref-corpus.txt" 2>&1 ||
  die "the unmutated build fails its own corpus ($out/ref-corpus.txt)"
"$out/ref/fuzz_parser" "$tree/fuzz/corpus/parser" "$tree/replays" > "$out/ref-parser.txt" 2>&1 ||
  die "the unmutated parser target fails its own inputs ($out/ref-parser.txt)"
echo "   built and corpus clean in $(( $(now) - t0 )) s"
if [ "$do_unit" = 1 ]; then
  ninja -C "$out/gcc" -j"$jobs" promise_test > "$out/unit-ref-build.log" 2>&1 || die "promise_test does not build"
  "$out/gcc/core/tests/promise_test" > "$out/unit-ref.txt" 2>&1 || die "promise_test fails unmutated ($out/unit-ref.txt)"
fi
# The property suite unmutated, with the settings every mutant gets: its time is the budget, and a
# failure here would be the harness's own (a mutant is never credited with it: its log would fail on ref).
for s in ${seeds//,/ }; do
  rdir="$out/ref-props"; [ "$s" = "$seed" ] || rdir="$out/ref-props-$s"
  rm -rf "$rdir"; mkdir -p "$rdir"
  ps=$(now)
  RICOCHET_KERNEL=robust RICOCHET_REPLAY_DIR="$rdir" RC_PARAMS="seed=$s max_success=$cases" \
    RICOCHET_SHRINK_TRIES=$shrink_tries timeout 1800 "$out/gcc/properties/ricochet_properties" > "$rdir.txt" 2>&1
  echo "   unmutated property suite: exit $? in $(( $(now) - ps )) s (RC_PARAMS=\"seed=$s max_success=$cases\")"
done

patches=()
for p in "$here"/[0-9][0-9]-*.patch; do
  nn=$(basename "$p" | cut -c1-2)
  if [ -n "$only" ] && ! [[ ",$only," == *",$nn,"* ]]; then continue; fi
  patches+=("$p")
done
[ ${#patches[@]} -gt 0 ] || die "no patch matches --only $only"

i=0
for p in "${patches[@]}"; do
  i=$((i + 1))
  name=$(basename "$p" .patch)
  nn=${name:0:2}
  work="$out/$nn"
  rm -rf "$work"
  mkdir -p "$work"
  start=$(now)
  echo "== [$i/${#patches[@]}] $name: $(head -1 "$p" | sed 's/^# //')"
  sync_tree
  patch -p1 -s -d "$tree" --no-backup-if-mismatch < "$p" > "$work/patch.log" 2>&1 || die "$name does not apply ($work/patch.log)"
  build_gcc "$work/gcc-build.log" || die "$name: the gcc build fails ($work/gcc-build.log)"
  echo "   built ($(( $(now) - start )) s)"

  # The committed corpus against the mutant: reported, not scored (it is not the harness generating).
  "$out/gcc/cli/ricochet" replay "$tree/replays" > "$work/corpus.txt" 2>&1
  corpus=$(grep -Eo '[0-9]+ failed' "$work/corpus.txt" | tail -1 | cut -d' ' -f1)
  corpus=${corpus:-?}

  unit="-"
  if [ "$do_unit" = 1 ]; then
    if ninja -C "$out/gcc" -j"$jobs" promise_test > "$work/unit-build.log" 2>&1; then
      timeout 300 "$out/gcc/core/tests/promise_test" > "$work/unit.txt" 2>&1 && unit=pass ||
        unit="FAIL:$(grep -Eo '^\[  FAILED  \] Promise\.[A-Za-z]+' "$work/unit.txt" | sed 's/.*Promise\.//' | sort -u | tr '\n' ' ')"
    else
      die "$name: promise_test does not build ($work/unit-build.log)"
    fi
  fi

  caught="-"
  log="-"
  to_bug="-"
  # The property suite, robust, fixed case count, once per seed.
  per_seed=()
  props_s=0
  prc_any=0
  for s in ${seeds//,/ }; do
    pdir="$work/props"; [ "$s" = "$seed" ] || pdir="$work/props-$s"
    ps=$(now)
    mkdir -p "$pdir"
    RICOCHET_KERNEL=robust RICOCHET_REPLAY_DIR="$pdir" RC_PARAMS="seed=$s max_success=$cases" \
      RICOCHET_SHRINK_TRIES=$shrink_tries timeout 1800 "$out/gcc/properties/ricochet_properties" > "$pdir.txt" 2>&1
    prc=$?
    pe=$(now)
    props_s=$(( props_s + pe - ps ))
    [ "$prc" = 0 ] || prc_any=$prc
    [ "$prc" = 124 ] && echo "   properties (seed $s): stopped by the 1800 s guard (a hang, not shrinking: that is bounded)"
    failed=$(grep -Eo '^\[  FAILED  \] Kernels/[A-Za-z]+\.[A-Za-z]+' "$pdir.txt" | sed 's/.*\.//' | sort -u | tr '\n' ' ')
    [ "$s" = "$seed" ] && failed_props=$failed
    echo "   properties (seed $s): exit $prc in $(( pe - ps )) s; failed: ${failed:-none}"
    hit=$(reproduced_log "$pdir" "$pdir-verdicts.txt")
    if [ -n "$hit" ]; then
      # Its property's cases until it failed, as the suite reports them ("NAME [robust] fails after N cases …").
      cases_to=$(grep -F "saved as $hit" "$pdir.txt" | head -1 | grep -Eo 'fails after [0-9]+ cases' | grep -Eo '[0-9]+')
      per_seed+=("$(( $(stat -c %Y "$hit") - ps )) (${cases_to:-?})")
      if [ "$caught" = "-" ]; then
        caught="property:$(basename "$hit" | sed 's/-[0-9a-f]*\.scene$//')"
        log=${hit#"$out/"}
      fi
    else
      per_seed+=("-")
    fi
  done
  prc=$prc_any
  # The median over the seeds, a seed without a log counting as longer than any.
  to_bug=$(printf '%s\n' "${per_seed[@]}" | sed 's/ .*//; s/^-$/999999999/' | sort -n |
    awk '{ v[NR] = $1 } END { m = v[int((NR + 1) / 2)]; if (NR % 2 == 0) m = (m + v[NR / 2 + 1]) / 2;
                              print (m >= 999999999 ? "-" : m) }')
  seed_list=$(IFS=/; echo "${per_seed[*]}")
  if [ "$caught" = "-" ] && [ "$do_fuzz" = 1 ]; then
    fs=$(now)
    build_clang "$work/clang-build.log" || die "$name: the clang build fails ($work/clang-build.log)"
    echo "   clang build $(( $(now) - fs )) s; fuzzing $fuzz_runs inputs per target: $fuzz_targets"
    fs=$(now)
    "$out/clang/cli/ricochet" fuzz --kernel robust --runs "$fuzz_runs" --seed "$seed" \
      --cache-dir "$work/fuzz-cache" --replay-dir "$work/fuzz" -- -timeout="$fuzz_timeout" > "$work/fuzz.txt" 2>&1
    frc=$?
    echo "   fuzz: exit $frc in $(( $(now) - fs )) s; logs: $(find "$work/fuzz" -name '*.scene' 2>/dev/null | wc -l)"
    hit=$(reproduced_log "$work/fuzz" "$work/fuzz-verdicts.txt")
    if [ -n "$hit" ]; then
      caught="fuzz:$(basename "$hit" | sed 's/^fuzz-//; s/-[0-9a-f]*\.scene$//')"
    else
      hit=$(reproduced_parser_input "$work/fuzz-cache" "$work/parser-verdicts.txt")
      [ -n "$hit" ] && caught="fuzz:parser"
    fi
    if [ -n "$hit" ]; then
      log=${hit#"$out/"}
      # The property suite's time (every seed's), then the campaign's until the log was written (the clang build
      # not counted).
      to_bug=$(( props_s + $(stat -c %Y "$hit") - fs ))
    fi
  fi
  # Reported but not caught: a harness failure whose saved log does not reproduce it.
  note=""
  [ "$caught" = "-" ] && [ "$prc" != 0 ] && note="properties failed (${failed_props% }) but no log reproduces"
  [ "$caught" = "-" ] && [ "${frc:-0}" = 1 ] && note="${note:+$note; }fuzz failed but no log reproduces"
  secs=$(( $(now) - start ))
  grep -v "^$name	" "$results" > "$results.new"; mv "$results.new" "$results"
  # Seconds to bug, then each seed's, last: a results.tsv of an older run (seven or eight columns) still reads.
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$name" "$caught" "$secs" "$log" "$corpus" "${unit% }" "$note" \
    "$to_bug" "$seeds: $seed_list" >> "$results"
  echo "   => ${caught/#-/SURVIVED} ($secs s; a reproducing log after $to_bug s; seeds $seeds: $seed_list)${note:+; $note}"
  unset frc
done

# Leave the scratch tree unmutated.
sync_tree

echo
echo "| mutant | caught by | seconds to bug (median) | properties' seconds to bug (cases), seed by seed | seconds | log | corpus logs failing | promise_test | note |"
echo "| --- | --- | ---: | --- | ---: | --- | ---: | --- | --- |"
# awk keeps empty fields (read with IFS=tab would merge two tabs, an empty note, and shift the columns after it).
sort "$results" | awk -F'\t' '{ printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", $1, $2, ($8 == "" ? "-" : $8), ($9 == "" ? "-" : $9), $3, $4, $5, $6, $7 }'
total=$(wc -l < "$results")
killed=$(awk -F'\t' '$2 != "-"' "$results" | wc -l)
echo
echo "score: $killed / $total mutants caught by the harness (properties, then fuzz, with a reproducing log)"
exit 0
