#!/usr/bin/env bash
# xvfb.sh WIDTHxHEIGHT COMMAND...: runs COMMAND on a virtual X server of its own with a screen of that size, and
# exits with COMMAND's status.
#
# In place of `xvfb-run -a`, which let one test in about a hundred fail under CI's parallel tests with SDL's "x11 not
# available": xvfb-run picks a display number by looking for a free lock file and then starts the server on it, so
# two tests starting at once, or one starting while another's server is still shutting down, can meet on the same
# display. Here the server picks the number itself (-displayfd), taking it as it starts, and tells it once it
# accepts connections; and the server is waited for until it has gone, so it never outlives its test.
set -euo pipefail
size=$1
shift
dir=$(mktemp -d)
server=
cleanup() {
  if [ -n "$server" ]; then
    kill "$server" 2>/dev/null || true
    wait "$server" 2>/dev/null || true
  fi
  rm -rf "$dir"
}
trap cleanup EXIT
mkfifo "$dir/display"
Xvfb -displayfd 3 -screen 0 "${size}x24" -nolisten tcp 3> "$dir/display" 2> "$dir/server.log" &
server=$!
# The number arrives when the server is ready; nothing (end of file) if it failed to start.
number=
read -r -t 60 number < "$dir/display" || true
if [ -z "$number" ]; then
  echo "the virtual X server did not start:"
  cat "$dir/server.log"
  exit 1
fi
status=0
DISPLAY=":$number" "$@" || status=$?
exit "$status"
