#!/usr/bin/env bash
# Time to bug of one built mutant: fuzz campaigns on fixed seeds, each in a fresh temporary project, timed until
# the log (for the parser target: the minimized input) that reproduces the mutant's failure is written.
#
#   properties/mutants/time_to_bug.sh --build DIR --clean DIR --target T [--seeds 1,2,3] [--modes after,before]
#                                     [--runs N] [--cap S] [--work DIR] [--label NAME] [--side-by-side]
#
# --build DIR: a clang build (libFuzzer) of the mutant, with cli/ricochet and fuzz/fuzz_T built. --clean DIR: a
# folder holding `ricochet` (and, for the parser target, `fuzz_parser`) built from the unmutated sources: what the
# saved log must pass on. Each campaign is, in WORK/LABEL-MODE-SEED/proj (an otherwise empty project: replays/ and
# fuzz/corpus/T/),
#   [RICOCHET_FUZZ_ALL_CHECKS=1] DIR/cli/ricochet fuzz --target T --kernel robust --bin-dir DIR/fuzz --seed SEED \
#       --jobs 1 --runs N --cache-dir ../cache --replay-dir ../found --json -- -timeout=120
# killed (SIGTERM) after S seconds (default 240): mode `before` sets RICOCHET_FUZZ_ALL_CHECKS=1 (every input every
# check, as before the check tiers), `after` leaves it unset (the tiers). N defaults to 20000. The project's
# fuzz/corpus/T/ is the committed fuzz/corpus/T/ less every input that already fails on the mutant (each run once
# by DIR/fuzz/fuzz_T with every check): otherwise a committed reproducer would make the campaign fail while it
# loads its seeds, and the time would measure nothing. --bin-dir holds the campaign to the mutant's own fuzz_T: a
# `ricochet` copied out of its build runs the fuzz_T of the tree it was built in, which may be the clean one; a
# campaign whose progress names other binaries is reported `wrong-binaries`, not scored. --side-by-side runs the
# modes of one seed at the same time (two campaigns, one worker each; on a loaded machine both then see the same load).
# Prints one TSV line per campaign: label, target, mode, seed, inputs (the worker's libFuzzer
# stat::number_of_executed_units, as the campaign's --json `runs` reports it; the failing input included), seconds
# (the log's mtime minus the moment the campaign started: the minimization and reduction included), fuzzing_s (the
# campaign's own fuzzing share, --json `seconds`), caught (yes: the log fails `ricochet replay` — for the
# parser, `fuzz_parser` — on the mutant and passes on the clean build; no: it does not; censored: no log within the
# cap or the runs), and the failing check. WORK (default: a new folder under ${TMPDIR:-/tmp}) is the only place
# written; it is kept, with each campaign's json, stderr and log. Exit 0 after every campaign, 2 on bad usage.
set -uo pipefail

src=$(cd "$(dirname "$0")/../.." && pwd)
build="" clean="" target="" seeds="1,2,3" modes="after,before" runs=20000 cap=240 work="" label="" side=0
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build=$(cd "$2" && pwd); shift 2 ;;
    --clean) clean=$(cd "$2" && pwd); shift 2 ;;
    --target) target=$2; shift 2 ;;
    --seeds) seeds=$2; shift 2 ;;
    --modes) modes=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    --cap) cap=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    --label) label=$2; shift 2 ;;
    --side-by-side) side=1; shift ;;
    -h|--help) sed -n '2,/^set /{/^set /!s/^# \{0,1\}//p}' "$0"; exit 0 ;;
    *) echo "time_to_bug.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
[ -n "$build" ] && [ -n "$clean" ] && [ -n "$target" ] || { echo "time_to_bug.sh: --build, --clean and --target are needed" >&2; exit 2; }
bin="$build/fuzz/fuzz_$target"
[ -x "$build/cli/ricochet" ] && [ -x "$bin" ] && [ -x "$clean/ricochet" ] || { echo "time_to_bug.sh: missing binaries" >&2; exit 2; }
[ "$target" != parser ] || [ -x "$clean/fuzz_parser" ] || { echo "time_to_bug.sh: the parser needs CLEAN/fuzz_parser" >&2; exit 2; }
[ -n "$label" ] || label=$target
[ -n "$work" ] || work=$(mktemp -d "${TMPDIR:-/tmp}/time-to-bug.XXXXXX")
mkdir -p "$work" && work=$(cd "$work" && pwd)
export RICOCHET_KERNEL=robust

# The seed corpus less what already fails on the mutant.
seedc="$work/$label-corpus"
rm -rf "$seedc" && mkdir -p "$seedc"
dropped=0
for f in "$src/fuzz/corpus/$target"/*; do
  if RICOCHET_FUZZ_ALL_CHECKS=1 nice "$bin" -artifact_prefix="$work/" "$f" >/dev/null 2>&1; then cp "$f" "$seedc/"; else dropped=$((dropped + 1)); echo "# $label: seed $(basename "$f") fails on the mutant: left out" >&2; fi
done
echo "# $label: $(ls "$seedc" | wc -l) seed inputs, $dropped left out" >&2

one() {  # one campaign: mode seed
  local mode=$1 seed=$2 w="$work/$label-$1-$2"
  rm -rf "$w" && mkdir -p "$w/proj/replays" "$w/proj/fuzz/corpus" "$w/cache" "$w/found"
  cp -r "$seedc" "$w/proj/fuzz/corpus/$target"
  local envs=()
  [ "$mode" = before ] && envs=(RICOCHET_FUZZ_ALL_CHECKS=1)
  local start; start=$(date +%s.%N)
  (cd "$w/proj" && env "${envs[@]}" timeout -s TERM "$cap" nice "$build/cli/ricochet" fuzz --target "$target" --kernel robust \
     --bin-dir "$build/fuzz" --seed "$seed" --jobs 1 --runs "$runs" --cache-dir "$w/cache" --replay-dir "$w/found" --json -- -timeout=120 \
     >"$w/out.json" 2>"$w/err.log")
  echo $? >"$w/rc"
  local log="" inputs fuzz_s check caught=censored secs=-
  inputs=$(jq -r '.targets[0].runs // "-"' "$w/out.json" 2>/dev/null || echo -)
  fuzz_s=$(jq -r '.seconds // "-" | if type == "number" then (. * 10 | round / 10) else . end' "$w/out.json" 2>/dev/null || echo -)
  check=$(jq -r '[.failures[]?.check // empty] | join(",")' "$w/out.json" 2>/dev/null)
  if [ "$target" = parser ]; then
    log=$(ls -tr "$w/cache/parser/robust/artifacts"/minimized-* 2>/dev/null | head -1)
  else
    log=$(ls -tr "$w/found"/*.scene 2>/dev/null | head -1)
  fi
  if [ -n "$log" ]; then
    secs=$(echo "$(date -r "$log" +%s.%N) - $start" | bc)
    secs=$(printf '%.1f' "$secs")
    if [ "$target" = parser ]; then
      "$bin" -artifact_prefix="$w/" "$log" >"$w/mutant.txt" 2>&1; local m=$?
      "$clean/fuzz_parser" -artifact_prefix="$w/" "$log" >"$w/clean.txt" 2>&1; local c=$?
    else
      "$build/cli/ricochet" replay "$log" >"$w/mutant.txt" 2>&1; local m=$?
      "$clean/ricochet" replay "$log" >"$w/clean.txt" 2>&1; local c=$?
    fi
    if [ "$m" != 0 ] && [ "$c" = 0 ]; then caught=yes; else caught="no(mutant=$m,clean=$c)"; fi
  fi
  [ -n "$check" ] || check=-
  # The campaign's own account of the binaries it ran ("  binaries DIR").
  grep -qxF "  binaries $build/fuzz" "$w/err.log" || caught=wrong-binaries
  printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$label" "$target" "$mode" "$seed" "$inputs" "$secs" "$fuzz_s" "$caught" "$check"
}

printf 'label\ttarget\tmode\tseed\tinputs\tseconds\tfuzzing_s\tcaught\tcheck\n'
for s in ${seeds//,/ }; do
  if [ "$side" = 1 ]; then
    for m in ${modes//,/ }; do one "$m" "$s" >"$work/$label-$m-$s.tsv" & done
    wait
    for m in ${modes//,/ }; do cat "$work/$label-$m-$s.tsv"; done
  else
    for m in ${modes//,/ }; do one "$m" "$s"; done
  fi
done
