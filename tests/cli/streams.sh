#!/usr/bin/env bash
# The program as a shell meets it: `resolve - --trace - < case.json` prints a trace another command reads from a pipe;
# a FIFO and a symlink given as --trace stay what they were and receive the trace; a path naming standard output
# (here a link to /proc/self/fd/1, never /dev/stdout itself) is standard output; a screenshot goes down a pipe but
# not to a terminal.
set -uo pipefail
program=$1
case_file=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "$*"; failures=$((failures + 1)); }

"$program" resolve "$case_file" --trace "$work/expected.json" > /dev/null || { echo "resolve failed"; exit 1; }

# Standard input to standard output, and down a pipe into validate.
"$program" resolve - --trace - < "$case_file" > "$work/piped.json" 2> "$work/stderr" || fail "resolve - --trace - failed"
cmp -s "$work/piped.json" "$work/expected.json" || fail "resolve - --trace - did not print exactly the trace"
grep -q "velocity phase" "$work/stderr" || fail "the summary did not go to stderr"
verdict=$("$program" resolve - --trace - < "$case_file" 2> /dev/null | "$program" validate -)
[ "$verdict" = "<stdin>: valid trace (format version 2, 1 frame, 2 iterations)" ] || fail "validate - said: $verdict"

# A FIFO read by another process.
mkfifo "$work/trace.fifo"
cat "$work/trace.fifo" > "$work/from-fifo.json" &
reader=$!
"$program" resolve "$case_file" --trace "$work/trace.fifo" > /dev/null || fail "resolve --trace FIFO failed"
# Replaced by a file, the FIFO would leave its reader waiting for ever.
[ -p "$work/trace.fifo" ] || { fail "the FIFO is no longer a FIFO"; kill "$reader"; }
wait "$reader"
cmp -s "$work/from-fifo.json" "$work/expected.json" || fail "the FIFO's reader did not receive the trace"

# A symlink to a file in another folder, and a dangling one.
mkdir "$work/results"
echo old > "$work/results/trace.json"
ln -s results/trace.json "$work/latest.json"
ln -s results/new.json "$work/dangling.json"
"$program" resolve "$case_file" --trace "$work/latest.json" > /dev/null || fail "resolve --trace symlink failed"
"$program" resolve "$case_file" --trace "$work/dangling.json" > /dev/null || fail "resolve --trace dangling symlink failed"
[ -L "$work/latest.json" ] && [ -L "$work/dangling.json" ] || fail "a symlink is no longer a link"
cmp -s "$work/results/trace.json" "$work/expected.json" || fail "the symlink's target did not receive the trace"
cmp -s "$work/results/new.json" "$work/expected.json" || fail "the dangling symlink's target was not made"
[ "$(ls -A "$work/results" | wc -l)" = 2 ] || fail "left behind in results/: $(ls -A "$work/results")"

# A path that is standard output (redirected to a file) is written as standard output: the trace alone, in place.
ln -s /proc/self/fd/1 "$work/stdout-link"
"$program" resolve "$case_file" --trace "$work/stdout-link" > "$work/redirected.json" 2> "$work/stderr" ||
  fail "resolve --trace (standard output by name) failed"
cmp -s "$work/redirected.json" "$work/expected.json" || fail "standard output by name did not get exactly the trace"
[ -L "$work/stdout-link" ] || fail "the link to standard output was replaced"

# A picture down a pipe, not to a terminal.
"$program" inspect "$case_file" --headless --screenshot - 2> "$work/stderr" | cat > "$work/piped.png" ||
  fail "inspect --screenshot - failed: $(cat "$work/stderr")"
[ "$(head -c 8 "$work/piped.png" | od -An -tx1 | tr -d ' ')" = 89504e470d0a1a0a ] || fail "inspect --screenshot - did not pipe a PNG"
if command -v script > /dev/null; then
  script -qec "'$program' inspect '$case_file' --headless --screenshot -" /dev/null > "$work/terminal" 2>&1
  code=$?
  [ "$code" = 2 ] || fail "a PNG to a terminal: exit code $code, expected 2"
  grep -q "standard output is a terminal" "$work/terminal" || fail "a PNG to a terminal: $(cat "$work/terminal")"
fi
test "$failures" = 0 || exit 1
echo "standard input and output, FIFOs, symlinks and standard output by name behave as a Unix tool's"
