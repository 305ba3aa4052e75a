#!/usr/bin/env bash
# Presses the navigation keys in the inspector's real window (under a virtual X server), then clicks its
# "Export table" button and checks that the exported table is the step the keys lead to:
# → → → (step 4 of contact 0), ↓ (contact 1), PgDn (the velocity phase), → (its first iteration's step 2).
set -euo pipefail
program=$1
case_file=$2
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/drive.sh" <<DRIVE
#!/usr/bin/env bash
set -euo pipefail
cd "$work"
source "$here/window_keys.sh"
start_window stderr "$program" inspect "$case_file" --size 1280x800
for key in Right Right Right Down Next Right; do press "\$key"; done
sleep 0.5
# The Export panel's second button, "Export table", at the layout's place for a 1280x800 window.
window_alive "before the click on Export table"
xdotool mousemove --window "\$window_id" 930 760 click 1
wait_for_file table.csv "exported table"
stop_window
DRIVE
chmod +x "$work/drive.sh"
"$here/xvfb.sh" 1600x1000 "$work/drive.sh"
test -s "$work/table.csv" || { echo "no table exported"; cat "$work/stderr"; exit 1; }
# The highlighted rows are the velocity phase's contact_velocity, after its choice step.
grep -q '^choice,contact,0,' "$work/table.csv" || { echo "not the velocity phase's first iteration"; cat "$work/table.csv"; exit 1; }
grep -q '^contact_velocity,contact_velocity,.*,yes$' "$work/table.csv" || { echo "wrong step"; cat "$work/table.csv"; exit 1; }
echo "keys and the export button work in the window"
