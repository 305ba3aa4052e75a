#!/usr/bin/env bash
# Takes a small lesson in the inspector's real window (under a virtual X server) with the keys alone, as a
# student would: → to the question, a wrong number and Enter, the right one and Enter, Enter to go on, Tab to
# an option and Enter, Esc to close. The progress file must then hold what the keys did.
set -euo pipefail
program=$1
case_file=$2
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/course" "$work/config"
cat > "$work/course/01-keys.md" <<LESSON
\`\`\`json
{
  "title": "Keys",
  "scene": "$case_file",
  "steps": [
    {"id": "closing", "at": "phase=preparation,contact=0,step=contact_velocity"},
    {"id": "desired", "at": "phase=velocity,iteration=0,step=desired_delta_velocity",
     "question": {"kind": "predict", "prompt": "What desired change?", "value": "desired_delta_velocity",
                  "tolerance": {"relative": 0.02}}},
    {"id": "model", "at": "phase=velocity,iteration=0,step=impulse",
     "question": {"kind": "choose", "prompt": "Which impulse?", "value": "impulse_model",
                  "options": [{"label": "frictionless", "value": "frictionless"},
                              {"label": "static", "value": "static"}]}}
  ]
}
\`\`\`

## closing
The \`contact_velocity\`.

## desired
The \`desired_delta_velocity\`.

## model
The \`impulse_model\`.
LESSON
cat > "$work/drive.sh" <<DRIVE
#!/usr/bin/env bash
set -euo pipefail
cd "$work"
source "$here/window_keys.sh"
XDG_CONFIG_HOME="$work/config" start_window stderr "$program" lesson 1 --lessons "$work/course" --size 1280x800
press Right                 # step 2: its answer field has the keyboard
type_text 5
press Return                # wrong: 33 % too low; the field gets the keyboard back, its text selected
type_text 7.5
press Return                # right
press Return                # answered: Enter goes on to step 3
press Tab                   # the first option
press Return                # checked: right
press Escape                # the window closes
for i in \$(seq 100); do kill -0 \$window_pid 2>/dev/null || break; sleep 0.1; done
if kill -0 \$window_pid 2>/dev/null; then echo "Esc did not close the window"; cat stderr; stop_window; exit 1; fi
wait \$window_pid
DRIVE
chmod +x "$work/drive.sh"
"$here/xvfb.sh" 1600x1000 "$work/drive.sh"
progress="$work/config/impulse-lab/progress.json"
test -s "$progress" || { echo "no progress saved"; cat "$work/stderr"; exit 1; }
# The listing counts the desired Δv right after a retry and the option right at the first try.
listing=$(XDG_CONFIG_HOME="$work/config" "$program" lesson --lessons "$work/course")
echo "$listing" | grep -q "1 right at the first try, 1 right after retries" || { echo "$listing"; cat "$progress"; exit 1; }
grep -q '"last_step": 2' "$progress" || { cat "$progress"; exit 1; }
grep -q '"answer": "7.5"' "$progress" || { cat "$progress"; exit 1; }
echo "the lesson's keys answer, retry, choose, go on and close the window"
