#!/bin/bash -eu
# Builds every ricochet fuzz target with the engine's compilers and flags ($CC $CXX $CFLAGS $CXXFLAGS
# $LIB_FUZZING_ENGINE) into $OUT, each with <target>_seed_corpus.zip and <target>.dict.
# ClusterFuzzLite/OSS-Fuzz run it in their builder image; fuzz/clusterfuzzlite_test.sh runs it locally.
# The shebang's -eu holds only when the file is run as a program; `bash build.sh` (fuzz/clusterfuzzlite_test.sh, the
# OSS-Fuzz helper) needs it said here, or a failed build goes on to copy what is not there.
set -eu
SRC_DIR="${RICOCHET_SRC:-$SRC/ricochet}"
BUILD="${WORK:-/tmp}/ricochet-fuzz-build"
TARGETS="parser static sweep scene disc meet"

# -ffp-contract=off comes from the project; the engine's sanitizer flags arrive in CFLAGS/CXXFLAGS. A unity build
# (each target's files compiled in batches): the same targets in under half the time (72 s against 160 s for
# fuzz/clusterfuzzlite_test.sh on 2 cores).
cmake -S "$SRC_DIR" -B "$BUILD" -G Ninja \
  -DCMAKE_C_COMPILER="$CC" -DCMAKE_CXX_COMPILER="$CXX" \
  -DCMAKE_C_FLAGS="$CFLAGS" -DCMAKE_CXX_FLAGS="$CXXFLAGS" \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_UNITY_BUILD=ON \
  -DRICOCHET_TESTS=OFF -DRICOCHET_BENCH=OFF \
  -DRICOCHET_FUZZ_ENGINE="$LIB_FUZZING_ENGINE"
cmake --build "$BUILD" -j"$(nproc)" --target $(for t in $TARGETS; do printf 'fuzz_%s ' "$t"; done)

for t in $TARGETS; do
  cp "$BUILD/fuzz/fuzz_$t" "$OUT/$t"
  cp "$SRC_DIR/fuzz/$t.dict" "$OUT/$t.dict"
  rm -f "$OUT/${t}_seed_corpus.zip"
  # Seeds: the committed regression inputs; the parser also starts from every replay log but those of
  # replays/peers/, which name the peer kernels: the parser target registers none, so it would reject each
  # at its kernel line, the same way.
  (cd "$SRC_DIR/fuzz/corpus/$t" && zip -q -r "$OUT/${t}_seed_corpus.zip" .)
  if [ "$t" = parser ]; then
    (cd "$SRC_DIR/replays" && zip -q -r "$OUT/${t}_seed_corpus.zip" . -i '*.scene' -x 'peers/*')
  fi
done
