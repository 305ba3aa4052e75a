# Sourced by the scripts that drive the real window with xdotool under Xvfb: start the program, wait on its
# window, press keys, and stop it, failing with the program's exit status and its stderr whenever it is gone.
# Without these checks a program that died before its window appeared went unnoticed: xdotool sends keys and
# clicks to an empty window id without an error, and the test failed much later on a missing output, with no
# word of why.

# start_window STDERR_FILE COMMAND...: runs COMMAND in the background and waits until its window is visible.
# Sets window_pid and window_id.
start_window() {
  window_stderr=$1
  shift
  "$@" 2> "$window_stderr" &
  window_pid=$!
  window_id=
  # Up to a minute: under CI's load (two cores, two tests at a time, sanitizers) the first frame can be slow.
  local tries
  for tries in $(seq 600); do
    window_alive "before its window appeared" || return 1
    window_id=$(xdotool search --onlyvisible --name "Impulse Lab" 2>/dev/null | head -1) || true
    [ -n "$window_id" ] && break
    sleep 0.1
  done
  [ -n "$window_id" ] || { echo "no window appeared in 60 s"; cat "$window_stderr"; return 1; }
  # Let the first frames lay the window out before the first key.
  sleep 1.5
}

# window_alive WHEN: fails, saying how the program ended and what it wrote, if it is no longer running.
window_alive() {
  kill -0 "$window_pid" 2>/dev/null && return 0
  local status=0
  wait "$window_pid" || status=$?
  echo "the program exited $1, with status $status:"
  cat "$window_stderr"
  return 1
}

# press KEY...: sends the keys to the window, after checking it is still there.
press() {
  window_alive "before the keys $*" || return 1
  xdotool key --window "$window_id" "$@"
  sleep 0.4
}

# type_text TEXT: types TEXT into the window, after checking it is still there.
type_text() {
  window_alive "before typing $1" || return 1
  xdotool type --window "$window_id" "$1"
  sleep 0.3
}

# wait_for_file FILE WHAT: waits up to 30 s for FILE to be non-empty while the program runs.
wait_for_file() {
  local tries
  for tries in $(seq 300); do
    [ -s "$1" ] && return 0
    window_alive "before $2" || return 1
    sleep 0.1
  done
  echo "no $2 in 30 s"
  cat "$window_stderr"
  return 1
}

# stop_window: ends the program if it still runs.
stop_window() {
  kill "$window_pid" 2>/dev/null || true
  wait "$window_pid" 2>/dev/null || true
}
