#!/usr/bin/env bash
# Run under xvfb-run in a directory holding scene.json and script.txt (see ScriptedViewerTest):
# the script prints a status line, then waits for a reload of scene.json; between the reloads this
# turns the wheel as a user would: with the pointer arriving over the sidebar from the image and
# the wheel turned at once (within one frame, before ImGui has seen the pointer there), then over
# the image (a zoom). Prints the viewer's output.
set -u
source "$(dirname "$0")/window_driver.sh"
binary=$1
start_viewer scene.json --script script.txt
focus_viewer

next_phase() { touch scene.json; }  # the script's wait-reload ends

# One xdotool command each: the move and the wheel reach the viewer in the same poll of events.
sidebar_scrolls() {
  for _ in 1 2 3 4 5; do
    xdotool mousemove --window "$window" 700 400 sleep 0.4 mousemove --window "$window" 150 400 click 4 click 4
    sleep 0.3
  done
}

wait_for_status 1 && sidebar_scrolls && next_phase
wait_for_status 2 && xdotool mousemove --window "$window" 700 400 sleep 0.4 click 4 click 4 sleep 0.3 && next_phase
finish_viewer
