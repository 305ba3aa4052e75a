#!/usr/bin/env bash
# The bench programs write their CSV as RFC 4180 (a scene named with a comma is one quoted cell) and atomically (a
# missing folder is refused before the run, nothing is left beside the file); --csv - puts it on standard output.
set -uo pipefail
world=$1
resolve=$2
scene=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "$*"; failures=$((failures + 1)); }

mkdir "$work/out"
cp "$scene" "$work/a, \"quoted\" scene.json"
"$world" "$work/a, \"quoted\" scene.json" --frames 2 --repeats 1 --csv "$work/out/world.csv" > /dev/null ||
  fail "impulse-bench-world failed"
sed -n 2p "$work/out/world.csv" | grep -q '^"a, ""quoted"" scene.json",' || fail "the scene's cell is not quoted: $(sed -n 2p "$work/out/world.csv")"
[ "$(ls -A "$work/out")" = world.csv ] || fail "left beside the CSV: $(ls -A "$work/out")"
"$world" - --frames 2 --repeats 1 --csv - < "$scene" > "$work/stdout" 2> "$work/stderr" || fail "--csv - failed"
[ "$(head -c 6 "$work/stdout")" = "scene," ] || fail "--csv - did not print the CSV alone: $(head -n 1 "$work/stdout")"
grep -q "^<stdin>" "$work/stderr" || fail "the table did not go to stderr"

"$resolve" --boxes 1 --repeats 1 --min-seconds 0.001 --csv "$work/out/resolve.csv" > /dev/null || fail "impulse-bench-resolve failed"
[ "$(head -n 1 "$work/out/resolve.csv")" = "boxes,contacts,iterations,friction,off_ns_per_contact,on_ns_per_contact,recording_ratio" ] ||
  fail "impulse-bench-resolve's header: $(head -n 1 "$work/out/resolve.csv")"
[ "$(wc -l < "$work/out/resolve.csv")" = 2 ] || fail "impulse-bench-resolve wrote $(wc -l < "$work/out/resolve.csv") lines"

for program in "$world $scene" "$resolve"; do
  code=0
  $program --csv "$work/missing/x.csv" > "$work/stdout" 2> "$work/stderr" || code=$?
  [ "$code" = 2 ] || fail "$program --csv into a missing folder: exit code $code, expected 2"
  grep -q "cannot write '$work/missing/x.csv': No such file or directory" "$work/stderr" || fail "$program: $(cat "$work/stderr")"
  [ ! -s "$work/stdout" ] || fail "$program ran before refusing its --csv"
done
test "$failures" = 0 || exit 1
echo "the bench programs write quoted CSV atomically, refuse an unwritable --csv before running, and take -"
