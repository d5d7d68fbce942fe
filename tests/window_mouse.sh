#!/usr/bin/env bash
# Run under xvfb-run in a directory holding scene.json and script.txt (see ScriptedViewerTest):
# the script prints a status line, then waits for a reload of scene.json; between the reloads this
# drives the mouse and keyboard as a user would: a drag over the sidebar (which ImGui keeps), a
# drag over the image (an orbit), W held down (flying forward). Prints the viewer's output.
set -u
source "$(dirname "$0")/window_driver.sh"
binary=$1
start_viewer scene.json --script script.txt
focus_viewer

drag() {  # $1 $2: from, $3 $4: to, in window coordinates
  xdotool mousemove --window "$window" "$1" "$2" sleep 0.3 mousedown 1 sleep 0.3 \
          mousemove --window "$window" "$3" "$4" sleep 0.3 mouseup 1 sleep 0.5
}
next_phase() { touch scene.json; }  # the script's wait-reload ends

wait_for_status 1 && drag 150 600 300 600 && next_phase   # over the sidebar
wait_for_status 2 && drag 700 400 850 400 && next_phase   # over the image
wait_for_status 3 && xdotool mousemove --window "$window" 700 400 keydown w sleep 0.6 keyup w sleep 0.3 && next_phase
finish_viewer
