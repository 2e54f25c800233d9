#!/bin/sh
# cli/apt-update.sh against a stand-in apt-get that fails its first N updates the way a mirror mid-sync does.
# Usage: apt_update_test.sh SOURCE_DIR
set -u
src=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat > "$tmp/apt-get" <<'STANDIN'
#!/bin/sh
# Counts its calls in $COUNT; fails while the count is at most $FAILS.
n=$(( $(cat "$COUNT" 2>/dev/null || echo 0) + 1 )); echo $n > "$COUNT"
[ "$1" = update ] || { echo "E: stand-in knows update only" >&2; exit 100; }
if [ "$n" -le "$FAILS" ]; then
  echo "E: Failed to fetch http://deb.debian.org/x/Packages.xz  File has unexpected size (1 != 2). Mirror sync in progress?" >&2
  exit 100
fi
exit 0
STANDIN
chmod +x "$tmp/apt-get"
status=0
# run FAILS TRIES WANT_RC WANT_CALLS: what apt-update.sh returns and how often it asked.
run() {
  rm -f "$tmp/count"
  COUNT="$tmp/count" FAILS=$1 APT_UPDATE_TRIES=$2 APT_UPDATE_WAIT=0 APT_GET="$tmp/apt-get" \
    bash "$src/cli/apt-update.sh" 2>"$tmp/err"
  rc=$? calls=$(cat "$tmp/count")
  if [ "$rc" = "$3" ] && [ "$calls" = "$4" ]; then
    echo "ok   $1 failures, $2 tries: exit $rc after $calls calls"
  else
    echo "FAIL $1 failures, $2 tries: exit $rc after $calls calls, expected exit $3 after $4"; cat "$tmp/err"; status=1
  fi
}
run 0 4 0 1   # a good mirror: one call
run 2 4 0 3   # mid-sync twice, then good
run 9 3 1 3   # never good: gives up after its tries, exit 1
grep -q "Mirror sync in progress" "$tmp/err" || { echo "FAIL: apt's last error not shown"; status=1; }
exit $status
