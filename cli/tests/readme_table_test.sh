#!/bin/sh
# The command table of docs/cli.md (the rows starting "| `ricochet ") is true, flag for flag: each row names a
# command the program has, each flag a row lists is one that command's --help lists and the other way round, and
# each flag is used by some test (a line of a test script or of an add_test that names the command and the flag).
#   readme_table_test.sh RICOCHET SOURCE_DIR
set -u
ricochet=$1 src=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=1; }

# The table's rows: its first cell, with `\|` (an escaped bar inside a cell) turned into "/".
grep '^| `ricochet ' "$src/docs/cli.md" | sed 's/\\|/\//g; s/^| \([^|]*\) |.*/\1/' >"$dir/rows"
[ -s "$dir/rows" ] || { echo "FAIL: no command table in $src/docs/cli.md"; exit 1; }

# One line per backquoted form, "COMMAND WORDS|FLAG FLAG…": the leading lowercase words are the command,
# every -x or --word token a flag; "(the same flags)" after a form gives it the flags of the one before.
sed 's/` (the same flags)/ @same`/g' "$dir/rows" | grep -o '`[^`]*`' | tr -d '`' | sed 's/^ricochet //' |
  while read -r form; do
    cmd=$(echo "$form" | sed 's/^\(\([a-z][a-z]* *\)*\).*/\1/; s/ *$//')
    flags=$(echo " $form" | grep -oE -- '[ [/]-{1,2}[a-z][a-z0-9-]*' | sed 's/^.//' | sort -u | tr '\n' ' ')
    case "$form" in *@same*) flags=$prev ;; esac
    [ -n "$cmd" ] && echo "$cmd|$flags"
    prev=$flags
  done >"$dir/forms"

# Every command the program lists in its help has a row.
"$ricochet" help >"$dir/help" 2>&1 || fail "ricochet help: exit $?"
sed -n '/^Subcommands:$/,$p' "$dir/help" | sed -n 's/^  \([a-z][a-z-]*\) .*/\1/p' >"$dir/commands"
[ -s "$dir/commands" ] || fail "no Subcommands: in ricochet help"
while read -r c; do
  cut -d'|' -f1 "$dir/forms" | cut -d' ' -f1 | grep -qxF "$c" || fail "command '$c' (ricochet help) has no row in docs/cli.md's table"
done <"$dir/commands"

# Where a test may use a flag: the test scripts and the CMake files that add tests, read once, and the guide whose
# every command CTest package/testing_guide runs (examples/gtest-kernel/guide_test.sh).
find "$src/cli" "$src/bench" "$src/fuzz" "$src/core" "$src/harness" "$src/peers" "$src/app" "$src/properties" \
  "$src/replays" "$src/examples" \
  \( -name '*test.sh' -o -name CMakeLists.txt \) ! -name readme_table_test.sh -exec cat {} + >"$dir/tests" 2>/dev/null
cat "$src/docs/testing-your-code.md" >>"$dir/tests"

while IFS='|' read -r cmd flags; do
  # A build without benchmarks (RICOCHET_BENCH=OFF) has a `bench` that only says so.
  case "$cmd" in bench|bench\ *) grep -q '^  bench .*not in this build' "$dir/help" && { echo "skip $cmd: not built"; continue; } ;; esac
  # shellcheck disable=SC2086  # $cmd is the command's words
  if ! "$ricochet" $cmd --help >"$dir/cmdhelp" 2>&1; then
    fail "docs/cli.md row '$cmd': ricochet $cmd --help fails: $(head -n 1 "$dir/cmdhelp")"; continue
  fi
  # The options of its help, one per line as ",-o,--output,": the lines of its Options: section (up to the
  # first blank line) that start, after spaces, with a flag.
  sed -n '/^Options:$/,/^$/p' "$dir/cmdhelp" | grep -E '^ +-' | sed 's/^ *//; s/ .*//; s/{[^}]*}//g; s/^/,/; s/$/,/' |
    grep -vxF ',-h,--help,' >"$dir/have"
  last=${cmd##* }
  for f in $flags; do
    grep -qF -- ",$f," "$dir/have" || fail "docs/cli.md row '$cmd' lists $f, which ricochet $cmd --help does not"
    grep -F -- "$f" "$dir/tests" | grep -qwF -- "$last" || fail "docs/cli.md row '$cmd': no test uses $last with $f"
  done
  while read -r names; do
    listed=no
    for f in $flags; do case "$names" in *",$f,"*) listed=yes ;; esac; done
    [ "$listed" = yes ] || fail "ricochet $cmd --help has $names, which the docs/cli.md row does not list"
  done <"$dir/have"
done <"$dir/forms"

[ "$failed" = 0 ] || exit 1
echo "ok: $(wc -l <"$dir/forms") forms of docs/cli.md's command table, $(cut -d'|' -f2 "$dir/forms" | wc -w) flags"
