#!/usr/bin/env bash
# The manual page help2man made from `impulse-lab --help-all`: a subsection for every command the program lists,
# the exit status and standard-stream sections, plain ASCII (help2man turns other characters into "?"), and it
# renders when man is installed.
set -uo pipefail
program=$1
manual=$2
failures=0
commands=$("$program" --help | sed -n '/^Commands:/,/^$/p' | grep -E '^  [a-z]' | awk '{print $1}')
test -n "$commands" || { echo "no commands in impulse-lab --help"; exit 1; }
for command in $commands; do
  grep -q "^\.SS \"impulse-lab $command[ :]" "$manual" || { echo "no subsection for $command"; failures=$((failures + 1)); }
done
for section in DESCRIPTION OPTIONS COMMANDS '"STANDARD STREAMS"' '"EXIT STATUS"'; do
  grep -q "^\.SH $section\$" "$manual" || { echo "no section $section"; failures=$((failures + 1)); }
done
if LC_ALL=C grep -n '[^ -~]' "$manual"; then echo "characters other than printable ASCII above"; failures=$((failures + 1)); fi
if grep -n '???' "$manual"; then echo "help2man could not convert the characters above"; failures=$((failures + 1)); fi
if command -v man > /dev/null; then
  rendered=$(MANWIDTH=80 man -l "$manual" 2>&1) || { echo "man -l failed"; failures=$((failures + 1)); }
  grep -q "impulse-lab run \[OPTIONS\] SCENE" <<< "$rendered" || { echo "man -l does not show the run command"; failures=$((failures + 1)); }
fi
test "$failures" = 0 || exit 1
echo "the manual page has every command ($(echo $commands | wc -w)), its exit status and standard streams"
