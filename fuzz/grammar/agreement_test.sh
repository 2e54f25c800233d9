#!/bin/sh
# The grammar oracle on fixed inputs (CTest fuzz_grammar_agreement): the reader and the independent
# acceptor agree on every replay log and committed parser input given, and on every malformed kind of
# malformed.sh, both reject at the line of the kind's diagnostic. Temporary folder only.
#   agreement_test.sh GRAMMAR_AGREEMENT MALFORMED_SH INPUT...
set -u
tool=$1
malformed=$2
shift 2
"$tool" "$@" || { echo "FAIL: the reader and the acceptor disagree on a committed input"; exit 1; }
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
kinds=$(sh "$malformed" --kinds)
n=0
for kind in $kinds; do
  want=$(sh "$malformed" --write "$kind" "$dir/$kind.scene") || { echo "FAIL: malformed.sh cannot write $kind"; exit 1; }
  line=${want%%:*}
  out=$("$tool" --reject-at "$line" "$dir/$kind.scene") || { echo "$out"; echo "FAIL: malformed kind $kind ($want)"; exit 1; }
  echo "$out" | head -1
  n=$((n + 1))
done
# The kinds come from malformed.sh's own case labels: an empty list would prove nothing.
[ "$n" -ge 25 ] || { echo "FAIL: only $n malformed kinds found"; exit 1; }
echo "malformed kinds: $n rejected by both at the diagnostic's line"
