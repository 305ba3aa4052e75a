#!/usr/bin/env bash
# The bash completion script the build generates from the program's flags completes what a user types: a command,
# a flag of that command, the names a choice takes, files for a file argument, and commands after `help`.
# Called as bash's completion would call it, with COMP_WORDS and COMP_CWORD set.
set -uo pipefail
script=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# shellcheck source=/dev/null
source "$script" || { echo "cannot source $script"; exit 1; }
complete -p impulse-lab > /dev/null || { echo "the script does not register a completion for impulse-lab"; exit 1; }

failures=0
# check "EXPECTED REPLY (sorted, space-separated)" WORD...  (the last word is the one being completed)
check() {
  local expected=$1
  shift
  COMP_WORDS=("$@")
  COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
  COMPREPLY=()
  _impulse_lab
  local got
  got=$(printf '%s\n' "${COMPREPLY[@]}" | sort | tr '\n' ' ' | sed 's/ $//')
  if [ "$got" != "$expected" ]; then
    echo "completing '$*': got '$got', expected '$expected'"
    failures=$((failures + 1))
  fi
}

check "resolve run" impulse-lab r
check "diff" impulse-lab dif
check "--frames" impulse-lab run scene.json --fr
check "--keep-partial" impulse-lab run --ke
check "--explain" impulse-lab resolve --exp
check "pgs pgs_split" impulse-lab run scene.json --preset pg
check "csv" impulse-lab diff a.json b.json --format c
check "resolve run" impulse-lab help r
check "" impulse-lab run scene.json --frames ""
mkdir "$work/scenes" && touch "$work/scenes/stack.json" "$work/scenes/sphere.json"
check "$work/scenes/sphere.json $work/scenes/stack.json" impulse-lab run "$work/scenes/s"
check "$work/scenes/stack.json" impulse-lab resolve case.json --trace "$work/scenes/st"
check "$work/scenes" impulse-lab bench --out "$work/sc"
test "$failures" = 0 || exit 1
echo "the generated completion completes commands, flags, choices and files"
