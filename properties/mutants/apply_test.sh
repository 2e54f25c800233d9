#!/bin/sh
# Every mutant still applies to the sources (run.sh stops at the first that does not): a change to core/
# that moves a mutated line must regenerate its patch. Usage: apply_test.sh SOURCE_DIR
set -u
src="$1"
status=0
n=0
for p in "$src"/properties/mutants/*.patch; do
  n=$((n + 1))
  git -C "$src" apply --check "$p" 2>/dev/null || { echo "FAIL: $(basename "$p") does not apply"; status=1; }
done
[ "$n" -ge 20 ] || { echo "FAIL: only $n mutants"; status=1; }
[ "$status" = 0 ] && echo "ok: all $n mutants apply"
exit "$status"
