#!/usr/bin/env bash
# Run under xvfb-run in a directory holding scene.json and script.txt (see ScriptedViewerTest):
# the script prints a status line, then waits for a reload of scene.json; meanwhile this
# Ctrl+clicks on the image at a quarter of its width from the left (a window of 380 + 768 pixels:
# the sidebar, then the image), as a user focusing on what is there would, then touches the file.
# Prints the viewer's output.
set -u
source "$(dirname "$0")/window_driver.sh"
binary=$1
start_viewer scene.json --script script.txt
focus_viewer
wait_for_status 1 && xdotool mousemove --window "$window" 572 384 sleep 0.3 keydown ctrl sleep 0.2 \
                             click 1 sleep 0.3 keyup ctrl sleep 0.5 && touch scene.json
finish_viewer
