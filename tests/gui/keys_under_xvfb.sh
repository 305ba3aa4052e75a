#!/usr/bin/env bash
# Presses the navigation keys in the inspector's real window (under a virtual X server), then clicks its
# "Export table" button and checks that the exported table is the step the keys lead to:
# → → → (step 4 of contact 0), ↓ (contact 1), PgDn (the velocity phase), → (its first iteration's step 2).
set -euo pipefail
program=$1
case_file=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cat > "$work/drive.sh" <<DRIVE
#!/usr/bin/env bash
set -euo pipefail
cd "$work"
"$program" inspect "$case_file" --size 1280x800 2> stderr &
pid=\$!
# Generous waits: under CI's load (two cores, two tests at a time) the first frames can take a second.
for i in \$(seq 150); do win=\$(xdotool search --onlyvisible --name "Impulse Lab" 2>/dev/null | head -1) && [ -n "\$win" ] && break; sleep 0.1; done
sleep 1.5
for key in Right Right Right Down Next Right; do xdotool key --window "\$win" "\$key"; sleep 0.4; done
sleep 0.5
# The Export panel's second button, "Export table", at the layout's place for a 1280x800 window.
xdotool mousemove --window "\$win" 930 760 click 1
for i in \$(seq 150); do [ -s table.csv ] && break; sleep 0.1; done
kill \$pid
wait \$pid || true
DRIVE
chmod +x "$work/drive.sh"
xvfb-run -a -s "-screen 0 1600x1000x24" "$work/drive.sh"
test -s "$work/table.csv" || { echo "no table exported"; cat "$work/stderr"; exit 1; }
# The highlighted rows are the velocity phase's contact_velocity, after its choice step.
grep -q '^choice,contact,0,' "$work/table.csv" || { echo "not the velocity phase's first iteration"; cat "$work/table.csv"; exit 1; }
grep -q '^contact_velocity,contact_velocity,.*,yes$' "$work/table.csv" || { echo "wrong step"; cat "$work/table.csv"; exit 1; }
echo "keys and the export button work in the window"
