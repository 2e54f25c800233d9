#!/bin/sh
# The replay corpus on both big-number backends: corpus_fingerprint built against the GMP core and against the
# Boost one prints the same bytes for every log of replays/ but replays/peers/ (whose kernels live in the peers'
# libraries, not in this core) under every kernel, with the logs' checks and with all of them.
#   bignum_corpus_test.sh GMP_FINGERPRINT BOOST_FINGERPRINT SOURCE_DIR
# Writes only under a temporary folder.
set -eu
gmp=$1 boost=$2 src=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$src"
find replays -name '*.scene' -not -path 'replays/peers/*' | LC_ALL=C sort >"$tmp/logs"
n=$(wc -l <"$tmp/logs")
[ "$n" -gt 40 ] || { echo "FAIL: only $n logs found under $src/replays"; exit 1; }
# shellcheck disable=SC2046
"$gmp" $(cat "$tmp/logs") >"$tmp/gmp.txt"
# shellcheck disable=SC2046
"$boost" $(cat "$tmp/logs") >"$tmp/boost.txt"
runs=$(grep -c ' hash ' "$tmp/gmp.txt")
if ! cmp -s "$tmp/gmp.txt" "$tmp/boost.txt"; then
  echo "FAIL: the GMP and Boost cores differ; first differing lines (gmp <, boost >):"
  diff "$tmp/gmp.txt" "$tmp/boost.txt" | head -n 12
  exit 1
fi
failed=$(grep '^  ' "$tmp/gmp.txt" | grep -vc '^  ok$' || true)
echo "$n logs, $runs runs ($failed of them with a failure or step error): identical on GMP and on Boost.Multiprecision"
