#!/bin/bash
# Runs .clusterfuzzlite/build.sh the way ClusterFuzzLite does, with the local clang, into temporary
# $OUT/$SRC/$WORK folders; checks that every target, its dictionary and its seed zip land in $OUT and that
# each target runs every one of its seeds and 100 inputs more under `robust`, finding nothing.
#
# The 100 inputs are the same on every run and every machine, so the verdict never rests on a campaign's luck
# (docs/fuzzing.md, "Reproducible campaigns", says what each measure is for):
# - a fixed -seed, -reload=0 (a reload is timed), no CMP- or memmem-guided mutation (they record addresses);
# - UBSan without vptr and pointer-overflow, whose branches follow addresses, and no stack-depth coverage, which
#   follows where the stack starts, as the project's own fuzz build (fuzz/CMakeLists.txt);
# - no address-space randomization (setarch -R), an empty environment and paths relative to $TMP, so that the
#   stack and the heap lie at the same addresses wherever $TMP is;
# - the seeds as a list sorted by name (-seed_inputs), not a folder, whose files libFuzzer takes in the order
#   the file system lists them.
# Where the system refuses setarch -R, each target runs its seeds only, and the test says so.
# Usage: clusterfuzzlite_test.sh SOURCE_DIR [CC CXX]
set -eu
SRC_DIR="$(cd "$1" && pwd)"
export CC="${2:-clang-14}" CXX="${3:-clang++-14}"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
export SRC="$TMP/src" WORK="$TMP/work" OUT="$TMP/out" RICOCHET_SRC="$SRC_DIR"
mkdir -p "$SRC" "$WORK" "$OUT"
export CFLAGS="-O1 -fno-omit-frame-pointer -gline-tables-only -fsanitize=address,undefined -fno-sanitize=vptr,pointer-overflow -fno-sanitize-recover=all -fsanitize=fuzzer-no-link -fno-sanitize-coverage=stack-depth"
export CXXFLAGS="$CFLAGS"
export LIB_FUZZING_ENGINE="-fsanitize=fuzzer"
bash "$SRC_DIR/.clusterfuzzlite/build.sh" > "$TMP/build.log" 2>&1 || { tail -40 "$TMP/build.log"; echo "FAIL: build.sh"; exit 1; }
more=100
fixed=(setarch -R)
if ! setarch -R true 2>/dev/null; then
  echo "note: this system refuses setarch -R (no ADDR_NO_RANDOMIZE): each target runs its seeds only"
  fixed=() more=0
fi
cd "$TMP"
status=0
for t in parser static sweep scene disc meet; do
  for f in "out/$t" "out/$t.dict" "out/${t}_seed_corpus.zip"; do
    [ -s "$f" ] || { echo "FAIL: $f missing"; status=1; }
  done
  [ -x "out/$t" ] || continue
  mkdir -p "seeds/$t" "new/$t" "art/$t" && (cd "seeds/$t" && unzip -q -o "../../out/${t}_seed_corpus.zip")
  find "seeds/$t" -type f | LC_ALL=C sort > "$t.seeds"
  n=$(wc -l < "$t.seeds")
  paste -sd, "$t.seeds" > "$t.list"
  # libFuzzer counts the seeds it loads among its -runs (and loads them all whatever -runs says): the seeds
  # and 100 more, so the check does not depend on how many seeds the corpus has grown to. New inputs go to
  # an empty folder, a failing one to art/: never into the folder the test is run from.
  runs=$((n + more))
  if env -i PATH=/usr/bin:/bin RICOCHET_KERNEL=robust "${fixed[@]}" "out/$t" -seed=1 -runs=$runs -reload=0 \
       -use_cmp=0 -use_memmem=0 -dict="out/$t.dict" -seed_inputs=@"$t.list" -artifact_prefix="art/$t/" "new/$t" \
       > "$t.log" 2>&1 && grep -q "Done $runs runs" "$t.log"; then
    # Its coverage at the end: the same number on every run.
    echo "ok   $t: built, $n seeds, $runs runs, $(grep -o 'DONE *cov: [0-9]* ft: [0-9]*' "$t.log" | sed 's/DONE *//')"
  else
    tail -20 "$t.log"; echo "FAIL: $t did not run $runs inputs"; status=1
  fi
done
exit $status
