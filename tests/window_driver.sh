# Sourced by the tests/window_*.sh drivers, which run the real viewer under xvfb-run and act on its
# window with xdotool as a user would. They set `binary` first; the viewer's output goes to
# out.txt in the working directory, and finish_viewer prints it with the viewer's exit code.

# Starts the viewer with these arguments and waits (up to 30 s) for its window: $pid, $window.
start_viewer() {
  "$binary" "$@" > out.txt 2>&1 & pid=$!
  window=$(timeout 30 xdotool search --sync --name '^ptview' | head -1)
  if [ -z "$window" ]; then echo "the viewer window never appeared"; kill $pid; exit 1; fi
}

focus_viewer() { xdotool windowfocus "$window" 2>/dev/null; }

statuses() { grep -c '^status ' out.txt; }
# $1: how many `status` lines of the viewer's script to wait for, up to 60 s.
wait_for_status() {
  for _ in $(seq 1 600); do [ "$(statuses)" -ge "$1" ] && return 0; sleep 0.1; done
  echo "timed out waiting for status line $1"; return 1
}

# Waits for the viewer to exit (killed after $1 seconds, 30 by default; the watchdog holds no
# pipe open), prints its output and exit code, and exits with that code.
finish_viewer() {
  ( sleep "${1:-30}"; kill $pid ) >/dev/null 2>&1 & watchdog=$!
  wait $pid; code=$?
  kill $watchdog 2>/dev/null
  cat out.txt
  echo "viewer exit code $code"
  exit $code
}
