#!/usr/bin/env bash
# Opens every lesson in the inspector's real window (under a virtual X server), walks to its last step with
# a script and saves a screenshot: each lesson starts, renders and closes by itself in window mode.
set -euo pipefail
program=$1
lessons=$2
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export XDG_CONFIG_HOME="$work/config"
count=0
for file in "$lessons"/[0-9][0-9]-*.md; do
  number=$((10#$(basename "$file" | cut -c1-2)))
  steps=$(grep -c '"id":' "$file")
  printf 'lesson step %d\n' "$steps" > "$work/script.txt"
  "$here/xvfb.sh" 1600x1000 \
    "$program" lesson "$number" --script "$work/script.txt" --screenshot "$work/lesson-$number.png" \
    2> "$work/stderr" || { echo "lesson $number failed:"; cat "$work/stderr"; exit 1; }
  test -s "$work/lesson-$number.png" || { echo "lesson $number: no screenshot"; exit 1; }
  if [ -s "$work/stderr" ]; then echo "lesson $number:"; cat "$work/stderr"; exit 1; fi
  count=$((count + 1))
done
test "$count" -eq 14 || { echo "expected 14 lessons, ran $count"; exit 1; }
echo "all $count lessons opened in the window"
