#!/usr/bin/env bash
# Ctrl-C in the middle of a long `run` (and SIGTERM): exit 130 (143), one line on stderr, the existing trace and
# states files unchanged byte for byte, and no temporary file left beside them.
set -euo pipefail
program=$1
scene=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for signal in INT TERM; do
  printf '{"an": "earlier trace"}\n' > "$work/out.json"
  printf 'earlier,states\n' > "$work/out.csv"
  cp "$work/out.json" "$work/out.json.before"
  cp "$work/out.csv" "$work/out.csv.before"
  "$program" run "$scene" --frames 100000 --trace "$work/out.json" --states "$work/out.csv" \
    > "$work/stdout" 2> "$work/stderr" &
  pid=$!
  sleep 1
  kill -s "$signal" "$pid"
  code=0
  wait "$pid" || code=$?
  expected=130
  [ "$signal" = TERM ] && expected=143
  test "$code" = "$expected" || { echo "SIG$signal: exit code $code, expected $expected"; cat "$work/stderr"; exit 1; }
  test "$(wc -l < "$work/stderr")" = 1 || { echo "SIG$signal: stderr is not one line:"; cat "$work/stderr"; exit 1; }
  grep -q "interrupted (SIG$signal)" "$work/stderr" || { cat "$work/stderr"; exit 1; }
  cmp "$work/out.json" "$work/out.json.before" || { echo "SIG$signal: out.json changed"; exit 1; }
  cmp "$work/out.csv" "$work/out.csv.before" || { echo "SIG$signal: out.csv changed"; exit 1; }
  rm "$work/out.json.before" "$work/out.csv.before" "$work/stdout" "$work/stderr"
  left=$(ls -A "$work" | grep -v -x -e out.json -e out.csv || true)
  test -z "$left" || { echo "SIG$signal: left behind: $left"; exit 1; }
done
echo "interrupted runs exit 130 and 143, leave the earlier files unchanged and no temporary file"
