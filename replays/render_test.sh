#!/bin/sh
# `ricochet render` of one corpus log draws it and marks the failure `replay` reports, the same text: a log
# that expects a failure is drawn with that failure marked, a log that expects none is drawn unmarked.
#   render_test.sh RICOCHET LOG
set -u
ricochet=$1 log=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL $log: $*"; for f in replay render; do echo "--- $f:"; cat "$dir/$f"; done; exit 1; }

"$ricochet" replay "$log" >"$dir/replay" 2>&1 || fail "replay: exit $?"
"$ricochet" render "$log" -o "$dir/x.svg" >"$dir/render" 2>&1 || fail "render: exit $?"
tail -n 1 "$dir/x.svg" | grep -qx '</svg>' || fail "the picture does not end with </svg>"
want=$(sed -n 's/.*expected failure reproduced: //p' "$dir/replay")
got=$(sed -n 's/^wrote .* (marked: \(.*\))$/\1/p' "$dir/render")
[ "$got" = "$want" ] || fail "render marks '$got'; replay reports '$want'"
echo "ok $log${want:+: $want}"
