#!/usr/bin/env bash
# Run under xvfb-run in a directory holding scene.json and script.txt (see ScriptedViewerTest):
# the script prints a status line, then waits for a reload of scene.json; between the reloads this
# edits and undoes as a user would, with the pointer over the image:
#   1. an orbit dragged over many frames, then Ctrl+Z;
#   2. Ctrl+Shift+Z;
#   3. three wheel notches (a zoom in one burst), then Ctrl+Z;
#   4. Ctrl+Y.
# Prints the viewer's output.
set -u
source "$(dirname "$0")/window_driver.sh"
binary=$1
start_viewer scene.json --script script.txt
focus_viewer

next_phase() { sleep 0.5; touch scene.json; }  # the script's wait-reload ends

orbit() {  # a drag in steps, so that several frames each move the camera a little
  xdotool mousemove --window "$window" 700 400 sleep 0.3 mousedown 1 sleep 0.2
  for x in 720 740 760 780 800; do xdotool mousemove --window "$window" "$x" 400 sleep 0.15; done
  xdotool mouseup 1 sleep 0.3
}
wheel_burst() {
  xdotool mousemove --window "$window" 700 400 sleep 0.3 click 4 sleep 0.15 click 4 sleep 0.15 click 4 sleep 1
}

wait_for_status 1 && orbit && xdotool key ctrl+z && next_phase
wait_for_status 2 && xdotool key ctrl+shift+z && next_phase
wait_for_status 3 && wheel_burst && xdotool key ctrl+z && next_phase
wait_for_status 4 && xdotool key ctrl+y && next_phase
finish_viewer
