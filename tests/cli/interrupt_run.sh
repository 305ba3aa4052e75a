#!/usr/bin/env bash
# Ctrl-C in the middle of a long `run` (and SIGTERM): exit 130 (143), the summary of the frames done on stdout and
# one line on stderr saying how many were done. Without --keep-partial the existing trace and states files stay
# unchanged byte for byte; with it they hold exactly the frames done, and validate accepts the trace. Either way no
# temporary file is left beside them.
set -euo pipefail
program=$1
scene=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

fail() { echo "$*"; echo "--- stderr:"; cat "$work/stderr"; exit 1; }

# interrupt SIGNAL [FLAGS...]: starts the run, signals it after a second, checks the exit code and the one line on
# stderr, and leaves the number of frames done in $done.
interrupt() {
  local signal=$1
  shift
  "$program" run "$scene" --frames 100000 --trace "$work/out.json" --states "$work/out.csv" "$@" \
    > "$work/stdout" 2> "$work/stderr" &
  local pid=$!
  sleep 1
  kill -s "$signal" "$pid"
  local code=0
  wait "$pid" || code=$?
  local expected=130
  [ "$signal" = TERM ] && expected=143
  test "$code" = "$expected" || fail "SIG$signal: exit code $code, expected $expected"
  # One line, besides run's early notes that the trace and the states will not hold the whole run.
  test "$(grep -vEc 'note: --(trace|states): at ' "$work/stderr")" = 1 || fail "SIG$signal: stderr is not one line"
  grep -q "interrupted (SIG$signal) after [0-9]* of 100000 frames" "$work/stderr" || fail "SIG$signal: no interrupted line"
  done=$(sed -n 's/.* after \([0-9]*\) of 100000 frames.*/\1/p' "$work/stderr")
  test "$done" -gt 0 || fail "SIG$signal: no frame done in a second"
  # The summary of the frames done: its header and its table, ending with the last frame done.
  grep -q ": 210 bodies, ground, $done of 100000 frames of" "$work/stdout" || fail "SIG$signal: no summary header"
  grep -q "^  *$((done - 1))  " "$work/stdout" || fail "SIG$signal: the summary does not end with frame $((done - 1))"
  grep -q "iteration limit (or every sweep) used in [0-9]* of $done frames" "$work/stdout" ||
    fail "SIG$signal: the summary does not count $done frames"
}

no_temporaries() {
  local left
  left=$(ls -A "$work" | grep -v -x -e out.json -e out.csv -e stdout -e stderr -e validate || true)
  test -z "$left" || fail "left behind: $left"
}

for signal in INT TERM; do
  printf '{"an": "earlier trace"}\n' > "$work/out.json"
  printf 'earlier,states\n' > "$work/out.csv"
  cp "$work/out.json" "$work/out.json.before"
  cp "$work/out.csv" "$work/out.csv.before"
  interrupt "$signal"
  grep -q "nothing written, the files already there are unchanged" "$work/stderr" || fail "SIG$signal: says nothing of the files"
  cmp "$work/out.json" "$work/out.json.before" || fail "SIG$signal: out.json changed"
  cmp "$work/out.csv" "$work/out.csv.before" || fail "SIG$signal: out.csv changed"
  rm "$work/out.json.before" "$work/out.csv.before"
  no_temporaries
done

# --keep-partial: the frames done are written, and are valid. (A recording of the first five frames and one contact keeps the trace
# small; the states hold every frame done.)
for signal in INT TERM; do
  rm -f "$work/out.json" "$work/out.csv"
  interrupt "$signal" --keep-partial --record frames=0..4 --record contacts=0
  grep -q "the frames done are written" "$work/stderr" || fail "SIG$signal --keep-partial: says nothing of the files"
  "$program" validate "$work/out.json" > "$work/validate" 2>&1 || fail "SIG$signal: the partial trace is invalid: $(cat "$work/validate")"
  recorded=$((done < 5 ? done : 5))
  grep -q "valid trace (format version [0-9]*, $recorded frame" "$work/validate" ||
    fail "SIG$signal: the trace does not hold $recorded frames: $(cat "$work/validate")"
  last=$(tail -n 1 "$work/out.csv" | cut -d, -f1)
  test "$last" = $((done - 1)) || fail "SIG$signal: the states end with frame $last, not $((done - 1))"
  rows=$(($(wc -l < "$work/out.csv") - 1))
  test "$rows" = $((210 * (done + 1))) || fail "SIG$signal: $rows state rows, expected 210 x ($done + 1)"
  no_temporaries
done
echo "interrupted runs exit 130 and 143 with the summary of the frames done; without --keep-partial the earlier" \
  "files stay unchanged, with it the frames done are written and valid; no temporary file is left"
