#!/usr/bin/env bash
# A window without --size fits the display: on a 1024x768 screen (a small laptop's) the lesson opens at 90 % of
# it, not at 1280x800 cut on three sides; --size still has the last word.
set -euo pipefail
program=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export XDG_CONFIG_HOME="$work/config"
size_of() {  # the width and height in a PNG's IHDR chunk, as "W H"
  local header
  header=$(od -An -tx1 -j16 -N8 "$1" | tr -d ' \n')
  echo "$((16#${header:0:8})) $((16#${header:8:8}))"
}
"$here/xvfb.sh" 1024x768 \
  "$program" lesson 1 --screenshot "$work/fit.png" 2> "$work/stderr" || { cat "$work/stderr"; exit 1; }
read -r width height <<< "$(size_of "$work/fit.png")"
# 90 % of what the display leaves free: at most 921 x 691, and not much less (no panel or dock under Xvfb).
{ [ "$width" -le 922 ] && [ "$height" -le 692 ] && [ "$width" -ge 880 ] && [ "$height" -ge 640 ]; } ||
  { echo "a window of ${width}x$height on a 1024x768 screen"; exit 1; }
"$here/xvfb.sh" 1024x768 \
  "$program" lesson 1 --size 800x600 --screenshot "$work/sized.png" 2> "$work/stderr" || { cat "$work/stderr"; exit 1; }
test "$(size_of "$work/sized.png")" = "800 600" || { echo "--size 800x600 gave $(size_of "$work/sized.png")"; exit 1; }
echo "a ${width}x$height window on a 1024x768 screen; --size 800x600 kept"
