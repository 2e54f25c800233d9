#!/bin/sh
# How fast each fuzz target runs, against the project's aims (fuzz/README.md, "Speed"), and how a campaign's
# inputs per second grow with `ricochet fuzz --jobs`. A measurement, not a test: the verdicts depend on the
# machine and its load, so no test asserts them (CTest fuzz_exec_rate_script checks the table's shape only).
# It writes only in a temporary folder, removed at its end (and in --artifacts DIR if named).
set -u

usage() {
  cat <<'EOF'
usage: fuzz/exec_rate.sh BUILD [--seconds N | --runs N] [--seed S] [--kernel K] [--target T[,T...]]...
                         [--jobs-scaling J,J,...] [--artifacts DIR]

Runs each fuzz target of the build folder BUILD alone, one after another, from a copy of its committed
inputs (fuzz/corpus/TARGET/ of the build's source tree) with its dictionary:
  RICOCHET_KERNEL=K BUILD/fuzz/fuzz_TARGET -seed=S -max_total_time=N -print_final_stats=1 -dict=... COPY
and prints a row per target: its runs (libFuzzer's stat::number_of_executed_units), the wall seconds of the
process (start-up and exit included; libFuzzer stops about a second past N), exec/s = runs / seconds, the aim
and whether it is met or missed by a factor. The aims: with
ASan+UBSan (the default build) static and sweep 30k, scene and disc 10k, parser 50k exec/s (meet: none yet); without them
(-DRICOCHET_FUZZ_SANITIZERS=OFF, campaign mode) static and sweep 100k. The header says which build it timed.

  --seconds N         fuzz each target for N s (default 20: the issue's measure)
  --runs N            run N inputs each instead (-runs=N; a quick look: no verdicts)
  --seed S            libFuzzer's -seed (default 1)
  --kernel K          the kernel under test (default robust)
  --target T,...      time only these (parser, static, sweep, scene, disc, meet); repeatable; default all six
  --jobs-scaling LIST instead, for each target, run `ricochet fuzz --target T --jobs J --time N --seed S`
                      (or --runs N) for each J in LIST (e.g. 1,2 or 1,2,4,8,16) on a fresh cache, and print
                      the inputs per second of all its workers together (each worker's runs over its own
                      time, summed: --json's exec_per_s) and the speed-up over the first J in LIST
  --artifacts DIR     keep the input of a target that fails (a bug, against robust) in DIR
Exit status: 0 every target timed; 1 a target missing, failing or not timed; 2 bad usage or no such build.
EOF
}

die() { echo "exec_rate.sh: error: $*" >&2; exit 2; }

build= seconds=20 runs= seed=1 kernel=robust targets= jobs= artifacts=
while [ $# -gt 0 ]; do
  case "$1" in
    -h|--help) usage; exit 0 ;;
    --seconds|--runs|--seed|--kernel|--target|--jobs-scaling|--artifacts)
      [ $# -ge 2 ] || die "$1 needs a value"
      case "$1" in
        --seconds) seconds=$2 ;; --runs) runs=$2 ;; --seed) seed=$2 ;; --kernel) kernel=$2 ;;
        --target) targets="$targets $(echo "$2" | tr ',' ' ')" ;; --jobs-scaling) jobs=$2 ;; --artifacts) artifacts=$2 ;;
      esac
      shift 2 ;;
    -*) die "unknown option $1 (--help lists them)" ;;
    *) [ -z "$build" ] || die "'$1': one build folder only (it is '$build'); several targets are --target A,B or --target A --target B"
       build=$1; shift ;;
  esac
done
[ -n "$build" ] || { usage >&2; exit 2; }
is_count() { case "$1" in ''|*[!0-9]*) return 1 ;; 0) return 1 ;; esac; }
is_count "$seconds" || die "--seconds $seconds: a whole number of seconds above 0"
[ -z "$runs" ] || is_count "$runs" || die "--runs $runs: a whole number above 0"
is_count "$seed" || die "--seed $seed: a whole number above 0"
[ -n "$targets" ] || targets="static sweep scene disc meet parser"
for t in $targets; do
  case "$t" in parser|static|sweep|scene|disc|meet) ;; *) die "--target $t: not one of parser, static, sweep, scene, disc, meet" ;; esac
done
if [ -n "$jobs" ]; then
  jobs=$(echo "$jobs" | tr ',' ' ')
  for j in $jobs; do is_count "$j" || die "--jobs-scaling: '$j' is not a number of jobs above 0"; done
fi
if [ -n "$artifacts" ]; then
  mkdir -p "$artifacts" || die "--artifacts $artifacts: cannot make the folder"
  artifacts=$(cd "$artifacts" && pwd)
fi

# The build: what CMake configured (its source tree, compiler, type, how the fuzz targets are built).
cache=$build/CMakeCache.txt
[ -f "$cache" ] || die "$build: no CMakeCache.txt, not a CMake build folder"
build=$(cd "$build" && pwd)
cached() { sed -n "s/^$1:[A-Z]*=//p" "$cache" | head -n 1; }
src=$(cached CMAKE_HOME_DIRECTORY)
mode=$(cached RICOCHET_FUZZ_MODE)
[ -d "$src/fuzz/corpus" ] || die "$build was configured from $src, which has no fuzz/corpus/"
case "$mode" in
  libfuzzer|engine) ;;
  standalone) die "$build builds the fuzz targets on the standalone driver (gcc, or RICOCHET_FUZZ=OFF): they only run given files; configure with clang-14 for libFuzzer (fuzz/README.md, \"Build\")" ;;
  *) die "$build has no fuzz targets (RICOCHET_FUZZ_MODE is '$mode')" ;;
esac
# Sanitizers: the fuzz build's own (RICOCHET_FUZZ_SANITIZERS, ON unless set OFF) or the flags of every file
# (the sanitize preset, an engine's CXXFLAGS).
flags=$(cached CMAKE_CXX_FLAGS)
if { [ "$mode" = libfuzzer ] && [ "$(cached RICOCHET_FUZZ_SANITIZERS)" != OFF ]; } ||
   case "$flags" in *-fsanitize=*address*|*-fsanitize=*undefined*) true ;; *) false ;; esac; then
  sanitized=yes what="ASan+UBSan"
else
  sanitized=no what="no sanitizers (campaign mode)"
fi
compiler=$(basename "$(cached CMAKE_CXX_COMPILER)")
type=$(cached CMAKE_BUILD_TYPE)

# aim TARGET: the issue's exec/s for TARGET in this build, or "-" where it names none.
aim() {
  if [ "$sanitized" = yes ]; then
    case "$1" in static|sweep) echo 30000 ;; scene|disc) echo 10000 ;; parser) echo 50000 ;; *) echo - ;; esac
  else
    case "$1" in static|sweep) echo 100000 ;; *) echo - ;; esac
  fi
}

tmp=$(mktemp -d) || die "cannot make a temporary folder"
trap 'rm -rf "$tmp"' EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
now() { date +%s.%N; }
load() { cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo unknown; }
if [ -n "$runs" ]; then budget="$runs runs" limit="-runs=$runs"; else budget="$seconds s" limit="-max_total_time=$seconds"; fi
if [ -n "$jobs" ]; then each="$budget per campaign"; else each="$budget per target alone"; fi
echo "exec_rate.sh: $build ($compiler $type, libFuzzer with $what), kernel $kernel, seed $seed, $each"
echo "machine: $(nproc) cores, load average $(load) at the start"
status=0

# field NAME FILE: the first number named NAME in the JSON document FILE (the campaign's are on one line; its
# first "exec_per_s" is the campaign's total, its first "workers" and "runs" the first target's).
field() { grep -o "\"$1\":[^,}]*" "$2" | head -n 1 | cut -d: -f2; }

# --jobs-scaling: ricochet fuzz with J workers on one target, its --json document's exec/s of all workers.
if [ -n "$jobs" ]; then
  ricochet=$build/cli/ricochet
  [ -x "$ricochet" ] || die "$ricochet: not built (cmake --build $build --target ricochet)"
  if [ -n "$runs" ]; then how="--runs $runs"; else how="--time $seconds"; fi
  echo "each: ricochet fuzz --target T --jobs J $how --seed $seed --kernel $kernel --no-merge, a fresh cache"
  [ -n "$runs" ] || echo "(a campaign by --time N fuzzes for 80 % of N; each worker's rate is its runs over its own time)"
  printf '\n%-8s %5s %8s %11s %14s %11s  %s\n' target jobs workers runs "exec/s in all" "per worker" speed-up
  mkdir "$tmp/here"
  for t in $targets; do
    base=
    for j in $jobs; do
      out=$tmp/$t-$j
      # From an empty folder: the campaign finds no project there, and writes only in the folders named.
      # shellcheck disable=SC2086  # $how is two words
      (cd "$tmp/here" && "$ricochet" fuzz --json --target "$t" --jobs "$j" $how --seed "$seed" --kernel "$kernel" \
         --no-merge --bin-dir "$build/fuzz" --cache-dir "$out.cache" --replay-dir "$out.replays" >"$out.json" 2>"$out.err")
      rc=$?
      all=$(field exec_per_s "$out.json") per=$(field exec_per_s_per_worker "$out.json")
      workers=$(field workers "$out.json") n=$(field runs "$out.json")
      if [ "$rc" -gt 1 ] || [ -z "$all" ]; then
        printf '%-8s %5s %8s %11s %14s %11s  %s\n' "$t" "$j" - - - - "FAILED"
        echo "  ricochet fuzz exited $rc: $(tail -n 3 "$out.err" | tr '\n' ' ')"
        status=1; continue
      fi
      [ "$rc" = 0 ] || { echo "  $t, --jobs $j: new failures (exit 1; the campaign's logs were in a temporary folder)"; status=1; }
      [ -n "$base" ] || base=$all
      printf '%-8s %5s %8s %11s %14.0f %11.0f  %s\n' "$t" "$j" "$workers" "$n" "$all" "$per" \
        "$(awk -v a="$all" -v b="$base" 'BEGIN { if (b > 0) printf "×%.2f", a / b; else print "-" }')"
    done
  done
  echo "load average $(load) at the end"
  exit "$status"
fi

printf '\n%-8s %10s %8s %9s %8s  %s\n' target runs seconds exec/s aim verdict
for t in $targets; do
  bin=$build/fuzz/fuzz_$t
  if [ ! -x "$bin" ]; then
    printf '%-8s %10s %8s %9s %8s  %s\n' "$t" - - - "$(aim "$t")" "MISSING: $bin not built (cmake --build $build --target fuzz_$t)"
    status=1; continue
  fi
  # A copy of the committed inputs: libFuzzer writes new inputs into the first corpus folder it is given.
  mkdir "$tmp/$t" && cp -R "$src/fuzz/corpus/$t/." "$tmp/$t/"
  dict=
  [ -f "$src/fuzz/$t.dict" ] && dict=-dict=$src/fuzz/$t.dict
  start=$(now)
  # shellcheck disable=SC2086  # $dict is one word or none
  RICOCHET_KERNEL=$kernel "$bin" -seed="$seed" "$limit" -print_final_stats=1 $dict -artifact_prefix="$tmp/$t-" "$tmp/$t" \
    >"$tmp/$t.log" 2>&1
  rc=$?
  end=$(now)
  n=$(sed -n 's/^stat::number_of_executed_units: *//p' "$tmp/$t.log" | tail -n 1)
  if [ "$rc" != 0 ] || [ -z "$n" ]; then
    printf '%-8s %10s %8s %9s %8s  %s\n' "$t" "${n:--}" - - "$(aim "$t")" "FAILED (exit $rc)"
    echo "  $t: $(grep -E '^(==ricochet-fuzz==|SUMMARY:|==[0-9]+== ?ERROR)' "$tmp/$t.log" | head -n 1)"
    if [ -n "$artifacts" ]; then
      for a in "$tmp/$t-"*; do [ -f "$a" ] && cp "$a" "$artifacts/" && echo "  its input: $artifacts/$(basename "$a")"; done
    else
      echo "  (--artifacts DIR keeps its input; ricochet fuzz --target $t converts such a failure into a scene log)"
    fi
    status=1; continue
  fi
  awk -v t="$t" -v n="$n" -v s0="$start" -v s1="$end" -v aim="$(aim "$t")" -v by_runs="$runs" 'BEGIN {
    s = s1 - s0; rate = n / s
    if (by_runs != "") verdict = "(by runs: no verdict)"
    else if (aim == "-") verdict = "(no aim for this build)"
    else if (rate >= aim) verdict = "met"
    else verdict = sprintf("missed by ×%.1f", aim / rate)
    printf "%-8s %10d %8.1f %9.0f %8s  %s\n", t, n, s, rate, aim, verdict
  }'
  rm -rf "${tmp:?}/$t"
done
echo "load average $(load) at the end"
exit "$status"
