#!/usr/bin/env bash
# Run under xvfb-run in a directory holding scene.json and script.txt (see ScriptedViewerTest):
# the script prints a status line, then waits for a reload of scene.json; between the reloads this
# drives the mouse and keyboard as a user would: a drag over the sidebar (which ImGui keeps), a
# drag over the image (an orbit), W held down (flying forward). Prints the viewer's output.
set -u
binary=$1
"$binary" scene.json --script script.txt > out.txt 2>&1 & pid=$!
window=$(timeout 30 xdotool search --sync --name '^ptview' | head -1)
if [ -z "$window" ]; then echo "the viewer window never appeared"; kill $pid; exit 1; fi
xdotool windowfocus "$window" 2>/dev/null

statuses() { grep -c '^status ' out.txt; }
wait_for_status() {  # $1: how many status lines to wait for
  for _ in $(seq 1 300); do [ "$(statuses)" -ge "$1" ] && return 0; sleep 0.1; done
  echo "timed out waiting for status line $1"; return 1
}
drag() {  # $1 $2: from, $3 $4: to, in window coordinates
  xdotool mousemove --window "$window" "$1" "$2" sleep 0.3 mousedown 1 sleep 0.3 \
          mousemove --window "$window" "$3" "$4" sleep 0.3 mouseup 1 sleep 0.5
}
next_phase() { touch scene.json; }  # the script's wait-reload ends

wait_for_status 1 && drag 150 600 300 600 && next_phase   # over the sidebar
wait_for_status 2 && drag 700 400 850 400 && next_phase   # over the image
wait_for_status 3 && xdotool mousemove --window "$window" 700 400 keydown w sleep 0.6 keyup w sleep 0.3 && next_phase
( sleep 30; kill $pid ) >/dev/null 2>&1 & watchdog=$!
wait $pid; code=$?
kill $watchdog 2>/dev/null
cat out.txt
echo "viewer exit code $code"
exit $code
