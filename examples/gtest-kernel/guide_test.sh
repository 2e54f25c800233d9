#!/bin/sh
# docs/testing-your-code.md, followed as a reader would: installs this build into BUILD/testing-guide/prefix and
# runs every block of the guide marked `<!-- guide: run -->` (must exit 0) or `<!-- guide: run, exits N -->` (must
# exit N: 1 for a ricochet command that fails, 8 for ctest with failing tests), in the guide's order, each from the same fresh folder, with RICOCHET_PREFIX, RICOCHET_BUILD and PATH set
# as the guide asks. Then checks what the guide says the reader sees: the BounceSpeed log with its lines, the
# SVG, and JUnit reports with a failing test case. Writes only under BUILD/testing-guide.
#   guide_test.sh SETTINGS    (SETTINGS: the shell file examples/CMakeLists.txt generates)
set -eu
. "$1"
work=$build_dir/testing-guide
guide=$source_dir/docs/testing-your-code.md
. "$source_dir/examples/plugin/example_steps.sh"
rm -rf "$work"
mkdir -p "$work/home" "$work/blocks"

install_ricochet
export RICOCHET_PREFIX="$prefix" RICOCHET_BUILD="$build_dir" PATH="$prefix/bin:$PATH"
# The reader's compilers are the ones this build used.
export CC="$cc" CXX="$cxx" CMAKE_GENERATOR="$generator" CMAKE_MAKE_PROGRAM="$make_program"

# Each marked block into blocks/N.sh, its expected status into blocks/N.expect.
awk -v dir="$work/blocks" '
  /^<!-- guide: run, exits [0-9]+ -->$/ { want = $5 + 0; next }
  /^<!-- guide: run -->$/ { want = 0; next }
  want != "" && /^```sh$/ { n++; file = sprintf("%s/%02d.sh", dir, n); print want > (dir "/" sprintf("%02d", n) ".expect"); inside = 1; next }
  inside && /^```$/ { inside = 0; want = ""; close(file); next }
  inside { print > file }
' "$guide"
count=$(ls "$work/blocks"/*.sh | wc -l)
[ "$count" -ge 8 ] || fail "only $count marked blocks in $guide"
# Every sh block of the guide is marked: none is left untried.
all=$(grep -c '^```sh$' "$guide")
[ "$all" = "$count" ] || fail "$guide has $all sh blocks, $count marked to run"

for block in "$work/blocks"/*.sh; do
  n=$(basename "$block" .sh)
  want=$(cat "$work/blocks/$n.expect")
  echo "== block $n (expects exit status $want)"
  sed 's/^/   /' "$block"
  set +e
  (cd "$work/home" && sh -e "$block") >"$work/blocks/$n.out" 2>&1
  status=$?
  set -e
  [ "$status" = "$want" ] || { tail -n 40 "$work/blocks/$n.out"; fail "block $n exits $status, expected $want"; }
done

echo "== what the guide says the reader sees"
home=$work/home
log=$home/mygame/found/BounceSpeed-2ef701f6342b2f5e.scene
[ -f "$log" ] || fail "no $log"
# The log's lines the guide shows, in its order.
sed -n '/^  ```text$/,/^  ```$/p' "$guide" | sed '1d;$d;s/^  //' >"$work/shown.txt"
[ -s "$work/shown.txt" ] || fail "the guide shows no log"
grep -vE '^(ricochet |from |expect state )' "$log" >"$work/log.txt"
diff "$work/shown.txt" "$work/log.txt" || fail "the log differs from what the guide shows"
# Step 6's next failure of the fixed bounce: a subnormal velocity.
grep -lx 'ball 0 0 0 1e-323' "$home"/mygame/found/BounceSpeed-*.scene >/dev/null ||
  fail "no BounceSpeed log of a ball moving (0, 1e-323), as the guide says"
grep -q '^<svg' "$home/bounce.svg" || fail "no SVG drawn"
ls "$home/mygame/found-fuzz/"*.scene >/dev/null 2>&1 || fail "the fuzz campaign saved no log"
for f in "$home/mygame/found-fuzz/"*.scene; do
  grep -qx 'domain coordinates 1000000' "$f" && grep -qx 'domain no-subnormals' "$f" && grep -qx 'check boundary' "$f" ||
    { cat "$f"; fail "$f is not the boundary failure in the domain the guide shows"; }
done
for report in ctest-junit.xml replay-junit.xml; do
  grep -q '<failure' "$home/$report" || fail "$report has no failing test case"
done
echo "PASS"
