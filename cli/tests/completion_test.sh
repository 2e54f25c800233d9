#!/bin/sh
# Shell completion (cli/completion.cpp): what `ricochet __complete` offers after given words, and the bash
# and zsh scripts of `ricochet completion`, run with the words a user would have typed. One case per call.
#   completion_test.sh RICOCHET CASE
#   completion_test.sh --cases     prints every case (the case labels below)
set -u
if [ "$1" = --cases ]; then sed -n 's/^  \([a-z][a-z0-9-]*\)) .*/\1/p' "$0"; exit 0; fi
ricochet=$1 case=$2
case "$ricochet" in /*) ;; *) ricochet=$PWD/$ricochet ;; esac  # the bash case runs it from another folder
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

fail() { echo "FAIL $case: $*"; for f in out err; do [ -f "$dir/$f" ] && { echo "--- $f:"; cat "$dir/$f"; }; done; exit 1; }
# offers 'MODE CANDIDATE...' WORD...: `ricochet __complete -- WORD...` prints exactly the mode, then the
# candidates, one per line (candidates never hold a space).
offers() {
  want=$1; shift
  "$ricochet" __complete -- "$@" >"$dir/out" 2>"$dir/err" || fail "__complete -- $* exited $?"
  got=$(tr '\n' ' ' <"$dir/out")
  [ "$got" = "$want " ] || fail "__complete -- $*: offered '$got', wanted '$want'"
}

# Every kernel, as completion offers them: the built-in four, then the peers this build has.
kernels="lecture-float lecture-double robust exact${RICOCHET_PEER_KERNELS:+ $RICOCHET_PEER_KERNELS}"

case "$case" in
  commands)        offers 'words run record replay render reduce check bench fuzz help completion' ""
                   offers 'words replay' rep
                   offers 'words record replay render reduce' re
                   offers 'words' __c ;;
  options)         offers 'words --help --hashes' replay --h
                   offers 'words -o' render x.scene -o
                   offers 'files' run -- --k ;;
  kernel-values)   offers "words $kernels plugin:" run --kernel ""
                   offers 'words robust' run x.scene --kernel ro
                   offers 'words robust' reduce x.scene --kernel ro
                   # bash splits --kernel=ro at '='; zsh and fish keep it one word.
                   offers "words $kernels plugin:" run --kernel = ""
                   offers 'words plugin:' fuzz --kernel p
                   offers 'words lecture-float lecture-double' run --kernel = l
                   offers 'words --kernel=robust' run --kernel=r
                   offers 'words static sweep scene' fuzz --target s
                   offers 'words disc' fuzz --target d ;;
  validator-values) offers 'words failure all' render --view ""
                   offers 'words bash zsh' completion ""
                   offers 'words record' help rec ;;
  paths)           offers 'files' run ""
                   offers 'words' run x.scene ""
                   offers 'files' replay a.scene ""
                   offers 'files' render x.scene -o ""
                   offers 'files' reduce x.scene -o ""
                   offers 'dirs' fuzz --cache-dir ""
                   offers 'files' replay --plugin ""
                   offers 'files' replay --junit ""
                   offers 'files' check --sarif ""
                   offers 'files' fuzz --junit ""
                   offers 'dirs' check --replay-dir = ""
                   offers 'words' run --frames ""
                   offers 'words' run x.scene --frames 3 "" ;;
  hidden)          "$ricochet" help >"$dir/out" 2>&1 || fail "help exited $?"
                   ! grep -q __complete "$dir/out" || fail "help lists __complete"
                   grep -q '^  completion ' "$dir/out" || fail "help lists no completion"
                   "$ricochet" __complet >"$dir/out" 2>"$dir/err"; rc=$?
                   [ $rc = 2 ] || fail "exit $rc for a typo of __complete, expected 2"
                   ! grep -q __complete "$dir/err" || fail "the typo is told about __complete"  ;;
  bad-shell)       "$ricochet" completion tcsh >"$dir/out" 2>"$dir/err"; rc=$?
                   [ $rc = 2 ] || fail "exit $rc, expected 2"
                   grep -q 'tcsh not in {bash,zsh}' "$dir/err" || fail "the error does not name the shells"
                   [ ! -s "$dir/out" ] || fail "a script was printed"  ;;
  bash)            command -v bash >/dev/null || { echo "skip $case: no bash"; exit 77; }
                   "$ricochet" completion bash >"$dir/ricochet.bash" || fail "completion bash exited $?"
                   bash -n "$dir/ricochet.bash" || fail "the bash script does not parse"
                   mkdir "$dir/logs"; : >"$dir/logs/a.scene"; : >"$dir/logs/b.txt"; mkdir "$dir/logs/sub"
                   # complete WORD...: COMPREPLY after the words, the last being completed, one per line.
                   cat >"$dir/try.bash" <<'EOF'
source "$1"; shift
complete_words() { COMP_WORDS=("$ricochet" "$@"); COMP_CWORD=$#; COMPREPLY=(); _ricochet; printf '%s\n' "${COMPREPLY[@]}"; }
cd "$1"; shift
echo "[rep]"; complete_words rep
echo "[kernel]"; complete_words run x.scene --kernel ""
echo "[kernel=]"; complete_words run --kernel = l
echo "[file]"; complete_words run a
echo "[dir]"; complete_words fuzz --cache-dir ""
echo "[view]"; complete_words render x.scene --view a
EOF
                   ricochet=$ricochet bash "$dir/try.bash" "$dir/ricochet.bash" "$dir/logs" >"$dir/out" 2>"$dir/err" ||
                     fail "the script failed"
                   # shellcheck disable=SC2086 # $kernels: one word per kernel
                   # shellcheck disable=SC2086 # $kernels: one word per kernel
                   printf '%s\n' "[rep]" replay "[kernel]" $kernels plugin: "[kernel=]" \
                     lecture-float lecture-double "[file]" a.scene "[dir]" sub "[view]" all >"$dir/want"
                   cmp -s "$dir/out" "$dir/want" || { echo "--- wanted:"; cat "$dir/want"; fail "bash completed otherwise"; }  ;;
  zsh)             command -v zsh >/dev/null || { echo "skip $case: no zsh"; exit 77; }
                   "$ricochet" completion zsh >"$dir/_ricochet" || fail "completion zsh exited $?"
                   zsh -n "$dir/_ricochet" || fail "the zsh script does not parse"
                   # compsys itself needs a terminal: its builtins are stood in for, printing what they are given.
                   cat >"$dir/try.zsh" <<'EOF'
compdef() { print "compdef $*"; }
compadd() { [[ $1 == -Q ]] && shift; [[ $1 == -- ]] && shift; print -l -- "$@"; }
compset() { print "compset $*"; }
_files() { print "_files $*"; }
source $1
try() { words=($ricochet "$@"); CURRENT=$#words; _ricochet; }
print "[rep]"; try rep
print "[kernel=]"; try run --kernel=l
print "[file]"; try run a
print "[dir]"; try fuzz --cache-dir ""
EOF
                   ricochet=$ricochet zsh -f "$dir/try.zsh" "$dir/_ricochet" >"$dir/out" 2>"$dir/err" || fail "the script failed"
                   printf '%s\n' "compdef _ricochet ricochet" "[rep]" replay "[kernel=]" --kernel=lecture-float \
                     --kernel=lecture-double "[file]" "compset -P *=" "_files " "[dir]" "compset -P *=" "_files -/" >"$dir/want"
                   cmp -s "$dir/out" "$dir/want" || { echo "--- wanted:"; cat "$dir/want"; fail "zsh completed otherwise"; }  ;;
  *) echo "unknown case $case" >&2; exit 1  ;;
esac
echo "ok $case"
