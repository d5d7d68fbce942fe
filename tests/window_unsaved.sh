#!/usr/bin/env bash
# Run under xvfb-run in a directory holding scene.json and script.txt (see ScriptedViewerTest):
# the script edits the scene and prints status lines, each followed by a wait-reload. After each
# status line this records the window's title in titles.txt, then does one step as a user would
# (the arguments after the binary, one per status line): a key for xdotool, `close` (the window
# manager's close button) or `none`; then writes whether the viewer still runs to steps.txt and
# touches scene.json, which ends the script's wait-reload. Prints the viewer's output and exits
# with its exit code.
set -u
binary=$1; shift
here=$(dirname "$0")
"$binary" scene.json --script script.txt > out.txt 2>&1 & pid=$!
window=$(timeout 30 xdotool search --sync --name '^ptview' | head -1)
if [ -z "$window" ]; then echo "the viewer window never appeared"; kill $pid; exit 1; fi
xdotool windowfocus "$window" 2>/dev/null

statuses() { grep -c '^status ' out.txt; }
wait_for_status() {  # $1: how many status lines to wait for
  for _ in $(seq 1 300); do [ "$(statuses)" -ge "$1" ] && return 0; sleep 0.1; done
  echo "timed out waiting for status line $1"; return 1
}
count=0
for step in "$@"; do
  count=$((count + 1))
  wait_for_status $count || break
  sleep 0.5  # the title follows the edits within a quarter of a second
  xdotool getwindowname "$window" >> titles.txt
  case $step in
    none) ;;
    close) /usr/bin/python3 "$here/x11_close_window.py" "$window" ;;
    *) xdotool key "$step" ;;
  esac
  sleep 1  # a few frames, at a slow software rasterizer's pace
  if kill -0 $pid 2>/dev/null; then echo "running after $step" >> steps.txt; else echo "exited after $step" >> steps.txt; fi
  touch scene.json
done
( sleep 30; kill $pid ) >/dev/null 2>&1 & watchdog=$!
wait $pid; code=$?
kill $watchdog 2>/dev/null
cat out.txt
echo "viewer exit code $code"
exit $code
