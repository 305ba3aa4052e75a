#!/usr/bin/env bash
# Opens the inspector's real window on a virtual X display, drives it with a script that ends with a
# screenshot, and checks the picture: the window mode starts, renders and closes by itself.
set -euo pipefail
program=$1
case_file=$2
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/script.txt" <<SCRIPT
next step 2
goto phase=velocity,step=impulse
export table $work/table.csv
SCRIPT
# A server of its own (xvfb.sh), so parallel tests do not collide.
"$here/xvfb.sh" 1600x1000 \
  "$program" inspect "$case_file" --size 1200x760 --script "$work/script.txt" --screenshot "$work/window.png" \
  2> "$work/stderr" || { cat "$work/stderr"; exit 1; }
test -s "$work/table.csv"
# The PNG header and the size in its IHDR chunk: 1200 x 760.
header=$(od -An -tx1 -N24 "$work/window.png" | tr -d ' \n')
test "${header:0:16}" = "89504e470d0a1a0a" || { echo "not a PNG"; exit 1; }
test "${header:32:16}" = "000004b0000002f8" || { echo "wrong size: ${header:32:16}"; exit 1; }
# Nothing on stderr: no Wayland or driver noise.
if [ -s "$work/stderr" ]; then cat "$work/stderr"; exit 1; fi
echo "window rendered and saved $(stat -c %s "$work/window.png") bytes"
