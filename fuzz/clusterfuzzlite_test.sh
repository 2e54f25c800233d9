#!/bin/bash
# Runs .clusterfuzzlite/build.sh the way ClusterFuzzLite does, with the local clang, into temporary
# $OUT/$SRC/$WORK folders; checks that every target, its dictionary and its seed zip land in $OUT and that
# each target runs every one of its seeds and 100 inputs more. Usage: clusterfuzzlite_test.sh SOURCE_DIR [CC CXX]
set -eu
SRC_DIR="$(cd "$1" && pwd)"
export CC="${2:-clang-14}" CXX="${3:-clang++-14}"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
export SRC="$TMP/src" WORK="$TMP/work" OUT="$TMP/out" RICOCHET_SRC="$SRC_DIR"
mkdir -p "$SRC" "$WORK" "$OUT"
export CFLAGS="-O1 -fno-omit-frame-pointer -gline-tables-only -fsanitize=address,undefined -fno-sanitize-recover=all -fsanitize=fuzzer-no-link"
export CXXFLAGS="$CFLAGS"
export LIB_FUZZING_ENGINE="-fsanitize=fuzzer"
bash "$SRC_DIR/.clusterfuzzlite/build.sh" > "$TMP/build.log" 2>&1 || { tail -40 "$TMP/build.log"; echo "FAIL: build.sh"; exit 1; }
status=0
for t in parser static sweep scene disc meet; do
  for f in "$OUT/$t" "$OUT/$t.dict" "$OUT/${t}_seed_corpus.zip"; do
    [ -s "$f" ] || { echo "FAIL: $f missing"; status=1; }
  done
  [ -x "$OUT/$t" ] || continue
  mkdir -p "$TMP/seeds/$t" && (cd "$TMP/seeds/$t" && unzip -q -o "$OUT/${t}_seed_corpus.zip")
  n=$(find "$TMP/seeds/$t" -type f | wc -l)
  # libFuzzer counts the seeds it loads among its -runs (and loads them all whatever -runs says): the seeds
  # and 100 more, so the check does not depend on how many seeds the corpus has grown to.
  runs=$((n + 100))
  if RICOCHET_KERNEL=robust "$OUT/$t" -runs=$runs -dict="$OUT/$t.dict" "$TMP/seeds/$t" > "$TMP/$t.log" 2>&1 &&
     grep -q "Done $runs runs" "$TMP/$t.log"; then
    echo "ok   $t: built, $n seeds, $runs runs"
  else
    tail -20 "$TMP/$t.log"; echo "FAIL: $t did not run $runs inputs"; status=1
  fi
done
exit $status
