#!/usr/bin/env bash
# Refreshes apt's package lists (as root), trying again when a mirror answers badly for a moment: Debian's
# mirrors sync several times a day, and an index fetched mid-sync fails its size or hash check ("File has
# unexpected size ... Mirror sync in progress?") for a few minutes. One such answer must not fail a build.
#
#   cli/apt-update.sh      exit 0 once `apt-get update` succeeds; exit 1, with apt's last error, after
#                          APT_UPDATE_TRIES tries (default 3), waiting 15 s, then 30 s... between them
#
# On exit 1 apt keeps the lists it had and the ones it did fetch ("ignored, or old ones used instead"): the
# callers (cli/dev.sh, .ci/cross.sh) go on to install and fail only where the install itself fails.
# Environment: APT_UPDATE_TRIES, APT_UPDATE_WAIT (seconds, the first wait; default 15), APT_GET (default
# apt-get: the tests put a stand-in there).
set -uo pipefail
tries=${APT_UPDATE_TRIES:-3}
wait_s=${APT_UPDATE_WAIT:-15}
apt_get=${APT_GET:-apt-get}
err=$(mktemp)
trap 'rm -f "$err"' EXIT
for ((i = 1; i <= tries; i++)); do
  # Acquire::Retries: apt itself fetches a failed file again (connection resets) before giving up on it.
  if DEBIAN_FRONTEND=noninteractive "$apt_get" update -q -o Acquire::Retries=3 >/dev/null 2>"$err"; then
    exit 0
  fi
  if [ "$i" -lt "$tries" ]; then
    echo "apt-update: apt-get update failed (try $i of $tries); trying again in $((wait_s * i)) s:" >&2
    grep -E '^(E|W):' "$err" | head -n 3 | sed 's/^/  /' >&2
    sleep $((wait_s * i))
  fi
done
echo "apt-update: apt-get update failed $tries times; apt keeps the lists it has. Its last error:" >&2
grep -E '^(E|W):' "$err" | head -n 5 | sed 's/^/  /' >&2
exit 1
